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
  Alcotest.(check string) "a model alone" "ABB IRB 4600-40/2.55" (name "ROB2_4600_2.55_40");
  Alcotest.(check string) "a model alone" "ABB IRB 6660-205/1.9" (name "IRB 6660");
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
  refused "IRB 7600" [ "several"; "irb7600-150-3.5"; "irb7600-400-2.55" ];
  refused "ROB1_910_0.55_3" [ "not in the library"; "ROB1_910SC_0.55_3" ];
  refused "ROB1_" [ "neither a library name nor a robot type"; "ROB1_120_0.58_3" ];
  refused "" [ "neither" ];
  match Robot_library.load "no-such-robot" with
  | Ok _ -> Alcotest.fail "no-such-robot found"
  | Error m -> Alcotest.(check bool) "load says no file" true (contains m "no file no-such-robot")

(* The one check of a description refused: the error, with its file, line and column. *)
let refused_description ~file text expect =
  match Robot.parse ~file text with
  | Ok _ -> Alcotest.failf "accepted: %s" expect
  | Error e -> Alcotest.(check string) expect expect (Robot.error_to_string e)

(* The robot types the gathered controller backups name (their SYSPAR/MOC.cfg, use_robot_type),
   each found as the arm it names: issue 17's arms. *)
let backup_types () =
  let name s = (get s (Robot_library.find s)).Robot.name in
  List.iter (fun (ty, expect) -> Alcotest.(check string) ty expect (name ty))
    [ ("ROB3_760_3.2_450", "ABB IRB 760-450/3.18");
      ("ROB1_2600ID_2.00_8", "ABB IRB 2600ID-8/2.00");
      ("ROB1_2600_ID_2_8", "ABB IRB 2600ID-8/2.00");
      ("ROB1_6660_1.90_205", "ABB IRB 6660-205/1.9");
      ("ROB1_6700_2.80_205", "ABB IRB 6700-205/2.80");
      ("ROB1_7600_2.55_400", "ABB IRB 7600-400/2.55");
      ("ROB1_1660ID_1.55_4", "ABB IRB 1660ID-4/1.55");
      ("ROB1_1660_ID_1.55_4", "ABB IRB 1660ID-4/1.55");
      ("irb1660id", "ABB IRB 1660ID-4/1.55");
      ("ROB1_910SC_0.55_3", "ABB IRB 910SC-3/0.55");
      ("ROB1_360_1.6_6", "ABB IRB 360-6/1600") ];
  (* the two IRB 6700 and the IRB 2600 and 2600ID stay apart *)
  Alcotest.(check string) "6700-200" "ABB IRB 6700-200/2.60" (name "ROB1_6700_2.6_200");
  Alcotest.(check string) "2600" "ABB IRB 2600-12/1.65" (name "irb2600");
  Alcotest.(check string) "2600ID" "ABB IRB 2600ID-8/2.00" (name "irb2600id")

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

(* The delta: at calibration the arms are level and the plate hangs on the axis at the depth the
   rods leave, sqrt(rod^2 - (R + a)^2), the flange d below it, pointing down; the reach is the
   working range's radius: a point that far out is reached level. *)
let delta_calibration n (r : Robot.t) k =
  let ax i = r.axes.(i - 1) in
  let f = Kinematics.forward k (Array.make 6 0.) in
  let rr = (ax 4).a +. (ax 1).a in
  let expect = { x = 0.; y = 0.; z = -. sqrt (((ax 1).d *. (ax 1).d) -. (rr *. rr)) -. (ax 4).d } in
  if distance f.trans expect > 1e-6 then
    Alcotest.failf "%s: flange at calibration [%g %g %g]" n f.trans.x f.trans.y f.trans.z;
  if angle_between f.rot { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } > 1e-9 then Alcotest.failf "%s: not pointing down" n;
  let reach = Option.get r.reach in
  let far = { f with trans = { x = reach; y = 0.; z = f.trans.z +. 100. } } in
  match Kinematics.inverse k far (Nearest (Array.make 6 0.)) with
  | Ok q -> ((Kinematics.forward k q).trans, false)
  | Error e -> Alcotest.failf "%s: the reach: %s" n (Motion_error.name e)

(* The SCARA: at calibration the two arms are in line along x, the flange at their end at axis
   1's height, pointing down; that is the reach. *)
let scara_calibration n (r : Robot.t) k =
  let ax i = r.axes.(i - 1) in
  let f = Kinematics.forward k (Array.make 6 0.) in
  let expect = { x = (ax 1).a +. (ax 2).a; y = 0.; z = (ax 1).d } in
  if distance f.trans expect > 1e-6 then
    Alcotest.failf "%s: flange at calibration [%g %g %g]" n f.trans.x f.trans.y f.trans.z;
  if angle_between f.rot { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } > 1e-9 then Alcotest.failf "%s: not pointing down" n;
  (f.trans, false)

let calibration_and_reach () =
  List.iter (fun (n, (r : Robot.t)) ->
      let k = Kinematics.create r in
      let w, off_level = match r.structure with
        | Robot.Delta -> delta_calibration n r k
        | Robot.Palletiser -> palletiser_calibration n r k
        | Robot.Scara -> scara_calibration n r k
        | Robot.Serial | Robot.Coupled_axis3 -> serial_calibration n r k in
      let reach = match r.reach with Some l -> l | None -> Alcotest.failf "%s: no reach" n in
      if Float.abs (w.x -. reach) > 0.025 *. reach || off_level then
        Alcotest.failf "%s: stretched at [%g %g %g], the reach is %g" n w.x w.y w.z reach)
    (robots ())

let show_q q = String.concat ", " (Array.to_list (Array.map (Printf.sprintf "%.9g") q))

(* The one check of FK then IK: the angles' pose, solved with their confdata, gives the pose and
   the confdata back, and the angles themselves where the arm has one solution per confdata (an
   offset wrist may have several: a general arm has up to 16). [Error] says what differs. *)
let fk_ik k q =
  let r = Kinematics.robot k in
  let p = Kinematics.forward k q in
  match Kinematics.inverse k p (With_conf (Kinematics.conf_of k q)) with
  | Error e -> Error (Motion_error.name e)
  | Ok q' ->
      let p' = Kinematics.forward k q' in
      let c = Kinematics.conf_of k q and c' = Kinematics.conf_of k q' in
      let dq = Array.fold_left Float.max 0. (Array.mapi (fun i a -> Float.abs (a -. q'.(i))) q) in
      if distance p.trans p'.trans > 1e-6 || angle_between p.rot p'.rot > 1e-6 then
        Error ("pose differs: " ^ show_q q')
      else if c <> c' then Error ("another confdata: " ^ show_q q')
      else if r.axes.(4).a = 0. && dq > 1e-6 then Error (Printf.sprintf "axes differ by %g: %s" dq (show_q q'))
      else Ok q'

(* Axis angles away from the singularities of the arm's structure, where FK then IK is a
   function: the wrist (axis 5 near 0), the elbow stretched, the wrist centre over axis 1, and a
   quadrant's edge of a present axis 1, 4 or 6 (where a confdata is not read back). *)
let regular k q =
  let r = Kinematics.robot k in
  let ax = r.axes in
  let edges = List.for_all (fun i -> not (Robot.present r (i + 1)) || Float.abs (Float.rem (Float.abs q.(i)) 90.) > 1e-6)
      [ 0; 3; 5 ] in
  edges &&
  match r.structure with
  | Robot.Delta ->
      (* away from an arm in line with its rod, where its two solutions meet *)
      let f = Kinematics.forward k q in
      let rr = ax.(3).a and l = ax.(0).a in
      let plate = { f.trans with z = f.trans.z +. ax.(3).d } in
      (not (Float.is_nan f.trans.x))
      && List.for_all (fun i ->
          let phi = rad (120. *. float_of_int i) and t = rad q.(i) in
          let dir = { x = cos phi; y = sin phi; z = 0. } in
          let shoulder = scale rr dir in
          let elbow = add shoulder (add (scale (l *. cos t) dir) { x = 0.; y = 0.; z = -. l *. sin t }) in
          (* the rod as seen in the arm's plane: the two solutions meet where it is in line with
             the upper arm *)
          let normal = { x = -. sin phi; y = cos phi; z = 0. } in
          let v = sub plate elbow in
          let v = sub v (scale (dot v normal) normal) in
          let u = sub elbow shoulder in
          (* and the elbow outside the line from the shoulder to the plate, as the arm is built *)
          let w = sub plate shoulder in
          let w = sub w (scale (dot w normal) normal) in
          dot (cross w u) normal < 0.
          && norm (cross u v) /. (norm u *. norm v) > 0.1) [ 0; 1; 2 ]
  | Robot.Palletiser ->
      let t2 = rad q.(1) and t3 = rad q.(2) in
      let f = Kinematics.forward k q in
      Float.abs (cos (t2 -. t3)) > 0.02 && Float.hypot f.trans.x f.trans.y > 5.
  | Robot.Scara ->
      (* the two arms in line (stretched or folded): the two elbows meet *)
      Float.abs (sin (rad q.(1))) > 0.02
  | Robot.Serial | Robot.Coupled_axis3 ->
      let q3 = if r.structure = Robot.Coupled_axis3 then q.(2) -. q.(1) else q.(2) in
      let t3 = rad (q3 +. ax.(2).offset) and ps = atan2 ax.(3).d ax.(2).a in
      let w = wrist k r q in
      (* an offset wrist's search may miss one of two solutions that merge near the wrist
         singularity (doc/rulings.md R-structure-offset): 20 degrees from it *)
      let zone = if ax.(4).a <> 0. then 20. else 2. in
      (not (Kinematics.wrist_singular ~zone k q)) && Float.abs (sin (t3 +. ps)) > 0.02
      && sqrt ((w.x *. w.x) +. (w.y *. w.y)) > 5.

(* FK then IK with the confdata of the angles gives the angles back, for every arm, on random
   axis angles within the ranges away from the singularities (as test_motion's K-inverse); at
   least 200 of the 500 are regular, so that no arm passes on discarded cases alone. *)
let round_trip () =
  List.iteri (fun i (n, (r : Robot.t)) ->
      let k = Kinematics.create r in
      let ax = r.axes in
      let gen = QCheck.Gen.(map (fun us -> Array.mapi (fun i u -> ax.(i).min +. u *. (ax.(i).max -. ax.(i).min)) us)
                              (array_repeat 6 (float_bound_inclusive 1.))) in
      let tried = ref 0 in
      QCheck.Test.check_exn ~rand:(Random.State.make [| 17 + i |])
        (QCheck.Test.make ~count:500 ~name:(n ^ ": forward then inverse") (QCheck.make ~print:show_q gen) (fun q ->
             QCheck.assume (regular k q);
             incr tried;
             match fk_ik k q with Ok _ -> true | Error m -> QCheck.Test.fail_reportf "%s" m));
      if !tried < 200 then Alcotest.failf "%s: only %d regular cases of 500" n !tried)
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
  let err extra expect = refused_description ~file:"r.robot" (base ^ extra) expect in
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
      | Robot.Serial | Robot.Scara ->
          (* a SCARA's axis 2 turns the outer arm and the flange with it *)
          if Float.abs (turned -. rad 25.) > 1e-9 then Alcotest.failf "%s: turned %g" n turned
      | Robot.Palletiser | Robot.Delta -> if turned > 1e-9 then Alcotest.failf "%s: the flange turned %g" n turned)
    (robots ());
  Alcotest.(check bool) "the IRB 2400 is coupled" true
    ((get "2400" (Robot_library.find "irb2400-10-1.5")).structure = Robot.Coupled_axis3);
  Alcotest.(check bool) "the IRB 4600 is not" true
    ((get "4600" (Robot_library.find "irb4600-40-2.55")).structure = Robot.Serial);
  let base = Robot.irb120_text in
  let err extra expect = refused_description ~file:"r.robot" (base ^ extra) expect in
  let line = List.length (String.split_on_char '\n' base) in
  err "structure delta-ish\n" (Printf.sprintf
    "r.robot:%d:11: robot description error: structure: expected serial, coupled-axis3, palletiser, delta or scara, found \"delta-ish\"" line);
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
  let err t expect = refused_description ~file:"p.robot" t expect in
  let replace a b = Str.global_replace (Str.regexp_string a) b text in
  err (replace "axis 6   260" "axis 4 0 0 0 0 -1 1 1\naxis 6   260")
    "p.robot:17:1: robot description error: axis 4: a palletiser has no axis 4 (its axes are 1, 2, 3 and 6)";
  err (replace "axis 2   1280    0" "axis 2   1280    5")
    "p.robot:15:1: robot description error: axis 2: a palletiser's alpha and offset must be 0 (doc/motion.md)";
  err (replace "axis 6   260     0     247      0     -300 300      300\n" "")
    "p.robot:20:1: robot description error: axis 6 is missing"

(* structure delta: axes 1 to 4, three equal arms; its description's errors. *)
let delta () =
  let r = get "360" (Robot_library.find "ROB1_360_1.13_1") in
  Alcotest.(check bool) "axes" true
    (List.map (Robot.present r) [ 1; 2; 3; 4; 5; 6 ] = [ true; true; true; true; false; false ]);
  let k = Kinematics.create r in
  let q = [| 20.; 30.; 40.; 75.; 0.; 0. |] in
  let c = Kinematics.conf_of k q in
  Alcotest.(check int) "cf4: axis 4's quadrant" 0 c.cf4;
  (match Kinematics.inverse k (Kinematics.forward k q) (With_conf { c with cf1 = 2; cf6 = -1; cfx = 7 }) with
   | Ok q' -> Alcotest.(check (float 1e-6)) "cf1, cf6 and cfx say nothing" q.(2) q'.(2)
   | Error e -> Alcotest.failf "with conf: %s" (Motion_error.name e));
  let text = Option.get (Robot_library.text "irb360-1-1.13") in
  let err t expect = refused_description ~file:"d.robot" t expect in
  let replace a b = Str.global_replace (Str.regexp_string a) b text in
  err (replace "axis 2   290     0     800" "axis 2   291     0     800")
    "d.robot:14:1: robot description error: axis 2: a delta's three arms have axis 1's a and d";
  err (replace "max_tcp_speed" "axis 5 0 0 0 0 -1 1 1\nmax_tcp_speed")
    "d.robot:17:1: robot description error: axis 5: a delta has no axis 5 (its axes are 1 to 4)"

(* structure scara: axes 1 to 4, axis 3 linear (mm, never a turn of 360), the flange level; a
   known pose, the two elbows by cfx, a height beyond the stroke refused; its description's errors. *)
let scara () =
  let r = get "910SC" (Robot_library.find "ROB1_910SC_0.55_3") in
  Alcotest.(check bool) "axes" true
    (List.map (Robot.present r) [ 1; 2; 3; 4; 5; 6 ] = [ true; true; true; true; false; false ]);
  let k = Kinematics.create r in
  (* axis 1 at 90 and axis 2 at -90: the inner arm along y, the outer arm back along x *)
  let p = Kinematics.forward k [| 90.; -90.; -50.; 30.; 0.; 0. |] in
  Alcotest.(check (list (float 1e-9))) "a known pose" [ 250.; 300.; 150. ] [ p.trans.x; p.trans.y; p.trans.z ];
  let c = Kinematics.conf_of k [| 90.; -90.; -50.; 30.; 0.; 0. |] in
  Alcotest.(check int) "cfx: axis 2 negative" 2 c.cfx;
  (match Kinematics.inverse k p (With_conf { c with cfx = 0 }) with
   | Ok q -> Alcotest.(check (float 1e-6)) "the other elbow" 90. q.(1)
   | Error e -> Alcotest.failf "the other elbow: %s" (Motion_error.name e));
  (match fk_ik k [| 90.; -90.; -50.; 30.; 0.; 0. |] with
   | Ok _ -> () | Error m -> Alcotest.fail m);
  let high = { p with trans = { p.trans with z = p.trans.z +. 51. } } in
  (match Kinematics.inverse k high (Nearest (Array.make 6 0.)) with
   | Error (Motion_error.Joint_out_of_range 3) -> ()
   | Error e -> Alcotest.failf "above the stroke: %s" (Motion_error.name e)
   | Ok q -> Alcotest.failf "above the stroke reached: %s" (show_q q));
  let low = { p with trans = { p.trans with z = p.trans.z -. 131. } } in
  (match Kinematics.inverse k low (Nearest (Array.make 6 0.)) with
   | Error (Motion_error.Joint_out_of_range 3) -> ()
   | Error e -> Alcotest.failf "below the stroke: %s" (Motion_error.name e)
   | Ok q -> Alcotest.failf "below the stroke reached (a turn of a linear axis?): %s" (show_q q));
  let tilted = { p with rot = omult p.rot (of_axis_angle { x = 1.; y = 0.; z = 0. } (rad 2.)) } in
  (match Kinematics.inverse k tilted (Nearest (Array.make 6 0.)) with
   | Error Motion_error.Out_of_reach -> ()
   | Error e -> Alcotest.failf "tilted: %s" (Motion_error.name e)
   | Ok _ -> Alcotest.fail "a tilted flange reached");
  let text = Option.get (Robot_library.text "irb910sc-3-0.55") in
  let replace a b = Str.global_replace (Str.regexp_string a) b text in
  let line_of w =
    let lines = String.split_on_char '\n' text in
    let rec go i = function [] -> 0 | l :: rest -> if String.starts_with ~prefix:w l then i else go (i + 1) rest in
    go 1 lines in
  refused_description ~file:"s.robot" (replace "axis 3     0     0       0" "axis 3     0     0      10")
    (Printf.sprintf "s.robot:%d:1: robot description error: axis 3: a SCARA's d must be 0 (axis 1's d is the height)"
       (line_of "axis 3 "));
  refused_description ~file:"s.robot" (replace "axis 2   250" "axis 2   0")
    (Printf.sprintf "s.robot:%d:1: robot description error: axis 2: a SCARA's arm length a must be positive"
       (line_of "axis 2 "));
  refused_description ~file:"s.robot" (replace "max_tcp_speed 6000" "axis 6 0 0 0 0 -1 1 1\nmax_tcp_speed 6000")
    (Printf.sprintf "s.robot:%d:1: robot description error: axis 6: a SCARA has no axis 6 (its axes are 1 to 4)"
       (line_of "max_tcp_speed 6000"))

let suite =
  ( "robot library",
    [ Alcotest.test_case "every description parses and is found by its robot type" `Quick all_parse;
      Alcotest.test_case "MOC.cfg robot types, names and their errors" `Quick by_moc_type;
      Alcotest.test_case "the robot types of the controller backups" `Quick backup_types;
      Alcotest.test_case "calibration position and reach of every arm" `Quick calibration_and_reach;
      Alcotest.test_case "FK then IK of every arm (QCheck)" `Quick round_trip;
      Alcotest.test_case "an axis beyond its range is refused" `Quick limits_refused;
      Alcotest.test_case "the reach line" `Quick reach_line;
      Alcotest.test_case "structure coupled-axis3" `Quick coupled_axis3;
      Alcotest.test_case "structure palletiser" `Quick palletiser;
      Alcotest.test_case "structure delta" `Quick delta;
      Alcotest.test_case "structure scara" `Quick scara ] )
