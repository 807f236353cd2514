open Geom

type conf = { cf1 : int; cf4 : int; cf6 : int; cfx : int }

type error = Motion_error.t

open Motion_error

type choice = With_conf of conf | Nearest of float array

(* The last answers of [forward] and [inverse], by their exact arguments: a program that passes
   the same points again (a loop, a cycle of targets) does not solve them again. Both are
   functions of their arguments alone (the matrices are a workspace), so an answer found here is
   the one computing would give, to the bit. *)
let memo_size = 8

type t = {
  robot : Robot.t;
  acc : Gsl.Matrix.matrix;
  link : Gsl.Matrix.matrix;
  tmp : Gsl.Matrix.matrix;
  forwards : (float array * pose) option array;
  mutable forward_next : int;
  inverses : (pose * choice * (float array, error) result) option array;
  mutable inverse_next : int;
}

let create robot =
  let m () = Gsl.Matrix.create ~init:0. 4 4 in
  { robot; acc = m (); link = m (); tmp = m (); forwards = Array.make memo_size None; forward_next = 0;
    inverses = Array.make memo_size None; inverse_next = 0 }

(* Equal to the bit for the answer's sake: a NaN is never found (it is computed again), and 0
   and -0 differ. *)
(* Inlined: called apart, each comparison boxes both floats (a memo look-up compares seven
   components with each of eight slots, twice a move). *)
let same_float (a : float) b = a = b && (a <> 0. || 1. /. a = 1. /. b) [@@inline]

let same_floats a b =
  let n = Array.length a in
  n = Array.length b && (let rec go i = i >= n || (same_float a.(i) b.(i) && go (i + 1)) in go 0)

let same_pose (a : pose) (b : pose) =
  same_float a.trans.x b.trans.x && same_float a.trans.y b.trans.y && same_float a.trans.z b.trans.z
  && same_float a.rot.q1 b.rot.q1 && same_float a.rot.q2 b.rot.q2 && same_float a.rot.q3 b.rot.q3
  && same_float a.rot.q4 b.rot.q4

let same_choice a b = match a, b with
  | With_conf c, With_conf d -> c.cf1 = d.cf1 && c.cf4 = d.cf4 && c.cf6 = d.cf6 && c.cfx = d.cfx
  | Nearest q, Nearest r -> same_floats q r
  | _ -> false

let memo_find slots found =
  let rec go i = if i >= memo_size then None else match slots.(i) with
      | Some e -> (match found e with Some _ as r -> r | None -> go (i + 1))
      | None -> None in
  go 0

(* [memo_find] for the inverse's slots without a closure and an option per slot looked at. *)
let inverse_find slots p choice =
  let rec go i = if i >= memo_size then None else match slots.(i) with
      | Some (p', c', q) -> if same_pose p p' && same_choice choice c' then Some q else go (i + 1)
      | None -> None in
  go 0

let robot k = k.robot

(* The standard DH transform of one link: Rz(theta) · Tz(d) · Tx(a) · Rx(alpha). *)
let set_link m (ax : Robot.axis) theta =
  let ct = cos theta and st = sin theta in
  let al = rad ax.alpha in
  let ca = cos al and sa = sin al in
  let s = Gsl.Matrix.set m in
  s 0 0 ct; s 0 1 (-. st *. ca); s 0 2 (st *. sa); s 0 3 (ax.a *. ct);
  s 1 0 st; s 1 1 (ct *. ca); s 1 2 (-. ct *. sa); s 1 3 (ax.a *. st);
  s 2 0 0.; s 2 1 sa; s 2 2 ca; s 2 3 ax.d;
  s 3 0 0.; s 3 1 0.; s 3 2 0.; s 3 3 1.

(* The DH chain's joint angles of axis angles, and back: on a parallel arm axis 3 is the upper
   arm's attitude, and joint 3 its angle against the lower arm (doc/motion.md R-structure). *)
let to_chain (r : Robot.t) q =
  match r.structure with
  | Serial | Palletiser | Delta | Scara -> q
  | Coupled_axis3 -> let c = Array.copy q in c.(2) <- q.(2) -. q.(1); c

let of_chain (r : Robot.t) c =
  match r.structure with
  | Serial | Palletiser | Delta | Scara -> c
  | Coupled_axis3 -> let q = Array.copy c in q.(2) <- c.(2) +. c.(1); q

(* The transform of the first [n] links into k.acc. *)
let chain k n q =
  let q = to_chain k.robot q in
  let axes = k.robot.axes in
  set_link k.acc axes.(0) (rad (q.(0) +. axes.(0).offset));
  for i = 1 to n - 1 do
    set_link k.link axes.(i) (rad (q.(i) +. axes.(i).offset));
    Gsl.Blas.gemm ~ta:Gsl.Blas.NoTrans ~tb:Gsl.Blas.NoTrans ~alpha:1. ~a:k.acc ~b:k.link ~beta:0. ~c:k.tmp;
    Gsl.Matrix.memcpy ~src:k.tmp ~dst:k.acc
  done

let rotation_of m = Array.init 9 (fun i -> Gsl.Matrix.get m (i / 3) (i mod 3))

(* The palletiser (Robot.Palletiser, doc/motion.md R-structure), in closed form: in the arm's
   vertical plane the lower arm leans forward by axis 2 from the vertical, the upper arm's end is
   axis 3 below the horizontal, and the flange hangs level, ahead of and below it; tool0 points
   down, its x axis backwards at axes 1 and 6 at 0 (as an IRB 120's pointing down), and axis 6
   turns it about its own z. *)
let pal_dims (r : Robot.t) =
  let ax k = r.axes.(k - 1) in
  ((ax 1).a, (ax 1).d, (ax 2).a, (ax 3).a, (ax 6).a, (ax 6).d)

let level_down = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. }

let pal_rot t1 t6 = omult (of_axis_angle { x = 0.; y = 0.; z = 1. } (t1 -. t6)) level_down

(* Radial distance and height of the upper arm's end, the wrist. *)
let pal_wrist r q =
  let a1, d1, l2, l3, _, _ = pal_dims r in
  let t2 = rad q.(1) and t3 = rad q.(2) in
  (a1 +. (l2 *. sin t2) +. (l3 *. cos t3), d1 +. (l2 *. cos t2) -. (l3 *. sin t3))

let pal_forward r q =
  let _, _, _, _, a6, d6 = pal_dims r in
  let radial, z = pal_wrist r q in
  let radial = radial +. a6 and z = z -. d6 in
  let t1 = rad q.(0) in
  { trans = { x = radial *. cos t1; y = radial *. sin t1; z }; rot = pal_rot t1 (rad q.(5)) }

(* The arm configuration of a palletiser's axes: the wrist behind axis 1, and the elbow bent the
   other way (the upper arm turned from the lower arm clockwise rather than counter-clockwise, in
   the plane seen with the arm pointing right). *)
let pal_arm r q =
  let radial, _ = pal_wrist r q in
  let t2 = rad q.(1) and t3 = rad q.(2) in
  (radial < 0., -. cos (t2 -. t3) > 0.)

(* The delta (Robot.Delta, doc/motion.md R-structure): three arms at 0, 120 and 240 degrees
   about the base's z, each an upper arm turned by its axis (0 level, positive down) and a
   parallelogram rod to the travelling plate, which stays level; axis 4 turns the flange about
   its z. All in closed form: the plate is where three spheres about the elbows meet. *)
let delta_dims (r : Robot.t) =
  let ax k = r.axes.(k - 1) in
  ((ax 4).a, (ax 1).a, (ax 1).d, (ax 4).d)

let delta_azimuth i = rad (120. *. float_of_int i)

let delta_elbow r i theta =
  let rr, l, _, _ = delta_dims r in
  let radial = rr +. (l *. cos theta) and phi = delta_azimuth i in
  { x = radial *. cos phi; y = radial *. sin phi; z = -. l *. sin theta }

(* The plate's centre: the lower of the two points at the rods' length from the three elbows. *)
let delta_plate r q =
  let _, _, rod, _ = delta_dims r in
  let e = Array.init 3 (fun i -> delta_elbow r i (rad q.(i))) in
  let ex = sub e.(1) e.(0) in
  let d = norm ex in
  let ex = scale (1. /. d) ex in
  let t = sub e.(2) e.(0) in
  let i = dot ex t in
  let ey = sub t (scale i ex) in
  let j = norm ey in
  if d < 1e-9 || j < 1e-9 then None
  else
    let ey = scale (1. /. j) ey in
    let ez = cross ex ey in
    let x = d /. 2. in
    let y = ((i *. i) +. (j *. j) -. (2. *. i *. x)) /. (2. *. j) in
    let zz = (rod *. rod) -. (x *. x) -. (y *. y) in
    if zz < 0. then None
    else
      let z = sqrt zz in
      let p1 = add e.(0) (add (scale x ex) (add (scale y ey) (scale z ez))) in
      let p2 = add e.(0) (add (scale x ex) (add (scale y ey) (scale (-. z) ez))) in
      Some (if p1.z < p2.z then p1 else p2)

let delta_rot t4 = omult (of_axis_angle { x = 0.; y = 0.; z = 1. } (-. t4)) level_down

let delta_forward r q =
  let _, _, _, drop = delta_dims r in
  match delta_plate r q with
  | Some p -> { trans = { p with z = p.z -. drop }; rot = delta_rot (rad q.(3)) }
  | None -> { trans = { x = nan; y = nan; z = nan }; rot = delta_rot (rad q.(3)) }

(* The SCARA (Robot.Scara, doc/rulings.md R-structure-scara), in closed form: the inner arm turned
   by axis 1 and the outer arm by axis 2 against it, about vertical axes; the quill at axis 1's d
   plus axis 3 (mm, positive up); the flange pointing down, as the palletiser's, turned about its
   z by axis 4. *)
let scara_dims (r : Robot.t) = (r.axes.(0).a, r.axes.(1).a, r.axes.(0).d)

let scara_forward r q =
  let l1, l2, d1 = scara_dims r in
  let t1 = rad q.(0) and t12 = rad (q.(0) +. q.(1)) in
  { trans = { x = (l1 *. cos t1) +. (l2 *. cos t12); y = (l1 *. sin t1) +. (l2 *. sin t12); z = d1 +. q.(2) };
    rot = pal_rot t12 (rad q.(3)) }

let forward_computed k q =
  if k.robot.structure = Robot.Scara then scara_forward k.robot q
  else if k.robot.structure = Robot.Delta then delta_forward k.robot q
  else if k.robot.structure = Robot.Palletiser then pal_forward k.robot q else begin
  chain k 6 q;
  let g = Gsl.Matrix.get k.acc in
  { trans = { x = g 0 3; y = g 1 3; z = g 2 3 }; rot = of_matrix (rotation_of k.acc) }
  end

let forward k q =
  match memo_find k.forwards (fun (q', f) -> if same_floats q q' then Some f else None) with
  | Some f -> f
  | None ->
      let f = forward_computed k q in
      k.forwards.(k.forward_next) <- Some (Array.copy q, f);
      k.forward_next <- (k.forward_next + 1) mod memo_size;
      f

(* An angle a rounding error below a quadrant's edge (axis 4 at -1e-14 degrees for 0) is on the
   edge: the quadrant of a computed 0 is 0, as the programmed one is. *)
let quadrant a = int_of_float (Float.floor ((a +. 1e-9) /. 90.))


let singular_zone = 1.0

let wrist_singular ?(zone = singular_zone) k q =
  k.robot.structure <> Robot.Palletiser && k.robot.structure <> Robot.Delta && k.robot.structure <> Robot.Scara &&
  let t5 = rad (q.(4) +. k.robot.axes.(4).offset) in
  Float.abs (sin t5) < sin (rad zone)

let pi = 4. *. atan 1.

(* Normalised to (-180, 180]. *)
let wrap a =
  let a = Float.rem a 360. in
  if a > 180. then a -. 360. else if a <= -180. then a +. 360. else a

(* The angle a + 360k within the axis range nearest to [target], if any. *)
let representative (ax : Robot.axis) a target =
  let within c = c >= ax.min -. 1e-9 && c <= ax.max +. 1e-9 in
  let clamp c = Float.min ax.max (Float.max ax.min c) in
  (* The turn nearest the target, else the next turn towards the range. *)
  let c = a +. 360. *. Float.round ((target -. a) /. 360.) in
  if within c then clamp c
  else
    let c1 = c +. 360. and c2 = c -. 360. in
    let d1 = Float.abs (c1 -. target) and d2 = Float.abs (c2 -. target) in
    match within c1, within c2 with
    | true, true -> clamp (if d1 <= d2 then c1 else c2)
    | true, false -> clamp c1
    | false, true -> clamp c2
    | false, false ->
        let a = wrap a in
        let r = ref nan in
        for k = -3 to 3 do
          let c = a +. 360. *. float_of_int k in
          if within c && (Float.is_nan !r || Float.abs (c -. target) < Float.abs (!r -. target)) then r := clamp c
        done;
        !r

(* The rotation of the first three links, in plain floats: the inverse needs it for every
   candidate, and it is three 3x3 products. *)
let dh_rot (ax : Robot.axis) theta =
  let ct = cos theta and st = sin theta in
  let al = rad ax.alpha in
  let ca = cos al and sa = sin al in
  [| ct; -. st *. ca; st *. sa; st; ct *. ca; -. ct *. sa; 0.; sa; ca |]

let mul3 a b =
  Array.init 9 (fun i -> let r = i / 3 and c = i mod 3 in
                 a.(3 * r) *. b.(c) +. a.(3 * r + 1) *. b.(3 + c) +. a.(3 * r + 2) *. b.(6 + c))

let r03_of k q =
  let ax = k.robot.axes in
  let r i = dh_rot ax.(i) (rad (q.(i) +. ax.(i).offset)) in
  mul3 (mul3 (r 0) (r 1)) (r 2)

(* A solution before the choice of turns: DH-free axis angles (degrees) and its cfx. *)
type raw = { angles : float array; raw_cfx : int }

(* [clamp]: an unreachable wrist centre is taken at the stretched or folded elbow nearest it, for
   the offset wrist's search, whose twin may just miss the reach near a solution. *)
let solutions ?(clamp = false) ?arm k (p : pose) ~t4_hint =
  let r = k.robot in
  let ax i = r.axes.(i) in
  let m = to_matrix p.rot in
  let z6 = { x = m.(2); y = m.(5); z = m.(8) } in
  let w = sub p.trans (scale (ax 5).d z6) in
  let rho = sqrt (w.x *. w.x +. w.y *. w.y) in
  let phi = if rho < 1e-9 then rad (t4_hint.(0) +. (ax 0).offset) else atan2 w.y w.x in
  let a2 = (ax 1).a and a3 = (ax 2).a and d4 = (ax 3).d in
  let l3 = sqrt (a3 *. a3 +. d4 *. d4) and ps = atan2 d4 a3 in
  let out = ref [] in
  List.iter (fun behind ->
      if (match arm with Some (b, _) -> b = behind | None -> true) then
      let t1 = if behind then phi +. pi else phi in
      let radial = if behind then -. rho else rho in
      let x = radial -. (ax 0).a and y = -. (w.z -. (ax 0).d) in
      let c = (x *. x +. y *. y -. a2 *. a2 -. l3 *. l3) /. (2. *. a2 *. l3) in
      if clamp || Float.abs c <= 1. +. 1e-12 then
        let c = Float.max (-1.) (Float.min 1. c) in
        List.iter (fun elbow ->
            if (match arm with Some (_, e) -> e = elbow | None -> true) then
            let beta = if elbow then -. acos c else acos c in
            let t3 = beta -. ps in
            let t2 = atan2 y x -. atan2 (l3 *. sin beta) (a2 +. l3 *. cos beta) in
            let q3 = [| deg t1 -. (ax 0).offset; deg t2 -. (ax 1).offset; deg t3 -. (ax 2).offset; 0.; 0.; 0. |] in
            let r03 = r03_of k q3 in
            (* R36 = R03^T R06 = Rz(t4) Ry(-t5) Rz(t6) for the twists 90, -90, 0. *)
            let r36 i j = r03.(i) *. m.(j) +. r03.(3 + i) *. m.(3 + j) +. r03.(6 + i) *. m.(6 + j) in
            let sb = Float.hypot (r36 0 2) (r36 1 2) in
            List.iter (fun flip ->
                let t4, t5, t6 =
                  if sb < 1e-9 then
                    let sum = atan2 (r36 1 0) (r36 0 0) in
                    let t4 = rad (t4_hint.(3) +. (ax 3).offset) in
                    let b = if r36 2 2 > 0. then 0. else pi in
                    (t4, -. b, if b = 0. then sum -. t4 else t4 -. sum)
                  else
                    let b = if flip then -. atan2 sb (r36 2 2) else atan2 sb (r36 2 2) in
                    let sb' = sin b in
                    let a = atan2 (r36 1 2 /. sb') (r36 0 2 /. sb') in
                    let c = atan2 (r36 2 1 /. sb') (-. r36 2 0 /. sb') in
                    (a, -. b, c)
                in
                let q = [| q3.(0); q3.(1); q3.(2); deg t4 -. (ax 3).offset; deg t5 -. (ax 4).offset;
                           deg t6 -. (ax 5).offset |] in
                let q = Array.map wrap (of_chain r q) in
                let cfx = (if behind then 4 else 0) + (if elbow then 2 else 0)
                          + (if q.(4) < 0. then 1 else 0) in
                out := { angles = q; raw_cfx = cfx } :: !out)
              (if sb < 1e-9 then [ false ] else [ false; true ]))
          [ false; true ])
    [ false; true ];
  List.rev !out

(* A palletiser's solutions: its flange must hang level, tool0's z down within [level_tolerance];
   two elbows, and the wrist ahead of or behind axis 1. *)
let level_tolerance = 1.0

let pal_solutions (r : Robot.t) (p : pose) ~t1_hint =
  let a1, d1, l2, l3, a6, d6 = pal_dims r in
  let m = to_matrix p.rot in
  (* tool0's z in the base frame is the matrix's third column; down is [0, 0, -1] *)
  if -. m.(8) < cos (rad level_tolerance) then []
  else
    let psi = atan2 (-. m.(3)) (-. m.(0)) in
    let rho = Float.hypot p.trans.x p.trans.y in
    let phi = if rho < 1e-9 then rad t1_hint else atan2 p.trans.y p.trans.x in
    let out = ref [] in
    List.iter (fun behind ->
        let t1 = if behind then phi +. pi else phi in
        let radial = if behind then -. rho else rho in
        (* the wrist relative to axis 2, in the arm's plane *)
        let x = radial -. a6 -. a1 and y = p.trans.z +. d6 -. d1 in
        let dist = Float.hypot x y in
        if dist > 1e-9 then begin
          let kk = ((dist *. dist) +. (l2 *. l2) -. (l3 *. l3)) /. (2. *. l2 *. dist) in
          if Float.abs kk <= 1. +. 1e-12 then
            let kk = Float.max (-1.) (Float.min 1. kk) in
            let beta = atan2 y x in
            List.iter (fun t2s ->
                let t2 = t2s -. beta in
                let ex = l2 *. sin t2 and ey = l2 *. cos t2 in
                let t3 = atan2 (ey -. y) (x -. ex) in
                let q = Array.map wrap [| deg t1; deg t2; deg t3; 0.; 0.; deg (t1 -. psi) |] in
                let behind', elbow = pal_arm r q in
                let cfx = (if behind' then 4 else 0) + if elbow then 2 else 0 in
                out := { angles = q; raw_cfx = cfx } :: !out)
              [ asin kk; pi -. asin kk ]
        end)
      [ false; true ];
    List.rev !out

(* Each arm's angle for a plate centre: the elbow outwards. *)
let delta_solution (r : Robot.t) (p : pose) ~t4_hint =
  let rr, l, rod, drop = delta_dims r in
  let m = to_matrix p.rot in
  if -. m.(8) < cos (rad level_tolerance) then None
  else
    let psi = atan2 (-. m.(3)) (-. m.(0)) in
    let c = { p.trans with z = p.trans.z +. drop } in
    let angle i =
      let phi = delta_azimuth i in
      let x' = (c.x *. cos phi) +. (c.y *. sin phi) and y' = (-. c.x *. sin phi) +. (c.y *. cos phi) in
      let a = 2. *. l *. (rr -. x') and b = 2. *. l *. c.z in
      let k = (rod *. rod) -. (rr *. rr) -. (l *. l) -. (x' *. x') -. (y' *. y') -. (c.z *. c.z) +. (2. *. rr *. x') in
      let n = Float.hypot a b in
      if n < 1e-9 || Float.abs (k /. n) > 1. then None
      else
        let base = atan2 b a and w = acos (k /. n) in
        let t1 = base +. w and t2 = base -. w in
        (* the two elbows are mirror images across the line from the shoulder to the plate (in
           the arm's plane: radial, height): the one outside it *)
        let outside t = ((x' -. rr) *. (-. l *. sin t)) -. (c.z *. l *. cos t) in
        Some (if outside t1 >= outside t2 then t1 else t2) in
    match angle 0, angle 1, angle 2 with
    | Some a, Some b, Some c ->
        (* axis 4 turns the flange about its z, down: the base's z the other way *)
        let t4 = -. psi in
        let q4 = deg t4 in
        let q4 = q4 +. (360. *. Float.round ((t4_hint -. q4) /. 360.)) in
        Some { angles = [| wrap (deg a); wrap (deg b); wrap (deg c); q4; 0.; 0. |]; raw_cfx = 0 }
    | _ -> None

(* A SCARA's solutions: the flange level as the palletiser's; two elbows (axis 2 positive or
   negative), cfx's bit 2 the negative one (doc/rulings.md R-structure-scara). *)
let scara_solutions (r : Robot.t) (p : pose) =
  let l1, l2, d1 = scara_dims r in
  let m = to_matrix p.rot in
  if -. m.(8) < cos (rad level_tolerance) then []
  else
    let psi = atan2 (-. m.(3)) (-. m.(0)) in
    let x = p.trans.x and y = p.trans.y in
    let c2 = ((x *. x) +. (y *. y) -. (l1 *. l1) -. (l2 *. l2)) /. (2. *. l1 *. l2) in
    if Float.abs c2 > 1. +. 1e-12 then []
    else
      let c2 = Float.max (-1.) (Float.min 1. c2) in
      List.map (fun negative ->
          let t2 = if negative then -. acos c2 else acos c2 in
          let t1 = atan2 y x -. atan2 (l2 *. sin t2) (l1 +. (l2 *. cos t2)) in
          let q = [| wrap (deg t1); wrap (deg t2); p.trans.z -. d1; wrap (deg (t1 +. t2 -. psi)); 0.; 0. |] in
          { angles = q; raw_cfx = (if q.(1) < 0. then 2 else 0) })
        [ false; true ]

(* Each axis at a turn within its range nearest to its target, or the first axis that has none;
   a SCARA's axis 3 is linear: no turns. *)
let place (r : Robot.t) raw targets =
  let q = Array.make 6 0. in
  let bad = ref 0 in
  for i = 5 downto 0 do
    let ax = r.axes.(i) in
    let c =
      if r.structure = Robot.Scara && i = 2 then
        (let a = raw.angles.(i) in
         if a >= ax.min -. 1e-9 && a <= ax.max +. 1e-9 then Float.min ax.max (Float.max ax.min a) else nan)
      else representative ax raw.angles.(i) targets.(i) in
    if Float.is_nan c then bad := i + 1 else q.(i) <- c
  done;
  if !bad = 0 then Ok q else Error (Joint_out_of_range !bad)

(* The arm configuration (wrist centre behind axis 1, behind the lower arm) of axis angles,
   from the planar geometry of axes 2 and 3 alone. *)
let arm_of k q =
  if k.robot.structure = Robot.Delta then (false, false)
  else if k.robot.structure = Robot.Scara then (false, q.(1) < 0.)
  else if k.robot.structure = Robot.Palletiser then pal_arm k.robot q else
  let q = to_chain k.robot q in
  let ax = k.robot.axes in
  let t2 = rad (q.(1) +. ax.(1).offset) and t3 = rad (q.(2) +. ax.(2).offset) in
  let a3 = ax.(2).a and d4 = ax.(3).d in
  let l3 = sqrt (a3 *. a3 +. d4 *. d4) and ps = atan2 d4 a3 in
  let radial = ax.(0).a +. ax.(1).a *. cos t2 +. l3 *. cos (t2 +. t3 +. ps) in
  (radial < 0., sin (t3 +. ps) < 0.)

let conf_of k q =
  if k.robot.structure = Robot.Delta then { cf1 = 0; cf4 = quadrant q.(3); cf6 = 0; cfx = 0 }
  else if k.robot.structure = Robot.Scara then
    { cf1 = quadrant q.(0); cf4 = quadrant q.(3); cf6 = 0; cfx = if q.(1) < 0. then 2 else 0 } else
  let behind, elbow = arm_of k q in
  let wrist = k.robot.structure <> Robot.Palletiser && q.(4) < 0. in
  let cfx = (if behind then 4 else 0) + (if elbow then 2 else 0) + (if wrist then 1 else 0) in
  { cf1 = quadrant q.(0); cf4 = quadrant q.(3); cf6 = quadrant q.(5); cfx }

(* An offset wrist (axis 5's a not 0: the CRB 15000), solved numerically: the analytic solutions
   of its spherical twin (the same arm with a5 = 0) seed a Newton iteration on the arm's own
   forward kinematics (doc/motion.md R-structure). *)
let newton_iterations = 60

(* The pose error of [q] to [p]: position (mm) and orientation (rotation vector, rad). *)
let pose_error k (p : pose) q =
  let f = forward k q in
  let dp = sub p.trans f.trans in
  let dq = omult p.rot (conj f.rot) in
  let dq = if dq.q1 < 0. then { q1 = -. dq.q1; q2 = -. dq.q2; q3 = -. dq.q3; q4 = -. dq.q4 } else dq in
  let s = Float.sqrt ((dq.q2 *. dq.q2) +. (dq.q3 *. dq.q3) +. (dq.q4 *. dq.q4)) in
  let angle = 2. *. atan2 s dq.q1 in
  let w = if s < 1e-300 then { x = 0.; y = 0.; z = 0. }
    else scale (angle /. s) { x = dq.q2; y = dq.q3; z = dq.q4 } in
  [| dp.x; dp.y; dp.z; w.x; w.y; w.z |]

(* Gaussian elimination with partial pivoting of a 6x6 system; None when singular. *)
let solve6 a b =
  let n = 6 in
  let a = Array.map Array.copy a and b = Array.copy b in
  let ok = ref true in
  for c = 0 to n - 1 do
    if !ok then begin
      let p = ref c in
      for r = c + 1 to n - 1 do if Float.abs a.(r).(c) > Float.abs a.(!p).(c) then p := r done;
      if Float.abs a.(!p).(c) < 1e-12 then ok := false
      else begin
        let t = a.(c) in a.(c) <- a.(!p); a.(!p) <- t;
        let t = b.(c) in b.(c) <- b.(!p); b.(!p) <- t;
        for r = c + 1 to n - 1 do
          let f = a.(r).(c) /. a.(c).(c) in
          for j = c to n - 1 do a.(r).(j) <- a.(r).(j) -. (f *. a.(c).(j)) done;
          b.(r) <- b.(r) -. (f *. b.(c))
        done
      end
    end
  done;
  if not !ok then None
  else begin
    let x = Array.make n 0. in
    for r = n - 1 downto 0 do
      let s = ref b.(r) in
      for j = r + 1 to n - 1 do s := !s -. (a.(r).(j) *. x.(j)) done;
      x.(r) <- !s /. a.(r).(r)
    done;
    Some x
  end

(* Newton on the six axes (degrees): the Jacobian by central differences; converged when the
   flange is within 1e-9 mm and 1e-12 rad of the pose. *)
let refine k (p : pose) q0 =
  let q = Array.copy q0 in
  let h = 1e-6 in
  let rec go n =
    let e = pose_error k p q in
    let small = Float.abs e.(0) +. Float.abs e.(1) +. Float.abs e.(2) < 1e-9
                && Float.abs e.(3) +. Float.abs e.(4) +. Float.abs e.(5) < 1e-12 in
    if small then Some q
    else if n = 0 then None
    else
      let jac = Array.make_matrix 6 6 0. in
      for j = 0 to 5 do
        let qp = Array.copy q and qm = Array.copy q in
        qp.(j) <- q.(j) +. h; qm.(j) <- q.(j) -. h;
        let ep = pose_error k p qp and em = pose_error k p qm in
        (* e decreases as q moves towards the pose: d(error)/dq = -J *)
        for i = 0 to 5 do jac.(i).(j) <- (em.(i) -. ep.(i)) /. (2. *. h) done
      done;
      match solve6 jac e with
      | None -> None
      | Some dq ->
          let biggest = Array.fold_left (fun m d -> Float.max m (Float.abs d)) 0. dq in
          let s = if biggest > 20. then 20. /. biggest else 1. in
          Array.iteri (fun i d -> q.(i) <- q.(i) +. (s *. d)) dq;
          go (n - 1)
  in
  go newton_iterations

let offset_wrist (r : Robot.t) =
  (r.structure = Robot.Serial || r.structure = Robot.Coupled_axis3) && r.axes.(4).a <> 0.

(* An offset wrist's flange is its spherical twin's (the same arm with a5 = 0) moved by a5 along
   frame 5's x axis, which is the tool's x axis turned back by axis 6 about the tool's z. So for
   each axis 6 angle the twin solves the pose moved back by that, and a solution is an axis 6
   angle the twin gives back: the difference is scanned every 2 degrees on each of the twin's
   branches (its cfx), its zeros bisected, and Newton polishes. *)
let offset_solutions ?arm k (p : pose) ~t4_hint =
  let r = k.robot in
  let a5 = r.axes.(4).a and off6 = r.axes.(5).offset in
  let twin =
    create { r with axes = Array.mapi (fun i (a : Robot.axis) -> if i = 4 then { a with a = 0. } else a) r.axes } in
  let m = to_matrix p.rot in
  let x6 = { x = m.(0); y = m.(3); z = m.(6) } and y6 = { x = m.(1); y = m.(4); z = m.(7) } in
  let branch label q6 =
    let t = rad (q6 +. off6) in
    let x5 = sub (scale (cos t) x6) (scale (sin t) y6) in
    let moved = { p with trans = sub p.trans (scale a5 x5) } in
    match List.find_opt (fun s -> s.raw_cfx = label) (solutions ~clamp:true ?arm twin moved ~t4_hint) with
    | Some s -> Some (wrap (s.angles.(5) -. q6), s)
    | None -> None in
  let found = ref [] in
  let keep (s : raw) =
    match refine k p s.angles with
    | None -> ()
    | Some q ->
        let q = Array.map wrap q in
        let c = conf_of k q in
        let same o = Array.for_all2 (fun a b -> Float.abs (wrap (a -. b)) < 1e-6) o.angles q in
        if not (List.exists same !found) then found := { angles = q; raw_cfx = c.cfx } :: !found in
  let rec bisect label lo flo hi n =
    let mid = (lo +. hi) /. 2. in
    match branch label mid with
    | None -> None
    | Some (fm, s) ->
        if n = 0 || Float.abs fm < 1e-12 then Some s
        else if (fm < 0.) = (flo < 0.) then bisect label mid fm hi (n - 1)
        else bisect label lo flo mid (n - 1) in
  (* a sign change between two angles, the difference continuous there (no turn of 360 between
     them); where it changes fast the interval is halved, as a pair of roots may hide in it *)
  let rec scan label lo flo hi fhi depth =
    if Float.abs (fhi -. flo) < 180. then begin
      if depth > 0 && Float.abs (fhi -. flo) > 10. then
        let mid = (lo +. hi) /. 2. in
        match branch label mid with
        | Some (fm, _) -> scan label lo flo mid fm (depth - 1); scan label mid fm hi fhi (depth - 1)
        | None -> ()
      else if flo = 0. then Option.iter keep (Option.map snd (branch label lo))
      else if (flo < 0.) <> (fhi < 0.) then Option.iter keep (bisect label lo flo hi 60)
    end in
  let step = 2. in
  for label = 0 to 7 do
    let prev = ref None and before = ref None in
    for i = 0 to int_of_float (360. /. step) do
      let q6 = -180. +. (float_of_int i *. step) in
      let here = branch label q6 in
      (match !prev, here with
       | Some (lo, flo, _), Some (fhi, _) -> scan label lo flo q6 fhi 5
       | _ -> ());
      (* two roots close together (the arm near a singularity) may not change the sign between
         two steps: a small local minimum of the difference is a start for Newton *)
      (match !before, !prev, here with
       | Some fb, Some (_, fm, sm), Some (fh, _)
         when Float.abs fm < 2. && Float.abs fm <= Float.abs fb && Float.abs fm <= Float.abs fh -> keep sm
       | _ -> ());
      before := Option.map (fun (_, f, _) -> f) !prev;
      prev := Option.map (fun (f, s) -> (q6, f, s)) here
    done
  done;
  List.rev !found

let nearest_of (r : Robot.t) sols q0 =
  let dist q = let d = ref 0. in
    for i = 0 to 5 do let e = q.(i) -. q0.(i) in d := !d +. e *. e done; !d in
  List.fold_left (fun acc s -> match acc, place r s q0 with
      | Ok a, (Ok b as x) -> if dist b < dist a then x else acc
      | Error _, (Ok _ as x) -> x
      | Ok _, Error _ -> acc
      | Error _, (Error _ as x) -> (match acc with Error (Joint_out_of_range _) -> acc | _ -> x))
    (Error Out_of_reach) sols

(* What of a confdata the arm can use: a palletiser has no axes 4 and 5 (cf4 and cfx's axis 5 bit
   say nothing of it). *)
let significant k c =
  match k.robot.structure with
  | Robot.Palletiser -> { c with cf4 = 0; cfx = c.cfx land 6 }
  | Robot.Delta -> { cf1 = 0; cf4 = c.cf4; cf6 = 0; cfx = 0 }
  | Robot.Scara -> { c with cf6 = 0; cfx = c.cfx land 2 }
  | Robot.Serial | Robot.Coupled_axis3 -> c

let rec inverse k p choice =
  let copy = Result.map Array.copy in
  match inverse_find k.inverses p choice with
  | Some q -> copy q
  | None ->
      let choice_kept = match choice with Nearest q0 -> Nearest (Array.copy q0) | c -> c in
      let q = inverse_computed k p choice in
      k.inverses.(k.inverse_next) <- Some (p, choice_kept, copy q);
      k.inverse_next <- (k.inverse_next + 1) mod memo_size;
      q

and inverse_computed k p choice =
  let r = k.robot in
  let choice = match choice with With_conf c -> With_conf (significant k c) | n -> n in
  let solutions ?arm k p ~t4_hint =
    if r.structure = Robot.Delta then Option.to_list (delta_solution r p ~t4_hint:t4_hint.(3))
    else if r.structure = Robot.Scara then
      List.filter (fun s -> match arm with None -> true | Some (_, e) -> s.raw_cfx = if e then 2 else 0)
        (scara_solutions r p)
    else if offset_wrist r then offset_solutions ?arm k p ~t4_hint
    else if r.structure = Robot.Palletiser then
      List.filter (fun s -> match arm with
          | None -> true
          | Some (b, e) -> s.raw_cfx = (if b then 4 else 0) + if e then 2 else 0)
        (pal_solutions r p ~t1_hint:t4_hint.(0))
    else solutions ?arm k p ~t4_hint in
  match choice with
  | With_conf c ->
      let mid cf = float_of_int cf *. 90. +. 45. in
      let hint = [| mid c.cf1; 0.; 0.; mid c.cf4; 0.; mid c.cf6 |] in
      (* Only the arm configuration cfx names is solved; the others only to tell an
         unreachable position from a configuration it cannot be reached in. *)
      let arm = (c.cfx land 4 <> 0, c.cfx land 2 <> 0) in
      (* one solution per cfx on a spherical wrist; an offset wrist may have more: the one within
         the ranges nearest the quadrants' middles *)
      (match List.filter (fun s -> s.raw_cfx = c.cfx) (solutions ~arm k p ~t4_hint:hint) with
       | [ s ] -> place r s hint
       | _ :: _ as matching ->
           let quadrants (s : raw) = match place r s hint with
             | Ok q -> let c' = conf_of k q in c'.cf1 = c.cf1 && c'.cf4 = c.cf4 && c'.cf6 = c.cf6
             | Error _ -> false in
           (match List.filter quadrants matching with
            | [] -> nearest_of r matching hint
            | exact -> nearest_of r exact hint)
       | [] -> if solutions k p ~t4_hint:hint = [] then Error Out_of_reach else Error Configuration_error)
  | Nearest q0 when offset_wrist r && (match refine k p q0 with Some _ -> true | None -> false) ->
      (* a path's next point is near its last: Newton from there, in the reference's configuration *)
      let q = Array.map wrap (Option.get (refine k p q0)) in
      let raw = { angles = q; raw_cfx = (conf_of k q).cfx } in
      (match place r raw q0 with
       | Ok q' when arm_of k q' = arm_of k q0 -> Ok q'
       | _ -> nearest_of r (solutions k p ~t4_hint:q0) q0)
  | Nearest q0 ->
      (* A path keeps its arm configuration: the reference's is tried first, alone. *)
      match nearest_of r (solutions ~arm:(arm_of k q0) k p ~t4_hint:q0) q0 with
      | Ok _ as ok -> ok
      | Error _ -> nearest_of r (solutions k p ~t4_hint:q0) q0
