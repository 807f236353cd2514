(* The memory of a run's motion (doc/motion.md, "Memory"): without history it does not grow with
   the moves made; with history (--samples, rapid-sem motion) it is charged against its budget. *)

module M = Rapid_semantics.Machine
module MP = Rapid_installed.Motion_routines
module MM = Rapid_motion_model

let loop ~moves ~zone ~speed ~p2 =
  Printf.sprintf {|MODULE memloop
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,%s,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    FOR i FROM 1 TO %d DO
      MoveL p2, %s, %s, tool0;
      MoveL p1, %s, %s, tool0;
    ENDFOR
    TPWrite "done";
  ENDPROC
ENDMODULE
|} p2 (moves / 2) speed zone speed zone

(* The robot of the run [start] made last. *)
let last_motion = ref None

let start ?history text =
  let f = Filename.temp_file "memloop" ".mod" in
  let oc = open_out_bin f in
  output_string oc text; close_out oc;
  match Rapid_load.Session.load ~io:Rapid_controller.Io_config.empty [ f ] with
  | Error _ -> Sys.remove f; Alcotest.fail "the loop does not load"
  | Ok loaded -> (
      Sys.remove f;
      let world = Rapid_controller.World.create ~statement_time:0. ~max_time:1e9 Rapid_controller.Io_config.empty in
      let motion = MP.create ?history () in
      match M.start ~host:(Rapid_run.Run.setup ~controller:world ~motion ()).host loaded.program ~entry:"main" with
      | Error m -> Alcotest.fail m
      | Ok cfg -> last_motion := Some motion; cfg)

(* Steps until [n] moves are planned or the run ends; the events are not kept. *)
let run_until cfg planned n =
  while M.outcome cfg = Rapid_runtime.Outcome.Running && !planned < n do
    List.iter (function Rapid_runtime.Event.Motion (Rapid_observable.Motion_event.Segment_planned _) -> incr planned | _ -> ()) (snd (M.step cfg))
  done

let live_words () = Gc.full_major (); (Gc.stat ()).live_words

(* 200,000 moves: the live heap after them is what it was after the first 20,000 (before, about
   1 KB a move stayed: 180 MB). *)
let bounded ~zone ~speed ~p2 ~moves () =
  let cfg = start (loop ~moves ~zone ~speed ~p2) in
  let planned = ref 0 in
  run_until cfg planned (moves / 10);
  let early = live_words () in
  run_until cfg planned max_int;
  let late = live_words () in
  Alcotest.(check int) "every move planned" (moves + 1) !planned;
  Alcotest.(check bool) "the run ended" true (M.outcome cfg = Rapid_runtime.Outcome.Ended);
  let grown = (late - early) * (Sys.word_size / 8) in
  if grown > 2_000_000 then
    Alcotest.failf "the live heap grew by %d bytes over %d moves" grown (moves - moves / 10)

(* The same in the closure engine, the one `rapid-sem run` uses: the live heap measured from
   inside the run, at the 2,000th move planned and at the last, without samples. *)
let bounded_closure ~moves () =
  let f = Filename.temp_file "memloop" ".mod" in
  let oc = open_out_bin f in
  output_string oc (loop ~moves ~zone:"z10" ~speed:"v1000" ~p2:"250"); close_out oc;
  let loaded = match Rapid_load.Session.load ~io:Rapid_controller.Io_config.empty [ f ] with
    | Ok l -> Sys.remove f; l
    | Error _ -> Sys.remove f; Alcotest.fail "the loop does not load" in
  let world = Rapid_controller.World.create ~statement_time:0. ~max_time:1e9 Rapid_controller.Io_config.empty in
  let host = (Rapid_run.Run.setup ~controller:world ~motion:(MP.create ()) ()).host in
  let planned = ref 0 and early = ref 0 and late = ref 0 in
  let on_event = function
    | Rapid_runtime.Event.Motion (Rapid_observable.Motion_event.Segment_planned _) ->
        incr planned;
        if !planned = moves / 10 then early := live_words ();
        if !planned = moves + 1 then late := live_words ()
    | _ -> () in
  (match Rapid_closure.Closure_engine.run ~host ~all_events:true ~on_event loaded.program ~entry:"main" with
   | Ok _ -> ()
   | Error m -> Alcotest.fail m);
  Alcotest.(check int) "every move planned" (moves + 1) !planned;
  let grown = (!late - !early) * (Sys.word_size / 8) in
  if grown > 2_000_000 then
    Alcotest.failf "the live heap grew by %d bytes over %d moves (closure engine)" grown (moves - moves / 10)

(* With history the moves kept are charged (Motion_primitives.history_bytes each) against the
   budget; the move beyond it ends the run as a resource exhausted, naming --max-memory. *)
let history_budget () =
  let budget = 100 * MP.history_bytes in
  let cfg = start ~history:budget (loop ~moves:1000 ~zone:"fine" ~speed:"v1000" ~p2:"250") in
  run_until cfg (ref 0) max_int;
  (match M.outcome cfg with
   | Rapid_runtime.Outcome.Resource_exhausted (m, at) ->
       (* At the move beyond the budget, the 101st: MoveL p1 (R-1.4-small2). *)
       (match at with
        | Some r -> let p = Rapid_syntax.Source.start r in
            Alcotest.(check (pair int int)) "at the move beyond" (8, 7) (p.line, p.col)
        | None -> Alcotest.fail "the history's exhaustion has no place");
       let has w = let n = String.length w in
         let rec go i = i + n <= String.length m && (String.sub m i n = w || go (i + 1)) in go 0 in
       if not (has "motion history" && has "--max-memory" && has (string_of_int budget) && has "memloop") then
         Alcotest.failf "the message: %s" m
   | _ -> Alcotest.fail "a history beyond its budget did not end the run");
  let cfg = start ~history:(2000 * MP.history_bytes) (loop ~moves:1000 ~zone:"fine" ~speed:"v1000" ~p2:"250") in
  run_until cfg (ref 0) max_int;
  Alcotest.(check bool) "within the budget, the run ends" true (M.outcome cfg = Rapid_runtime.Outcome.Ended);
  (* The history is there: the path's pieces from the first move on. *)
  let segments = MM.Planner.segments (MP.planner (Option.get !last_motion)) in
  Alcotest.(check int) "every segment kept" 1001 (List.length segments)

(* Forgetting changes no answer from the present on: a planner that forgets at every plan answers
   as one that keeps everything, for poses, axes, spans and ready times. *)
let forget_same () =
  let kin = MM.Kinematics.create MM.Robot.irb120 in
  let keep = MM.Planner.create ~joints:[| 0.; 20.; 10.; 0.; 60.; 0. |] kin
  and forget = MM.Planner.create ~joints:[| 0.; 20.; 10.; 0.; 60.; 0. |] kin in
  let rng = Random.State.make [| 21 |] in
  let zones = [| "fine"; "z1"; "z10"; "z50"; "z200" |] and speeds = [| "v100"; "v1000"; "vmax" |] in
  let find t n = Option.get (MM.Motion_data.find t n) in
  let now = ref 0. in
  for i = 0 to 1999 do
    let target = { MM.Geom.x = 300. +. Random.State.float rng 100.; y = Random.State.float rng 400. -. 200.;
                   z = 250. +. Random.State.float rng 100. } in
    let rt = { MM.Frames.pose = { trans = target; rot = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } };
               conf = { cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } } in
    let speed = find MM.Motion_data.speeddata speeds.(Random.State.int rng 3) in
    let speed = if speed.v_tcp > 7000. then { speed with v_tcp = 6200. } else speed in
    let m = MM.Planner.move speed (find MM.Motion_data.zonedata zones.(Random.State.int rng 5)) (Linear rt) in
    (MM.Planner.settings keep).conf_l <- false; (MM.Planner.settings forget).conf_l <- false;
    if i mod 97 = 50 then begin
      MM.Planner.stop keep ~at:!now; MM.Planner.stop forget ~at:!now;
      now := !now +. 0.3;
      MM.Planner.start keep ~at:!now; MM.Planner.start forget ~at:!now
    end;
    MM.Planner.forget forget ~before:!now ~keep:(max 0 (i - 3));
    match MM.Planner.plan keep ~now:!now m, MM.Planner.plan forget ~now:!now m with
    | Ok a, Ok b ->
        (* Merged pauses round differently in the last bits; the clock counts microseconds. *)
        if Float.abs (a.ready_time -. b.ready_time) > 1e-9 then
          Alcotest.failf "move %d: ready %.17g, forgetting %.17g (now %.17g)" i a.ready_time b.ready_time !now;
        for k = 0 to 4 do
          let t = !now +. float_of_int k *. 0.01 in
          let pa = MM.Planner.pose_at keep t and pb = MM.Planner.pose_at forget t in
          if MM.Geom.distance pa.trans pb.trans > 1e-6 then Alcotest.failf "move %d: the pose at %g differs" i t
        done;
        List.iter (fun id ->
            (* A time already passed may read earlier (pauses merged): the present on is the same. *)
            let us x = Float.round (Float.max x !now *. 1e6) in
            let span p = Option.map (fun (s, e) -> (us s, us e)) (MM.Planner.segment_span p id) in
            if id >= 0 && span keep <> span forget then
              Alcotest.failf "move %d: the span of move %d differs" i id) [ i - 2; i - 1; i ];
        now := Float.max !now a.ready_time
    | Error _, Error _ -> ()
    | _ -> Alcotest.failf "move %d: one planner refused it" i
  done;
  let pieces = List.length (MM.Planner.pieces forget) in
  if pieces > 50 then Alcotest.failf "%d pieces kept after forgetting" pieces

let count_sub s w =
  let n = String.length w in
  let rec go i acc =
    if i + n > String.length s then acc else go (i + 1) (if String.sub s i n = w then acc + 1 else acc) in
  go 0 0

(* A point passed again and again is named once in each view (stacking its name at every pass
   took time cubic in the passes); a long path's CSV has at most Path_output.csv_max_rows rows. *)
let output_bounded () =
  let kin = MM.Kinematics.create MM.Robot.irb120 in
  let p = MM.Planner.create ~joints:[| 0.; 20.; 10.; 0.; 60.; 0. |] kin in
  let rt y = { MM.Frames.pose = { trans = { x = 350.; y; z = 300. }; rot = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } };
               conf = { cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } } in
  let find t n = Option.get (MM.Motion_data.find t n) in
  (MM.Planner.settings p).conf_l <- false;
  let now = ref 0. in
  for i = 0 to 3999 do
    let m = MM.Planner.move ~label:(if i mod 2 = 0 then "pA" else "pB") (find MM.Motion_data.speeddata "v1000")
        (find MM.Motion_data.zonedata "fine") (Linear (rt (if i mod 2 = 0 then 100. else -100.))) in
    match MM.Planner.plan p ~now:!now m with
    | Ok r -> now := r.ready_time
    | Error e -> Alcotest.fail (MM.Motion_error.name e)
  done;
  let svg = MM.Path_output.path_svg p in
  (* the side view (x-z) sees pA and pB at one spot: one label names both *)
  Alcotest.(check (pair int int)) "pA named once in each view" (1, 1) (count_sub svg ">pA<", count_sub svg ">pA, pB<");
  let m = MM.Planner.move ~t:1e5 (find MM.Motion_data.speeddata "v1000") (find MM.Motion_data.zonedata "fine")
      (Linear (rt 0.)) in
  (match MM.Planner.plan p ~now:!now m with Ok _ -> () | Error e -> Alcotest.fail (MM.Motion_error.name e));
  let rows = count_sub (MM.Path_output.csv p) "\n" in
  if rows > MM.Path_output.csv_max_rows + 2 then Alcotest.failf "%d rows" rows

let suite =
  ( "motion memory",
    [ Alcotest.test_case "200,000 fine moves: the live heap stays bounded" `Quick
        (bounded ~zone:"fine" ~speed:"v1000" ~p2:"250" ~moves:200_000);
      Alcotest.test_case "z200 moves of 1 mm at vmax: the live heap stays bounded" `Quick
        (bounded ~zone:"z200" ~speed:"vmax" ~p2:"-249" ~moves:20_000);
      Alcotest.test_case "20,000 moves in the closure engine: the live heap stays bounded" `Quick
        (bounded_closure ~moves:20_000);
      Alcotest.test_case "the history with samples is refused past its budget" `Quick history_budget;
      Alcotest.test_case "forgetting changes no answer from the present on" `Quick forget_same;
      Alcotest.test_case "a point passed often is named once; a long path's CSV is bounded" `Quick output_bounded ] )
