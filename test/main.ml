let () =
  Alcotest.run "rapid-sem"
    [ Test_lexer.suite; Test_parser.suite; Test_printer.suite; Test_roundtrip.suite;
      Test_fuzz.suite; Test_cli.suite; Test_messages.suite;
      Test_realworld.suite; Test_tables.suite; Test_semantics.suite;
      Test_values.suite; Test_engines.suite ]
