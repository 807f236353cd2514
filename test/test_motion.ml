(* The motion model (lib/motion_model, doc/motion.md): each law of doc/motion.md by its rule
   name, as unit tests and QCheck properties. *)

open Rapid_motion_model
open Geom

let kin = Kinematics.create Robot.irb120
let down = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. }
let conf0 = { Kinematics.cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 }
let target ?(rot = down) ?(conf = conf0) x y z = { Frames.pose = { trans = { x; y; z }; rot }; conf }
let speed n = Option.get (Motion_data.find Motion_data.speeddata n)
let zone n = Option.get (Motion_data.find Motion_data.zonedata n)
(* Axis 5 at 90: the IRB 120's tool0 pointing down at [302, 0, 558]. *)
let rest = [| 0.; 0.; 0.; 0.; 90.; 0. |]

let close ?(eps = 1e-6) what a b =
  if Float.abs (a -. b) > eps then Alcotest.failf "%s: expected %.9g, got %.9g" what b a

let close_pos ?(eps = 1e-6) what a b =
  if distance a b > eps then
    Alcotest.failf "%s: expected [%g %g %g], got [%g %g %g]" what b.x b.y b.z a.x a.y a.z

let ok what = function
  | Ok x -> x
  | Error e -> Alcotest.failf "%s: %s" what (Motion_error.name e)

let planner ?(joints = rest) () = Planner.create ~joints kin

let plan ?(now = 0.) p m = ok "plan" (Planner.plan p ~now m)

let run_property ~seed ~count ~name arb prop =
  QCheck.Test.check_exn ~rand:(Random.State.make [| seed |]) (QCheck.Test.make ~count ~name arb prop)

(* ------------------------------------------------------------------ robot and kinematics *)

(* K-home: installed-facts.md §3, the flange at about [374, 0, 630] at all axes 0, tool0 along +X. *)
let test_home () =
  let h = Kinematics.forward kin (Array.make 6 0.) in
  close_pos "home position" h.trans { x = 374.; y = 0.; z = 630. };
  close "home q1" h.rot.q1 (sqrt 0.5); close "home q3" h.rot.q3 (sqrt 0.5);
  close "home q2" h.rot.q2 0.; close "home q4" h.rot.q4 0.;
  let tool_z = rotate h.rot { x = 0.; y = 0.; z = 1. } in
  close_pos "tool0 points along +X" tool_z { x = 1.; y = 0.; z = 0. };
  let r = Kinematics.forward kin rest in
  close_pos "axis 5 at 90" r.trans { x = 302.; y = 0.; z = 558. };
  close "pointing down" (angle_between r.rot down) 0.;
  Alcotest.(check bool) "home conf" true (Kinematics.conf_of kin (Array.make 6 0.) = conf0)

(* Sample axis angles within the ranges, away from the three singularities where the inverse is
   not unique: the wrist (axis 5 near 0), the elbow stretched, the wrist centre over axis 1. *)
let regular_joints =
  let ax = Robot.irb120.axes in
  QCheck.Gen.(map (fun us -> Array.mapi (fun i u -> ax.(i).min +. u *. (ax.(i).max -. ax.(i).min)) us)
                (array_repeat 6 (float_bound_inclusive 1.)))

let regular q =
  let ax = Robot.irb120.axes in
  let t3 = rad (q.(2) +. ax.(2).offset) and ps = atan2 ax.(3).d ax.(2).a in
  let f = Kinematics.forward kin q in
  let w = sub f.trans (scale ax.(5).d (rotate f.rot { x = 0.; y = 0.; z = 1. })) in
  (not (Kinematics.wrist_singular ~zone:2. kin q))
  && Float.abs (sin (t3 +. ps)) > 0.02
  && sqrt ((w.x *. w.x) +. (w.y *. w.y)) > 5.
  && Array.for_all (fun a -> Float.abs (Float.rem (Float.abs a) 90.) > 1e-6) [| q.(0); q.(3); q.(5) |]

let show_q q = String.concat ", " (Array.to_list (Array.map (Printf.sprintf "%.9g") q))

(* K-inverse: FK then IK with the same confdata gives the same axis angles, and FK again the same
   pose, within 1e-6. *)
let test_fk_ik () =
  run_property ~seed:120 ~count:3000 ~name:"forward then inverse kinematics is the identity"
    (QCheck.make ~print:show_q regular_joints) (fun q ->
      QCheck.assume (regular q);
      let p = Kinematics.forward kin q in
      match Kinematics.inverse kin p (With_conf (Kinematics.conf_of kin q)) with
      | Error e -> QCheck.Test.fail_reportf "%s" (Motion_error.name e)
      | Ok q' ->
          let dq = Array.fold_left Float.max 0. (Array.mapi (fun i a -> Float.abs (a -. q'.(i))) q) in
          let p' = Kinematics.forward kin q' in
          if dq > 1e-6 then QCheck.Test.fail_reportf "axes differ by %g: %s" dq (show_q q')
          else if distance p.trans p'.trans > 1e-6 || angle_between p.rot p'.rot > 1e-6 then
            QCheck.Test.fail_reportf "pose differs"
          else
            (* The nearest solution to the angles themselves is the angles. *)
            match Kinematics.inverse kin p (Nearest q) with
            | Ok q'' -> Array.for_all2 (fun a b -> Float.abs (a -. b) < 1e-6) q q''
            | Error _ -> false)

let test_ik_errors () =
  let far = { trans = { x = 900.; y = 0.; z = 300. }; rot = down } in
  (match Kinematics.inverse kin far (Nearest rest) with
   | Error Motion_error.Out_of_reach -> ()
   | _ -> Alcotest.fail "900 mm away is out of reach");
  (* A position the arm reaches only with axis 1 beyond its 165 degrees: behind the robot. *)
  let behind = Kinematics.forward kin [| 0.; 0.; 0.; 0.; 90.; 0. |] in
  let behind = { behind with trans = { behind.trans with x = -. behind.trans.x } } in
  (match Kinematics.inverse kin behind (With_conf { conf0 with cf1 = 1 }) with
   | Error (Motion_error.Joint_out_of_range 1) -> ()
   | Ok q -> Alcotest.failf "expected joint 1 out of range, got %s" (show_q q)
   | Error e -> Alcotest.failf "expected joint 1 out of range, got %s" (Motion_error.name e));
  Alcotest.(check string) "error name" "joint 4 out of range" (Motion_error.name (Joint_out_of_range 4));
  Alcotest.(check (option string)) "CalcJointT \\ErrorNumber" (Some "ERR_ROBLIMIT")
    (Motion_error.errnum Out_of_reach)

(* ------------------------------------------------------------------ the description file *)

(* The built-in IRB 120 description with line [n] (from 0) replaced by [l]. *)
let replace_line n l =
  String.concat "\n" (List.mapi (fun i x -> if i = n then l else x) (String.split_on_char '\n' Robot.irb120_text))

(* A description refused with exactly the message [expected]. *)
let err text expected =
  match Robot.parse ~file:"r.robot" text with
  | Ok _ -> Alcotest.failf "accepted, expected %s" expected
  | Error e -> Alcotest.(check string) expected expected (Robot.error_to_string e)

let test_description () =
  (match Robot.parse ~file:"irb120.robot" Robot.irb120_text with
   | Ok r -> Alcotest.(check bool) "the built-in text is the built-in robot" true (r = Robot.irb120)
   | Error e -> Alcotest.fail (Robot.error_to_string e));
  Alcotest.(check string) "name" "ABB IRB 120" Robot.irb120.name;
  close "axis 6 speed" Robot.irb120.axes.(5).speed 420.;
  close "axis 3 min" Robot.irb120.axes.(2).min (-110.);
  err (replace_line 4 "axis 2      270        0          0     -90          -110   x110      250")
    "r.robot:5:61: robot description error: axis 2 max: expected a number, found \"x110\"";
  err (replace_line 4 "axes 2") "r.robot:5:1: robot description error: unknown keyword \"axes\" (expected name, structure, axis, external, max_tcp_speed or reach)";
  err (replace_line 4 "") "r.robot:11:1: robot description error: axis 2 is missing";
  err (replace_line 5 "axis 3      70       -90          0       0          70  -110      250")
    "r.robot:6:54: robot description error: axis 3: range min 70 is not below max -110";
  err (replace_line 5 "axis 2      70       -90          0       0          70  -110      250")
    "r.robot:6:6: robot description error: axis 2 given twice";
  err (replace_line 6 "axis 4      0         90        302       0          -160   160      0")
    "r.robot:7:70: robot description error: axis 4: speed must be positive";
  err (replace_line 6 "axis 4      0         90        302       0          -160   160")
    "r.robot:7:61: robot description error: axis 4: expected 7 numbers (a alpha d offset min max speed), found 6";
  err (replace_line 6 "axis 4      0         -90        302       0          -160   160   320")
    "r.robot:7:1: robot description error: unsupported kinematic structure (axis 4: alpha must be 90): the inverse kinematics solves arms with twists -90 0 -90 90 -90 0 (doc/motion.md)";
  err (replace_line 9 "") "r.robot:11:1: robot description error: max_tcp_speed is missing";
  err (replace_line 1 "name \"IRB") "r.robot:2:6: robot description error: unterminated name: a closing \" is missing";
  (match Robot.load "/nonexistent/robot.txt" with
   | Error e -> Alcotest.(check int) "unreadable file at 1" 1 e.line
   | Ok _ -> Alcotest.fail "read a file that does not exist");
  (* Another arm of the same structure: a shoulder offset (IRB 140-like) still inverts. *)
  let text = replace_line 3 "axis 1      70       -90        352       0          -180   180      200" in
  match Robot.parse ~file:"r" text with
  | Error e -> Alcotest.fail (Robot.error_to_string e)
  | Ok r ->
      let k = Kinematics.create r in
      let q = [| 20.; 10.; -20.; 30.; 50.; -40. |] in
      let q' = ok "inverse" (Kinematics.inverse k (Kinematics.forward k q) (With_conf (Kinematics.conf_of k q))) in
      Array.iteri (fun i a -> close (Printf.sprintf "axis %d" (i + 1)) q'.(i) a) q

(* Issue 21, item 3: the numbers of a description within num and within the model's ranges
   (R-2.13-numbers2), at the offending word; before, a length of 1e300 reached the run and
   ended in an internal error. *)
let test_description_numbers () =
  let axis2 a alpha d offset min max speed =
    replace_line 4 (Printf.sprintf "axis 2 %s %s %s %s %s %s %s" a alpha d offset min max speed) in
  let pre = "r.robot:5:" and model = ", the range of the model (doc/motion.md)" in
  err (axis2 "1e300" "0" "0" "-90" "-110" "110" "250")
    (pre ^ "8: robot description error: axis 2 a: 1e300 is beyond the range of num (at most 3.40282347E+38, §2.13)");
  err (axis2 "0x10" "0" "0" "-90" "-110" "110" "250")
    (pre ^ "8: robot description error: axis 2 a: expected a number, found \"0x10\"");
  err (axis2 "1_0" "0" "0" "-90" "-110" "110" "250")
    (pre ^ "8: robot description error: axis 2 a: expected a number, found \"1_0\"");
  err (axis2 "2e5" "0" "0" "-90" "-110" "110" "250")
    (pre ^ "8: robot description error: axis 2 a: 2e5 is outside -100000 .. 100000 mm" ^ model);
  err (axis2 "1e-300" "0" "0" "-90" "-110" "110" "250")
    (pre ^ "8: robot description error: axis 2 a: 1e-300 is below 0.001 mm, the model's resolution "
     ^ "(0 or at least 0.001)");
  err (axis2 "270" "0" "0" "400" "-110" "110" "250")
    (pre ^ "16: robot description error: axis 2 offset: 400 is outside -360 .. 360 degrees" ^ model);
  err (axis2 "270" "0" "0" "-90" "-1e6" "110" "250")
    (pre ^ "20: robot description error: axis 2 min: -1e6 is outside -100000 .. 100000 degrees" ^ model);
  err (axis2 "270" "0" "0" "-90" "-110" "110" "1e-300")
    (pre ^ "29: robot description error: axis 2 speed: 1e-300 is outside 0.001 .. 100000 degrees/s" ^ model);
  err (axis2 "270" "0" "0" "-90" "-110" "110" "nan")
    (pre ^ "29: robot description error: axis 2 speed: expected a number, found \"nan\"");
  err (replace_line 4 "axis 0x2 270 0 0 -90 -110 110 250")
    (pre ^ "6: robot description error: axis number must be 1 to 6, found \"0x2\"");
  err (replace_line 9 "max_tcp_speed 1e300")
    ("r.robot:10:15: robot description error: max_tcp_speed: 1e300 is beyond the range of num "
     ^ "(at most 3.40282347E+38, §2.13)");
  err (replace_line 9 "max_tcp_speed 3e38")
    ("r.robot:10:15: robot description error: max_tcp_speed: 3e38 is outside 0.001 .. 100000 mm/s" ^ model);
  err (Robot.irb120_text ^ "external eax_a linear 0 1e300 100\n")
    ("r.robot:11:25: robot description error: eax_a max: 1e300 is beyond the range of num "
     ^ "(at most 3.40282347E+38, §2.13)");
  err (Robot.irb120_text ^ "external eax_a linear 0 1000 100 track 1e30 0 0\n")
    ("r.robot:11:40: robot description error: eax_a track: 1e30 is outside -100000 .. 100000 (a direction)" ^ model);
  (* the largest figures the model takes, and a byte order mark first, are accepted *)
  match Robot.parse ~file:"r.robot" ("\xEF\xBB\xBF" ^ replace_line 9 "max_tcp_speed 100000") with
  | Ok r -> close "max_tcp_speed" r.max_tcp_speed 100000.
  | Error e -> Alcotest.fail (Robot.error_to_string e)

(* ------------------------------------------------------------------ data and frames *)

let test_data () =
  let v = speed "V100" in
  close "v100 v_tcp" v.v_tcp 100.; close "v100 v_ori" v.v_ori 500.;
  close "v100 v_leax" v.v_leax 5000.; close "v100 v_reax" v.v_reax 1000.;
  Alcotest.(check int) "speeddata v5 … v7000 and vmax" 26 (List.length Motion_data.speeddata);
  close "vmax is MaxRobSpeed" (speed "vmax").v_tcp Robot.irb120.max_tcp_speed;
  let z = zone "z50" in
  Alcotest.(check bool) "z50 fly-by" false z.finep;
  close "z50 pzone_tcp" z.pzone_tcp 50.; close "z50 zone_ori" z.zone_ori 7.5;
  Alcotest.(check bool) "fine" true (zone "fine").finep;
  close "z200 pzone_ori" (zone "z200").pzone_ori 300.;
  Alcotest.(check int) "zonedata fine, z0 … z200" 15 (List.length Motion_data.zonedata);
  close "stoptime1_5" (Option.get (Motion_data.find Motion_data.stoppointdata "stoptime1_5")).stoptime 1.5;
  close "load0 mass" Motion_data.load0.mass 0.001;
  Alcotest.(check bool) "tool0 held by the robot" true Motion_data.tool0.tool_robhold

let gripper = { Motion_data.tool0 with tframe = { trans = { x = 0.; y = 0.; z = 100. };
                                                  rot = of_axis_angle { x = 0.; y = 1.; z = 0. } (rad 30.) } }
let table = { Motion_data.wobj0 with uframe = { trans = { x = 300.; y = -100.; z = 200. };
                                                rot = of_axis_angle { x = 0.; y = 0.; z = 1. } (rad 90.) };
                                     oframe = { trans = { x = 10.; y = 20.; z = 0. }; rot = unit_orient } }

let test_frames () =
  let q = [| 10.; 20.; 10.; 30.; 40.; 50. |] in
  let rt = ok "CalcRobT" (Frames.calc_rob_t kin q gripper table) in
  (* The TCP in the world is the object frame applied to the robtarget. *)
  let tcp_world = pmult (Kinematics.forward kin q) gripper.tframe in
  close_pos "robtarget in the work object" (pvect (Frames.object_frame table) rt.pose.trans) tcp_world.trans;
  let q' = ok "CalcJointT" (Frames.calc_joint_t kin rt gripper table) in
  Array.iteri (fun i a -> close (Printf.sprintf "CalcJointT axis %d" (i + 1)) q'.(i) a) q;
  let cp = ok "CPos" (Frames.c_pos kin ~joints:q gripper table) in
  close_pos "CPos is CRobT's trans" cp rt.pose.trans;
  (* A stationary tool and a robot-held work object: the same round trip. *)
  let fixed_tool = { gripper with tool_robhold = false } and held = { table with wobj_robhold = true } in
  let rt2 = ok "CalcRobT stationary" (Frames.calc_rob_t kin q fixed_tool held) in
  let q2 = ok "CalcJointT stationary" (Frames.calc_joint_t kin rt2 fixed_tool held) in
  Array.iteri (fun i a -> close (Printf.sprintf "stationary axis %d" (i + 1)) q2.(i) a) q;
  match Frames.calc_rob_t kin q gripper held with
  | Error Motion_error.Robhold_conflict -> ()
  | _ -> Alcotest.fail "both held by the robot"

(* F-stationary (R-4.1-o): a stationary tool and a work object the robot carries. The TCP moves
   on a straight line in the work object at v_tcp when the orientation does not change. *)
let test_stationary_tool () =
  let fixed_tool = { gripper with tool_robhold = false; tframe = { gripper.tframe with trans = { x = 450.; y = 0.; z = 250. } } }
  and held = { table with wobj_robhold = true; uframe = { trans = { x = 0.; y = 0.; z = 60. }; rot = unit_orient };
                          oframe = { trans = { x = 20.; y = 0.; z = 0. }; rot = unit_orient } } in
  let qa = [| 10.; 20.; 10.; 30.; 40.; 50. |] in
  let a = ok "CalcRobT stationary" (Frames.calc_rob_t kin qa fixed_tool held) in
  let b = { a with Frames.pose = offs a.pose 30. (-40.) 0. } in
  let p = planner () in
  let r0 = plan p (Planner.move ~tool:fixed_tool ~wobj:held (speed "v1000") (zone "fine") (Joint a)) in
  let now = r0.ready_time in
  let at t = ok "CRobT" (Frames.c_rob_t kin ~joints:(ok "CJointT" (Planner.joints_at p t)) fixed_tool held) in
  close_pos "at the first target" (at now).pose.trans a.pose.trans;
  let r = plan p ~now (Planner.move ~tool:fixed_tool ~wobj:held (speed "v100") (zone "fine") (Linear b)) in
  close "50 mm at v100" (r.ready_time -. now) 0.5;
  close_pos "halfway on the line in the work object" (at (now +. 0.25)).pose.trans (offs a.pose 15. (-20.) 0.).trans;
  close_pos "at the second target" (at r.ready_time).pose.trans b.pose.trans;
  let flange = Kinematics.forward kin (ok "CJointT" (Planner.joints_at p r.ready_time)) in
  let tcp_in_object = pmult (pinv (pmult flange (Frames.object_frame held))) fixed_tool.tframe in
  close_pos "the fixed TCP is at the target in the carried work object" tcp_in_object.trans b.pose.trans

let test_position_functions () =
  let p = { trans = { x = 100.; y = 200.; z = 300. }; rot = of_axis_angle { x = 0.; y = 0.; z = 1. } (rad 90.) } in
  let o = offs p 10. 20. 30. in
  close_pos "Offs" o.trans { x = 110.; y = 220.; z = 330. };
  close "Offs keeps the orientation" (angle_between o.rot p.rot) 0.;
  (* RelTool: the displacement in the tool frame, whose x is the world's y here. *)
  let r = rel_tool p 10. 0. 0. () in
  close_pos "RelTool displacement" r.trans { x = 100.; y = 210.; z = 300. };
  let r = rel_tool p 0. 0. 0. ~rz:90. () in
  close "RelTool \\Rz" (angle_between r.rot (of_axis_angle { x = 0.; y = 0.; z = 1. } (rad 180.))) 0.;
  (* x first, then the new y: Rx(90) then Ry(90) in the tool frame. *)
  let r = rel_tool identity 0. 0. 0. ~rx:90. ~ry:90. () in
  close_pos "RelTool order" (rotate r.rot { x = 0.; y = 0.; z = 1. }) { x = 1.; y = 0.; z = 0. };
  (* MirPos in the world xz-plane seen as a frame whose xy-plane it is: y mirrored. *)
  let plane = { trans = origin; rot = of_axis_angle { x = 1.; y = 0.; z = 0. } (rad 90.) } in
  let pt = { trans = { x = 100.; y = 50.; z = 20. }; rot = down } in
  let m = mir_pos ~point:pt ~plane () in
  close_pos "MirPos translation" m.trans { x = 100.; y = -50.; z = 20. };
  let rm = to_matrix m.rot in
  let det = rm.(0) *. (rm.(4) *. rm.(8) -. rm.(5) *. rm.(7)) -. rm.(1) *. (rm.(3) *. rm.(8) -. rm.(5) *. rm.(6))
            +. rm.(2) *. (rm.(3) *. rm.(7) -. rm.(4) *. rm.(6)) in
  close "MirPos keeps a right-handed frame" det 1.;
  let mm = mir_pos ~point:m ~plane () in
  close_pos "MirPos twice" mm.trans pt.trans;
  close "MirPos twice, orientation" (angle_between mm.rot pt.rot) 0.

(* ------------------------------------------------------------------ time *)

(* T-cartesian: the 500 mm MoveL at v100 to a fine point takes 5 s. *)
let test_movel_5s () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 300. (-250.) 300.))) in
  let now = r0.ready_time in
  let r = plan p ~now (Planner.move (speed "v100") (zone "fine") (Linear (target 300. 250. 300.))) in
  close "ready when in position" r.ready_time (now +. 5.);
  close "finished" (Planner.finished_by p) (now +. 5.);
  close_pos "halfway" (Planner.pose_at p (now +. 2.5)).trans { x = 300.; y = 0.; z = 300. };
  close_pos "there" (Planner.pose_at p (now +. 7.)).trans { x = 300.; y = 250.; z = 300. }

let test_speed_arguments () =
  let robot = Robot.irb120 and vs = Profile.velset_default in
  let tm ?v ?t s = { Profile.speed = speed s; v; t } in
  let d ?(vs = vs) ?(angle = 0.) t = ok "duration" (Profile.cartesian robot vs t ~length:500. ~angle) in
  close "\\V replaces v_tcp" (d (tm ~v:250. "v100")) 2.;
  close "\\T is the whole time" (d (tm ~t:7. "v100")) 7.;
  close "VelSet override" (d ~vs:{ override = 50.; max = 5000. } (tm "v100")) 10.;
  close "VelSet override and \\T" (d ~vs:{ override = 50.; max = 5000. } (tm ~t:2. "v100")) 4.;
  close "VelSet Max caps" (d ~vs:{ override = 100.; max = 250. } (tm "v1000")) 2.;
  close "MaxRobSpeed caps" (d ~vs:{ override = 100.; max = 100000. } (tm "v7000")) (500. /. 6200.);
  close "reorientation limits" (d ~angle:90. (tm "v7000")) (90. /. 500.);
  (match Profile.cartesian robot vs { (tm "v100") with speed = { (speed "v100") with v_tcp = 0. } } ~length:1. ~angle:0. with
   | Error (Motion_error.Invalid_speed _) -> ()
   | _ -> Alcotest.fail "a zero v_tcp cannot move 1 mm")

(* T-joint: the axis that needs the longest time sets the duration. *)
let test_movej_slowest_axis () =
  let p = planner ~joints:(Array.make 6 0.) () in
  let r = plan p (Planner.move (speed "v7000") (zone "fine") (Abs_joint [| 50.; 0.; 0.; 0.; 0.; 210. |])) in
  close "axis 6: 210 degrees at 420 deg/s" r.ready_time 0.5;
  let q = ok "joints" (Planner.joints_at p 0.25) in
  close "axes move together: axis 1 halfway" q.(0) 25.;
  close "axes move together: axis 6 halfway" q.(5) 105.;
  (* A slow TCP speed dominates the axes: not less than L / v_tcp. *)
  let p = planner ~joints:(Array.make 6 0.) () in
  let r = plan p (Planner.move (speed "v5") (zone "fine") (Abs_joint [| 10.; 0.; 0.; 0.; 0.; 0. |])) in
  close "chord at v5" r.ready_time (2. *. 374. *. sin (rad 5.) /. 5.)

(* T-scale: durations scale inversely with speed. *)
let test_scaling () =
  let gen = QCheck.Gen.(quad (float_range 0. 800.) (float_range 0. 180.) (float_range 5. 1000.) (float_range 1. 5.)) in
  run_property ~seed:7 ~count:2000 ~name:"durations scale inversely with speed"
    (QCheck.make gen) (fun (length, angle, v, k) ->
      let robot = Robot.irb120 and vs = Profile.velset_default in
      let sp f = { Profile.speed = { v_tcp = v *. f; v_ori = 100. *. f; v_leax = 0.; v_reax = 0. }; v = None; t = None } in
      let d1 = ok "d1" (Profile.cartesian robot vs (sp 1.) ~length ~angle)
      and dk = ok "dk" (Profile.cartesian robot vs (sp k) ~length ~angle) in
      let j1 = ok "j1" (Profile.joint robot vs (sp 1.) ~deltas:[||] ~length ~angle)
      and jk = ok "jk" (Profile.joint robot vs (sp k) ~deltas:[||] ~length ~angle) in
      Float.abs (d1 -. k *. dk) <= 1e-9 *. d1 && Float.abs (j1 -. k *. jk) <= 1e-9 *. j1)

let test_movec () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 400. (-100.) 300.))) in
  let now = r0.ready_time in
  (* A half circle of radius 100 through [500, 0]: 100 pi mm at v100. *)
  let r = plan p ~now (Planner.move (speed "v100") (zone "fine") (Circular (target 500. 0. 300., target 400. 100. 300.))) in
  close ~eps:1e-9 "half circle" (r.ready_time -. now) (4. *. atan 1.);
  let mid = (Planner.pose_at p (now +. 2. *. atan 1.)).trans in
  close_pos "through the circle point" mid { x = 500.; y = 0.; z = 300. };
  let quarter = (Planner.pose_at p (now +. atan 1.)).trans in
  close "on the circle" (distance quarter { x = 400.; y = 0.; z = 300. }) 100.;
  match Planner.plan p ~now:r.ready_time
          (Planner.move (speed "v100") (zone "fine") (Circular (target 450. 100. 300., target 500. 100. 300.))) with
  | Error Motion_error.Circle_uncertain -> ()
  | _ -> Alcotest.fail "three points on a line make no circle"

(* ------------------------------------------------------------------ zones *)

let corner_pieces p =
  List.filter (fun (i : Planner.piece_info) -> match i.kind with Planner.Corner _ -> true | _ -> false) (Planner.pieces p)

(* Z-clip: the zone is reduced to half the neighbouring segment. *)
let test_zone_clipping () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 300. 0. 300.))) in
  let now = r0.ready_time in
  let _ = plan p ~now (Planner.move (speed "v100") (zone "z50") (Linear (target 400. 0. 300.))) in
  let _ = plan p ~now (Planner.move (speed "v100") (zone "fine") (Linear (target 400. 40. 300.))) in
  match corner_pieces p with
  | [ c ] ->
      (* r = min(50, 100/2, 40/2) = 20 mm on both sides; 0.2 s at 100 mm/s each. *)
      close "corner starts 20 mm before p1" c.t_from (now +. 0.8);
      close "corner ends 20 mm after p1" c.t_to (now +. 1.2);
      close_pos "corner start" (Planner.pose_at p c.t_from).trans { x = 380.; y = 0.; z = 300. };
      close_pos "corner end" (Planner.pose_at p c.t_to).trans { x = 400.; y = 20.; z = 300. };
      (* The quadratic Bezier's middle: a quarter of the way from the chord's middle to p1. *)
      close_pos "corner middle" (Planner.pose_at p (now +. 1.)).trans { x = 395.; y = 5.; z = 300. };
      close "fly-by costs no time" (Planner.finished_by p) (now +. 1.4)
  | l -> Alcotest.failf "expected one corner, got %d" (List.length l)

(* PP-fine, PP-flyby: the program pointer leaves a stop point when the robot is in position, a
   fly-by point the look-ahead horizon before its zone. *)
let test_program_pointer () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 300. 0. 300.))) in
  let now = r0.ready_time in
  let r1 = plan p ~now (Planner.move (speed "v100") (zone "z10") (Linear (target 400. 0. 300.))) in
  close "fly-by: 0.1 s before the zone at 90 mm" r1.ready_time (now +. 0.9 -. 0.1);
  let r2 = plan p ~now:r1.ready_time (Planner.move (speed "v100") (zone "fine") ~conc:true (Linear (target 400. 100. 300.))) in
  close "\\Conc: when its motion starts (the corner)" r2.ready_time (now +. 0.9);
  let r3 = plan p ~now:r2.ready_time (Planner.move (speed "v100") (zone "fine")
                                        ~inpos:(Option.get (Motion_data.find Motion_data.stoppointdata "stoptime0_5"))
                                        (Linear (target 300. 100. 300.))) in
  close "stoptime: in position and 0.5 s" r3.ready_time (now +. 3. +. 0.5);
  Alcotest.(check int) "ids" 3 r3.id;
  close "ready_time again" (Planner.ready_time p 1) r1.ready_time

(* Z-failure: a next move that comes after the corner had to begin makes the point a stop. *)
let test_corner_failure () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 300. 0. 300.))) in
  let now = r0.ready_time in
  let _ = plan p ~now (Planner.move (speed "v100") (zone "z10") (Linear (target 400. 0. 300.))) in
  let r = plan p ~now:(now +. 0.95) (Planner.move (speed "v100") (zone "fine") (Linear (target 400. 100. 300.))) in
  Alcotest.(check bool) "warned" true (r.warnings = [ Planner.Corner_path_failure 1 ]);
  Alcotest.(check int) "no corner" 0 (List.length (corner_pieces p));
  close "stops at p1, then 1 s" r.ready_time (now +. 2.)

(* ------------------------------------------------------------------ errors and settings *)

let test_move_errors () =
  let p = planner () in
  let expect what e m =
    match Planner.plan p ~now:0. m with
    | Error e' when e' = e -> ()
    | Error e' -> Alcotest.failf "%s: got %s" what (Motion_error.name e')
    | Ok _ -> Alcotest.failf "%s: planned" what in
  expect "out of reach" Motion_error.Out_of_reach (Planner.move (speed "v100") (zone "fine") (Linear (target 700. 0. 300.)));
  expect "MoveAbsJ beyond axis 3" (Motion_error.Joint_out_of_range 3)
    (Planner.move (speed "v100") (zone "fine") (Abs_joint [| 0.; 0.; 80.; 0.; 0.; 0. |]));
  (* From rest (cfx 0) the nearest solution keeps axis 5 positive; the same pose with the wrist
     turned over (axis 4 - 180, axis 5 negative) is cfx 1, and a linear move cannot get there. *)
  let qa = [| 0.; 10.; 10.; 60.; 60.; 0. |] in
  let flipped = { Frames.pose = Kinematics.forward kin qa; conf = { (Kinematics.conf_of kin qa) with cfx = 1 } } in
  ignore (ok "the flipped wrist exists" (Kinematics.inverse kin flipped.pose (With_conf flipped.conf)));
  expect "ConfL: the configuration would change" Motion_error.Configuration_error
    (Planner.move (speed "v100") (zone "fine") (Linear flipped));
  (* Axis 5 at 0.5 degrees: within the 1 degree of the wrist singularity. *)
  let qs = [| 0.; 10.; -10.; 0.; 0.5; 0. |] in
  let sing = { Frames.pose = Kinematics.forward kin qs; conf = Kinematics.conf_of kin qs } in
  expect "SingArea \\Off" Motion_error.Close_to_singularity (Planner.move (speed "v100") (zone "fine") (Linear sing));
  (Planner.settings p).sing_area_wrist <- true;
  let r = plan p (Planner.move (speed "v100") (zone "fine") (Linear sing)) in
  Alcotest.(check bool) "SingArea \\Wrist passes" true (r.ready_time > 0.);
  (* An error leaves the queue as it was. *)
  Alcotest.(check int) "one move planned" 1 (List.length (Planner.segments p));
  expect "neither held: a stationary tool and a fixed work object" Motion_error.Robhold_conflict
    (Planner.move ~tool:{ Motion_data.tool0 with tool_robhold = false } (speed "v100") (zone "fine") (Linear sing));
  expect "both held" Motion_error.Robhold_conflict
    (Planner.move ~wobj:{ Motion_data.wobj0 with wobj_robhold = true } (speed "v100") (zone "fine") (Linear sing))

(* S-level: StorePath keeps level 1 stopped while level 2 moves; RestoPath brings it back. *)
let test_path_level () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 300. 0. 300.))) in
  let now = r0.ready_time in
  let a = plan p ~now (Planner.move (speed "v100") (zone "fine") (Linear (target 400. 0. 300.))) in
  Planner.stop p ~at:(now +. 0.3);
  Alcotest.(check int) "level 1" 1 (Planner.path_level p);
  ok "StorePath" (Planner.store_path p ~at:(now +. 0.5));
  Alcotest.(check int) "level 2" 2 (Planner.path_level p);
  (match Planner.store_path p ~at:(now +. 0.5) with
   | Error (Motion_error.Path_level _) -> ()
   | _ -> Alcotest.fail "StorePath twice");
  let up = plan p ~now:(now +. 0.5) (Planner.move (speed "v100") (zone "fine") (Linear (target 330. 0. 350.))) in
  close "level 2 moves at once" up.ready_time (now +. 1.0);
  close_pos "level 2 under way" (Planner.pose_at p (now +. 0.75)).trans { x = 330.; y = 0.; z = 325. };
  let down = plan p ~now:up.ready_time (Planner.move (speed "v100") (zone "fine") (Linear (target 330. 0. 300.))) in
  ok "RestoPath" (Planner.resto_path p ~at:down.ready_time);
  Alcotest.(check int) "level 1 again" 1 (Planner.path_level p);
  (match Planner.resto_path p ~at:down.ready_time with
   | Error (Motion_error.Path_level _) -> ()
   | _ -> Alcotest.fail "RestoPath on level 1");
  close "level 1 still stopped" (Planner.ready_time p a.id) infinity;
  close "a dropped level's move keeps its time" (Planner.ready_time p up.id) (now +. 1.0);
  Planner.start p ~at:(now +. 2.);
  close "StartMove resumes level 1" (Planner.ready_time p a.id) (now +. 2.7);
  close_pos "from where it stopped" (Planner.pose_at p (now +. 2.)).trans { x = 330.; y = 0.; z = 300. }

(* Bad input never raises: not-a-number targets and speeds, and any description text. *)
let test_bad_input () =
  let p = planner () in
  let bad = target nan 0. 300. in
  let refused m = match Planner.plan p ~now:0. m with Error _ -> true | Ok _ -> false in
  Alcotest.(check bool) "NaN target" true (refused (Planner.move (speed "v100") (zone "fine") (Linear bad)));
  Alcotest.(check bool) "NaN circle point" true
    (refused (Planner.move (speed "v100") (zone "fine") (Circular (bad, target 350. 0. 300.))));
  Alcotest.(check bool) "NaN axis" true
    (refused (Planner.move (speed "v100") (zone "fine") (Abs_joint [| nan; 0.; 0.; 0.; 0.; 0. |])));
  Alcotest.(check bool) "NaN speed" true
    (refused (Planner.move { (speed "v100") with v_tcp = nan } (zone "fine") (Linear (target 350. 0. 300.))));
  Alcotest.(check int) "nothing planned" 0 (List.length (Planner.segments p));
  (* A fly-by move that goes nowhere takes no time and has no piece; the next one still corners. *)
  let here = Kinematics.forward kin rest in
  let _ = plan p (Planner.move (speed "v100") (zone "z10") (Linear { Frames.pose = here; conf = conf0 })) in
  let r = plan p (Planner.move (speed "v100") (zone "fine") (Linear (target 302. 0. 458.))) in
  close "then 100 mm" r.ready_time 1.;
  let lines = String.split_on_char '\n' Robot.irb120_text in
  run_property ~seed:5 ~count:2000 ~name:"the description parser answers every text"
    (QCheck.make ~print:Fun.id
       QCheck.Gen.(oneof [ string_size ~gen:printable (int_bound 200);
                           map (fun (i, junk) -> String.concat "\n" (List.mapi (fun j l -> if j = i then junk else l) lines))
                             (pair (int_bound (List.length lines)) (string_size ~gen:printable (int_bound 40))) ]))
    (fun text -> match Robot.parse ~file:"f" text with
       | Ok _ -> true
       | Error e -> e.line >= 1 && e.col >= 1 && String.length (Robot.error_to_string e) > 0)

let test_stop_start_clear () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 300. 0. 300.))) in
  let now = r0.ready_time in
  let r = plan p ~now (Planner.move (speed "v100") (zone "fine") (Linear (target 400. 0. 300.))) in
  Planner.stop p ~at:(now +. 0.3);
  close "stopped: no end" (Planner.ready_time p r.id) infinity;
  close_pos "stands still" (Planner.pose_at p (now +. 5.)).trans { x = 330.; y = 0.; z = 300. };
  Planner.start p ~at:(now +. 2.);
  close "StartMove: 1.7 s later" (Planner.ready_time p r.id) (now +. 2.7);
  close_pos "goes on" (Planner.pose_at p (now +. 2.2)).trans { x = 350.; y = 0.; z = 300. };
  Planner.clear p ~at:(now +. 2.2);
  close "ClearPath: done" (Planner.finished_by p) (now +. 2.2);
  close_pos "stays" (Planner.pose_at p (now +. 9.)).trans { x = 350.; y = 0.; z = 300. };
  let r = plan p ~now:(now +. 3.) (Planner.move (speed "v100") (zone "fine") (Linear (target 350. 50. 300.))) in
  close "the next move starts from there" r.ready_time (now +. 3.5)

(* T-distance: the time at which the TCP has gone a distance along a segment (TriggL, TriggIO,
   TriggInt), from its start or back from its end, with a shift of path time; it follows
   StopMove and StartMove, and a mark goes with the path ClearPath or RestoPath drops. *)
let test_time_at_distance () =
  let p = planner () in
  let r0 = plan p (Planner.move (speed "v1000") (zone "fine") (Joint (target 300. (-250.) 300.))) in
  let now = r0.ready_time in
  let some what = function Some t -> t | None -> Alcotest.failf "%s: dropped" what in
  let at ?from_end ?shift id d = some "time" (Planner.time_at_distance ?from_end ?shift p id d) in
  (* 500 mm at v100: 100 mm/s. *)
  let r = plan p ~now (Planner.move (speed "v100") (zone "fine") (Linear (target 300. 250. 300.))) in
  close "length" (Planner.segment_length p r.id) 500.;
  close "speed" (Planner.segment_speed p r.id) 100.;
  close "100 mm from the start" (at r.id 100.) (now +. 1.);
  close "at the start" (at r.id 0.) now;
  close "100 mm before the end" (at ~from_end:true r.id 100.) (now +. 4.);
  close "at the end" (at ~from_end:true r.id 0.) (now +. 5.);
  close "beyond the length from the start: the end" (at r.id 600.) (now +. 5.);
  close "beyond the length from the end: the start" (at ~from_end:true r.id 600.) now;
  close "0.2 s before the end" (at ~from_end:true ~shift:(-0.2) r.id 0.) (now +. 4.8);
  close "a delay after the end" (at ~from_end:true ~shift:0.3 r.id 0.) (now +. 5.3);
  close "never before the move's motion" (at ~shift:(-3.) r.id 100.) now;
  close_pos "the TCP is there then" (Planner.pose_at p (at r.id 100.)).trans { x = 300.; y = -150.; z = 300. };
  (* StopMove holds it, StartMove shifts it by the pause; ClearPath drops what is not reached. *)
  let reached = Planner.mark p r.id 100. and ahead = Planner.mark p r.id 300. in
  Planner.stop p ~at:(now +. 0.5);
  close "stopped short: never" (some "stopped" (Planner.mark_time p ahead)) infinity;
  Planner.start p ~at:(now +. 2.);
  close "after StartMove" (some "started" (Planner.mark_time p ahead)) (now +. 4.5);
  Planner.clear p ~at:(now +. 3.);
  Alcotest.(check bool) "ClearPath drops the mark not reached" true (Planner.mark_time p ahead = None);
  Alcotest.(check bool) "a mark reached stays" true (Planner.mark_time p reached <> None);
  Planner.release p reached; Planner.release p ahead;
  (* A fly-by point: the end is where the segment's law reaches its point, the middle of a
     symmetric corner path (z10 between two 100 mm segments at v100: 0.9 s to 1.1 s). *)
  let now = now +. 3. in
  let a = plan p ~now (Planner.move (speed "v100") (zone "z10") (Linear (target 300. 0. 300.))) in
  let _ = plan p ~now:a.ready_time (Planner.move (speed "v100") (zone "fine") (Linear (target 400. 0. 300.))) in
  close "a fly-by point's end" (at ~from_end:true a.id 0.) (now +. 1.);
  (* A circle: the arc length, at constant angular speed. *)
  let now = Planner.finished_by p in
  let _ = plan p ~now (Planner.move (speed "v1000") (zone "fine") (Joint (target 400. (-100.) 300.))) in
  let now = Planner.finished_by p in
  let arc = Planner.Circular (target 500. 0. 300., target 400. 100. 300.) in
  let c = plan p ~now (Planner.move (speed "v100") (zone "fine") arc) in
  close ~eps:1e-6 "half the arc" (at c.id (50. *. 4. *. atan 1.)) (now +. 2. *. atan 1.);
  (* RestoPath drops the marks of level 2. *)
  let now = Planner.finished_by p in
  ok "StorePath" (Planner.store_path p ~at:now);
  let up = plan p ~now (Planner.move (speed "v100") (zone "fine") (Linear (target 400. 100. 350.))) in
  let m = Planner.mark ~from_end:true p up.id 0. in
  close "level 2" (some "level 2" (Planner.mark_time p m)) (now +. 0.5);
  ok "RestoPath" (Planner.resto_path p ~at:(now +. 0.5));
  Alcotest.(check bool) "RestoPath drops level 2's marks" true (Planner.mark_time p m = None)

(* ------------------------------------------------------------------ paths, properties *)

(* Targets the IRB 120 reaches comfortably, pointing down. *)
let point_gen = QCheck.Gen.(triple (float_range 250. 420.) (float_range (-150.) 150.) (float_range 200. 400.))
let program_gen =
  QCheck.Gen.(list_size (int_range 2 8)
                (pair (pair point_gen (int_bound 4)) (pair (oneofl [ "fine"; "z1"; "z10"; "z50"; "z200" ]) (oneofl [ "v50"; "v200"; "v1000" ]))))

let show_program l =
  String.concat "; " (List.map (fun (((x, y, z), k), (zn, v)) -> Printf.sprintf "%d [%.1f %.1f %.1f] %s %s" k x y z zn v) l)

(* Plans a program at once (each move as soon as the program may go on); [k] picks MoveL, MoveC
   (through a point beside the chord) or MoveJ. *)
let plan_program ?(speed_of = speed) l =
  let p = planner () in
  (Planner.settings p).conf_l <- false;
  let now = ref 0. and from = ref { x = 302.; y = 0.; z = 558. } in
  List.iter (fun (((x, y, z), k), (zn, v)) ->
      let tg = target x y z in
      let motion =
        if k = 3 then Planner.Joint tg
        else if k = 4 && distance !from tg.pose.trans > 20. then
          let m = lerp !from tg.pose.trans 0.5 and d = sub tg.pose.trans !from in
          let side = scale (0.3 /. Float.max 1e-9 (norm { d with z = 0. })) { x = -. d.y; y = d.x; z = 0. } in
          let side = if norm side < 1e-6 then { x = 0.3 *. norm d; y = 0.; z = 0. } else scale (norm d) side in
          Planner.Circular (target (m.x +. side.x) (m.y +. side.y) m.z, tg)
        else Planner.Linear tg in
      match Planner.plan p ~now:!now (Planner.move (speed_of v) (zone zn) motion) with
      | Ok r -> now := Float.max !now r.ready_time; from := tg.pose.trans
      | Error _ -> ())
    l;
  p

(* T-scale through the planner: a program of linear and circular moves to stop points, every
   speed component times k (below the caps), ends k times sooner. *)
let test_scaling_planned () =
  run_property ~seed:13 ~count:300 ~name:"planned programs scale inversely with speed"
    (QCheck.make ~print:(fun (l, v, k) -> Printf.sprintf "v %g k %g: %s" v k (show_program l))
       QCheck.Gen.(triple program_gen (float_range 5. 500.) (float_range 1. 5.)))
    (fun (l, v, k) ->
      let l = List.filter_map (fun ((pt, kind), _) -> if kind = 3 then None else Some ((pt, kind), ("fine", ""))) l in
      let finished f =
        let sd = { Motion_data.v_tcp = f *. v; v_ori = f *. 100.; v_leax = 0.; v_reax = 0. } in
        Planner.finished_by (plan_program ~speed_of:(fun _ -> sd) l) in
      let t1 = finished 1. and tk = finished k in
      QCheck.assume (t1 > 0.);
      Float.abs (t1 -. k *. tk) <= 1e-9 *. t1)

(* L-sum: the length of the path of stop points is the sum of its segments' lengths. *)
let test_length_sum () =
  run_property ~seed:11 ~count:150 ~name:"a path's length is the sum of its segments'"
    (QCheck.make ~print:show_program program_gen) (fun l ->
      let l = List.map (fun (pk, (_, v)) -> (pk, ("fine", v))) l in
      let p = plan_program l in
      let total = List.fold_left (fun acc (s : Planner.segment_info) -> acc +. s.seg_length) 0. (Planner.segments p) in
      let cartesian = List.for_all (fun (s : Planner.segment_info) -> s.seg_kind <> "MoveJ") (Planner.segments p) in
      QCheck.assume cartesian;
      (* Sampled piece by piece, so that no chord cuts the turn at a stop point. *)
      let sampled = ref 0. in
      List.iter (fun (i : Planner.piece_info) ->
          let n = 2000 in
          let prev = ref (Planner.pose_at p i.t_from).trans in
          for k = 1 to n do
            let q = (Planner.pose_at p (i.t_from +. (i.t_to -. i.t_from) *. float_of_int k /. float_of_int n)).trans in
            sampled := !sampled +. distance !prev q; prev := q
          done) (Planner.pieces p);
      Float.abs (!sampled -. total) <= 1e-6 *. Float.max 1. total)

(* I-continuous: position and orientation are continuous at segment and corner boundaries. *)
let test_continuity () =
  run_property ~seed:12 ~count:300 ~name:"interpolation is continuous at boundaries"
    (QCheck.make ~print:show_program program_gen) (fun l ->
      let p = plan_program l in
      let eps = 1e-7 in
      List.for_all (fun (i : Planner.piece_info) ->
          List.for_all (fun t ->
              let a = Planner.pose_at p (t -. eps) and b = Planner.pose_at p (t +. eps) in
              (* at most 2 eps at the fastest speed used (1000 mm/s, 500 deg/s, or an axis) *)
              distance a.trans b.trans < 1e-3 && angle_between a.rot b.rot < 1e-3) [ i.t_from; i.t_to ])
        (Planner.pieces p))

(* ------------------------------------------------------------------ output *)

let test_output () =
  let p = planner () in
  let _ = plan p (Planner.move ~label:"p1" (speed "v1000") (zone "z10") (Linear (target 350. (-100.) 300.))) in
  let _ = plan p (Planner.move ~label:"p<2>" (speed "v1000") (zone "fine") (Linear (target 350. 100. 300.))) in
  let svg = Path_output.path_svg p and tl = Path_output.timeline_svg p in
  let has s sub = try ignore (Str.search_forward (Str.regexp_string sub) s 0); true with Not_found -> false in
  Alcotest.(check bool) "labels" true (has svg ">p1<" && has svg "p&lt;2&gt;");
  Alcotest.(check bool) "corner drawn" true (has svg "#e67e00");
  Alcotest.(check bool) "two views" true (has svg "Top view" && has svg "Side view");
  Alcotest.(check bool) "timeline moves" true (has tl "MoveL");
  let csv = Path_output.csv ~step:0.1 p in
  let lines = List.filter (( <> ) "") (String.split_on_char '\n' csv) in
  Alcotest.(check string) "CSV header" "t,x,y,z,q1,q2,q3,q4,j1,j2,j3,j4,j5,j6" (List.hd lines);
  Alcotest.(check int) "CSV columns" 14 (List.length (String.split_on_char ',' (List.nth lines 1)));
  let last = List.nth lines (List.length lines - 1) in
  match String.split_on_char ',' last with
  | t :: x :: y :: z :: _ ->
      close ~eps:1e-4 "last row at the end" (float_of_string t) (Planner.finished_by p);
      close_pos ~eps:1e-3 "last row at p2" { x = float_of_string x; y = float_of_string y; z = float_of_string z } { x = 350.; y = 100.; z = 300. }
  | _ -> Alcotest.fail "CSV row"

let suite =
  ( "motion",
    [ Alcotest.test_case "K-home: the IRB 120's home pose" `Quick test_home;
      Alcotest.test_case "the robot description's numbers (R-2.13-numbers2)" `Quick test_description_numbers;
      Alcotest.test_case "K-inverse: FK then IK, random" `Quick test_fk_ik;
      Alcotest.test_case "K-errors: reach and axis range" `Quick test_ik_errors;
      Alcotest.test_case "the robot description and its errors" `Quick test_description;
      Alcotest.test_case "predefined motion data" `Quick test_data;
      Alcotest.test_case "F-frames: CalcRobT, CalcJointT, CPos" `Quick test_frames;
      Alcotest.test_case "F-stationary: a stationary tool" `Quick test_stationary_tool;
      Alcotest.test_case "T-scale: planned programs, random" `Quick test_scaling_planned;
      Alcotest.test_case "Offs, RelTool, MirPos" `Quick test_position_functions;
      Alcotest.test_case "T-cartesian: 500 mm MoveL at v100 fine = 5 s" `Quick test_movel_5s;
      Alcotest.test_case "T-args: \\V, \\T, VelSet, MaxRobSpeed" `Quick test_speed_arguments;
      Alcotest.test_case "T-joint: the slowest axis" `Quick test_movej_slowest_axis;
      Alcotest.test_case "T-scale: inverse to speed, random" `Quick test_scaling;
      Alcotest.test_case "G-circle: MoveC" `Quick test_movec;
      Alcotest.test_case "Z-clip: half the neighbouring segment" `Quick test_zone_clipping;
      Alcotest.test_case "PP: program pointer and motion pointer" `Quick test_program_pointer;
      Alcotest.test_case "Z-failure: corner path failure" `Quick test_corner_failure;
      Alcotest.test_case "errors of moves, ConfL, SingArea" `Quick test_move_errors;
      Alcotest.test_case "StopMove, StartMove, ClearPath" `Quick test_stop_start_clear;
      Alcotest.test_case "T-distance: the time at a distance along a segment" `Quick test_time_at_distance;
      Alcotest.test_case "bad input never raises" `Quick test_bad_input;
      Alcotest.test_case "S-level: StorePath, RestoPath" `Quick test_path_level;
      Alcotest.test_case "L-sum: path length, random" `Quick test_length_sum;
      Alcotest.test_case "I-continuous: at boundaries, random" `Quick test_continuity;
      Alcotest.test_case "SVG and CSV output" `Quick test_output ] )
