(* The closure engine against the machine on what the spec/ cases show one at a time: the user
   level of NOSTEPIN routines (§7.3: RaiseToUser \Continue whose user handler ends by RAISE or
   EXIT, \BreakOff with \ErrorNumber and RETRY, an error leaving a NOSTEPIN function, R-7.3-o to
   R-7.3-q) and §7.4's kept program pointer inside NOSTEPIN routines, the handler ending every way
   (R-7.4-m, R-7.6-m). Same events (with their virtual times) and the same outcome. *)

module M = Rapid_semantics.Machine
module E = Test_engines

let load ?io texts =
  let modules = List.map (fun (name, text) ->
      match Rapid_syntax.Parse.parse_string ~name:(name ^ ".mod") text with
      | Ok m -> m
      | Error d -> Alcotest.failf "%s" (Rapid_syntax.Diagnostic.to_string d)) texts in
  match Rapid_load.Session.load_modules ?io modules with
  | Ok l -> l.program
  | Error _ -> Alcotest.fail "does not check"

let both ?(io = Rapid_controller.Io_config.empty) texts =
  let program = load ~io texts in
  let run f = f (Rapid_controller.World.create io) in
  let m_events, m_outcome =
    run (fun world -> E.machine_run ~world Rapid_runtime.Limits.default program ~entry:"main" ~max_steps:1_000_000) in
  let c_events, c_outcome =
    run (fun world -> E.closure_run ~world Rapid_runtime.Limits.default program ~entry:"main" ~fuel:1_000_000) in
  Alcotest.(check string) "outcome" (E.outcome_text m_outcome) (E.outcome_text c_outcome);
  (match E.difference m_events c_events with None -> () | Some d -> Alcotest.failf "%s" d);
  List.filter_map (function Rapid_runtime.Event.Output s -> Some s | _ -> None) c_events

let user_text = {rapid|MODULE user
  VAR num count := 0;
  PROC main()
    TPWrite "start";
    outer_raise;
    TPWrite "after raise";
    breakoff_case;
    TPWrite "after breakoff";
    unhandled_case;
    TPWrite "after unhandled";
    exit_case;
    TPWrite "not reached";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
  PROC outer_raise()
    tool_continue 7;
  ERROR
    TPWrite "outer_raise handler " \Num:=ERRNO;
    RAISE;
  UNDO
    TPWrite "outer_raise undo";
  ENDPROC
  PROC breakoff_case()
    tool_breakoff;
    TPWrite "breakoff next";
  ERROR
    TPWrite "breakoff handler " \Num:=ERRNO;
    count := count + 1;
    IF count < 3 RETRY;
    TRYNEXT;
  ENDPROC
  PROC unhandled_case()
    VAR num x;
    x := tool_fn(0);
    TPWrite "x " \Num:=x;
  ERROR
    TPWrite "unhandled_case handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
  PROC exit_case()
    tool_continue 9;
  ERROR
    TPWrite "exit_case handler " \Num:=ERRNO;
    EXIT;
  UNDO
    TPWrite "exit_case undo";
  ENDPROC
ENDMODULE
|rapid}

let tools_text = {rapid|MODULE tools (NOSTEPIN)
  VAR errnum mine := -1;
  PROC tool_continue(num n)
    inner_continue n;
  UNDO
    TPWrite "tool_continue undo";
  ENDPROC
  PROC inner_continue(num n)
    RAISE n;
  ERROR
    RaiseToUser \Continue;
  UNDO
    TPWrite "inner_continue undo";
  ENDPROC
  PROC tool_breakoff()
    inner_breakoff;
  UNDO
    TPWrite "tool_breakoff undo";
  ENDPROC
  PROC inner_breakoff()
    BookErrNo mine;
    RAISE 5;
  ERROR
    RaiseToUser \BreakOff \ErrorNumber:=mine;
  UNDO
    TPWrite "inner_breakoff undo";
  ENDPROC
  FUNC num tool_fn(num d)
    RETURN 1 / d;
  UNDO
    TPWrite "tool_fn undo";
  ENDFUNC
ENDMODULE
|rapid}

let user_level () =
  let out = both [ ("user", user_text); ("tools", tools_text) ] in
  (* \Continue, RAISE in the user handler: the NOSTEPIN routines are dropped without UNDO. *)
  Alcotest.(check bool) "no UNDO of the NOSTEPIN routines" false (List.mem "inner_continue undo" out);
  Alcotest.(check bool) "BreakOff: the routines above run UNDO" true (List.mem "tool_breakoff undo" out);
  Alcotest.(check bool) "BreakOff: not the one that raised" false (List.mem "inner_breakoff undo" out);
  Alcotest.(check bool) "EXIT in the user handler" true (List.mem "exit_case undo" out)

let main_text = {rapid|MODULE amain
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num tries := 0;
  PROC main()
    MoveJ p10, v1000, fine, tool0;
    MoveJ \Conc, p20, v10, fine, tool0;
    waiter;
    TPWrite "after";
  ERROR
    tries := tries + 1;
    TPWrite "main handler " \Num:=ERRNO;
    IF tries = 1 RETRY;
    RETURN;
  ENDPROC
ENDMODULE
|rapid}

let async_tools_text = {rapid|MODULE atools (NOSTEPIN)
  PROC waiter()
    inner_wait;
  UNDO
    TPWrite "waiter undo";
  ENDPROC
  PROC inner_wait()
    WaitTime 5;
    TPWrite "waited";
  UNDO
    TPWrite "inner_wait undo";
  ENDPROC
ENDMODULE
|rapid}

(* The stimulus of both tests: a collision at 3 s and another at 6 s. *)
let two_collisions () =
  match Rapid_controller.Io_config.parse ~file:"c.io" "at 3 collision\nat 6 collision\n" with
  | Ok io -> io | Error m -> Alcotest.fail m

let kept_pointer () =
  let io = two_collisions () in
  List.iter (fun ending ->
      let text = Str.global_replace (Str.regexp_string "IF tries = 1 RETRY;") ("IF tries = 1 " ^ ending ^ ";") main_text in
      let out = both ~io [ ("amain", text); ("atools", async_tools_text) ] in
      Alcotest.(check bool) (ending ^ ": the handler ran") true (List.mem "main handler 1108" out))
    [ "RETRY"; "TRYNEXT"; "RETURN"; "RAISE"; "EXIT" ]

(* An asynchronous error that the kept handler lets go (RAISE) stays asynchronous where it is
   handled next: TRYNEXT there executes as RETRY (R-7.4-m); a recovery point takes it or not. *)
let propagated_text = {rapid|MODULE e1
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    middle;
    TPWrite "main after";
  ERROR (LONG_JMP_ALL_ERR)
    TPWrite "main recovery " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
  PROC middle()
    MoveJ p10, v1000, fine, tool0;
    MoveJ \Conc, p20, v10, fine, tool0;
    deeper;
    TPWrite "middle after";
  ERROR
    TPWrite "middle handler " \Num:=ERRNO;
    WaitTime 1;
    TPWrite "middle waited";
    RAISE;
  UNDO
    TPWrite "middle undo";
  ENDPROC
  PROC deeper()
    WaitTime 10;
    TPWrite "deeper waited";
  ERROR
    TPWrite "deeper handler";
    RETRY;
  UNDO
    TPWrite "deeper undo";
  ENDPROC
ENDMODULE
|rapid}

let kept_error_propagated () =
  let io = two_collisions () in
  let replace a b text = Str.global_replace (Str.regexp_string a) b text in
  List.iter (fun (middle_end, recovery, main_end) ->
      let text = propagated_text
                 |> replace "    RAISE;\n" ("    " ^ middle_end ^ "\n")
                 |> replace "  ERROR (LONG_JMP_ALL_ERR)" recovery
                 |> replace "    TRYNEXT;\n" ("    " ^ main_end ^ "\n") in
      let out = both ~io [ ("e1", text) ] in
      Alcotest.(check bool) "the kept handler ran" true (List.mem "middle handler 1108" out))
    [ ("RAISE;", "  ERROR (LONG_JMP_ALL_ERR)", "TRYNEXT;"); ("RAISE;", "  ERROR", "TRYNEXT;");
      ("RAISE;", "  ERROR", "RETURN;"); ("RETURN;", "  ERROR", "TRYNEXT;"); ("EXIT;", "  ERROR", "TRYNEXT;");
      ("TRYNEXT;", "  ERROR (LONG_JMP_ALL_ERR)", "RETRY;") ]

let suite =
  ( "engines-kept",
    [ Alcotest.test_case "machine = closure: the user level of NOSTEPIN routines" `Quick user_level;
      Alcotest.test_case "machine = closure: a kept program pointer in NOSTEPIN routines" `Quick kept_pointer;
      Alcotest.test_case "machine = closure: a kept error raised on, TRYNEXT as RETRY" `Quick kept_error_propagated ] )
