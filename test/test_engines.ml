(* The two engines against each other (doc/semantics.md, "The second engine"): every format 3
   run case of spec/ runs under the small-step machine and under the closure engine, and both
   must make the same observable events, in the same order, and end the same way: the same kind
   of outcome and, when the system error handler stops the task, the same error, number, place
   and call chain. Step counts are each engine's own and are not compared. *)

open Rapid_syntax
module M = Rapid_semantics.Machine
module C = Rapid_closure.Closure_engine

(* Every folder of spec/: the run cases among them are compared, the controller's, the
   motion's and the services' included. *)
let folders =
  Sys.readdir "../spec" |> Array.to_list
  |> List.filter (fun f -> Sys.is_directory (Filename.concat "../spec" f))
  |> List.sort compare

let event_text (e : Rapid_runtime.Event.t) =
  let region r = Source.to_string r ^ "-" ^ (let q = Source.stop r in Printf.sprintf "%d:%d" q.line q.col) in
  match e with
  | Output s -> "output " ^ s
  | Erase -> "erase"
  | Log s -> "log " ^ s
  | Routine_entered r -> "entered " ^ r
  | Routine_left r -> "left " ^ r
  | Error_raised { name; number; at } -> Printf.sprintf "raised %s %d %s" name number (region at)
  | Error_handled { name; routine } -> Printf.sprintf "handled %s in %s" name routine
  | Undo_run r -> "undo " ^ r
  | Task_ended -> "task ended"
  | Stubbed { routine; at } -> Printf.sprintf "stubbed %s %s" routine (region at)
  (* The controller's and motion's events: the machine's alone (doc/semantics.md). *)
  | Controller (Signal_changed { time; signal; value }) -> Printf.sprintf "%.6f signal %s = %g" time signal value
  | Controller (Interrupt_occurred { time; number }) -> Printf.sprintf "%.6f interrupt %d" time number
  | Controller (Interrupt_discarded { time; number; reason }) ->
      Printf.sprintf "%.6f interrupt %d discarded: %s" time number reason
  | Trap_entered { trap; number; time } -> Printf.sprintf "%.6f trap entered %s %d" time trap number
  | Trap_left { trap; time } -> Printf.sprintf "%.6f trap left %s" time trap
  | Motion m -> "motion " ^ Rapid_observable.Motion_event.to_string m
  | Event_log (Err_log { id; kind; arguments }) ->
      Printf.sprintf "errlog %d %s %s" id kind (String.concat "|" arguments)
  | Event_log Skip_warning -> "skipwarn"
  | Observed o -> Rapid_runtime.Observation.to_string o

(* The outcome as the two engines must agree on it. A run cut short by the machine's step limit
   and one cut short by the closure engine's fuel are both "exhausted": what a step and a unit
   of fuel are differs. *)
let outcome_text (o : Rapid_runtime.Outcome.t) =
  match o with
  | Ended -> "ended"
  | Stopped { name; number; at; chain; about } ->
      Printf.sprintf "stopped %s %d %s (%s)%s" name number (Source.to_string at) (String.concat " <- " chain)
        (match about with Some a -> " about " ^ a | None -> "")
  | Running | Resource_exhausted _ -> "exhausted"
  | Unsupported { name; at; _ } -> Printf.sprintf "unsupported %s %s" name (Source.to_string at)
  | Deadlock _ -> "deadlock"
  | Stuck m -> "stuck " ^ m

let io_of (case : Rapid_conformance.Spec_case.t) =
  match case.run with
  | Some { io = Some file; _ } -> (
      match Rapid_controller.Io_config.read_file file with Ok io -> io | Error m -> Alcotest.fail m)
  | _ -> Rapid_controller.Io_config.empty

let load (case : Rapid_conformance.Spec_case.t) =
  let modules = List.filter_map (fun f -> Result.to_option (Parse.parse_file f)) case.files in
  match Rapid_load.Session.load_modules ~allow_unknown:case.allow_unknown ~io:(io_of case) modules with
  | Ok loaded -> Some loaded.program
  | Error _ -> None

(* The controller of a case, made afresh for each engine: its signals and stimulus, its clock,
   and a mass memory of its own (as the spec runner makes them). *)
let with_world (case : Rapid_conformance.Spec_case.t) f =
  let run = Option.get case.run in
  let world = Rapid_controller.World.create ?statement_time:run.statement_time ?max_time:run.max_time (io_of case) in
  let sandbox = Rapid_controller.File_sandbox.temporary () in
  Option.iter (Rapid_controller.File_sandbox.seed sandbox ~device:"HOME:") run.home;
  let services = Rapid_controller.Services.create ~sandbox () in
  Rapid_controller.World.set_services world services;
  Rapid_conformance.Loopback_lock.exclusive case (fun () ->
      Fun.protect (fun () -> f world)
        ~finally:(fun () -> Rapid_controller.Services.close_all services; Rapid_controller.File_sandbox.remove sandbox))

let machine_run ?stub_unmodelled ?world limits program ~entry ~max_steps =
  (* Observed: the store writes, arguments and returned values of schema rapid-sem/2 too. *)
  match M.start ~host:(Rapid_run.Run.setup ?controller:world ()).host ?stub_unmodelled ~observe:true ~limits program ~entry with
  | Error m -> Alcotest.failf "machine: %s" m
  | Ok cfg ->
      let events = ref [] in
      while M.outcome cfg = Running && M.steps cfg < max_steps do
        events := List.rev_append (snd (M.step cfg)) !events
      done;
      (List.rev !events, M.outcome cfg)

let closure_run ?stub_unmodelled ?world limits program ~entry ~fuel =
  match C.events ~host:(Rapid_run.Run.setup ?controller:world ()).host ?stub_unmodelled ~observe:true ~limits ~fuel program ~entry with
  | Error m -> Alcotest.failf "closure engine: %s" m
  | Ok (events, r) -> (events, r.outcome)

(* Events come in two streams, each compared in its order: the program's (output, calls,
   errors, traps) and the world's (signal changes, interrupts, moves), which carry their virtual
   times. Between the two the engines may differ: the machine reports what the world did during
   a step before the step's own events, and a step may run on into the next statement's entry. *)
let streams events = List.partition (fun e -> not (Rapid_runtime.Event.world_event e)) events

let is_prefix a b =
  let rec prefix a b = match a, b with [], _ -> true | x :: a, y :: b -> x = y && prefix a b | _ :: _, [] -> false in
  let ap, aw = streams a and bp, bw = streams b in
  prefix ap bp && prefix aw bw

(* The first difference, with a little context. *)
let difference machine closure =
  let rec go what i m c =
    match m, c with
    | [], [] -> None
    | x :: m, y :: c when x = y -> go what (i + 1) m c
    | _ ->
        let show = function [] -> "(nothing)" | e :: _ -> event_text e in
        Some (Printf.sprintf "%s %d: machine %s, closure %s" what i (show m) (show c))
  in
  let mp, mw = streams machine and cp, cw = streams closure in
  match go "event" 0 mp cp with Some d -> Some d | None -> go "world event" 0 mw cw

let compare_case path () =
  let case = Rapid_conformance.Spec_case.read path in
  match case.run, load case with
  | Some run, Some program ->
      let limits = { Rapid_runtime.Limits.default with
                     retry_limit = Option.value run.retry_limit ~default:Rapid_runtime.Limits.default.retry_limit } in
      let budget = Option.value run.max_steps ~default:10_000_000 in
      let stub_unmodelled = case.stub_unmodelled in
      let m_events, m_outcome =
        with_world case (fun world -> machine_run ~stub_unmodelled ~world limits program ~entry:run.entry ~max_steps:budget) in
      let c_events, c_outcome =
        with_world case (fun world -> closure_run ~stub_unmodelled ~world limits program ~entry:run.entry ~fuel:budget) in
      begin
      Alcotest.(check string) "outcome" (outcome_text m_outcome) (outcome_text c_outcome);
      (* Making only the output events (as rapid-sem run does) changes nothing else. *)
      (match with_world case (fun world ->
           C.events ~host:(Rapid_run.Run.setup ~controller:world ()).host ~stub_unmodelled ~limits ~fuel:budget ~all_events:false program ~entry:run.entry) with
       | Ok (quiet, r) ->
           let outputs = List.filter (function Rapid_runtime.Event.Output _ | Rapid_runtime.Event.Erase | Rapid_runtime.Event.Log _ -> true | _ -> false) in
           Alcotest.(check (list string)) "output-only events" (List.map event_text (outputs c_events))
             (List.map event_text quiet);
           Alcotest.(check string) "output-only outcome" (outcome_text c_outcome) (outcome_text r.outcome)
       | Error m -> Alcotest.fail m);
      let cut_short = (m_outcome = Running || c_outcome = Running) in
      if cut_short then begin
        (* Cut short at different points: one event list must begin the other. *)
        if not (is_prefix m_events c_events || is_prefix c_events m_events) then
          Alcotest.failf "events differ before the limit: %s"
            (Option.value (difference m_events c_events) ~default:"")
      end
      else begin
        match difference m_events c_events with
        | None -> ()
        | Some d -> Alcotest.failf "%s" d
      end
      end
  | Some _, None -> Alcotest.failf "%s does not check" path
  | None, _ -> ()

let run_cases () =
  List.concat_map (fun folder ->
      Rapid_conformance.Spec_runner.find_cases (Filename.concat "../spec" folder)
      |> List.filter (fun path ->
          (* Several tasks (format 4) are compared below (compare_tasks_case). *)
          match (Rapid_conformance.Spec_case.read path).run with
          | Some r -> r.tasks = [] | None -> false))
    folders

(* ------------------------------------------------------------------ several tasks (ch. 14) *)

module TS = Rapid_semantics.Task_set
module CT = Rapid_closure.Closure_tasks

type tasks_run = {
  events : (string * Rapid_runtime.Event.t) list;          (* each with its task, in order *)
  outcome : Rapid_runtime.Outcome.t;
  task_outcomes : (string * Rapid_runtime.Outcome.t) list;
}

(* The same controller for each engine: the case's signals, stimulus, clock and mass memory. *)
let tasks_world (run : Rapid_conformance.Spec_case.run) f =
  let io = match run.io with
    | Some file -> (match Rapid_controller.Io_config.read_file file with Ok io -> io | Error m -> Alcotest.fail m)
    | None -> Rapid_controller.Io_config.empty in
  let world = Rapid_controller.World.create ?statement_time:run.statement_time ?max_time:run.max_time io in
  let sandbox = Rapid_controller.File_sandbox.temporary () in
  Option.iter (Rapid_controller.File_sandbox.seed sandbox ~device:"HOME:") run.home;
  let services = Rapid_controller.Services.create ~sandbox () in
  Rapid_controller.World.set_services world services;
  let robot = match run.robot with
    | Some file -> (match Rapid_motion_model.Robot.load file with Ok r -> Some r | Error _ -> Alcotest.fail file)
    | None -> None in
  let motion = Rapid_installed.Motion_routines.create ?robot () in
  Fun.protect (fun () -> f ~io ~world ~motion)
    ~finally:(fun () -> Rapid_controller.Services.close_all services; Rapid_controller.File_sandbox.remove sandbox)

let specs_of (run : Rapid_conformance.Spec_case.run) =
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  List.map (fun (name, files) ->
      let entry = match List.find_opt (fun (t, _) -> same t name) (List.rev run.task_entries) with
        | Some (_, r) -> r | None -> run.entry in
      { Rapid_run.Task_load.name; files; entry }) run.tasks

(* [None] when the tasks are refused (both engines load them alike: Task_load). *)
let machine_tasks ?seed ~stub_unmodelled ~allow_unknown ~max_steps ~io ~world ~motion ?motion_task specs =
  match Rapid_run.Run.machine_tasks ~stub_unmodelled ~allow_unknown ~observe:true ~io ?seed ?motion_task ~controller:world ~motion specs with
  | Error _ -> None
  | Ok (ts, _) ->
      let events = ref [] in
      let rec loop () =
        if TS.steps ts < max_steps then
          match TS.step ts with
          | None -> ()
          | Some (name, _, es) -> List.iter (fun e -> events := (name, e) :: !events) es; loop ()
      in
      loop ();
      Some { events = List.rev !events; outcome = TS.outcome ts;
             task_outcomes = List.map (fun (n, cfg) -> (n, TS.task_outcome ts cfg)) (TS.tasks ts) }

let closure_tasks ?seed ~stub_unmodelled ~allow_unknown ~max_steps ~io ~world ~motion ?motion_task specs =
  match Rapid_run.Run.closure_tasks ~stub_unmodelled ~allow_unknown ~io ?seed ?motion_task ~controller:world ~motion specs with
  | Error _ -> None
  | Ok (ct, _) ->
      let events = ref [] in
      let r = CT.run ~fuel:max_steps ~observe:true ~on_event:(fun name e -> events := (name, e) :: !events) ct in
      Some { events = List.rev !events; outcome = r.outcome;
             task_outcomes = List.map (fun (t : CT.task_result) -> (t.name, t.task_outcome)) r.tasks }

(* Both engines' runs of several tasks: the same outcome, the same outcome for each task, and
   the same events of every task in the same order, the tasks' events interleaved alike: the
   program's stream and the world's, each in its order, as [difference] compares one task. *)
let tasks_agree what (m : tasks_run) (c : tasks_run) =
  Alcotest.(check string) (what ^ ": outcome") (outcome_text m.outcome) (outcome_text c.outcome);
  (* A deadlock's message names each task and what it waits for, so whole messages. *)
  let full (o : Rapid_runtime.Outcome.t) = match o with Deadlock m -> "deadlock: " ^ m | o -> outcome_text o in
  Alcotest.(check (list (pair string string))) (what ^ ": each task's outcome")
    (List.map (fun (n, o) -> (n, full o)) m.task_outcomes) (List.map (fun (n, o) -> (n, full o)) c.task_outcomes);
  let text (n, e) = n ^ " " ^ event_text e in
  let rec go stream i m c =
    match m, c with
    | [], [] -> ()
    | x :: m, y :: c when text x = text y -> go stream (i + 1) m c
    | _ ->
        let show = function [] -> "(nothing)" | e :: _ -> text e in
        Alcotest.failf "%s: %s %d: machine %s, closure %s" what stream i (show m) (show c) in
  let split = List.partition (fun (_, e) -> not (Rapid_runtime.Event.world_event e)) in
  let mp, mw = split m.events and cp, cw = split c.events in
  go "event" 0 mp cp;
  go "world event" 0 mw cw

let compare_tasks_case ?seed path () =
  let case = Rapid_conformance.Spec_case.read path in
  let run = Option.get case.run in
  let max_steps = Option.value run.max_steps ~default:10_000_000 in
  let seed = match seed with Some s -> Some s | None -> run.schedule in
  let specs = specs_of run in
  let go engine = Rapid_conformance.Loopback_lock.exclusive case @@ fun () -> tasks_world run (fun ~io ~world ~motion ->
      engine ?seed ~stub_unmodelled:case.stub_unmodelled ~allow_unknown:case.allow_unknown ~max_steps ~io ~world ~motion
        ?motion_task:run.motion_task specs) in
  match go machine_tasks, go closure_tasks with
  | None, None -> ()
  | Some _, None | None, Some _ -> Alcotest.fail "one engine refused the tasks, the other did not"
  | Some m, Some c ->
      let what = Printf.sprintf "%s%s" (Filename.basename path)
          (match seed with Some s -> Printf.sprintf " (seed %d)" s | None -> "") in
      tasks_agree what m c

(* Two tasks of random statements around a shared persistent (ch. 14): writes, reads, waits for
   the other task (WaitUntil with a time-out, a busy wait of an empty loop), empty and full
   loops, calls, errors and their handlers, RETRY, the clock; both engines, round robin and a
   seed each, must agree as on the cases above. *)
let random_tasks () =
  let open QCheck.Gen in
  let statement = oneofl [
      "shared := shared + 1;"; "mine := mine + shared;"; "TPWrite \"s \" \\Num:=shared;";
      "WaitTime 0.002;"; "WaitUntil shared > 3 \\MaxTime:=0.05;"; "FOR i FROM 1 TO 3 DO\n    ENDFOR";
      "FOR i FROM 1 TO 2 DO\n      shared := shared + i;\n    ENDFOR";
      "WHILE shared < 2 AND mine < 50 DO\n      mine := mine + 1;\n    ENDWHILE";
      "work;"; "IF shared MOD 2 = 0 THEN\n      TPWrite \"even\";\n    ELSE\n      shared := shared * 2;\n    ENDIF";
      "mine := 1 / (shared - shared);"; "shared := shared - 1;";
      (* a timer whose trap writes the shared persistent, served at either task's points *)
      "ITimer \\Single, 0.003, t1;"; "ISleep t1;"; "IWatch t1;";
      (* a semaphore on a shared bool, a meeting point of both tasks *)
      "WaitTestAndSet lock;\n    shared := shared + 10;\n    lock := FALSE;";
      "WaitSyncTask meet, both \\TimeOut:=0.04;";
      "TEST shared\n    CASE 1, 2:\n      TPWrite \"small\";\n    DEFAULT:\n      mine := mine - 1;\n    ENDTEST";
      "IF mine > 40 RETURN;" ] in
  let task =
    let* body = list_size (int_range 1 6) statement in
    let* work_body = list_size (int_range 1 3) statement in
    let work_body = List.filter (fun s -> s <> "work;" && s <> "IF mine > 40 RETURN;") work_body in
    let* trap = oneofl [ "shared := shared + 100;"; "TPWrite \"tick\";\n    shared := shared * 2;"; "mine := 1 / 0;" ] in
    let* init = oneofl [ " := 0"; " := 1"; "" ] in
    let* handler = oneofl [ ""; "  ERROR\n    IF ERRNO = ERR_DIVZERO TRYNEXT;\n    RAISE;\n";
                            "  ERROR\n    mine := 0;\n    shared := shared + 1;\n    IF shared < 6 RETRY;\n    TRYNEXT;\n" ] in
    return (Printf.sprintf
              "MODULE m\n  PERS num shared%s;\n  PERS bool lock;\n  PERS tasks both{2} := [[\"T_ROB1\"],[\"T_B\"]];\n\
               \  VAR syncident meet;\n  VAR intnum t1;\n  VAR num mine := 0;\n  PROC work()\n    %s\n  ENDPROC\n\
               \  TRAP tick\n    %s\n  ENDTRAP\n\
               \  PROC main()\n    CONNECT t1 WITH tick;\n    %s\n%s  ENDPROC\nENDMODULE\n"
              init (String.concat "\n    " (if work_body = [] then [ "mine := mine + 1;" ] else work_body))
              trap (String.concat "\n    " body) handler) in
  let gen = triple task task (oneofl [ None; Some 1; Some 2; Some 5; Some 11 ]) in
  let dir = Filename.temp_file "rapid-sem-tasks" "" in
  Sys.remove dir; Unix.mkdir dir 0o755;
  let write name text =
    let path = Filename.concat dir name in
    let oc = open_out_bin path in
    output_string oc text; close_out oc; path in
  let compared = ref 0 and ended = ref 0 in
  let agree_on (a, b, seed) =
    let specs = [ { Rapid_run.Task_load.name = "T_ROB1"; files = [ write "a.mod" a ]; entry = "main" };
                  { Rapid_run.Task_load.name = "T_B"; files = [ write "b.mod" b ]; entry = "main" } ] in
    let run engine =
      let world = Rapid_controller.World.create ~statement_time:0.001 Rapid_controller.Io_config.empty in
      engine ?seed ~stub_unmodelled:false ~allow_unknown:false ~max_steps:1_000_000 ~io:Rapid_controller.Io_config.empty
        ~world ~motion:(Rapid_installed.Motion_routines.create ()) ?motion_task:None specs in
    match run machine_tasks, run closure_tasks with
    | None, None -> true
    | Some m, Some c -> (
        incr compared;
        if m.outcome = Rapid_runtime.Outcome.Ended then incr ended;
        match tasks_agree "random tasks" m c with
        | () -> true
        | exception e -> QCheck.Test.fail_reportf "%s" (Printexc.to_string e))
    | _ -> QCheck.Test.fail_reportf "one engine refused the tasks"
  in
  QCheck.Test.check_exn ~rand:(Random.State.make [| 20261128 |])
    (QCheck.Test.make ~count:200 ~name:"machine = closure on random pairs of tasks"
       (QCheck.make ~print:(fun (a, b, seed) ->
            Printf.sprintf "seed %s\n%s\n%s" (match seed with Some s -> string_of_int s | None -> "none") a b) gen)
       agree_on);
  (* Not refused, and not all ending the same way: the pairs ran. *)
  Alcotest.(check bool) (Printf.sprintf "pairs run (%d), some ended (%d), some not" !compared !ended) true
    (!compared = 200 && !ended > 20 && !ended < 200)

let task_cases () =
  List.concat_map (fun folder ->
      Rapid_conformance.Spec_runner.find_cases (Filename.concat "../spec" folder)
      |> List.filter (fun path ->
          match (Rapid_conformance.Spec_case.read path).run with
          | Some r -> r.tasks <> [] | None -> false))
    folders

(* The conformance suite's run cases under the closure engine, through the spec runner, the
   cases of several tasks included: every one must pass, none is skipped. *)
let spec_under_closure () =
  let failures = List.concat_map (fun folder ->
      Rapid_conformance.Spec_runner.find_cases (Filename.concat "../spec" folder)
      |> List.filter_map (fun path ->
          let case = Rapid_conformance.Spec_case.read path in
          if case.run = None then None
          else
            let o = Rapid_conformance.Spec_runner.run_case ~engine:Closure case in
            (* Nothing is skipped: several tasks (format 4) run too (Closure_tasks). *)
            if o.verdict <> Passed then Some (path ^ ": " ^ o.detail) else None)) folders in
  Alcotest.(check (list string)) "spec/ run cases failing under --engine closure" [] failures


(* ------------------------------------------------------------------ programs beyond spec/ *)

(* Programs that mix what the spec/ cases show one at a time: GOTO out of loops, RETRY and
   TRYNEXT inside loops, long jumps over UNDO handlers, late binding with arguments, CallByVar,
   conditional arguments, INOUT bindings, and the num operators on edge values (the closure
   engine computes num operators on its own fast path; Arith computes them for the machine). *)
let programs = [
  ("traps: in an error handler, in UNDO, with EXIT, with their own handlers, during a poll", {rapid|MODULE tr
  VAR intnum t1;
  VAR intnum t2;
  VAR intnum t3;
  VAR num hits := 0;
  VAR num polls := 0;
  TRAP counting
    hits := hits + 1;
    TPWrite "trap " \Num:=INTNO;
  ENDTRAP
  TRAP failing
    TPWrite "failing";
    RAISE 41;
  ERROR
    TPWrite "trap handler " \Num:=ERRNO;
    IF hits < 3 RETRY;
    RETURN;
  ENDTRAP
  FUNC bool ready()
    polls := polls + 1;
    RETURN polls > 3;
  ENDFUNC
  PROC inner()
    WHILE hits < 5 DO
      WaitTime 0.01;
    ENDWHILE
    RAISE 42;
  UNDO
    TPWrite "undo inner";
    WaitTime 0.02;
  ENDPROC
  PROC main()
    CONNECT t1 WITH counting;
    ITimer 0.013, t1;
    CONNECT t2 WITH failing;
    ITimer \Single, 0.03, t2;
    inner;
    TPWrite "not reached";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    WaitUntil ready() \PollRate:=0.01;
    ISleep t1;
    WaitTime 0.05;
    IWatch t1;
    IDelete t1;
    CONNECT t3 WITH counting;
    ITimer \Single, 0.001, t3;
    WaitTime 0.01;
    TPWrite "hits " \Num:=hits;
    EXIT;
  ENDPROC
ENDMODULE
|rapid});
  ("a long jump from a trap into a loop, and a trap whose error stops the task", {rapid|MODULE tr2
  VAR intnum t1;
  VAR num n := 0;
  TRAP failing
    RAISE 43;
  ENDTRAP
  PROC work()
    FOR i FROM 1 TO 100 DO
      n := n + 1;
    ENDFOR
  ENDPROC
  PROC main()
    CONNECT t1 WITH failing;
    ITimer \Single, 0.0015, t1;
    WHILE n < 1000 DO
      work;
    ENDWHILE
    TPWrite "n " \Num:=n;
    ITimer \Single, 0.001, t1;
    WaitTime 1;
  ERROR (43)
    TPWrite "recovered at " \Num:=n;
    IF n < 500 RETRY;
    TRYNEXT;
  ENDPROC
ENDMODULE
|rapid});
  ("control and RETRY in loops", {rapid|MODULE g1
  VAR num count := 0;
  VAR num arr{3} := [1, 2, 3];
  PERS num pp := 5;
  VAR num x;
  PROC main()
    VAR num i;
    VAR num d := 0;
    i := 0;
  lbl:
    i := i + 1;
    FOR k FROM 3 TO 1 DO
      IF k = 2 GOTO after;
      TPWrite "k=" \Num:=k;
    ENDFOR
  after:
    IF i < 3 GOTO lbl;
    TPWrite "i=" \Num:=i;
    FOR j FROM 0 TO 1 STEP 0.25 DO
      count := count + 1;
    ENDFOR
    TPWrite "count=" \Num:=count;
    WHILE TRUE DO
      count := count + 1;
      IF count > 10 BREAK;
      IF count MOD 2 = 0 CONTINUE;
      TPWrite "odd " \Num:=count;
    ENDWHILE
    TEST count
    CASE 1, 2, 11:
      TPWrite "eleven";
    DEFAULT:
      TPWrite "other";
    ENDTEST
    x := arr{d};
    TPWrite "after error";
    d := 1 / d;
    TPWrite "after error 2";
    arr{d + 3} := 1;
    TPWrite "end";
  ERROR
    TPWrite "handler " \Num:=ERRNO;
    IF ERRNO = ERR_OUTOFBND THEN
      d := d + 1;
      IF d < 4 RETRY;
      TRYNEXT;
    ENDIF
    d := 1;
    RETRY;
  ENDPROC
ENDMODULE
|rapid});
  ("long jumps, UNDO, late binding, conditional arguments", {rapid|MODULE g2
  VAR num log := 0;
  PROC main()
    VAR num r;
    r := outer(3);
    TPWrite "r=" \Num:=r;
    lvl1;
    TPWrite "back";
    CallByVar "cb", 2;
    % "cb" + "1" % ;
    % "late" % 7, \flag;
    TPWrite "done";
  ERROR (LONG_JMP_ALL_ERR)
    TPWrite "main got " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
  FUNC num outer(num n)
    IF n = 0 RAISE 12;
    RETURN outer(n - 1) + 1;
  ERROR
    IF ERRNO = 12 RETURN 100;
  ENDFUNC
  PROC lvl1()
    lvl2;
  UNDO
    TPWrite "undo1";
  ENDPROC
  PROC lvl2()
    VAR num z;
    lvl3;
  ERROR
    TPWrite "lvl2 handler";
    RAISE;
  UNDO
    TPWrite "undo2";
  ENDPROC
  PROC lvl3()
    RAISE 33;
  UNDO
    TPWrite "undo3";
  ENDPROC
  PROC cb1()
    TPWrite "cb1";
  ENDPROC
  PROC cb2()
    TPWrite "cb2";
  ENDPROC
  PROC late(num a, \switch flag)
    TPWrite "late " \Num:=a;
    IF Present(flag) TPWrite "flag";
    opt;
    opt \v:=3;
    sw \s;
  ENDPROC
  PROC opt(\num v)
    IF Present(v) TPWrite "v=" \Num:=v;
    inner \v?v;
  ENDPROC
  PROC inner(\num v)
    TPWrite "inner present " \Bool:=Present(v);
  ENDPROC
  PROC sw(\switch s)
    inner2 \s?s;
  ENDPROC
  PROC inner2(\switch s)
    TPWrite "s " \Bool:=Present(s);
  ENDPROC
ENDMODULE
|rapid});
  ("INOUT bindings and ERR_FNCNORET", {rapid|MODULE g3
  VAR num v := 1;
  PERS num p := 2;
  PROC main()
    io v;
    io p;
    TPWrite "v=" \Num:=v;
    f_no;
  ERROR
    TPWrite "main h " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
  PROC io(INOUT num x)
    x := x + 10;
    TPWrite "isvar " \Bool:=IsVar(x);
    TPWrite "ispers " \Bool:=IsPers(x);
    tovar x;
  ERROR
    TPWrite "io h " \Num:=ERRNO;
    IF ERRNO = ERR_ARGNOTVAR TRYNEXT;
  ENDPROC
  PROC tovar(VAR num y)
    y := y + 1;
  ENDPROC
  PROC f_no()
    VAR num q;
    q := nf();
  ENDPROC
  FUNC num nf()
    TPWrite "in nf";
  ENDFUNC
ENDMODULE
|rapid});
  ("handlers in loops, RETURN from a handler, RAISE; and UNDO errors", {rapid|MODULE h1
  VAR num n := 0;
  PROC main()
    VAR num r;
    FOR i FROM 1 TO 3 DO
      r := f(i);
      TPWrite "r=" \Num:=r;
    ENDFOR
    p1;
    TPWrite "after p1";
    RAISE ERR_DIVZERO;
    TPWrite "after raise";
    r := g();
  ERROR
    TPWrite "main errno " \Num:=ERRNO;
    IF ERRNO = 20 THEN
      TPWrite "twenty";
    ENDIF
    TRYNEXT;
  ENDPROC
  FUNC num f(num k)
    WHILE TRUE DO
      IF k = 2 RAISE 7;
      RETURN k * 10;
    ENDWHILE
  ERROR
    TPWrite "f handler";
    RETURN -1;
  ENDFUNC
  PROC p1()
    RAISE 20;
  ERROR
    TPWrite "p1 handler";
    RAISE;
  ENDPROC
  FUNC num g()
    EXIT;
  UNDO
    TPWrite "undo g";
    n := 1 / n;
  ENDFUNC
ENDMODULE
|rapid});
  ("a long jump to a routine in its error handler", {rapid|MODULE lj2
  PROC main()
    RAISE 3;
    TPWrite "after";
  ERROR (5)
    TPWrite "main handler " \Num:=ERRNO;
    IF ERRNO = 3 q;
    TRYNEXT;
  ENDPROC
  PROC q()
    p;
  UNDO
    TPWrite "undo q";
  ENDPROC
  PROC p()
    RAISE 5;
  UNDO
    TPWrite "undo p";
  ENDPROC
ENDMODULE
|rapid});
  ("RETRY after a long jump, EXIT through UNDO handlers, an error in UNDO", {rapid|MODULE e1
  VAR num z := 0;
  VAR num tries := 0;
  PROC main()
    p;
    TPWrite "back " \Num:=tries;
    q;
  ERROR (7)
    tries := tries + 1;
    TPWrite "main recovery " \Num:=ERRNO;
    IF tries < 3 RETRY;
    TRYNEXT;
  UNDO
    TPWrite "undo main";
  ENDPROC
  PROC p()
    r;
  ERROR
    TPWrite "p handler (skipped by the long jump)";
  UNDO
    TPWrite "undo p";
  ENDPROC
  PROC r()
    RAISE 7;
  ENDPROC
  PROC q()
    s;
  UNDO
    TPWrite "undo q";
    z := 1 / z;
  ENDPROC
  PROC s()
    EXIT;
  UNDO
    TPWrite "undo s";
  ENDPROC
ENDMODULE
|rapid});
  ("a wait", {rapid|MODULE un
  PROC main()
    TPWrite "a";
    WaitTime 1;
  ENDPROC
ENDMODULE
|rapid});
  ("the value of an I/O signal not connected", {rapid|MODULE sig
  VAR signaldi di1;
  PROC main()
    VAR num x;
    TPWrite "a";
    x := di1;
    TPWrite "b";
  ENDPROC
ENDMODULE
|rapid});
  ("the RETRY count of a WHILE retried from its condition", {rapid|MODULE rc
  VAR num i := 0;
  PROC main()
    WHILE check() DO
      i := i + 1;
    ENDWHILE
    TPWrite "i=" \Num:=i;
  ERROR
    TPWrite "retry";
    RETRY;
  ENDPROC
  FUNC bool check()
    IF i >= 20 RETURN FALSE;
    IF i MOD 2 = 0 THEN
      i := i + 1;
      RAISE 5;
    ENDIF
    RETURN TRUE;
  ENDFUNC
ENDMODULE
|rapid});
  ("num operators on edge values", {rapid|MODULE arith
  CONST num vals{12} := [0, -0, 1, -1, 0.1, 3, 8388608, 16777217, 3.4e38, -3.4e38, 1e-45, 2.5];
  VAR num r;
  VAR bool b;
  VAR string s;
  PROC main()
    FOR i FROM 1 TO 12 DO
      FOR j FROM 1 TO 12 DO
        s := "";
        r := vals{i} + vals{j};
        s := s + ValToStr(r) + " ";
        r := vals{i} - vals{j};
        s := s + ValToStr(r) + " ";
        r := vals{i} * vals{j};
        s := s + ValToStr(r) + " ";
        r := vals{i} / vals{j};
        s := s + ValToStr(r) + " ";
        r := vals{i} - 1;
        r := vals{i} + 0.5;
        r := vals{i} * 3;
        s := s + ValToStr(r) + " ";
        b := vals{i} < vals{j};
        s := s + ValToStr(b);
        b := vals{i} <= vals{j};
        s := s + ValToStr(b);
        b := vals{i} > vals{j};
        s := s + ValToStr(b);
        b := vals{i} >= vals{j};
        s := s + ValToStr(b);
        b := vals{i} = vals{j};
        s := s + ValToStr(b);
        b := vals{i} <> vals{j};
        s := s + ValToStr(b);
        IF vals{i} < vals{j} AND vals{i} <> 0 OR (NOT (vals{i} >= 2.5)) s := s + "c";
        WHILE vals{i} > 2.5 AND vals{i} <> 0 AND s <> "" DO
          s := "";
        ENDWHILE
        TPWrite s;
      ENDFOR
    ENDFOR
  ERROR
    TPWrite "error " + ValToStr(ERRNO = ERR_DIVZERO) + ValToStr(ERRNO = ERR_OVERFLOW);
    TRYNEXT;
  ENDPROC
ENDMODULE
|rapid});
]

let load_text ?(allow_unknown = false) ?io name text =
  match Parse.parse_string ~name:(name ^ ".mod") text with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Rapid_load.Session.load_modules ~allow_unknown ?io [ m ] with
      | Ok l -> l.program
      | Error _ -> Alcotest.failf "%s does not check" name)

let agree ?(limits = Rapid_runtime.Limits.default) ?(budget = 10_000_000) program =
  let m_events, m_outcome = machine_run limits program ~entry:"main" ~max_steps:budget in
  let c_events, c_outcome = closure_run limits program ~entry:"main" ~fuel:budget in
  begin
    Alcotest.(check string) "outcome" (outcome_text m_outcome) (outcome_text c_outcome);
    (match difference m_events c_events with None -> () | Some d -> Alcotest.failf "%s" d)
  end;
  (c_events, c_outcome)

let program_agrees (name, text) () =
  let events, _ = agree (load_text "program" text) in
  Alcotest.(check bool) (name ^ ": something was written") true
    (List.exists (function Rapid_runtime.Event.Output _ -> true | _ -> false) events)

(* The controller under both engines (doc/controller.md): waits, signals with a stimulus,
   interrupts and their traps, clocks, motion, a long jump from a trap between statements
   (R-7.2-m): the same events, with their virtual times, and the same outcome. *)
let controller_runs () =
  let io = match Rapid_controller.Io_config.parse ~file:"ctl.io"
                   "signal di1 di\nsignal do1 do\nsignal ai1 ai\nat 0.35 di1 1\nat 0.6 ai1 4.5\n" with
    | Ok io -> io | Error m -> Alcotest.fail m in
  let both text =
    let program = load_text ~io "ctl" text in
    let run f = let w = Rapid_controller.World.create ~statement_time:0.01 io in f w in
    let m_events, m_outcome = run (fun world -> machine_run ~world Rapid_runtime.Limits.default program ~entry:"main" ~max_steps:1_000_000) in
    let c_events, c_outcome = run (fun world -> closure_run ~world Rapid_runtime.Limits.default program ~entry:"main" ~fuel:1_000_000) in
    Alcotest.(check string) "outcome" (outcome_text m_outcome) (outcome_text c_outcome);
    (match difference m_events c_events with None -> () | Some d -> Alcotest.failf "%s" d);
    Alcotest.(check bool) "the controller was seen" true
      (List.exists (function Rapid_runtime.Event.Controller _ | Rapid_runtime.Event.Trap_entered _ | Rapid_runtime.Event.Motion _ -> true | _ -> false) c_events);
    c_events
  in
  let program body = "MODULE ctl\n  VAR intnum i1;\n  VAR intnum i2;\n  VAR clock c1;\n  VAR num n := 0;\n  PROC main()\n    VAR num x;\n    TPWrite \"a\";\n" ^ body ^ "\n    TPWrite \"b\" \\Num:=n;\n  ERROR (40)\n    TPWrite \"recovered\";\n    TRYNEXT;\n  ENDPROC\n  TRAP t1\n    n := n + 1;\n    SetDO do1, 1 - do1;\n  ENDTRAP\n  TRAP t2\n    RAISE 40;\n  ENDTRAP\nENDMODULE\n" in
  let outputs events = List.filter_map (function Rapid_runtime.Event.Output s -> Some s | _ -> None) events in
  ignore (both (program "    WaitDI di1, 1;\n    x := di1;\n    TPWrite \"di1 \" \\Num:=x;"));
  ignore (both (program "    CONNECT i1 WITH t1;\n    ISignalDI di1, 1, i1;\n    WaitTime 1;\n    n := n + do1;"));
  ignore (both (program "    CONNECT i1 WITH t1;\n    ITimer 0.1, i1;\n    ClkStart c1;\n    WaitUntil ai1 > 4 \\PollRate:=0.05;\n    x := ClkRead(c1);\n    TPWrite \"t \" \\Num:=x;\n    IDelete i1;"));
  ignore (both (program "    do1 := 1;\n    PulseDO \\PLength:=0.2, do1;\n    WaitDO do1, 0;\n    x := do1;"));
  ignore (both (program "    MoveJ [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, z50, tool0;\n    MoveL [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;"));
  let events = both (program "    CONNECT i2 WITH t2;\n    ITimer \\Single, 0.015, i2;\n    TPWrite \"one\";\n    TPWrite \"two\";") in
  Alcotest.(check (list string)) "a long jump between statements (R-7.2-m)"
    [ "a"; "one"; "recovered"; "two"; "b0" ] (outputs events);
  (* --max-time ends a program that never touches the controller at the same statement in both
     (the closure engine counts such statements itself and charges the clock later). *)
  let looping = load_text "loop" "MODULE l\n  PROC main()\n    VAR num i;\n    WHILE TRUE DO\n      i := i + 1;\n      IF i MOD 7 = 0 TPWrite \"i \" \\Num:=i;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n" in
  List.iter (fun (statement_time, max_time) ->
      let run f = f (Rapid_controller.World.create ~statement_time ~max_time Rapid_controller.Io_config.empty) in
      let m_events, m_outcome = run (fun world -> machine_run ~world Rapid_runtime.Limits.default looping ~entry:"main" ~max_steps:10_000_000) in
      let c_events, c_outcome = run (fun world -> closure_run ~world Rapid_runtime.Limits.default looping ~entry:"main" ~fuel:10_000_000) in
      (match m_outcome, c_outcome with
       | Resource_exhausted (m, _), Resource_exhausted (c, _) -> Alcotest.(check string) "the time limit" m c
       | _ -> Alcotest.failf "time limit: %s / %s" (outcome_text m_outcome) (outcome_text c_outcome));
      (match difference m_events c_events with None -> () | Some d -> Alcotest.failf "time limit %g: %s" max_time d);
      Alcotest.(check bool) "some output" true (List.exists (function Rapid_runtime.Event.Output _ -> true | _ -> false) c_events))
    [ (0.01, 5.); (0.003, 1.); (0.0001, 0.05); (0.25, 10.) ];
  (* A deadlock, and the virtual time limit, end both alike. *)
  ignore (both (program "    WaitDO do1, 1;"));
  ignore (both (program "    CONNECT i1 WITH t1;\n    ITimer 0.1, i1;\n    WHILE TRUE DO\n      WaitTime 100;\n    ENDWHILE"))

(* §1.4, the memory budget (doc/user-guide.md, "Resources"): both engines count the same bytes
   by the model of Value.bytes (module data, each activation, in arguments, absent optional
   parameters, routine data), so that with a small budget both stop at the same call, with the
   same events before it. *)
let memory_budget () =
  let text = {rapid|MODULE mem
  VAR num table{20} := [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20];
  VAR num calls := 0;
  VAR num big{40};
  PROC down(num n, string s, \num extra{*})
    VAR num work{8};
    TPWrite "depth " \Num:=n;
    down n + 1, s + "ab" \extra:=table;
  ENDPROC
  PROC down2(num n \num opt{*})
    VAR num big{40};
    TPWrite "depth2 " \Num:=n;
    down2 n + 1;
  ENDPROC
  PROC main()
    TPWrite "start";
    down 1, "";
  ENDPROC
  PROC main2()
    down2 1;
  ENDPROC
  PROC down3(num n)
    TPWrite "depth3 " \Num:=n;
    down3 n + 1;
  ENDPROC
  PROC main3()
    down3 1;
  ENDPROC
  FUNC pos shift(pos p, num dx, string s, num dz)
    VAR pos q;
    q := p;
    q.x := p.x + dx + StrLen(s);
    q.z := dz;
    RETURN q;
  ENDFUNC
  PROC down4(num n, string s, INOUT num total, VAR num count)
    VAR pos p;
    total := total + StrLen(StrPart(s + "abc", 1, 2));
    count := count + 1;
    p := shift(p, n, s + "x", StrLen(s));
    TPWrite "depth4 " \Num:=p.x;
    down4 n + 1, s, total, calls;
  ENDPROC
  PROC main4()
    VAR num t := 0;
    down4 1, "abcdefghijabcdefghijabcdefghijabcdefghijabcdefghij", t, calls;
  ENDPROC
  FUNC pos offs4(pos p, num dx, num dy, num dz)
    VAR pos q;
    q := p;
    q.x := p.x + dx;
    q.z := q.z + dz;
    RETURN q;
  ENDFUNC
  PROC down5(num n, pos p)
    VAR pos r;
    VAR num k := 1;
    r := offs4(p, 1, -1, 0.5);
    r := offs4(r, k, n, k);
    TPWrite "depth5 " \Num:=r.x;
    down5 n + 1, r;
  ENDPROC
  PROC main5()
    VAR pos p;
    down5 1, p;
  ENDPROC
  FUNC num first_of(num a{*}, num b, num c, num d)
    RETURN a{1} + b + c + d;
  ENDFUNC
  PROC down6(num n)
    VAR num s;
    s := first_of(big, n, 2, 3);
    TPWrite "depth6 " \Num:=s;
    down6 n + 1;
  ENDPROC
  PROC main6()
    down6 1;
  ENDPROC
ENDMODULE
|rapid} in
  let program = load_text "mem" text in
  List.iter (fun max_memory ->
      List.iter (fun entry ->
          let limits = { Rapid_runtime.Limits.default with max_memory } in
          let m_events, m_outcome = machine_run limits program ~entry ~max_steps:10_000_000 in
          let c_events, c_outcome = closure_run limits program ~entry ~fuel:10_000_000 in
          (match m_outcome, c_outcome with
           | Resource_exhausted _, Resource_exhausted _ -> ()
           | _ -> Alcotest.failf "budget %d, %s: %s / %s" max_memory entry (outcome_text m_outcome) (outcome_text c_outcome));
          (match difference m_events c_events with None -> () | Some d -> Alcotest.failf "budget %d, %s: %s" max_memory entry d);
          Alcotest.(check bool) "some calls ran" true (List.length c_events > 4))
        [ "main"; "main2"; "main3"; "main4"; "main5"; "main6" ])
    [ 40_000; 60_000; 90_001 ]

(* Found by the fuzzing campaign (rapid-sem fuzz --seed 7 --mismatching, program 771): an index
   that is an integer value far outside the dimension. R-3.6: "an integer outside 1..dimension
   is ERR_OUTOFBND"; 1E20 is an integer value (a single holds it exactly). The closure engine
   follows R-3.6; the machine raises ERR_NOTINTVAL for an integer of magnitude 10^15 or more
   (reported; machine.ml is not this branch's to change), so the two are not compared here. *)
let huge_integer_index () =
  let program = load_text "idx" {rapid|MODULE idx
  VAR num gmat{2, 3};
  VAR num garr{5};
  VAR num k := 1E20;
  PROC main()
    TPWrite "a";
    garr{k} := 5;
  ENDPROC
  PROC main2()
    gmat{1, Trunc((1E20 + 6))} := 5;
  ENDPROC
ENDMODULE
|rapid} in
  List.iter (fun (entry, line) ->
      let expected = Printf.sprintf "stopped ERR_OUTOFBND 1020 idx.mod:%d:5 (%s) about index 1E+20 outside the \
                                     dimension 1 to %d" line entry (if entry = "main" then 5 else 3) in
      (match C.events ~host:(Rapid_run.Run.setup ()).host program ~entry with
       | Error m -> Alcotest.fail m
       | Ok (_, r) -> Alcotest.(check string) ("closure " ^ entry) expected (outcome_text r.outcome));
      (* The machine agrees since its integers have no bound of their own (R-3.6). *)
      let _, o = machine_run Rapid_runtime.Limits.default program ~entry ~max_steps:10_000 in
      Alcotest.(check string) ("machine " ^ entry) expected (outcome_text o))
    [ ("main", 7); ("main2", 10) ]

(* §5.4, §1.4: recursion as deep as the default limit allows runs; one call more exhausts the
   call depth, in both engines alike. *)
let recursion depth =
  Printf.sprintf "MODULE deep\n  FUNC num down(num n)\n    IF n = 0 RETURN 0;\n    RETURN down(n - 1) + 1;\n  ENDFUNC\n  PROC main()\n    TPWrite \"d=\" \\Num:=down(%d);\n  ENDPROC\nENDMODULE\n" depth

let deep_recursion () =
  (* main and 10,000 - 1 activations of down: the deepest chain the default limit allows. *)
  let events, outcome = agree (load_text "deep" (recursion 9998)) in
  Alcotest.(check string) "outcome" "ended" (outcome_text outcome);
  Alcotest.(check bool) "d=9998" true (List.mem (Rapid_runtime.Event.Output "d=9998") events);
  let _, outcome = agree (load_text "deeper" (recursion 9999)) in
  Alcotest.(check string) "one call more" "exhausted" (outcome_text outcome)

(* A call chain deeper than the native stack holds ends as resource exhaustion, cleanly. *)
let native_stack () =
  let program = load_text "unbounded" (recursion 100_000_000) in
  let limits = { Rapid_runtime.Limits.default with max_call_depth = max_int } in
  match C.run ~host:(Rapid_run.Run.setup ()).host ~limits program ~entry:"main" with
  | Error m -> Alcotest.fail m
  | Ok { outcome = Resource_exhausted (m, _); _ } ->
      Alcotest.(check bool) ("the reason names the native stack: " ^ m) true
        (Str.string_match (Str.regexp ".*native stack") m 0)
  | Ok { outcome; _ } -> Alcotest.failf "expected exhaustion, got %s" (outcome_text outcome)

(* Fuel: one unit per statement started, per loop iteration and per routine entered. *)
let fuel () =
  let program = load_text "fuel"
      "MODULE fuel\n  PROC p()\n  ENDPROC\n  PROC main()\n    VAR num i;\n    WHILE i < 3 DO\n      i := i + 1;\n      p;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n" in
  (match C.run ~host:(Rapid_run.Run.setup ()).host program ~entry:"main" with
   | Ok { outcome = Ended; fuel_used } ->
       (* the WHILE statement, 4 tests of its condition, 3 x (2 statements and 1 routine) *)
       Alcotest.(check int) "fuel used" 14 fuel_used
   | _ -> Alcotest.fail "the program did not end");
  match C.run ~host:(Rapid_run.Run.setup ()).host ~fuel:13 program ~entry:"main" with
  | Ok { outcome = Running; _ } -> ()
  | _ -> Alcotest.fail "13 units of fuel do not suffice"

(* Names neither declared nor installed (--allow-unknown) are execution errors when reached. *)
let unknown_names () =
  let events, _ = agree (load_text ~allow_unknown:true "unknown" {rapid|MODULE unk
  VAR num x;
  PROC main()
    TPWrite "a";
    NoSuchProc 1;
    TPWrite "b";
    x := nosuchfun(2);
    TPWrite "c";
    x := nosuchdata + 1;
    TPWrite "d";
  ERROR
    TPWrite "h " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
|rapid}) in
  let raised = List.filter_map (function Rapid_runtime.Event.Error_raised { name; _ } -> Some name | _ -> None) events in
  Alcotest.(check (list string)) "errors" [ "ERR_REFUNKPRC"; "ERR_REFUNKFUN"; "ERR_REFUNKDAT" ] raised

let no_entry () =
  let program = load_text "entry" "MODULE e\n  PROC p(num x)\n  ENDPROC\nENDMODULE\n" in
  Alcotest.(check bool) "no entry routine" true (Result.is_error (C.run ~host:(Rapid_run.Run.setup ()).host program ~entry:"main"));
  Alcotest.(check bool) "an entry routine needs no parameters" true (Result.is_error (C.run ~host:(Rapid_run.Run.setup ()).host program ~entry:"p"))

(* Random programs (gen_programs.ml): the engines agree on each. *)
let random_programs () =
  let agree_on text =
    match Parse.parse_string ~name:"generated.mod" text with
    | Error d -> QCheck.Test.fail_reportf "does not parse: %s" (Diagnostic.to_string d)
    | Ok m -> (
        match Rapid_load.Session.load_modules [ m ] with
        | Error _ -> QCheck.Test.fail_reportf "does not check"
        | Ok l ->
            let budget = 1_000_000 and limits = Rapid_runtime.Limits.default in
            let m_events, m_outcome = machine_run limits l.program ~entry:"main" ~max_steps:budget in
            let c_events, c_outcome = closure_run limits l.program ~entry:"main" ~fuel:budget in
            if outcome_text m_outcome <> outcome_text c_outcome then
              QCheck.Test.fail_reportf "outcomes: machine %s, closure %s" (outcome_text m_outcome)
                (outcome_text c_outcome)
            else (
              match difference m_events c_events with
              | None -> true
              | Some d -> QCheck.Test.fail_reportf "%s" d))
  in
  QCheck.Test.check_exn ~rand:(Random.State.make [| 20261123 |])
    (QCheck.Test.make ~count:150 ~name:"machine = closure on random programs"
       (QCheck.make ~print:(fun s -> s) Gen_programs.gen) agree_on)

(* Schema rapid-sem/2's events, observed, from the fuzzer's generator too: late binding,
   long jumps, UNDO, RETRY and TRYNEXT, every parameter mode (lib/fuzz/program_gen.ml). *)
let fuzz_programs_observed () =
  let rand = Random.State.make [| 20261127 |] in
  let compared = ref 0 in
  for i = 1 to 300 do
    let source = Rapid_fuzz.Program_gen.to_source (Rapid_fuzz.Program_gen.generate rand) in
    match Parse.parse_string ~name:"generated.mod" source with
    | Error _ -> ()
    | Ok m -> (
        (* The fuzzer's controller: its signals, and the stimulus of di1. *)
        match Rapid_fuzz.Fuzz_run.load m with
        | Error _ -> ()
        | Ok l ->
            incr compared;
            let budget = 200_000 and limits = Rapid_runtime.Limits.default in
            let world () = Rapid_controller.World.create Rapid_fuzz.Fuzz_run.io in
            let m_events, m_outcome = machine_run ~world:(world ()) limits l.program ~entry:"main" ~max_steps:budget in
            let c_events, c_outcome = closure_run ~world:(world ()) limits l.program ~entry:"main" ~fuel:budget in
            let cut_short = m_outcome = Running || c_outcome = Running
                            || (match m_outcome, c_outcome with Resource_exhausted _, _ | _, Resource_exhausted _ -> true | _ -> false) in
            if cut_short then begin
              if not (is_prefix m_events c_events || is_prefix c_events m_events) then
                Alcotest.failf "program %d: %s\n%s" i (Option.value (difference m_events c_events) ~default:"") source
            end
            else begin
              if outcome_text m_outcome <> outcome_text c_outcome then
                Alcotest.failf "program %d: outcomes: machine %s, closure %s\n%s" i (outcome_text m_outcome)
                  (outcome_text c_outcome) source;
              match difference m_events c_events with
              | None -> ()
              | Some d -> Alcotest.failf "program %d: %s\n%s" i d source
            end)
  done;
  (* The generator builds checked programs: nearly all of them are compared. *)
  Alcotest.(check bool) "programs compared" true (!compared >= 290)

(* Random programs of the controller: timers, traps that count, raise, call a routine that raises
   or EXIT, waits, IDisable/IEnable, ISleep/IWatch, loops and calls with UNDO, handlers that RETRY,
   TRYNEXT, RETURN or RAISE, error recovery points; random statement times. Both engines must
   make the same events and end alike. *)
let controller_programs () =
  let open QCheck.Gen in
  let pick l = oneofl l in
  let gen =
    let* statement_time = pick [ 0.001; 0.004; 0.01; 0.03 ] in
    let* period = pick [ "0.005"; "0.012"; "0.02"; "0.05" ] in
    let* single = bool in
    let* second = pick [ "0.007"; "0.025"; "0.04" ] in
    let* trap1 = pick [ "hits := hits + 1;"; "hits := hits + 1;\n    TPWrite \"tick \" \\Num:=INTNO;";
                        "hits := hits + 1;\n    IF hits = 3 RAISE 41;"; "hits := hits + 1;\n    WaitTime 0.003;" ] in
    let* trap2 = pick [ "RAISE 42;"; "deep;"; "hits := hits + 10;"; "IF hits > 2 EXIT;"; "RAISE 43;" ] in
    let* recovery = pick [ ""; " (41)"; " (42, 43)"; " (LONG_JMP_ALL_ERR)" ] in
    let* ending = pick [ "RETRY;"; "TRYNEXT;"; "RETURN;"; "RAISE;"; "IF tries < 3 RETRY;\n    TRYNEXT;" ] in
    let statement = pick [
        "TPWrite \"s \" \\Num:=hits;"; "WaitTime 0.01;"; "WaitTime 0.03;";
        "FOR i FROM 1 TO 5 DO\n      n := n + 1;\n    ENDFOR"; "work;";
        "IDisable;\n    WaitTime 0.02;\n    IEnable;"; "ISleep t1;\n    WaitTime 0.02;\n    IWatch t1;";
        "WaitUntil hits > 2 \\MaxTime:=0.2;"; "n := n + 1;"; "IF n > 3 THEN\n      work;\n    ENDIF";
        (* IEnable last in a list: the interrupts queued meanwhile are served at its end *)
        "IF n >= 0 THEN\n      IDisable;\n      WaitTime 0.02;\n      IEnable;\n    ENDIF" ] in
    let* body = list_size (int_range 2 7) statement in
    let* work_body = list_size (int_range 1 3) statement in
    let work_body = List.filter (fun s -> s <> "work;" && s <> "IF n > 3 THEN\n      work;\n    ENDIF") work_body in
    return (statement_time, Printf.sprintf {|MODULE rc
  VAR intnum t1;
  VAR intnum t2;
  VAR num hits := 0;
  VAR num n := 0;
  VAR num tries := 0;
  TRAP first
    %s
  ENDTRAP
  TRAP second
    %s
  ENDTRAP
  PROC deep()
    RAISE 42;
  UNDO
    TPWrite "undo deep";
  ENDPROC
  PROC work()
    n := n + 1;
    %s
  UNDO
    TPWrite "undo work";
  ENDPROC
  PROC main()
    CONNECT t1 WITH first;
    ITimer %s%s, t1;
    CONNECT t2 WITH second;
    ITimer \Single, %s, t2;
    %s
    TPWrite "end " \Num:=hits;
  ERROR%s
    tries := tries + 1;
    TPWrite "handler " \Num:=ERRNO;
    %s
  ENDPROC
ENDMODULE
|} trap1 trap2 (String.concat "\n    " work_body)
                   (if single then "\\Single, " else "") period second (String.concat "\n    " body) recovery ending)
  in
  let agree_on (statement_time, text) =
    let program = load_text "rc" text in
    let run f = f (Rapid_controller.World.create ~statement_time ~max_time:20. Rapid_controller.Io_config.empty) in
    let budget = 200_000 in
    let m_events, m_outcome = run (fun world -> machine_run ~world Rapid_runtime.Limits.default program ~entry:"main" ~max_steps:budget) in
    let c_events, c_outcome = run (fun world -> closure_run ~world Rapid_runtime.Limits.default program ~entry:"main" ~fuel:budget) in
    match m_outcome, c_outcome with
    | Running, _ | _, Running -> is_prefix m_events c_events || is_prefix c_events m_events
    | _ ->
        if outcome_text m_outcome <> outcome_text c_outcome then
          QCheck.Test.fail_reportf "outcomes: machine %s, closure %s" (outcome_text m_outcome) (outcome_text c_outcome)
        else match difference m_events c_events with
          | None -> true
          | Some d -> QCheck.Test.fail_reportf "%s" d
  in
  QCheck.Test.check_exn ~rand:(Random.State.make [| 20261127 |])
    (QCheck.Test.make ~count:300 ~name:"machine = closure on random controller programs"
       (QCheck.make ~print:(fun (t, s) -> Printf.sprintf "statement time %g\n%s" t s) gen) agree_on)

let suite =
  ( "engines",
    Alcotest.test_case "machine = closure on 150 random programs" `Quick random_programs ::
    Alcotest.test_case "machine = closure, observed, on 300 fuzz programs" `Quick fuzz_programs_observed ::
    Alcotest.test_case "machine = closure on 300 random controller programs" `Quick controller_programs ::
    Alcotest.test_case "machine = closure on 200 random pairs of tasks" `Quick random_tasks ::
    Alcotest.test_case "the spec/ run cases pass under the closure engine" `Quick spec_under_closure
    :: Alcotest.test_case "machine = closure: the controller, signals, traps, motion" `Quick controller_runs
    :: Alcotest.test_case "the memory budget: the same bytes, the same call" `Quick memory_budget
    :: Alcotest.test_case "an integer index far beyond the dimension (R-3.6)" `Quick huge_integer_index
    :: Alcotest.test_case "recursion 10,000 deep, and one call more" `Quick deep_recursion
    :: Alcotest.test_case "the native stack ends a run cleanly" `Quick native_stack
    :: Alcotest.test_case "fuel" `Quick fuel
    :: Alcotest.test_case "entry routines" `Quick no_entry
    :: Alcotest.test_case "machine = closure: unknown names reached" `Quick unknown_names
    :: List.map (fun (name, text) -> Alcotest.test_case ("machine = closure: " ^ name) `Quick
                    (program_agrees (name, text))) programs
    @ List.map (fun path ->
        let name = String.concat "/" (List.rev (List.filteri (fun i _ -> i < 2)
                                                  (List.rev (String.split_on_char '/' path)))) in
        Alcotest.test_case ("machine = closure: " ^ name) `Quick (compare_case path)) (run_cases ())
    @ List.map (fun path ->
        Alcotest.test_case ("machine = closure, several tasks: " ^ Filename.basename path) `Quick
          (compare_tasks_case path)) (task_cases ())
    @ List.concat_map (fun path ->
        (* Every case again under several schedules: round robin and five seeds. *)
        List.map (fun seed ->
            Alcotest.test_case (Printf.sprintf "machine = closure, several tasks, seed %d: %s" seed (Filename.basename path))
              `Quick (compare_tasks_case ~seed path)) [ 1; 2; 3; 7; 99 ]) (task_cases ()) )
