let suite = ("cli", ([] : unit Alcotest.test_case list))
