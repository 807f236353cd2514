let suite = ("parser", ([] : unit Alcotest.test_case list))
