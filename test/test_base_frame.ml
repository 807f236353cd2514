(* A robot's base frame (doc/motion.md, law F-base; doc/rulings.md R-bk-12): targets in the world
   brought into the base frame before the inverse kinematics, the position functions answering
   through it, a track moving it, the path drawn where the cell mounts the robot. *)

open Rapid_motion_model
open Geom

let close ?(eps = 1e-6) what a b =
  if Float.abs (a -. b) > eps then Alcotest.failf "%s: expected %.9g, got %.9g" what b a

let close_pose ?(eps = 1e-6) what (a : pose) (b : pose) =
  if distance a.trans b.trans > eps || angle_between a.rot b.rot > eps then
    Alcotest.failf "%s: expected [%g %g %g], got [%g %g %g]" what b.trans.x b.trans.y b.trans.z
      a.trans.x a.trans.y a.trans.z

let ok what = function Ok x -> x | Error e -> Alcotest.failf "%s: %s" what (Motion_error.name e)

let run_property ~seed ~count ~name arb prop =
  QCheck.Test.check_exn ~rand:(Random.State.make [| seed |]) (QCheck.Test.make ~count ~name arb prop)

let placed b = { Robot.irb120 with base_frame = b }
let u = Ext_axes.unused
let no_ext = [| u; u; u; u; u; u |]
let down = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. }
let speed n = Option.get (Motion_data.find Motion_data.speeddata n)
let zone n = Option.get (Motion_data.find Motion_data.zonedata n)
let rest = [| 0.; 0.; 0.; 0.; 90.; 0. |]

(* A random base frame: an origin within 5 m, a random unit quaternion. *)
let gen_base =
  QCheck.Gen.(map (fun ((x, y, z), (a, b, c, d)) ->
      let n = sqrt ((a *. a) +. (b *. b) +. (c *. c) +. (d *. d)) in
      let n = if n < 1e-3 then 1. else n in
      let rot = if n = 1. && a = 0. && b = 0. && c = 0. && d = 0. then unit_orient
        else normalize { q1 = a /. n; q2 = b /. n; q3 = c /. n; q4 = d /. n } in
      { trans = { x; y; z }; rot })
      (pair (triple (float_range (-5000.) 5000.) (float_range (-5000.) 5000.) (float_range (-5000.) 5000.))
         (quad (float_range (-1.) 1.) (float_range (-1.) 1.) (float_range (-1.) 1.) (float_range (-1.) 1.))))

(* F-base: CalcRobT is the base frame times the forward kinematics, and CalcJointT of it gives the
   axes back, over random base frames and axes. *)
let test_frames () =
  let gen = QCheck.Gen.(pair gen_base (array_size (return 6) (float_range (-60.) 60.))) in
  run_property ~seed:81 ~count:500 ~name:"F-base" (QCheck.make gen) (fun (b, q) ->
      q.(4) <- 30. +. Float.abs q.(4);
      let kin = Kinematics.create (placed b) in
      let p = Planner.create kin in
      let base = Planner.base p no_ext in
      match Frames.calc_rob_t ?base kin q Motion_data.tool0 Motion_data.wobj0 with
      | Error _ -> QCheck.assume_fail ()
      | Ok rt ->
          close_pose ~eps:1e-6 "in the world" rt.pose (pmult b (Kinematics.forward kin q));
          let q' = ok "calc_joint_t" (Frames.calc_joint_t ?base kin rt Motion_data.tool0 Motion_data.wobj0) in
          Array.for_all2 (fun x y -> Float.abs (x -. y) < 1e-6) q q')

(* A MoveL to a world target that only the moved robot reaches: the planned end is the target in
   the world, the axes there are the base frame's solution, and pose_at draws the path in the
   world frame; the same target is out of reach of the robot at the world's origin. *)
let test_move () =
  let b = { trans = { x = 1000.; y = -2000.; z = 300. }; rot = of_axis_angle { x = 0.; y = 0.; z = 1. } (rad 90.) } in
  let world = { trans = { x = 1000.; y = -1650.; z = 750. }; rot = omult b.rot down } in
  let target = { Frames.pose = world; conf = { cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } } in
  let kin = Kinematics.create (placed b) in
  let p = Planner.create ~joints:rest kin in
  let mv = Planner.move (speed "v100") (zone "fine") (Linear target) in
  let r = ok "plan" (Planner.plan p ~now:0. mv) in
  close_pose "pose_at the end, world" (Planner.pose_at p r.ready_time) world;
  let q = ok "joints" (Planner.joints_at p r.ready_time) in
  close_pose "the base frame's solution" (pmult b (Kinematics.forward kin q)) world;
  let start = pmult b (Kinematics.forward kin rest) in
  close ~eps:1e-6 "v100 over the distance in the world" r.ready_time (distance start.trans world.trans /. 100.);
  let upright = Planner.create ~joints:rest (Kinematics.create Robot.irb120) in
  (match Planner.plan upright ~now:0. mv with
   | Ok _ -> Alcotest.fail "the upright robot reached a target 2 m away"
   | Error _ -> ());
  (* a work object in the world: the target in it is the same point *)
  let wobj = { Motion_data.wobj0 with uframe = { trans = { x = 1000.; y = -2000.; z = 0. }; rot = unit_orient } } in
  let in_wobj = { target with pose = pmult (pinv wobj.uframe) world } in
  let p2 = Planner.create ~joints:rest kin in
  let r2 = ok "plan in the work object" (Planner.plan p2 ~now:0. (Planner.move ~wobj (speed "v100") (zone "fine")
                                                                 (Linear in_wobj))) in
  close_pose "the same point" (Planner.pose_at p2 r2.ready_time) world;
  let rt = ok "CRobT in the work object"
      (Frames.c_rob_t ?base:(Planner.base p2 no_ext) kin ~joints:(ok "j" (Planner.joints_at p2 r2.ready_time))
         Motion_data.tool0 wobj) in
  close_pose "CRobT reads the work object's coordinates" rt.pose in_wobj.pose

(* R-bk-12 with law X-track: a track carries the base frame, which is given at the track's 0. *)
let test_track () =
  let text = Robot.irb120_text ^ "external eax_a linear 0 2000 1000 track 1 0 0\n" in
  let r = match Robot.parse ~file:"track" text with Ok r -> r | Error e -> Alcotest.fail (Robot.error_to_string e) in
  let b = { trans = { x = 0.; y = 500.; z = 100. }; rot = of_axis_angle { x = 0.; y = 0.; z = 1. } (rad 180.) } in
  let r = { r with base_frame = b } in
  match Base_frame.in_world r [| 300.; u; u; u; u; u |] with
  | None -> Alcotest.fail "no base"
  | Some w ->
      close_pose "the track's translation times the base frame" w
        { trans = { x = 300.; y = 500.; z = 100. }; rot = b.rot };
      Alcotest.(check bool) "no track, the world's frame: none" true (Base_frame.in_world Robot.irb120 no_ext = None)

(* The path drawn with the robot's base where the cell mounts it, in the world frame. *)
let test_drawing () =
  let count_bases svg =
    let n = String.length "robot-base" in
    let rec go i acc = if i + n > String.length svg then acc
      else go (i + 1) (if String.sub svg i n = "robot-base" then acc + 1 else acc) in go 0 0 in
  let b = { trans = { x = 2000.; y = 0.; z = 0. }; rot = unit_orient } in
  let p = Planner.create ~joints:rest (Kinematics.create (placed b)) in
  let t = { Frames.pose = { trans = { x = 2302.; y = 100.; z = 500. }; rot = down };
            conf = { cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } } in
  let _ = ok "plan" (Planner.plan p ~now:0. (Planner.move (speed "v100") (zone "fine") (Linear t))) in
  let svg = Path_output.path_svg p in
  Alcotest.(check int) "the base drawn in both views" 2 (count_bases svg);
  Alcotest.(check bool) "the segment's target in the world" true
    (List.for_all (fun (s : Planner.segment_info) -> distance s.target t.pose.trans < 1e-6) (Planner.segments p));
  let p0 = Planner.create ~joints:rest (Kinematics.create Robot.irb120) in
  Alcotest.(check int) "at the world's origin: not drawn" 0 (count_bases (Path_output.path_svg p0))

(* --base-frame [TASK=]X,Y,Z,Q1,Q2,Q3,Q4 as the command line reads it. *)
let test_options () =
  match Rapid_run.Run_setup.parse_base_frames [ "1,2,3,1,0,0,0"; "T_ROB2=0,0,800,0,0,0,1"; "t_rob2=5,0,0,1,0,0,0" ] with
  | Error m -> Alcotest.fail m
  | Ok frames ->
      let x t = Option.map (fun (b : pose) -> b.trans.x) (Rapid_run.Run_setup.base_frame_for frames t) in
      Alcotest.(check (option (float 0.))) "the run's robot" (Some 1.) (x None);
      Alcotest.(check (option (float 0.))) "the last for a task, letter case aside" (Some 5.) (x (Some "T_ROB2"));
      Alcotest.(check (option (float 0.))) "none for another" None (x (Some "T_ROB3"));
      List.iter (fun t -> match Rapid_run.Run_setup.parse_base_frames [ t ] with
          | Ok _ -> Alcotest.failf "accepted %S" t
          | Error m -> if not (String.length m > 22 && String.sub m 0 22 = "rapid-sem: --base-fram") then
                Alcotest.failf "message %S" m)
        [ "=1,2,3,1,0,0,0"; "T=1,2,3"; "1,2,3,0,0,0,0"; "T=x" ]

let suite =
  ( "base frames",
    [ Alcotest.test_case "F-base: CalcRobT then CalcJointT through a base frame, random" `Quick test_frames;
      Alcotest.test_case "F-base: a world target reached by a moved, turned robot" `Quick test_move;
      Alcotest.test_case "F-base with X-track: the track carries the base frame" `Quick test_track;
      Alcotest.test_case "F-base: the path and the base drawn in the world" `Quick test_drawing;
      Alcotest.test_case "--base-frame [TASK=]X,Y,Z,Q1,Q2,Q3,Q4" `Quick test_options ] )
