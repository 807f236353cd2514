let suite = ("fuzz", ([] : unit Alcotest.test_case list))
