(* The event routines of a controller backup (SYS.cfg's CAB_EXEC_HOOKS; doc/rulings.md R-bk-6,
   R-bk-8 to R-bk-10): which a backup's tasks run and in which order (lib/load/backup.ml), the
   sequence of routines both engines run alike (Machine.start and Closure_engine.run with
   ~before and ~after), and a backup's run byte for byte the same twice. *)

open Rapid_syntax
module M = Rapid_semantics.Machine
module C = Rapid_closure.Closure_engine
module Backup = Rapid_load.Backup
module E = Rapid_runtime.Event

let ( // ) = Filename.concat

let write = Test_backup.write
let temp_backup = Test_backup.temp_backup

let contains part w =
  let n = String.length part in
  let rec at i = i + n <= String.length w && (String.sub w i n = part || at (i + 1)) in
  at 0

(* R-bk-8: POWER_ON in every task; RESET, START before the entry routine and STOP after it in a
   NORMAL task only; within one event by -SeqNo, then SYS.cfg's order; -AllTask, -AllMotionTask,
   -Task; the events a run never makes happen are warnings. *)
let which_run () =
  let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n\
             \ -Name \"T_BG\" -Type \"SEMISTATIC\" -Entry \"bg\"\n\
             \ -Name \"T_N\" -Type \"NORMAL\"\n#\n\
             CAB_EXEC_HOOKS:\n -Routine \"p\" -Shelf \"POWER_ON\" -AllTask\n\
             \ -Routine \"s2\" -Shelf \"START\" -Task \"T_ROB1\" -SeqNo 2\n\
             \ -Routine \"s1\" -Shelf \"START\" -AllMotionTask -SeqNo 1\n\
             \ -Routine \"r\" -Shelf \"RESET\" -AllTask\n\
             \ -Routine \"st\" -Shelf \"STOP\" -Task \"t_n\"\n\
             \ -Routine \"x\" -Shelf \"RESTART\" -Task \"T_ROB1\"\n\
             \ -Routine \"q\" -Shelf \"QSTOP\" -AllTask\n\
             \ -Routine \"y\" -Shelf \"BOOT\" -Task \"T_ROB1\"\n\
             \ -Routine \"z\" -Shelf \"START\"\n\
             \ -Routine \"w\" -Shelf \"START\" -Task \"T_NONE\"\n#\n" in
  let main = "MODULE A\n  PROC main()\n  ENDPROC\nENDMODULE\n" in
  let dir = temp_backup [ ("SYSPAR/SYS.cfg", sys); ("RAPID/TASK1/PROGMOD/A.mod", main);
                          ("RAPID/TASK2/PROGMOD/B.mod", main); ("RAPID/TASK3/PROGMOD/C.mod", main) ] in
  match Backup.read dir with
  | Error m -> Alcotest.fail m
  | Ok b ->
      let names l = List.map (fun (e : Backup.event_routine) -> e.routine ^ "/" ^ e.event) l in
      let task n = List.find (fun (t : Backup.task) -> t.name = n) b.tasks in
      let l = Alcotest.(list string) in
      Alcotest.check l "T_ROB1 before" [ "p/POWER_ON"; "r/RESET"; "s1/START"; "s2/START" ]
        (names (task "T_ROB1").before);
      Alcotest.check l "T_ROB1 after" [] (names (task "T_ROB1").after);
      Alcotest.check l "SEMISTATIC: POWER_ON only" [ "p/POWER_ON" ] (names (task "T_BG").before);
      Alcotest.check l "SEMISTATIC: no STOP" [] (names (task "T_BG").after);
      Alcotest.check l "T_N before" [ "p/POWER_ON"; "r/RESET" ] (names (task "T_N").before);
      Alcotest.check l "-Task letter case aside" [ "st/STOP" ] (names (task "T_N").after);
      List.iter (fun (what, part) ->
          Alcotest.(check bool) what true (List.exists (contains part) b.warnings))
        [ ("RESTART never happens", "SYS.cfg:14: warning: the event routine x (RESTART) is not run in task T_ROB1");
          ("QSTOP never happens", "the event routine q (QSTOP) is not run in task T_BG");
          ("RESET not in a SEMISTATIC task",
           "the event routine r (RESET) is not run in task T_BG: the task is SEMISTATIC");
          ("an unknown event", "SYS.cfg:16: warning: the event routine y: -Shelf \"BOOT\" is none of");
          ("no task named", "SYS.cfg:17: warning: the event routine z names no task");
          ("a task not run", "SYS.cfg:18: warning: the event routine w (START): no task T_NONE runs") ]

(* The engines: the routines of a sequence one after the other, events and outcome alike. *)
let machine_events program ~before ~after =
  match M.start ~host:(Rapid_run.Run.setup ()).host ~observe:true ~before ~after program ~entry:"main" with
  | Error m -> Error m
  | Ok cfg ->
      let events = ref [] in
      while M.outcome cfg = Running && M.steps cfg < 1_000_000 do
        events := List.rev_append (snd (M.step cfg)) !events
      done;
      Ok (List.rev !events, M.outcome cfg)

let closure_events program ~before ~after =
  let events = ref [] in
  match C.run ~host:(Rapid_run.Run.setup ()).host ~observe:true ~before ~after
          ~on_event:(fun e -> events := e :: !events) program ~entry:"main" with
  | Error m -> Error m
  | Ok r -> Ok (List.rev !events, r.outcome)

let load text =
  match Parse.parse_string ~name:"events.mod" text with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Rapid_load.Session.load_modules [ m ] with
      | Ok l -> l.program
      | Error _ -> Alcotest.fail "does not check")

let program = {|MODULE Events
  VAR num n := 0;
  PROC power_on()
    n := n + 1;
    TPWrite "power on " \Num:=n;
  ENDPROC
  PROC reset_cycle()
    n := 10;
    TPWrite "reset";
    ExitCycle;
    TPWrite "never";
  ENDPROC
  PROC early()
    TPWrite "early";
    RETURN;
    TPWrite "never";
  ENDPROC
  PROC main()
    VAR num five := 5;
    n := n + five;
    TPWrite "main " \Num:=n;
  ENDPROC
  PROC on_stop()
    TPWrite "stop " \Num:=n;
  ENDPROC
  PROC fails()
    VAR num zero := 0;
    TPWrite "fails";
    n := n / zero;
  ENDPROC
  PROC leaves()
    TPWrite "leaves";
    EXIT;
  ENDPROC
  FUNC num f()
    RETURN 1;
  ENDFUNC
ENDMODULE
|}

let outputs events = List.filter_map (function E.Output s -> Some s | _ -> None) events

let text = function
  | Rapid_runtime.Outcome.Ended -> "ended"
  | Stopped { name; _ } -> "stopped " ^ name
  | _ -> "other"

let sequences () =
  let p = load program in
  List.iter (fun (what, before, after, expected, ending) ->
      match machine_events p ~before ~after, closure_events p ~before ~after with
      | Ok (me, mo), Ok (ce, co) ->
          Alcotest.(check (list string)) (what ^ ": the machine's output") expected (outputs me);
          Alcotest.(check string) (what ^ ": the machine's end") ending (text mo);
          let routine_events = List.filter_map (function
              | E.Routine_entered r -> Some ("entered " ^ r) | Routine_left r -> Some ("left " ^ r)
              | Task_ended -> Some "task ended" | Output s -> Some ("output " ^ s) | _ -> None) in
          Alcotest.(check (list string)) (what ^ ": the engines alike") (routine_events me) (routine_events ce);
          Alcotest.(check string) (what ^ ": the closure engine's end") ending (text co)
      | Error m, _ | _, Error m -> Alcotest.failf "%s: %s" what m)
    [ ("power on, reset, start, main, stop", [ "power_on"; "reset_cycle"; "early" ], [ "on_stop" ],
       [ "power on 1"; "reset"; "early"; "main 15"; "stop 15" ], "ended");
      ("an error in an event routine stops the task", [ "fails" ], [ "on_stop" ], [ "fails" ],
       "stopped ERR_DIVZERO");
      ("EXIT in an event routine ends the task", [ "leaves" ], [ "on_stop" ], [ "leaves" ], "ended");
      ("an error in main: no STOP routine", [ "power_on" ], [ "fails"; "on_stop" ], [ "power on 1"; "main 6"; "fails" ],
       "stopped ERR_DIVZERO");
      ("ExitCycle in the last routine ends the task", [], [ "reset_cycle" ], [ "main 5"; "reset" ], "ended") ];
  (* A routine of the sequence that is no procedure without parameters: both refuse to start. *)
  List.iter (fun (before, after) ->
      match machine_events p ~before ~after, closure_events p ~before ~after with
      | Error _, Error _ -> ()
      | _ -> Alcotest.failf "started with %s" (String.concat ", " (before @ after)))
    [ ([ "absent" ], []); ([], [ "f" ]) ]

(* The done-when item of issue 17: a backup's run --json is byte for byte the same twice. *)
let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

let twice () =
  let run engine =
    let out = Filename.temp_file "rapid-sem" ".json" in
    let status = Sys.command (Printf.sprintf "cd golden && %s run --json --engine %s backup-events > %s 2>/dev/null"
                                (Filename.quote binary) engine (Filename.quote out)) in
    let ic = open_in_bin out in
    let text = really_input_string ic (in_channel_length ic) in
    close_in ic; Sys.remove out;
    (status, text) in
  List.iter (fun engine ->
      let s1, a = run engine and s2, b = run engine in
      Alcotest.(check int) (engine ^ ": exit 0") 0 s1;
      Alcotest.(check int) (engine ^ ": exit 0 again") 0 s2;
      Alcotest.(check bool) (engine ^ ": events") true (String.length a > 1000);
      Alcotest.(check string) (engine ^ ": byte for byte the same") a b)
    [ "closure"; "machine" ]

(* Several tasks with event routines: both engines make the same events in the same order for
   every schedule (only the steps of task-end and end are each engine's own). *)
let schedules () =
  let run engine seed =
    let out = Filename.temp_file "rapid-sem" ".json" in
    ignore (Sys.command (Printf.sprintf
                           "cd golden && %s run --json --engine %s --schedule %d backup-events > %s 2>/dev/null"
                           (Filename.quote binary) engine seed (Filename.quote out)));
    let ic = open_in_bin out in
    let text = really_input_string ic (in_channel_length ic) in
    close_in ic; Sys.remove out;
    List.filter (fun l -> not (contains "\"steps\"" l)) (String.split_on_char '\n' text) in
  List.iter (fun seed ->
      Alcotest.(check (list string)) (Printf.sprintf "schedule %d" seed) (run "machine" seed) (run "closure" seed))
    [ 1; 2; 3; 7; 11 ]

let suite =
  ( "event routines",
    [ Alcotest.test_case "which run, in which order" `Quick which_run;
      Alcotest.test_case "the sequence in both engines" `Quick sequences;
      Alcotest.test_case "a backup's run --json twice" `Quick twice;
      Alcotest.test_case "the engines alike for every schedule" `Quick schedules ] )
