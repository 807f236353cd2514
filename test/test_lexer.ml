let suite = ("lexer", ([] : unit Alcotest.test_case list))
