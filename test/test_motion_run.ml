(* Moves in the machine (doc/motion.md, "Moves in the machine"): what spec/ cannot state — the
   motion events of a run, and real programs of test/realworld that only lacked motion. *)

module M = Rapid_semantics.Machine
module MP = Rapid_installed.Motion_routines
module MM = Rapid_motion_model

type run = { outcome : Rapid_runtime.Outcome.t; output : string list; motion : Rapid_observable.Motion_event.t list; cfg : M.config;
             robot : MP.state }

let run ?robot ?io ?(allow_unknown = false) ?(max_time = 3600.) ?(statement_time = 0.) files =
  let io = match io with
    | None -> Rapid_controller.Io_config.empty
    | Some f -> (match Rapid_controller.Io_config.read_file f with Ok c -> c | Error m -> Alcotest.fail m) in
  let robot = match robot with
    | None -> MM.Robot.irb120
    | Some f -> (match MM.Robot.load f with Ok r -> r | Error e -> Alcotest.fail (MM.Robot.error_to_string e)) in
  match Rapid_load.Session.load ~allow_unknown ~io files with
  | Error _ -> Alcotest.failf "%s does not load" (String.concat " " files)
  | Ok loaded -> (
      let world = Rapid_controller.World.create ~statement_time ~max_time io in
      let motion = MP.create ~robot () in
      match M.start ~host:(Rapid_run.Run.setup ~controller:world ~motion:motion ()).host loaded.program ~entry:"main" with
      | Error m -> Alcotest.fail m
      | Ok cfg ->
          let output = ref [] and moves = ref [] in
          while M.outcome cfg = Rapid_runtime.Outcome.Running && M.steps cfg < 5_000_000 do
            let _, events = M.step cfg in
            List.iter (function
                | Rapid_runtime.Event.Output s -> output := s :: !output
                | Rapid_runtime.Event.Motion e -> moves := e :: !moves
                | _ -> ()) events
          done;
          { outcome = M.outcome cfg; output = List.rev !output; motion = List.rev !moves; cfg; robot = motion })

let write_temp text =
  let f = Filename.temp_file "motion" ".mod" in
  let oc = open_out_bin f in
  output_string oc text; close_out oc; f

let planned r = List.filter (function Rapid_observable.Motion_event.Segment_planned _ -> true | _ -> false) r.motion

(* Every move planned begins before it ends, and is seen to end exactly once, at the time it was
   seen to (a task that ends lets the robot finish). *)
let lifecycle r =
  let n = List.length (planned r) in
  let started = Array.make n nan and ended = Array.make n nan in
  List.iter (function
      | Rapid_observable.Motion_event.Segment_started { id; time; _ } ->
          if not (Float.is_nan started.(id)) then Alcotest.failf "move %d started twice" id;
          started.(id) <- time
      | Rapid_observable.Motion_event.Segment_ended { id; time; _ } ->
          if not (Float.is_nan ended.(id)) then Alcotest.failf "move %d ended twice" id;
          ended.(id) <- time
      | _ -> ()) r.motion;
  Array.iteri (fun id e ->
      if Float.is_nan e || Float.is_nan started.(id) then Alcotest.failf "move %d did not start and end" id;
      if started.(id) > e +. 1e-9 then Alcotest.failf "move %d ends before it starts" id) ended;
  (started, ended)

let cell = {|MODULE cell
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR num i;
    MoveJ p1, v1000, fine, tool0;
    FOR i FROM 1 TO 5 DO
      MoveL p2, v500, z50, tool0;
      MoveL Offs(p2, 0, 0, 100), v500, z10, tool0;
      MoveL p1, v500, z50, tool0;
      MoveC Offs(p1, 50, 50, 0), Offs(p1, 0, 100, 0), v200, z20, tool0;
    ENDFOR
    MoveL \Conc, p1, v100, z10, tool0;
  ENDPROC
ENDMODULE
|}

let events_of_a_run () =
  let r = run [ write_temp cell ] in
  Alcotest.(check bool) "ended" true (r.outcome = Rapid_runtime.Outcome.Ended);
  Alcotest.(check int) "moves planned" 22 (List.length (planned r));
  let started, ended = lifecycle r in
  (* Moves follow each other: each begins where (or before: its corner) the one before ends. *)
  for id = 1 to Array.length started - 1 do
    if started.(id) > ended.(id - 1) +. 1e-6 then
      Alcotest.failf "move %d begins at %g, after move %d ended at %g" id started.(id) (id - 1) ended.(id - 1)
  done;
  (* The last move, \Conc, ends after the task did: the robot finishes its path (R-4.1-h). *)
  let p = MP.planner r.robot in
  Alcotest.(check (float 1e-6)) "the last move ends when the robot stands still"
    (MM.Planner.finished_by p) ended.(Array.length ended - 1)

(* The program pointer never leaves a stop point before the robot is there. *)
let program_pointer_at_stop_points () =
  let r = run [ write_temp cell ] in
  List.iter (function
      | Rapid_observable.Motion_event.Segment_planned { zone = "fine"; ready_time; end_time; id; _ } ->
          if ready_time < end_time -. 1e-9 then Alcotest.failf "move %d: ready %g before the end %g" id ready_time end_time
      | _ -> ()) r.motion

(* test/realworld: the deburring cell of CAD output runs to its end on an arm large enough for its
   work objects (large-arm.robot) with its spindle's signals (deburring.io). *)
let deburring_runs () =
  let d = Filename.concat "realworld" in
  let r = run ~robot:(d "large-arm.robot") ~io:(d "deburring.io") [ d "CadDeburrFrame.mod" ] in
  Alcotest.(check bool) "ended" true (r.outcome = Rapid_runtime.Outcome.Ended);
  Alcotest.(check int) "moves" 693 (List.length (planned r));
  ignore (lifecycle r)

(* The palletiser loops for ever: it palletises until the virtual time runs out. *)
let palletiser_runs () =
  let d = Filename.concat "realworld" in
  let r = run ~robot:(d "large-arm.robot") ~io:(d "palletiser.io") ~allow_unknown:true ~max_time:300.
      [ d "Palletizer.mod" ] in
  (match r.outcome with
   | Rapid_runtime.Outcome.Resource_exhausted _ -> ()
   | _ -> Alcotest.fail "expected the virtual time to run out");
  if List.length (planned r) < 100 then Alcotest.failf "only %d moves" (List.length (planned r));
  Alcotest.(check bool) "both pallets filled" true (List.mem "Both pallets full, waiting for exchange" r.output)

(* test/realworld: the polishing cell's targets give the track's position (eax_a, 950 to 2000 mm);
   on the large arm carried by a track (large-arm-track.robot) it runs to its end, and on the same
   arm without the track its first move to a work object is out of reach. *)
let polishing_runs_on_its_track () =
  let d = Filename.concat "realworld" in
  let r = run ~robot:(d "large-arm-track.robot") ~io:(d "polishing.io") [ d "CadPolishCover.mod" ] in
  Alcotest.(check bool) "ended" true (r.outcome = Rapid_runtime.Outcome.Ended);
  Alcotest.(check int) "moves" 189 (List.length (planned r));
  ignore (lifecycle r);
  let fixed = run ~robot:(d "large-arm.robot") ~io:(d "polishing.io") [ d "CadPolishCover.mod" ] in
  match fixed.outcome with
  | Rapid_runtime.Outcome.Stopped { name; at; _ } ->
      Alcotest.(check string) "without the track" "ERR_ROBLIMIT" name;
      Alcotest.(check int) "at the first move to a work object" 344 (Rapid_syntax.Source.start at).line
  | _ -> Alcotest.fail "expected ERR_ROBLIMIT without the track"

let suite =
  ( "motion-run",
    [ Alcotest.test_case "move events: every move starts and ends once, in order" `Quick events_of_a_run;
      Alcotest.test_case "the program pointer waits at stop points" `Quick program_pointer_at_stop_points;
      Alcotest.test_case "realworld: the deburring cell runs to its end" `Quick deburring_runs;
      Alcotest.test_case "realworld: the palletiser palletises" `Quick palletiser_runs;
      Alcotest.test_case "realworld: the polishing cell runs on its track" `Quick polishing_runs_on_its_track ] )

(* The stimulus's collisions (doc/controller.md). *)
let collision_lines () =
  let parse text = Rapid_controller.Io_config.parse ~file:"c.io" text in
  (match parse "signal di1 di\nat 1 di1 1\nat 2.5 collision\nat 3 collision\n" with
   | Ok c -> Alcotest.(check (list (float 0.))) "collisions" [ 2.5; 3. ] c.collisions
   | Error m -> Alcotest.fail m);
  (match parse "at 2 collision\nat 1 collision\n" with
   | Error m -> Alcotest.(check string) "order" "c.io:2:4: io error: the events are not in order of time" m
   | Ok _ -> Alcotest.fail "accepted collisions out of order");
  match parse "at 2 collision\n" |> Result.map (fun _ -> ()), parse "at 2\n" with
  | Ok (), Error m -> Alcotest.(check string) "form" "c.io:1:1: io error: expected: at TIME NAME VALUE, or at TIME collision" m
  | Error m, _ -> Alcotest.fail m
  | Ok (), Ok _ -> Alcotest.fail "accepted a bad at line"

let suite = (fst suite, snd suite @ [ Alcotest.test_case "collisions in the stimulus" `Quick collision_lines ])

(* The waits of move instructions are forgotten when they end: a run of many moves keeps none. *)
let waits_forgotten () =
  let text = {|MODULE w
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    FOR i FROM 1 TO 50 DO
      MoveL p1, v1000, fine, tool0;
      MoveL p2, v1000, fine, tool0;
    ENDFOR
  ENDPROC
ENDMODULE
|} in
  let r = run [ write_temp text ] in
  Alcotest.(check bool) "ended" true (r.outcome = Rapid_runtime.Outcome.Ended);
  Alcotest.(check int) "move waits in progress" 0 (MP.move_waits_in_progress r.robot)

let suite = (fst suite, snd suite @ [ Alcotest.test_case "move waits are forgotten when they end" `Quick waits_forgotten ])
