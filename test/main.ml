let () =
  Alcotest.run "rapid-sem"
    [ Test_lexer.suite;
      Test_parser.suite;
      Test_printer.suite;
      Test_ast_erase.suite;
      Test_roundtrip.suite;
      Test_fuzz.suite;
      Test_cli.suite;
      Test_messages.suite;
      Test_realworld.suite;
      Test_tables.suite;
      Test_semantics.suite;
      Test_values.suite;
      Test_campaign.suite;
      Test_memory.suite;
      Test_motion.suite;
      Test_ext_axes.suite;
      Test_controller.suite;
      Test_installed.suite;
      Test_check_output.suite;
      Test_robustness.suite;
      Test_motion_run.suite;
      Test_motion_memory.suite;
      Test_impl_runner.suite;
      Test_services.suite;
      Test_debugger.suite;
      Test_engines.suite;
      Test_closure_call.suite;
      Test_closure_fused.suite;
      Test_engines_kept.suite;
      Test_start_sharing.suite;
      Test_tasks.suite;
      Test_observation.suite;
      Test_realprog2.suite;
    ]
