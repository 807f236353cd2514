(* The robot library (lib/motion_model/robot_library.ml, robots/*.robot; doc/motion.md, "The robot
   library"): every description parses, is found by its name and by its MOC.cfg robot type, has the
   reach its product name gives, and its kinematics invert. *)

open Rapid_motion_model
open Geom

let contains t w =
  let n = String.length w in
  let rec go i = i + n <= String.length t && (String.sub t i n = w || go (i + 1)) in
  go 0

let get what = function Ok x -> x | Error m -> Alcotest.failf "%s: %s" what m

let robots () = List.map (fun n -> (n, get n (Robot_library.find n))) (Robot_library.names ())

let all_parse () =
  let names = Robot_library.names () in
  Alcotest.(check bool) "at least the arms of issue 17" true (List.length names >= 10);
  List.iter (fun n ->
      let text = Option.get (Robot_library.text n) in
      (* the embedded text is the file's, and it parses as --robot FILE would read it *)
      ignore (get n (Result.map_error Robot.error_to_string (Robot.parse ~file:n text)));
      let ty = Option.get (Robot_library.robot_type n) in
      let by_type = get ty (Robot_library.find ty) and by_name = get n (Robot_library.find n) in
      Alcotest.(check string) (n ^ " by its robot type") by_name.Robot.name by_type.Robot.name)
    names

let by_moc_type () =
  let name s = (get s (Robot_library.find s)).Robot.name in
  Alcotest.(check string) "2400" "ABB IRB 2400-10/1.5" (name "ROB1_2400_1.5_10");
  Alcotest.(check string) "4600" "ABB IRB 4600-40/2.55" (name "ROB1_4600_2.55_40");
  Alcotest.(check string) "120" "ABB IRB 120-3/0.58" (name "ROB1_120_0.58_3");
  Alcotest.(check string) "a variant word" "ABB IRB 1200-5/0.9" (name "ROB1_1200_0.9_5_TypeB");
  Alcotest.(check string) "a reach written 0_9" "ABB IRB 1200-5/0.9" (name "ROB1_1200_0_9_5");
  Alcotest.(check string) "ROB2" "ABB IRB 7600-150/3.5" (name "ROB2_7600_3.5_150");
  Alcotest.(check string) "a model alone" "ABB IRB 7600-150/3.5" (name "IRB 7600");
  Alcotest.(check string) "a library name" "ABB IRB 2400-16/1.5" (name "irb2400-16-1.5");
  Alcotest.(check string) "a library file name" "ABB IRB 2400-16/1.5" (name "irb2400-16-1.5.robot");
  let refused s expect =
    match Robot_library.find s with
    | Ok r -> Alcotest.failf "%s: expected an error, found %s" s r.Robot.name
    | Error m ->
        List.iter (fun w ->
            if not (contains m w) then Alcotest.failf "%s: %S lacks %S" s m w) expect in
  refused "ROB1_2400_1.5_12" [ "ROB1_2400_1.5_12"; "not in the library"; "ROB1_2400_1.5_10"; "ROB1_4600_2.55_40" ];
  refused "irb4600" [ "several"; "irb4600-40-2.55"; "irb4600-60-2.05" ];
  refused "ROB1_" [ "neither a library name nor a robot type"; "ROB1_120_0.58_3" ];
  refused "" [ "neither" ];
  match Robot_library.load "no-such-robot" with
  | Ok _ -> Alcotest.fail "no-such-robot found"
  | Error m -> Alcotest.(check bool) "load says no file" true (contains m "no file no-such-robot")

(* The wrist centre of axis angles. *)
let wrist k (r : Robot.t) q =
  let f = Kinematics.forward k q in
  sub f.trans (scale r.axes.(5).d (rotate f.rot { x = 0.; y = 0.; z = 1. }))

(* At the calibration position (all axes 0) the lower arm stands up and the upper arm points
   forward: the wrist centre is at [a1 + d4, 0, d1 + a2 + a3] and tool0 points along +X; stretched
   forward (axis 2 at 90, the upper arm in line with the lower arm) the wrist centre is at the
   reach the product specification gives, within 2.5 % (the published figure is rounded: the
   IRB 1600-6/1.2's 1.2 m is 1225 mm of its dimensions, the IRB 2400-10's 1.55 m 1572 mm). *)
let serial_calibration n (r : Robot.t) k =
  let ax i = r.axes.(i - 1) in
  let w = wrist k r (Array.make 6 0.) in
  let expect = { x = (ax 1).a +. (ax 4).d; y = 0.; z = (ax 1).d +. (ax 2).a +. (ax 3).a +. (ax 5).a } in
  if distance w expect > 1e-6 then Alcotest.failf "%s: wrist centre at calibration [%g %g %g]" n w.x w.y w.z;
  let f = Kinematics.forward k (Array.make 6 0.) in
  let along = rotate f.rot { x = 0.; y = 0.; z = 1. } in
  if distance along { x = 1.; y = 0.; z = 0. } > 1e-9 then Alcotest.failf "%s: tool0 not along +X" n;
  let q2 = Float.min 90. (ax 2).max in
  let q3 = deg (atan2 (ax 3).a (ax 4).d) -. 90. in
  let q3 = if r.structure = Robot.Coupled_axis3 then q3 +. q2 else q3 in
  let w = wrist k r [| 0.; q2; q3; 0.; 0.; 0. |] in
  (w, q2 = 90. && (ax 5).a = 0. && Float.abs (w.z -. (ax 1).d) > 1e-6)

(* The palletiser: at calibration the lower arm stands up, the upper arm is level and the flange
   hangs [a6, d6] ahead of and below its end, pointing down; stretched, axis 2 at its forward
   limit and axis 3 level, the flange is at the reach. *)
let palletiser_calibration n (r : Robot.t) k =
  let ax i = r.axes.(i - 1) in
  let f = Kinematics.forward k (Array.make 6 0.) in
  let expect = { x = (ax 1).a +. (ax 3).a +. (ax 6).a; y = 0.; z = (ax 1).d +. (ax 2).a -. (ax 6).d } in
  if distance f.trans expect > 1e-6 then
    Alcotest.failf "%s: flange at calibration [%g %g %g]" n f.trans.x f.trans.y f.trans.z;
  if angle_between f.rot { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } > 1e-9 then Alcotest.failf "%s: not pointing down" n;
  ((Kinematics.forward k [| 0.; (ax 2).max; 0.; 0.; 0.; 0. |]).trans, false)

let calibration_and_reach () =
  List.iter (fun (n, (r : Robot.t)) ->
      let k = Kinematics.create r in
      let w, off_level = match r.structure with
        | Robot.Palletiser -> palletiser_calibration n r k
        | Robot.Serial | Robot.Coupled_axis3 -> serial_calibration n r k in
      let reach = match r.reach with Some l -> l | None -> Alcotest.failf "%s: no reach" n in
      if Float.abs (w.x -. reach) > 0.025 *. reach || off_level then
        Alcotest.failf "%s: stretched at [%g %g %g], the reach is %g" n w.x w.y w.z reach)
    (robots ())

let show_q q = String.concat ", " (Array.to_list (Array.map (Printf.sprintf "%.9g") q))

(* FK then IK with the confdata of the angles gives the angles back, for every arm, on random
   axis angles within the ranges away from the singularities (as test_motion's K-inverse). *)
let round_trip () =
  List.iteri (fun i (n, (r : Robot.t)) ->
      let k = Kinematics.create r in
      let ax = r.axes in
      let gen = QCheck.Gen.(map (fun us -> Array.mapi (fun i u -> ax.(i).min +. u *. (ax.(i).max -. ax.(i).min)) us)
                              (array_repeat 6 (float_bound_inclusive 1.))) in
      (* away from the singularities: the wrist (axis 5 near 0), the elbow stretched, the wrist
         centre over axis 1; a quadrant's edge is not where a confdata is read back *)
      let regular q =
        let edges = Array.for_all (fun a -> Float.abs (Float.rem (Float.abs a) 90.) > 1e-6) [| q.(0); q.(3); q.(5) |] in
        match r.structure with
        | Robot.Palletiser ->
            let t2 = rad q.(1) and t3 = rad q.(2) in
            let f = Kinematics.forward k q in
            edges && Float.abs (cos (t2 -. t3)) > 0.02 && Float.hypot f.trans.x f.trans.y > 5.
        | Robot.Serial | Robot.Coupled_axis3 ->
            let q3 = if r.structure = Robot.Coupled_axis3 then q.(2) -. q.(1) else q.(2) in
            let t3 = rad (q3 +. ax.(2).offset) and ps = atan2 ax.(3).d ax.(2).a in
            let w = wrist k r q in
            (* an offset wrist's search may miss one of two solutions that merge near the wrist
               singularity (doc/rulings.md R-structure-offset): 20 degrees from it *)
            let zone = if ax.(4).a <> 0. then 20. else 2. in
            (not (Kinematics.wrist_singular ~zone k q)) && Float.abs (sin (t3 +. ps)) > 0.02
            && sqrt ((w.x *. w.x) +. (w.y *. w.y)) > 5. && edges in
      QCheck.Test.check_exn ~rand:(Random.State.make [| 17 + i |])
        (QCheck.Test.make ~count:500 ~name:(n ^ ": forward then inverse") (QCheck.make ~print:show_q gen) (fun q ->
             QCheck.assume (regular q);
             let p = Kinematics.forward k q in
             match Kinematics.inverse k p (With_conf (Kinematics.conf_of k q)) with
             | Error e -> QCheck.Test.fail_reportf "%s" (Motion_error.name e)
             | Ok q' ->
                 let p' = Kinematics.forward k q' in
                 if distance p.trans p'.trans > 1e-6 || angle_between p.rot p'.rot > 1e-6 then
                   QCheck.Test.fail_reportf "pose differs: %s" (show_q q');
                 let c = Kinematics.conf_of k q and c' = Kinematics.conf_of k q' in
                 if c <> c' then QCheck.Test.fail_reportf "another confdata: %s" (show_q q');
                 (* an offset wrist may have several solutions of one confdata (a general arm has up
                    to 16): the pose and the confdata are what it must give back *)
                 let dq = Array.fold_left Float.max 0. (Array.mapi (fun i a -> Float.abs (a -. q'.(i))) q) in
                 if r.axes.(4).a = 0. && dq > 1e-6 then QCheck.Test.fail_reportf "axes differ by %g: %s" dq (show_q q');
                 true)))
    (robots ())

(* Each axis of every arm: MoveAbsJ to its limit moves, one degree beyond either end is
   refused as that axis out of range (ERR_ROBLIMIT where the engines raise it). *)
let limits_refused () =
  let v = Option.get (Motion_data.find Motion_data.speeddata "v1000")
  and fine = Option.get (Motion_data.find Motion_data.zonedata "fine") in
  List.iter (fun (n, (r : Robot.t)) ->
      let k = Kinematics.create r in
      Array.iteri (fun i (ax : Robot.axis) ->
          if Robot.present r (i + 1) then
          List.iter (fun (at, beyond) ->
              let q = Array.make 6 0. in
              (* axis 3's end may need axis 2 off 0 to stay clear of nothing: the model has no
                 collisions, so the other axes stay at 0 *)
              q.(i) <- at;
              let p = Planner.create k in
              (match Planner.plan p ~now:0. (Planner.move v fine (Abs_joint (Array.copy q))) with
               | Ok _ -> ()
               | Error e -> Alcotest.failf "%s: axis %d at %g: %s" n (i + 1) at (Motion_error.name e));
              q.(i) <- beyond;
              match Planner.plan (Planner.create k) ~now:0. (Planner.move v fine (Abs_joint q)) with
              | Error (Motion_error.Joint_out_of_range j) when j = i + 1 -> ()
              | Error e -> Alcotest.failf "%s: axis %d at %g: %s" n (i + 1) beyond (Motion_error.name e)
              | Ok _ -> Alcotest.failf "%s: axis %d at %g moved" n (i + 1) beyond)
            [ (ax.min, ax.min -. 1.); (ax.max, ax.max +. 1.) ]) r.axes)
    (robots ())

(* The reach line: optional, one positive length, once. *)
let reach_line () =
  let base = Robot.irb120_text in
  let err extra expect =
    match Robot.parse ~file:"r.robot" (base ^ extra) with
    | Ok _ -> Alcotest.failf "%S accepted" extra
    | Error e -> Alcotest.(check string) extra expect (Robot.error_to_string e) in
  let line = List.length (String.split_on_char '\n' base) in
  (match Robot.parse ~file:"r.robot" (base ^ "reach 580\n") with
   | Ok r -> Alcotest.(check (option (float 0.))) "reach" (Some 580.) r.reach
   | Error e -> Alcotest.fail (Robot.error_to_string e));
  Alcotest.(check (option (float 0.))) "no reach" None Robot.irb120.reach;
  err "reach 0\n" (Printf.sprintf "r.robot:%d:7: robot description error: reach must be positive" line);
  err "reach -5\n" (Printf.sprintf "r.robot:%d:7: robot description error: reach must be positive" line);
  err "reach 580\nreach 580\n"
    (Printf.sprintf "r.robot:%d:1: robot description error: reach given twice" (line + 1));
  err "reach\n" (Printf.sprintf "r.robot:%d:1: robot description error: reach: expected one number (mm)" line);
  err "reach x\n"
    (Printf.sprintf "r.robot:%d:7: robot description error: reach: expected a number, found \"x\"" line)

(* structure coupled-axis3: axis 2 alone leaves the upper arm's attitude, so the flange keeps its
   orientation; on a serial arm it turns with axis 2. *)
let coupled_axis3 () =
  List.iter (fun (n, (r : Robot.t)) ->
      let k = Kinematics.create r in
      let f q = Kinematics.forward k q in
      let a = f [| 0.; 0.; 10.; 0.; 30.; 0. |] and b = f [| 0.; 25.; 10.; 0.; 30.; 0. |] in
      let turned = angle_between a.rot b.rot in
      match r.structure with
      | Robot.Coupled_axis3 -> if turned > 1e-9 then Alcotest.failf "%s: turned %g" n turned
      | Robot.Serial -> if Float.abs (turned -. rad 25.) > 1e-9 then Alcotest.failf "%s: turned %g" n turned
      | Robot.Palletiser -> if turned > 1e-9 then Alcotest.failf "%s: the flange turned %g" n turned)
    (robots ());
  Alcotest.(check bool) "the IRB 2400 is coupled" true
    ((get "2400" (Robot_library.find "irb2400-10-1.5")).structure = Robot.Coupled_axis3);
  Alcotest.(check bool) "the IRB 4600 is not" true
    ((get "4600" (Robot_library.find "irb4600-40-2.55")).structure = Robot.Serial);
  let base = Robot.irb120_text in
  let err extra expect =
    match Robot.parse ~file:"r.robot" (base ^ extra) with
    | Ok _ -> Alcotest.failf "%S accepted" extra
    | Error e -> Alcotest.(check string) extra expect (Robot.error_to_string e) in
  let line = List.length (String.split_on_char '\n' base) in
  err "structure delta-ish\n" (Printf.sprintf
    "r.robot:%d:11: robot description error: structure: expected serial, coupled-axis3 or palletiser, found \"delta-ish\"" line);
  err "structure serial\nstructure serial\n"
    (Printf.sprintf "r.robot:%d:1: robot description error: structure given twice" (line + 1));
  err "structure\n" (Printf.sprintf "r.robot:%d:1: robot description error: structure: expected one word" line)

(* structure palletiser: axes 1, 2, 3 and 6; the flange hangs level, so a pose tilted more than
   1 degree is out of reach; axes 4 and 5 stand at 0 whatever MoveAbsJ gives them. *)
let palletiser () =
  let text = Option.get (Robot_library.text "irb660-180-3.15") in
  let r = get "660" (Robot_library.find "ROB1_660_3.15_180") in
  Alcotest.(check bool) "axes" true (List.map (Robot.present r) [ 1; 2; 3; 4; 5; 6 ] = [ true; true; true; false; false; true ]);
  let k = Kinematics.create r in
  let q = [| 20.; 30.; 40.; 0.; 0.; -50. |] in
  let p = Kinematics.forward k q in
  let tilted = { p with rot = omult p.rot (of_axis_angle { x = 1.; y = 0.; z = 0. } (rad 2.)) } in
  (match Kinematics.inverse k tilted (Nearest q) with
   | Error Motion_error.Out_of_reach -> ()
   | Error e -> Alcotest.failf "tilted: %s" (Motion_error.name e)
   | Ok _ -> Alcotest.fail "a tilted flange reached");
  let slightly = { p with rot = omult p.rot (of_axis_angle { x = 1.; y = 0.; z = 0. } (rad 0.5)) } in
  (match Kinematics.inverse k slightly (Nearest q) with
   | Ok q' -> Alcotest.(check (float 1e-6)) "within 1 degree: the level pose's axis 2" q.(1) q'.(1)
   | Error e -> Alcotest.failf "slightly tilted: %s" (Motion_error.name e));
  let c = Kinematics.conf_of k q in
  (match Kinematics.inverse k p (With_conf { c with cf4 = 3; cfx = c.cfx lor 1 }) with
   | Ok q' -> Alcotest.(check (float 1e-6)) "cf4 and cfx's axis 5 bit say nothing" q.(5) q'.(5)
   | Error e -> Alcotest.failf "with conf: %s" (Motion_error.name e));
  let v = Option.get (Motion_data.find Motion_data.speeddata "v1000")
  and fine = Option.get (Motion_data.find Motion_data.zonedata "fine") in
  let pl = Planner.create k in
  (match Planner.plan pl ~now:0. (Planner.move v fine (Abs_joint [| 10.; 0.; 0.; 9E9; -400.; 5. |])) with
   | Ok _ ->
       let j = match Planner.joints_at pl 10. with Ok j -> j | Error e -> Alcotest.fail (Motion_error.name e) in
       Alcotest.(check (list (float 1e-9))) "axes 4 and 5 at 0" [ 10.; 0.; 0.; 0.; 0.; 5. ]
         (Array.to_list (Array.sub j 0 6))
   | Error e -> Alcotest.failf "MoveAbsJ: %s" (Motion_error.name e));
  let err t expect =
    match Robot.parse ~file:"p.robot" t with
    | Ok _ -> Alcotest.failf "accepted: %s" expect
    | Error e -> Alcotest.(check string) expect expect (Robot.error_to_string e) in
  let replace a b = Str.global_replace (Str.regexp_string a) b text in
  err (replace "axis 6   260" "axis 4 0 0 0 0 -1 1 1\naxis 6   260")
    "p.robot:17:1: robot description error: axis 4: a palletiser has no axis 4 (its axes are 1, 2, 3 and 6)";
  err (replace "axis 2   1280    0" "axis 2   1280    5")
    "p.robot:15:1: robot description error: axis 2: a palletiser's alpha and offset must be 0 (doc/motion.md)";
  err (replace "axis 6   260     0     247      0     -300 300      300\n" "")
    "p.robot:20:1: robot description error: axis 6 is missing"

let suite =
  ( "robot library",
    [ Alcotest.test_case "every description parses and is found by its robot type" `Quick all_parse;
      Alcotest.test_case "MOC.cfg robot types, names and their errors" `Quick by_moc_type;
      Alcotest.test_case "calibration position and reach of every arm" `Quick calibration_and_reach;
      Alcotest.test_case "FK then IK of every arm (QCheck)" `Quick round_trip;
      Alcotest.test_case "an axis beyond its range is refused" `Quick limits_refused;
      Alcotest.test_case "the reach line" `Quick reach_line;
      Alcotest.test_case "structure coupled-axis3" `Quick coupled_axis3;
      Alcotest.test_case "structure palletiser" `Quick palletiser ] )
