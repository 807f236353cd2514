(* External axes in the motion model (doc/motion.md, "External axes"): each law X-… by its
   name, as unit tests and QCheck properties. *)

open Rapid_motion_model
open Geom

let close ?(eps = 1e-6) what a b =
  if Float.abs (a -. b) > eps then Alcotest.failf "%s: expected %.9g, got %.9g" what b a

let close_pos ?(eps = 1e-6) what a b =
  if distance a b > eps then
    Alcotest.failf "%s: expected [%g %g %g], got [%g %g %g]" what b.x b.y b.z a.x a.y a.z

let ok what = function Ok x -> x | Error e -> Alcotest.failf "%s: %s" what (Motion_error.name e)

let run_property ~seed ~count ~name arb prop =
  QCheck.Test.check_exn ~rand:(Random.State.make [| seed |]) (QCheck.Test.make ~count ~name arb prop)

let with_externals lines = Robot.irb120_text ^ String.concat "" (List.map (fun l -> l ^ "\n") lines)

let track_text =
  with_externals [ "external eax_a linear 0 2000 1000 track 1 0 0"; "external eax_b rotating -180 180 90" ]

let track_robot = match Robot.parse ~file:"track" track_text with
  | Ok r -> r | Error e -> failwith (Robot.error_to_string e)

let kin = Kinematics.create track_robot
let down = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. }
let conf0 = { Kinematics.cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 }
let target x y z = { Frames.pose = { trans = { x; y; z }; rot = down }; conf = conf0 }
let speed n = Option.get (Motion_data.find Motion_data.speeddata n)
let zone n = Option.get (Motion_data.find Motion_data.zonedata n)
let rest = [| 0.; 0.; 0.; 0.; 90.; 0. |]
let u = Ext_axes.unused
let eax ?(a = u) ?(b = u) ?(c = u) () = [| a; b; c; u; u; u |]

(* ------------------------------------------------------------------ X-desc *)

let test_description () =
  let r = track_robot in
  Alcotest.(check int) "two external axes" 2 (List.length r.externals);
  let a = List.nth r.externals 0 and b = List.nth r.externals 1 in
  Alcotest.(check string) "eax_a" "eax_a" a.name;
  Alcotest.(check int) "eax_b's component" 1 b.index;
  Alcotest.(check bool) "eax_a linear, a track along x" true
    (a.kind = Ext_axes.Linear && a.track = Some { x = 1.; y = 0.; z = 0. });
  Alcotest.(check bool) "eax_b rotating, no track" true (b.kind = Ext_axes.Rotating && b.track = None);
  close "eax_b speed" b.speed 90.;
  Alcotest.(check int) "the default robot has none" 0 (List.length Robot.irb120.externals);
  (* A track's direction is normalised. *)
  (match Robot.parse ~file:"d" (with_externals [ "external eax_c linear -5 5 10 track 0 3 4" ]) with
   | Ok r -> close_pos "unit direction" (Option.get (List.hd r.externals).track) { x = 0.; y = 0.6; z = 0.8 }
   | Error e -> Alcotest.fail (Robot.error_to_string e));
  let line = 11 in
  let refused text col msg =
    match Robot.parse ~file:"r" (with_externals [ text ]) with
    | Ok _ -> Alcotest.failf "accepted: %s" text
    | Error e ->
        Alcotest.(check string) ("error of " ^ text)
          (Printf.sprintf "r:%d:%d: robot description error: %s" line col msg) (Robot.error_to_string e) in
  refused "external eax_g linear 0 1 1" 10 "external axis name must be eax_a to eax_f, found \"eax_g\"";
  refused "external eax_a sliding 0 1 1" 16 "eax_a: expected linear or rotating, found \"sliding\"";
  refused "external eax_a linear 0 1" 25 "eax_a: expected 3 numbers (min max speed), found 2";
  refused "external eax_a linear 0 x 1" 25 "eax_a max: expected a number, found \"x\"";
  refused "external eax_a linear 5 5 1" 23 "eax_a: range min 5 is not below max 5";
  refused "external eax_a linear 0 5 0" 27 "eax_a: speed must be positive";
  refused "external eax_a rotating 0 5 1 track 1 0 0" 31 "eax_a: only a linear axis can be a track";
  refused "external eax_a linear 0 5 1 track 0 0 0" 29 "eax_a: track: the direction is zero";
  refused "external eax_a linear 0 5 1 track 1 0" 29 "eax_a: track: expected 3 numbers (a direction DX DY DZ), found 2";
  refused "external" 1 "external: expected NAME linear|rotating MIN MAX SPEED [track DX DY DZ]";
  (match Robot.parse ~file:"r" (with_externals [ "external eax_b linear 0 1 1"; "external eax_b rotating 0 1 1" ]) with
   | Error e -> Alcotest.(check string) "twice" "r:12:10: robot description error: external axis eax_b given twice" (Robot.error_to_string e)
   | Ok _ -> Alcotest.fail "an axis twice accepted");
  (match Robot.parse ~file:"r" (with_externals [ "external eax_a linear 0 1 1 track 1 0 0"; "external eax_b linear 0 1 1 track 0 1 0" ]) with
   | Error e -> Alcotest.(check string) "two tracks" "r:12:29: robot description error: eax_b: a second track: the robot stands on one" (Robot.error_to_string e)
   | Ok _ -> Alcotest.fail "two tracks accepted")

(* ------------------------------------------------------------------ X-target *)

let test_target () =
  let axes = track_robot.externals in
  let from = [| 100.; 30.; u; u; u; u |] in
  let e = ok "resolve" (Ext_axes.resolve axes ~from (eax ~b:(-40.) ~c:7. ())) in
  close "9E9 keeps eax_a" e.(0) 100.;
  close "eax_b programmed" e.(1) (-40.);
  Alcotest.(check bool) "eax_c, absent, is ignored" true (Ext_axes.is_unused e.(2));
  Alcotest.(check bool) "9E9 as a num holds it is unused" true (Ext_axes.is_unused (Int32.float_of_bits (Int32.bits_of_float 9e9)));
  Alcotest.(check bool) "a large position is not" false (Ext_axes.is_unused 1e9);
  let refused what v = match Ext_axes.resolve axes ~from v with
    | Error (Motion_error.External_out_of_range n) -> Alcotest.(check string) what "eax_a" n
    | _ -> Alcotest.failf "%s: not refused" what in
  refused "beyond max" (eax ~a:2000.5 ());
  refused "below min" (eax ~a:(-0.5) ());
  refused "not a number" (eax ~a:nan ());
  Alcotest.(check string) "message" "external axis eax_a out of range" (Motion_error.name (External_out_of_range "eax_a"));
  let i = Ext_axes.initial axes in
  close "initial eax_a" i.(0) 0.; close "initial eax_b" i.(1) 0.;
  Alcotest.(check bool) "initial eax_c" true (Ext_axes.is_unused i.(2));
  (* 0 outside the range: the nearer end. *)
  let r = match Robot.parse ~file:"r" (with_externals [ "external eax_d linear 100 500 10" ]) with Ok r -> r | Error _ -> assert false in
  close "initial inside the range" (Ext_axes.initial r.externals).(3) 100.

(* ------------------------------------------------------------------ X-time *)

let test_time () =
  let axes = track_robot.externals in
  let t ~override ~v_leax ~v_reax from e = ok "time" (Ext_axes.time axes ~override ~v_leax ~v_reax ~from e) in
  let z = [| 0.; 0.; u; u; u; u |] in
  close "linear at v_leax" (t ~override:100. ~v_leax:200. ~v_reax:1000. z [| 300.; 0.; u; u; u; u |]) 1.5;
  close "linear capped by the axis" (t ~override:100. ~v_leax:5000. ~v_reax:1000. z [| 300.; 0.; u; u; u; u |]) 0.3;
  close "rotating at v_reax" (t ~override:100. ~v_leax:5000. ~v_reax:45. z [| 0.; -90.; u; u; u; u |]) 2.;
  close "the longest" (t ~override:100. ~v_leax:200. ~v_reax:45. z [| 300.; 135.; u; u; u; u |]) 3.;
  close "VelSet scales" (t ~override:50. ~v_leax:200. ~v_reax:45. z [| 200.; 0.; u; u; u; u |]) 2.;
  close "nothing moves" (t ~override:100. ~v_leax:0. ~v_reax:0. z z) 0.;
  (match Ext_axes.time axes ~override:100. ~v_leax:0. ~v_reax:10. ~from:z [| 1.; 0.; u; u; u; u |] with
   | Error (Motion_error.Invalid_speed _) -> ()
   | _ -> Alcotest.fail "v_leax 0 with the track to move")

(* Durations scale inversely with v_leax and v_reax (below the axes' own speeds), through the
   planner: MoveExtJ of random positions. *)
let test_time_scales () =
  let gen = QCheck.Gen.(quad (float_range 0. 2000.) (float_range (-180.) 180.) (float_range 1. 40.) (float_range 1.5 4.)) in
  run_property ~seed:47 ~count:300 ~name:"X-scale" (QCheck.make gen) (fun (a, b, v, k) ->
      let dur vl vr =
        let p = Planner.create ~joints:rest kin in
        let sp = { Motion_data.v_tcp = 100.; v_ori = 500.; v_leax = vl; v_reax = vr } in
        let r = ok "plan" (Planner.plan p ~now:0. (Planner.move ~eax:(eax ~a ~b ()) sp (zone "fine") External_only)) in
        r.ready_time in
      let t1 = dur v (v /. 2.) and tk = dur (v *. k) (v *. k /. 2.) in
      QCheck.assume (t1 > 1e-6);
      Float.abs (t1 /. tk -. k) < 1e-9 *. k)

(* ------------------------------------------------------------------ X-track *)

let test_track () =
  let p = Planner.create ~joints:rest kin in
  (* The arm's home pointing down is [302, 0, 558]; the track at 500 puts it at 802. *)
  let r = ok "plan" (Planner.plan p ~now:0. (Planner.move ~eax:(eax ~a:500. ()) (speed "v100") (zone "fine")
                                                 (Linear (target 802. 0. 558.)))) in
  close "T = max(500 / 100, 500 / 1000)" r.ready_time 5.;
  close_pos "halfway, world" (Planner.pose_at p 2.5).trans { x = 552.; y = 0.; z = 558. };
  let e = ok "external_at" (Planner.external_at p 2.5) in
  close "the track halfway" e.(0) 250.;
  let q = ok "joints_at" (Planner.joints_at p 5.) in
  Array.iteri (fun i a -> close (Printf.sprintf "axis %d back at home" (i + 1)) a rest.(i)) q;
  (* The TCP stands while the base moves under it: only the external-axis term. *)
  let r = ok "plan" (Planner.plan p ~now:5. (Planner.move ~eax:(eax ~a:700. ()) (speed "v100") (zone "fine")
                                                 (Linear (target 802. 0. 558.)))) in
  close "0.2 s" r.ready_time 5.2;
  close_pos "the TCP stays" (Planner.pose_at p 5.1).trans { x = 802.; y = 0.; z = 558. };
  let q = ok "joints" (Planner.joints_at p 5.1) in
  let base = Planner.base p (ok "ext" (Planner.external_at p 5.1)) in
  close_pos "forward kinematics on the moved base" (pmult (Option.get base) (Kinematics.forward kin q)).trans { x = 802.; y = 0.; z = 558. };
  (* A position out of the arm's reach from where the track puts the base. *)
  (match Planner.plan p ~now:6. (Planner.move ~eax:(eax ~a:0. ()) (speed "v100") (zone "fine") (Linear (target 802. 0. 558.))) with
   | Error Motion_error.Out_of_reach -> ()
   | _ -> Alcotest.fail "out of reach from the base at 0");
  (* A joint move takes the TCP's chord in the world into account. *)
  let p = Planner.create ~joints:rest kin in
  let r = ok "plan" (Planner.plan p ~now:0. (Planner.move ~eax:(eax ~a:600. ()) (speed "v100") (zone "fine") (Abs_joint rest))) in
  close "MoveAbsJ: 600 mm chord at v100" r.ready_time 6.;
  (* The default robot keeps 9E9 for every component. *)
  let p = Planner.create ~joints:rest (Kinematics.create Robot.irb120) in
  let r = ok "plan" (Planner.plan p ~now:0. (Planner.move ~eax:(eax ~a:300. ()) (speed "v100") (zone "fine") External_only)) in
  close "no axis: no time" r.ready_time 0.;
  Alcotest.(check bool) "all unused" true (Array.for_all Ext_axes.is_unused (ok "ext" (Planner.external_at p 1.)))

(* Law X-track with the frames: CalcRobT then CalcJointT on a moved base is the identity, over
   random axes and track positions. *)
let test_track_frames () =
  let gen = QCheck.Gen.(pair (float_range 0. 2000.) (array_size (return 6) (float_range (-60.) 60.))) in
  run_property ~seed:48 ~count:500 ~name:"X-frames" (QCheck.make gen) (fun (a, q) ->
      q.(4) <- 30. +. Float.abs q.(4);
      let base = Ext_axes.base track_robot.externals [| a; 0.; u; u; u; u |] in
      match Frames.calc_rob_t ?base kin q Motion_data.tool0 Motion_data.wobj0 with
      | Error _ -> QCheck.assume_fail ()
      | Ok rt ->
          close "x shifts with the track" rt.pose.trans.x ((Kinematics.forward kin q).trans.x +. a) ~eps:1e-6;
          let q' = ok "calc_joint_t" (Frames.calc_joint_t ?base kin rt Motion_data.tool0 Motion_data.wobj0) in
          Array.for_all2 (fun x y -> Float.abs (x -. y) < 1e-6) q q')

(* Fly-by points with external axes: the axes stay continuous through the corner. *)
let test_corner () =
  let p = Planner.create ~joints:rest kin in
  let _ = ok "a" (Planner.plan p ~now:0. (Planner.move ~eax:(eax ~a:100. ()) (speed "v100") (zone "z10") (Linear (target 402. 0. 558.)))) in
  let _ = ok "b" (Planner.plan p ~now:0. (Planner.move ~eax:(eax ~a:100. ~b:30. ()) (speed "v100") (zone "fine") (Linear (target 502. 0. 558.)))) in
  List.iter (fun (pc : Planner.piece_info) ->
      let at t = ok "ext" (Planner.external_at p t) in
      let e0 = at (pc.t_from -. 1e-7) and e1 = at (pc.t_from +. 1e-7) in
      close ~eps:1e-3 "eax_a continuous" e0.(0) e1.(0);
      close ~eps:1e-3 "eax_b continuous" e0.(1) e1.(1)) (Planner.pieces p);
  let e = ok "end" (Planner.external_at p (Planner.finished_by p)) in
  close "eax_a at the end" e.(0) 100.; close "eax_b at the end" e.(1) 30.

(* Bad external axis values are errors, never exceptions: any floats, any length, any move. *)
let test_bad_values () =
  let value = QCheck.Gen.(oneof [ float; oneofl [ nan; infinity; neg_infinity; 9e9; 8999999488.; -0.; 1e300 ];
                                  float_range (-300.) 2300. ]) in
  let gen = QCheck.Gen.(pair (array_size (int_range 0 8) value) (int_range 0 3)) in
  run_property ~seed:49 ~count:2000 ~name:"X-bad" (QCheck.make gen) (fun (e, kind) ->
      let p = Planner.create ~joints:rest kin in
      let motion = match kind with
        | 0 -> Planner.External_only | 1 -> Planner.Abs_joint rest
        | 2 -> Planner.Linear (target 502. 0. 558.) | _ -> Planner.Joint (target 502. 0. 558.) in
      (match Planner.plan p ~now:0. (Planner.move ~eax:e (speed "v100") (zone "z10") motion) with
       | Ok _ -> ignore (Planner.pose_at p 0.5); ignore (Planner.external_at p 0.5); ignore (Planner.joints_at p 0.5)
       | Error _ -> ());
      true)

(* The CSV has a column per external axis, by name; the default robot's has none. *)
let test_csv () =
  let p = Planner.create ~joints:rest kin in
  let _ = ok "plan" (Planner.plan p ~now:0. (Planner.move ~eax:(eax ~a:100. ~b:(-45.) ()) (speed "v100") (zone "fine") External_only)) in
  let lines = String.split_on_char '\n' (String.trim (Path_output.csv ~step:0.25 p)) in
  Alcotest.(check string) "header" "t,x,y,z,q1,q2,q3,q4,j1,j2,j3,j4,j5,j6,eax_a,eax_b" (List.hd lines);
  (* eax_b's 45 degrees at 90 deg/s: 0.5 s; at 0.25 s both axes are halfway. *)
  let row = String.split_on_char ',' (List.nth lines 2) in
  close "t" (float_of_string (List.nth row 0)) 0.25;
  close ~eps:1e-4 "eax_a halfway" (float_of_string (List.nth row 14)) 50.;
  close ~eps:1e-4 "eax_b halfway" (float_of_string (List.nth row 15)) (-22.5);
  close ~eps:1e-4 "the base moved the TCP" (float_of_string (List.nth row 1)) 352.;
  let p0 = Planner.create ~joints:rest (Kinematics.create Robot.irb120) in
  Alcotest.(check string) "no column without external axes" "t,x,y,z,q1,q2,q3,q4,j1,j2,j3,j4,j5,j6"
    (List.hd (String.split_on_char '\n' (Path_output.csv p0)))

let suite =
  ( "external axes",
    [ Alcotest.test_case "X-desc: external axes in the description, and their errors" `Quick test_description;
      Alcotest.test_case "X-target: 9E9 keeps, an absent axis is ignored, the range" `Quick test_target;
      Alcotest.test_case "X-time: v_leax, v_reax, the axis speed, VelSet" `Quick test_time;
      Alcotest.test_case "X-time: durations scale inversely with v_leax and v_reax, random" `Quick test_time_scales;
      Alcotest.test_case "X-track: the base moves with the track" `Quick test_track;
      Alcotest.test_case "X-track: CalcRobT then CalcJointT on a moved base, random" `Quick test_track_frames;
      Alcotest.test_case "X-interp: external axes through a corner" `Quick test_corner;
      Alcotest.test_case "the CSV's external axis columns" `Quick test_csv;
      Alcotest.test_case "bad external axis values never raise, random" `Quick test_bad_values ] )
