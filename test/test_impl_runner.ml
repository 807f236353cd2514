(* rapid-sem spec --impl: the conformance suite through the oracle's protocol, its JUnit XML and
   JSON reports (doc/oracle.md). The implementation is rapid-sem itself behind the protocol, and
   a wrapper that alters one output line. *)

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"
let cases = "golden/spec-impl-cases"

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

let contains s sub =
  let n = String.length sub and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = sub || go (i + 1)) in
  go 0

let run_with script =
  Unix.putenv "RAPID_SEM" binary;
  let junit = Filename.temp_file "junit" ".xml" and json = Filename.temp_file "report" ".json" in
  let buffer = Buffer.create 256 in
  let out = Format.formatter_of_buffer buffer in
  let passed, failed =
    Rapid_conformance.Impl_runner.run ~junit ~json
      ~template:(Printf.sprintf "sh golden/%s {mode} {options} {files}" script) out cases in
  Format.pp_print_flush out ();
  let x = read_file junit and j = Yojson.Safe.from_string (read_file json) in
  Sys.remove junit; Sys.remove json;
  (passed, failed, x, j)

let field name = function `Assoc f -> List.assoc name f | _ -> `Null

let self_agrees () =
  let passed, failed, xml, json = run_with "spec-impl-self.sh" in
  Alcotest.(check (pair int int)) "passed, failed" (4, 0) (passed, failed);
  Alcotest.(check bool) "JUnit: the totals" true (contains xml "<testsuites name=\"rapid-sem conformance\" tests=\"4\" failures=\"0\"");
  Alcotest.(check bool) "JUnit: a suite per section" true (contains xml "<testsuite name=\"§4.18\"");
  Alcotest.(check bool) "JUnit: a test case per case" true (contains xml "name=\"golden/spec-impl-cases/18-for-step.mod\"");
  Alcotest.(check bool) "JSON: passed" true (field "passed" json = `Int 4)

let wrong_is_caught () =
  let passed, failed, xml, json = run_with "spec-impl-wrong.sh" in
  Alcotest.(check (pair int int)) "passed, failed" (2, 2) (passed, failed);
  Alcotest.(check bool) "JUnit: failures" true (contains xml "failures=\"2\"");
  Alcotest.(check bool) "JUnit: the failure says what differs" true (contains xml "<failure message=\"output &quot;1!&quot;");
  Alcotest.(check bool) "JSON: failed" true (field "failed" json = `Int 2)

(* Several tasks (format 4) through {tasks}: doc/oracle.md, "Several tasks"; R-14-p. *)

module IR = Rapid_conformance.Impl_runner
module TS = Rapid_oracle.Task_streams

let reference = Filename.quote binary ^ " run --json {options} {tasks} {files}"
let self_tasks = "sh golden/spec-impl-self.sh {mode} {options} {tasks} {files}"

let several_tasks (c : Rapid_conformance.Spec_case.t) =
  match c.run with Some { tasks = _ :: _; _ } -> true | _ -> false

(* Every case of several tasks in spec/, wherever it is: rapid-sem behind the protocol with
   {tasks} passes each, its events compared task by task with rapid-sem's own. *)
let self_passes_every_format_4_case () =
  Unix.putenv "RAPID_SEM" binary;
  let paths, _ = Rapid_conformance.Spec_runner.collect "../spec" in
  let cases = List.filter several_tasks (List.map Rapid_conformance.Spec_case.read paths) in
  Alcotest.(check bool) "spec/ has cases of several tasks" true (List.length cases >= 29);
  List.iter (fun (c : Rapid_conformance.Spec_case.t) ->
      let r = IR.run_case ~reference ~template:self_tasks c in
      Alcotest.(check (pair bool string)) c.path (true, "") (r.passed, r.detail)) cases

(* The cases of the mass memory (@home, files made and read again): each run behind the
   protocol has a mass memory of its own (--fs), so rapid-sem passes them, and neither run
   leaves a mass memory in the current folder. *)
let mass_memory_of_its_own () =
  Unix.putenv "RAPID_SEM" binary;
  let before = Sys.file_exists ".rapid-sem" in
  List.iter (fun path ->
      let c = Rapid_conformance.Spec_case.read ("../spec/" ^ path) in
      let r = IR.run_case ~reference ~template:self_tasks c in
      Alcotest.(check (pair bool string)) path (true, "") (r.passed, r.detail))
    [ "06-backward/7-5-manual-example.mod"; "13-services/13-dir.mod"; "13-services/13-open-errors.mod";
      "13-services/15-text-tables.mod"; "13-services/15-write-from-file.mod" ];
  Alcotest.(check bool) "no .rapid-sem made here" before (Sys.file_exists ".rapid-sem");
  let c = Rapid_conformance.Spec_case.read "../spec/13-services/15-text-tables.mod" in
  let words = String.split_on_char ' ' (IR.command ~fs:[ "--fs"; "D" ] ~template:"tool {options}" c) in
  Alcotest.(check bool) "--fs D in {options}" true
    (let rec has = function "--fs" :: "D" :: _ -> true | _ :: l -> has l | [] -> false in has words)

let case_at path = Rapid_conformance.Spec_case.read ("golden/spec-impl-tasks-cases/" ^ path)

(* {tasks} spelled as rapid-sem run spells the options; {files} empty beside it; a case of one
   task leaves {tasks} empty. *)
let tasks_placeholder () =
  let cmd = IR.command ~template:"tool {mode} {options} {tasks} [{files}]" in
  let dir = "golden/spec-impl-tasks-cases/" in
  Alcotest.(check string) "an entry per task"
    (Printf.sprintf "tool run  --task %s --task %s --entry %s []"
       (Filename.quote ("T_ROB1=" ^ dir ^ "02-entry-per-task.task/a.mod"))
       (Filename.quote ("T_B=" ^ dir ^ "02-entry-per-task.task/b.mod")) (Filename.quote "T_B=serve"))
    (cmd (case_at "02-entry-per-task.task"));
  Alcotest.(check bool) "the schedule" true
    (contains (cmd (case_at "01-persistent-hand-shake-seeded.task")) " --schedule 12345 ");
  Alcotest.(check bool) "the motion task" true
    (contains (cmd (case_at "06-motion-task-named.task")) (" --motion-task " ^ Filename.quote "T_MOVE" ^ " "));
  Alcotest.(check string) "one task: no {tasks}, the files"
    (Printf.sprintf "tool run   [%s]" (Filename.quote (dir ^ "05-get-task-name-one-task.mod")))
    (cmd (case_at "05-get-task-name-one-task.mod"))

(* {options} carries @max-steps and @robot, so that rapid-sem behind the protocol passes the
   cases that need them (an endless loop, a robot on a track). *)
let options_of_limits_and_robot () =
  Unix.putenv "RAPID_SEM" binary;
  let read p = Rapid_conformance.Spec_case.read ("../spec/" ^ p) in
  let loop = read "04-run/19-endless-loop.mod" and track = read "motion/46-track-movel.mod" in
  Alcotest.(check bool) "--max-steps" true
    (contains (IR.command ~template:"tool {options} {files}" loop) " --max-steps 100000 ");
  Alcotest.(check bool) "--robot" true
    (contains (IR.command ~template:"tool {options} {files}" track)
       (" --robot " ^ Filename.quote "../spec/motion/robot/track.robot" ^ " "));
  List.iter (fun (c : Rapid_conformance.Spec_case.t) ->
      let r = IR.run_case ~reference ~template:self_tasks c in
      Alcotest.(check (pair bool string)) c.path (true, "") (r.passed, r.detail)) [ loop; track ]

(* rapid-sem oracle's programs are one task each: the same template serves. *)
let oracle_template () =
  let cmd template = Rapid_oracle.Implementation.command_line ~template ~files:[ "a.mod"; "b.mod" ] in
  Alcotest.(check string) "{tasks} is nothing" "tool  'a.mod' 'b.mod'" (cmd "tool {tasks} {files}");
  Alcotest.(check string) "the files appended" "tool  'a.mod' 'b.mod'" (cmd "tool {tasks}");
  Alcotest.(check string) "{file}" "tool 'a.mod'" (cmd "tool {file}")

let without_tasks_skipped () =
  let r = IR.run_case ~reference ~template:"sh golden/spec-impl-self.sh {mode} {options} {files}"
      (case_at "02-entry-per-task.task") in
  Alcotest.(check (pair bool bool)) "skipped, not failed" (false, true) (r.passed, r.skipped);
  Alcotest.(check string) "why" "several tasks (format 4): the template has no {tasks}" r.detail

let wrong_tasks_caught () =
  Unix.putenv "RAPID_SEM" binary;
  let r = IR.run_case ~reference ~template:"sh golden/spec-impl-tasks-store.sh {mode} {options} {tasks} {files}"
      (case_at "01-persistent-hand-shake-seeded.task") in
  Alcotest.(check (pair bool string)) "the task and its event"
    (false, {|task T_B, event 3: expected {"event":"store","place":"state","task":"T_B","value":"2"}, got {"event":"store","place":"state","task":"T_B","value":"21"}|})
    (r.passed, r.detail)

let stream schema lines =
  { Rapid_oracle.Event_stream.schema = Some schema; events = List.map Yojson.Safe.from_string lines }

let v2 = stream "rapid-sem/2"
let ev task kind extra = Printf.sprintf {|{"event":"%s","task":"%s"%s}|} kind task extra
let out task text = ev task "output" (Printf.sprintf {|,"text":"%s"|} text)
let the_end = {|{"event":"end","outcome":"ended","steps":7,"at":null}|}

let verdict_text = function
  | TS.Agree n -> Printf.sprintf "agree %d" n
  | Diverge d -> TS.report d
  | Broken m -> "broken: " ^ m

let check_verdict what expected v = Alcotest.(check string) what expected (verdict_text v)

let compare_task_streams () =
  let reference = v2 [ out "A" "a1"; out "B" "b1"; out "A" "a2"; out "B" "b2"; the_end ] in
  check_verdict "the tasks interleaved otherwise" "agree 5"
    (TS.compare ~expected:reference ~actual:(v2 [ out "B" "b1"; out "B" "b2"; out "A" "a1"; out "A" "a2"; the_end ]) ());
  check_verdict "a task's own order"
    {|task B, event 1: expected {"event":"output","task":"B","text":"b1"}, got {"event":"output","task":"B","text":"b2"}|}
    (TS.compare ~expected:reference ~actual:(v2 [ out "A" "a1"; out "B" "b2"; out "A" "a2"; out "B" "b1"; the_end ]) ());
  check_verdict "an output told as the other task's"
    {|task A, event 2: expected {"event":"output","task":"A","text":"a2"}, got (no more events)|}
    (TS.compare ~expected:reference ~actual:(v2 [ out "A" "a1"; out "B" "b1"; out "B" "a2"; out "B" "b2"; the_end ]) ());
  check_verdict "of two divergences, the one rapid-sem came to first"
    {|task B, event 1: expected {"event":"output","task":"B","text":"b1"}, got {"event":"output","task":"B","text":"x"}|}
    (TS.compare ~expected:reference ~actual:(v2 [ out "A" "a1"; out "B" "x"; out "A" "y"; out "B" "b2"; the_end ]) ());
  check_verdict "a task rapid-sem did not run"
    {|task C, event 1: expected (no more events), got {"event":"output","task":"C","text":"c"}|}
    (TS.compare ~expected:reference ~actual:(v2 [ out "A" "a1"; out "B" "b1"; out "A" "a2"; out "B" "b2"; out "C" "c"; the_end ]) ());
  (* The task's name is the implementation's text: escaped like the rest (R-1-oracle2n). *)
  check_verdict "a task name of control bytes, escaped"
    ({|task \1B[2J, event 1: expected (no more events), got {"event":"output","task":"\u001b[2J","text":"c"}|})
    (TS.compare ~expected:reference
       ~actual:(v2 [ out "A" "a1"; out "B" "b1"; out "A" "a2"; out "B" "b2"; out "\027[2J" "c"; the_end ]) ());
  check_verdict "the end object, its steps not compared" "agree 5"
    (TS.compare ~expected:reference
       ~actual:(v2 [ out "A" "a1"; out "B" "b1"; out "A" "a2"; out "B" "b2"; {|{"event":"end","outcome":"ended","at":null}|} ]) ());
  check_verdict "the run's end"
    {|run, event 1: expected {"at":null,"event":"end","outcome":"ended"}, got {"at":null,"event":"end","outcome":"stopped"}|}
    (TS.compare ~expected:reference
       ~actual:(v2 [ out "A" "a1"; out "B" "b1"; out "A" "a2"; out "B" "b2"; {|{"event":"end","outcome":"stopped","at":null}|} ]) ());
  check_verdict "ignored kinds" "agree 1"
    (TS.compare ~ignore:[ "output" ] ~expected:reference ~actual:(v2 [ out "B" "zz"; the_end ]) ());
  check_verdict "another schema"
    "broken: the implementation's first line names the schema rapid-sem/1; expected rapid-sem/2 (the schema of several tasks)"
    (TS.compare ~expected:reference ~actual:(stream "rapid-sem/1" [ the_end ]) ())

(* The world's events are one stream in their order, whichever task they name (as rapid-sem
   compares its engines): a signal's changes out of order diverge even when each task's agree. *)
let world_stream () =
  let signal task v = ev task "signal-changed" (Printf.sprintf {|,"time":0.1,"signal":"do1","value":%d|} v) in
  let reference = v2 [ out "A" "a"; signal "A" 1; out "B" "b"; signal "B" 0; the_end ] in
  check_verdict "in order" "agree 5"
    (TS.compare ~expected:reference ~actual:(v2 [ out "B" "b"; out "A" "a"; signal "A" 1; signal "B" 0; the_end ]) ());
  check_verdict "out of order"
    {|world, event 1: expected {"event":"signal-changed","signal":"do1","task":"A","time":0.1,"value":1}, got {"event":"signal-changed","signal":"do1","task":"B","time":0.1,"value":0}|}
    (TS.compare ~expected:reference ~actual:(v2 [ out "A" "a"; out "B" "b"; signal "B" 0; signal "A" 1; the_end ]) ());
  Alcotest.(check (list string)) "the streams, tasks first"
    [ "task A"; "task B"; "world"; "run" ]
    (List.map fst (TS.streams reference.events))

let suite =
  ("impl-runner", [
      Alcotest.test_case "rapid-sem behind the protocol agrees with the suite" `Quick self_agrees;
      Alcotest.test_case "a wrong implementation is caught, in JUnit and JSON too" `Quick wrong_is_caught;
      Alcotest.test_case "with {tasks}: every case of several tasks passes" `Quick self_passes_every_format_4_case;
      Alcotest.test_case "{tasks}: the options of rapid-sem run" `Quick tasks_placeholder;
      Alcotest.test_case "{options}: @max-steps and @robot" `Quick options_of_limits_and_robot;
      Alcotest.test_case "a mass memory of its own for each run (--fs, @home)" `Quick mass_memory_of_its_own;
      Alcotest.test_case "without {tasks}: several tasks skipped" `Quick without_tasks_skipped;
      Alcotest.test_case "oracle: {tasks} is nothing for one task" `Quick oracle_template;
      Alcotest.test_case "several tasks: a wrong store caught at the task's event" `Quick wrong_tasks_caught;
      Alcotest.test_case "several tasks: compared task by task" `Quick compare_task_streams;
      Alcotest.test_case "several tasks: the world's stream" `Quick world_stream ])
