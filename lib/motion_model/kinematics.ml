open Geom

type conf = { cf1 : int; cf4 : int; cf6 : int; cfx : int }

type error = Motion_error.t

open Motion_error

type t = {
  robot : Robot.t;
  acc : Gsl.Matrix.matrix;
  link : Gsl.Matrix.matrix;
  tmp : Gsl.Matrix.matrix;
}

let create robot =
  let m () = Gsl.Matrix.create ~init:0. 4 4 in
  { robot; acc = m (); link = m (); tmp = m () }

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
  | Serial -> q
  | Coupled_axis3 -> let c = Array.copy q in c.(2) <- q.(2) -. q.(1); c

let of_chain (r : Robot.t) c =
  match r.structure with
  | Serial -> c
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

let forward k q =
  chain k 6 q;
  let g = Gsl.Matrix.get k.acc in
  { trans = { x = g 0 3; y = g 1 3; z = g 2 3 }; rot = of_matrix (rotation_of k.acc) }

(* An angle a rounding error below a quadrant's edge (axis 4 at -1e-14 degrees for 0) is on the
   edge: the quadrant of a computed 0 is 0, as the programmed one is. *)
let quadrant a = int_of_float (Float.floor ((a +. 1e-9) /. 90.))


let singular_zone = 1.0

let wrist_singular ?(zone = singular_zone) k q =
  let t5 = rad (q.(4) +. k.robot.axes.(4).offset) in
  Float.abs (sin t5) < sin (rad zone)

type choice = With_conf of conf | Nearest of float array

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

let solutions ?arm k (p : pose) ~t4_hint =
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
      if Float.abs c <= 1. +. 1e-12 then
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

(* Each axis at a turn within its range nearest to its target, or the first axis that has none. *)
let place (r : Robot.t) raw targets =
  let q = Array.make 6 0. in
  let bad = ref 0 in
  for i = 5 downto 0 do
    let c = representative r.axes.(i) raw.angles.(i) targets.(i) in
    if Float.is_nan c then bad := i + 1 else q.(i) <- c
  done;
  if !bad = 0 then Ok q else Error (Joint_out_of_range !bad)

(* The arm configuration (wrist centre behind axis 1, behind the lower arm) of axis angles,
   from the planar geometry of axes 2 and 3 alone. *)
let arm_of k q =
  let q = to_chain k.robot q in
  let ax = k.robot.axes in
  let t2 = rad (q.(1) +. ax.(1).offset) and t3 = rad (q.(2) +. ax.(2).offset) in
  let a3 = ax.(2).a and d4 = ax.(3).d in
  let l3 = sqrt (a3 *. a3 +. d4 *. d4) and ps = atan2 d4 a3 in
  let radial = ax.(0).a +. ax.(1).a *. cos t2 +. l3 *. cos (t2 +. t3 +. ps) in
  (radial < 0., sin (t3 +. ps) < 0.)

let conf_of k q =
  let behind, elbow = arm_of k q in
  let cfx = (if behind then 4 else 0) + (if elbow then 2 else 0) + (if q.(4) < 0. then 1 else 0) in
  { cf1 = quadrant q.(0); cf4 = quadrant q.(3); cf6 = quadrant q.(5); cfx }

let nearest_of (r : Robot.t) sols q0 =
  let dist q = let d = ref 0. in
    for i = 0 to 5 do let e = q.(i) -. q0.(i) in d := !d +. e *. e done; !d in
  List.fold_left (fun acc s -> match acc, place r s q0 with
      | Ok a, (Ok b as x) -> if dist b < dist a then x else acc
      | Error _, (Ok _ as x) -> x
      | Ok _, Error _ -> acc
      | Error _, (Error _ as x) -> (match acc with Error (Joint_out_of_range _) -> acc | _ -> x))
    (Error Out_of_reach) sols

let inverse k p choice =
  let r = k.robot in
  match choice with
  | With_conf c ->
      let mid cf = float_of_int cf *. 90. +. 45. in
      let hint = [| mid c.cf1; 0.; 0.; mid c.cf4; 0.; mid c.cf6 |] in
      (* Only the arm configuration cfx names is solved; the others only to tell an
         unreachable position from a configuration it cannot be reached in. *)
      let arm = (c.cfx land 4 <> 0, c.cfx land 2 <> 0) in
      (match List.find_opt (fun s -> s.raw_cfx = c.cfx) (solutions ~arm k p ~t4_hint:hint) with
       | Some s -> place r s hint
       | None -> if solutions k p ~t4_hint:hint = [] then Error Out_of_reach else Error Configuration_error)
  | Nearest q0 ->
      (* A path keeps its arm configuration: the reference's is tried first, alone. *)
      match nearest_of r (solutions ~arm:(arm_of k q0) k p ~t4_hint:q0) q0 with
      | Ok _ as ok -> ok
      | Error _ -> nearest_of r (solutions k p ~t4_hint:q0) q0
