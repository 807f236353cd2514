let suite = ("roundtrip", ([] : unit Alcotest.test_case list))
