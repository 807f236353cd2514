let suite = ("printer", ([] : unit Alcotest.test_case list))
