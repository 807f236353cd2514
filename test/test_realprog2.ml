(* What the second real-programs campaign (doc/real-programs.md) found, pinned: the two engines
   refuse a run the same way when an initial value of module data names a data object that is
   neither declared nor installed (--allow-unknown: a module of a program whose other modules are
   missing, `VAR robtarget p := A_1;`). Reading the unknown name is ERR_REFUNKDAT (ch. 12), as
   in a statement; the machine said ERR_EXECPHR there before. A run with no entry routine is
   refused with the same words by both. *)

open Rapid_syntax
open Rapid_load
open Rapid_semantics
module M = Machine
module C = Rapid_closure.Closure_engine

let load name text =
  match Parse.parse_string ~name:(name ^ ".mod") text with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Session.load_modules ~allow_unknown:true [ m ] with
      | Ok l -> l.program
      | Error _ -> Alcotest.failf "%s does not check with --allow-unknown" name)

let machine_refusal p ~entry =
  match M.start ~host:(Rapid_run.Run.setup ()).host p ~entry with Ok _ -> "(runs)" | Error m -> m

let closure_refusal p ~entry =
  match C.events ~host:(Rapid_run.Run.setup ()).host p ~entry with Ok _ -> "(runs)" | Error m -> m

let check_both what p ~entry expected =
  Alcotest.(check string) (what ^ ": machine") expected (machine_refusal p ~entry);
  Alcotest.(check string) (what ^ ": closure engine") expected (closure_refusal p ~entry)

let unknown_in_initial_value () =
  let p = load "unknown_init" {rapid|MODULE unknown_init
  VAR num a := b;
  PROC main()
    TPWrite "a" \Num:=a;
  ENDPROC
ENDMODULE|rapid} in
  check_both "whole name" p ~entry:"main" "the initial value of a: ERR_REFUNKDAT";
  let p = load "unknown_component" {rapid|MODULE unknown_component
  CONST num a := 1;
  VAR num c := q.x + a;
  PROC main()
  ENDPROC
ENDMODULE|rapid} in
  check_both "component of an unknown name" p ~entry:"main" "the initial value of c: ERR_REFUNKDAT"

let no_entry () =
  let p = load "no_entry" {rapid|MODULE no_entry
  PROC other()
  ENDPROC
ENDMODULE|rapid} in
  check_both "no main" p ~entry:"main"
    "no procedure main without parameters to run (§9.1): run the task's procedure other with --entry other"

(* A long path of zone points (a CAD path exported as thousands of fly-by MoveL) made every
   check of the running moves walk the queue once per queued move; [Planner.segment_spans]
   walks it once for all. It must answer what [Planner.segment_span] answers for every move, at
   every point of a run. *)
let spans_agree () =
  let open Rapid_motion_model in
  let kin = Kinematics.create Robot.irb120 in
  let p = Planner.create ~joints:[| 0.; 0.; 0.; 0.; 90.; 0. |] kin in
  let speed = Option.get (Motion_data.find Motion_data.speeddata "v100") in
  let zone n = Option.get (Motion_data.find Motion_data.zonedata n) in
  let down = { Geom.q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } in
  let conf0 = { Kinematics.cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } in
  let ids = ref [] and seen = ref 0 in
  for i = 0 to 59 do
    let x = 300. +. float_of_int (i mod 7) *. 15. and y = float_of_int (i mod 5) *. 12. -. 24. in
    let target = { Frames.pose = { Geom.trans = { Geom.x; y; z = 400. }; rot = down }; conf = conf0 } in
    let z = if i mod 13 = 12 then "fine" else if i mod 2 = 0 then "z1" else "z10" in
    (match Planner.plan p ~now:(float_of_int i *. 0.05) (Planner.move speed (zone z) (Linear target)) with
     | Ok r -> ids := r.id :: !ids
     | Error e -> Alcotest.failf "plan %d: %s" i (Motion_error.name e));
    let all = List.rev !ids in
    let spans = Planner.segment_spans p all in
    List.iter (fun id ->
        let one = Planner.segment_span p id and many = spans id in
        if one <> None then incr seen;
        if one <> many then Alcotest.failf "move %d after %d moves: the spans differ" id (i + 1)) all
  done;
  if !seen < 60 then Alcotest.failf "only %d spans in the queue" !seen

let suite =
  ( "realprog2",
    [ Alcotest.test_case "unknown name in an initial value: ERR_REFUNKDAT in both engines" `Quick unknown_in_initial_value;
      Alcotest.test_case "no entry routine: one refusal in both engines" `Quick no_entry;
      Alcotest.test_case "segment_spans answers segment_span for every queued move" `Quick spans_agree ] )
