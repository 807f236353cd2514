(* Issue 21, items 5 and 8: the work of a run is bounded by what the user can see. An error
   recovered by calling the routine again from its handler costs the same at every depth in both
   engines (a raise used to copy the call chain in the closure engine: quadratic), and waits
   count against the step limit. *)

module M = Rapid_semantics.Machine
module C = Rapid_closure.Closure_engine

(* p raises at every level and its handler calls p again, [depth] levels deep (§7.1, §4.11). *)
let handler_recursion depth =
  Printf.sprintf
    "MODULE rec\n  VAR num n := 0;\n  PROC p(num k)\n    n := n + 1;\n    RAISE 43;\n  ERROR\n\
    \    IF k < %d p k + 1;\n    RETURN;\n  ENDPROC\n  PROC main()\n    p 1;\n\
    \    TPWrite \"n \" \\Num:=n;\n  ENDPROC\nENDMODULE\n" depth

let limits = { Rapid_runtime.Limits.default with max_call_depth = 30_000 }

(* Bytes allocated by [f], minor and major heaps together. *)
let allocated f =
  Gc.full_major ();
  let before = Gc.allocated_bytes () in
  f ();
  Gc.allocated_bytes () -. before

let closure program () =
  match C.run ~host:(Rapid_run.Run.setup ()).host ~limits ~all_events:false program ~entry:"main" with
  | Ok { outcome = Ended; _ } -> ()
  | Ok { outcome; _ } -> Alcotest.failf "closure: %s" (Test_engines.outcome_text outcome)
  | Error m -> Alcotest.fail m

let machine program () =
  match M.start ~host:(Rapid_run.Run.setup ()).host ~limits program ~entry:"main" with
  | Error m -> Alcotest.fail m
  | Ok cfg ->
      while M.outcome cfg = Running do ignore (M.step cfg) done;
      if M.outcome cfg <> Ended then Alcotest.failf "machine: %s" (Test_engines.outcome_text (M.outcome cfg))

(* Per level, the allocation at 8,000 levels stays that at 2,000 (a copy of the chain at each
   raise makes it four times as much), and so does the deepest: 20,000 levels in the machine,
   12,000 in the closure engine (its native stack, 8 MB, ends a run at about 17,000). *)
let per_level_bounded () =
  let per_level run depth =
    let program = Test_engines.load_text "rec" (handler_recursion depth) in
    allocated (run program) /. float_of_int depth in
  List.iter (fun (name, run, depth) ->
      let small = per_level run 2_000 and large = per_level run 8_000 in
      if large > 1.5 *. small then
        Alcotest.failf "%s: %.0f bytes a level at 2,000 levels, %.0f at 8,000" name small large;
      let deepest = per_level run depth in
      if deepest > 1.5 *. small then
        Alcotest.failf "%s: %.0f bytes a level at 2,000 levels, %.0f at %d" name small deepest depth)
    [ ("closure", closure, 12_000); ("machine", machine, 20_000) ]

let engines_agree () =
  let events, outcome = Test_engines.agree ~limits (Test_engines.load_text "rec" (handler_recursion 5_000)) in
  Alcotest.(check string) "outcome" "ended" (Test_engines.outcome_text outcome);
  Alcotest.(check bool) "n 5000" true (List.mem (Rapid_runtime.Event.Output "n 5000") events)

(* Item 8: each poll of a WaitUntil and each move of the clock in a wait is a unit of work, as
   it is a step of the machine, so that --max-steps ends a wait that --max-time would let run
   for a very long time: 1,000 polls of a second, or 10,000 timer firings queued behind
   IDisable, do not fit in 200 units of fuel or 200 steps. *)
let waits_spend_fuel () =
  let bodies = [ "WaitUntil FALSE \\PollRate:=1;";
                 "CONNECT t WITH tr;\n    IDisable;\n    ITimer 0.1, t;\n    WaitTime 1000;" ] in
  List.iter (fun body ->
      let text = Printf.sprintf "MODULE w\n  VAR intnum t;\n  TRAP tr\n  ENDTRAP\n  PROC main()\n    %s\n\
                                \    TPWrite \"end\";\n  ENDPROC\nENDMODULE\n" body in
      let program = Test_engines.load_text "w" text in
      let world () = Rapid_controller.World.create ~max_time:2000. Rapid_controller.Io_config.empty in
      (match C.run ~host:(Rapid_run.Run.setup ~controller:(world ()) ()).host ~fuel:200 ~all_events:false program ~entry:"main" with
       | Ok { outcome = Running; fuel_used } ->
           Alcotest.(check bool) "within the fuel" true (fuel_used <= 200)
       | Ok { outcome; _ } -> Alcotest.failf "closure, %s: %s" body (Test_engines.outcome_text outcome)
       | Error m -> Alcotest.fail m);
      match M.start ~host:(Rapid_run.Run.setup ~controller:(world ()) ()).host program ~entry:"main" with
      | Error m -> Alcotest.fail m
      | Ok cfg ->
          while M.outcome cfg = Running && M.steps cfg < 200 do ignore (M.step cfg) done;
          Alcotest.(check bool) ("machine, still waiting: " ^ body) true (M.outcome cfg = Running))
    bodies

let suite =
  ( "waits",
    [ Alcotest.test_case "recovery by recursion: the same bytes a level at any depth" `Quick per_level_bounded;
      Alcotest.test_case "recovery by recursion: machine = closure" `Quick engines_agree;
      Alcotest.test_case "a wait's polls and moves of the clock spend fuel" `Quick waits_spend_fuel ] )
