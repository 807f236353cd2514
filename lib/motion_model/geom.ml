type pos = Rapid_observable.Pose.pos = { x : float; y : float; z : float }
type orient = Rapid_observable.Pose.orient = { q1 : float; q2 : float; q3 : float; q4 : float }
type pose = Rapid_observable.Pose.t = { trans : pos; rot : orient }

let origin = { x = 0.; y = 0.; z = 0. }
let unit_orient = { q1 = 1.; q2 = 0.; q3 = 0.; q4 = 0. }
let identity = { trans = origin; rot = unit_orient }

let add a b = { x = a.x +. b.x; y = a.y +. b.y; z = a.z +. b.z }
let sub a b = { x = a.x -. b.x; y = a.y -. b.y; z = a.z -. b.z }
let scale k a = { x = k *. a.x; y = k *. a.y; z = k *. a.z }
let dot a b = a.x *. b.x +. a.y *. b.y +. a.z *. b.z
let cross a b =
  { x = a.y *. b.z -. a.z *. b.y; y = a.z *. b.x -. a.x *. b.z; z = a.x *. b.y -. a.y *. b.x }
let norm a = sqrt (dot a a)
let distance a b = norm (sub a b)
let lerp a b s = { x = a.x +. s *. (b.x -. a.x); y = a.y +. s *. (b.y -. a.y); z = a.z +. s *. (b.z -. a.z) }

let pi = 4. *. atan 1.
let deg r = r *. 180. /. pi
let rad d = d *. pi /. 180.

let omult a b =
  { q1 = a.q1 *. b.q1 -. a.q2 *. b.q2 -. a.q3 *. b.q3 -. a.q4 *. b.q4;
    q2 = a.q1 *. b.q2 +. a.q2 *. b.q1 +. a.q3 *. b.q4 -. a.q4 *. b.q3;
    q3 = a.q1 *. b.q3 -. a.q2 *. b.q4 +. a.q3 *. b.q1 +. a.q4 *. b.q2;
    q4 = a.q1 *. b.q4 +. a.q2 *. b.q3 -. a.q3 *. b.q2 +. a.q4 *. b.q1 }

let conj q = { q with q2 = -. q.q2; q3 = -. q.q3; q4 = -. q.q4 }

let odot a b = a.q1 *. b.q1 +. a.q2 *. b.q2 +. a.q3 *. b.q3 +. a.q4 *. b.q4

let normalize q =
  let n = sqrt (odot q q) in
  if n = 0. then unit_orient else { q1 = q.q1 /. n; q2 = q.q2 /. n; q3 = q.q3 /. n; q4 = q.q4 /. n }

(* v + 2 w × (w × v + s v), w the vector part: no matrix needed. *)
let rotate q v =
  (* add v (scale 2. (cross w t)), t = add (cross w v) (scale q.q1 v), the same operations in the
     same order on unboxed floats: no intermediate vector allocated (nine a move). *)
  let tx = (q.q3 *. v.z -. q.q4 *. v.y) +. q.q1 *. v.x
  and ty = (q.q4 *. v.x -. q.q2 *. v.z) +. q.q1 *. v.y
  and tz = (q.q2 *. v.y -. q.q3 *. v.x) +. q.q1 *. v.z in
  { x = v.x +. 2. *. (q.q3 *. tz -. q.q4 *. ty);
    y = v.y +. 2. *. (q.q4 *. tx -. q.q2 *. tz);
    z = v.z +. 2. *. (q.q2 *. ty -. q.q3 *. tx) }

let of_axis_angle axis a =
  let n = norm axis in
  if n = 0. then unit_orient
  else
    let s = sin (a /. 2.) /. n in
    { q1 = cos (a /. 2.); q2 = axis.x *. s; q3 = axis.y *. s; q4 = axis.z *. s }

let to_matrix q =
  let { q1 = w; q2 = x; q3 = y; q4 = z } = q in
  [| 1. -. 2. *. (y *. y +. z *. z); 2. *. (x *. y -. w *. z); 2. *. (x *. z +. w *. y);
     2. *. (x *. y +. w *. z); 1. -. 2. *. (x *. x +. z *. z); 2. *. (y *. z -. w *. x);
     2. *. (x *. z -. w *. y); 2. *. (y *. z +. w *. x); 1. -. 2. *. (x *. x +. y *. y) |]

(* Shepperd's method: divide by the largest of the four candidates, so no precision is lost
   near any rotation. *)
let of_matrix m =
  let r i j = m.(3 * i + j) in
  let tr = r 0 0 +. r 1 1 +. r 2 2 in
  let q =
    if tr > r 0 0 && tr > r 1 1 && tr > r 2 2 then
      let s = 2. *. sqrt (1. +. tr) in
      { q1 = s /. 4.; q2 = (r 2 1 -. r 1 2) /. s; q3 = (r 0 2 -. r 2 0) /. s; q4 = (r 1 0 -. r 0 1) /. s }
    else if r 0 0 >= r 1 1 && r 0 0 >= r 2 2 then
      let s = 2. *. sqrt (Float.max 0. (1. +. r 0 0 -. r 1 1 -. r 2 2)) in
      { q1 = (r 2 1 -. r 1 2) /. s; q2 = s /. 4.; q3 = (r 0 1 +. r 1 0) /. s; q4 = (r 0 2 +. r 2 0) /. s }
    else if r 1 1 >= r 2 2 then
      let s = 2. *. sqrt (Float.max 0. (1. +. r 1 1 -. r 0 0 -. r 2 2)) in
      { q1 = (r 0 2 -. r 2 0) /. s; q2 = (r 0 1 +. r 1 0) /. s; q3 = s /. 4.; q4 = (r 1 2 +. r 2 1) /. s }
    else
      let s = 2. *. sqrt (Float.max 0. (1. +. r 2 2 -. r 0 0 -. r 1 1)) in
      { q1 = (r 1 0 -. r 0 1) /. s; q2 = (r 0 2 +. r 2 0) /. s; q3 = (r 1 2 +. r 2 1) /. s; q4 = s /. 4. }
  in
  let q = normalize q in
  (* One sign for each orientation: q1 > 0, or the first non-zero component positive. *)
  let e = 1e-12 in
  let neg =
    if Float.abs q.q1 > e then q.q1 < 0.
    else if Float.abs q.q2 > e then q.q2 < 0.
    else if Float.abs q.q3 > e then q.q3 < 0.
    else q.q4 < 0. in
  if neg then { q1 = -. q.q1; q2 = -. q.q2; q3 = -. q.q3; q4 = -. q.q4 } else q

let angle_between a b =
  let d = Float.min 1. (Float.abs (odot (normalize a) (normalize b))) in
  2. *. acos d

let slerp a b s =
  let d = odot a b in
  let b, d = if d < 0. then ({ q1 = -. b.q1; q2 = -. b.q2; q3 = -. b.q3; q4 = -. b.q4 }, -. d) else (b, d) in
  let ka, kb =
    if d > 0.9999995 then (1. -. s, s)
    else
      let th = acos d in
      let st = sin th in
      (sin ((1. -. s) *. th) /. st, sin (s *. th) /. st)
  in
  normalize { q1 = ka *. a.q1 +. kb *. b.q1; q2 = ka *. a.q2 +. kb *. b.q2;
              q3 = ka *. a.q3 +. kb *. b.q3; q4 = ka *. a.q4 +. kb *. b.q4 }

(* The translation added on unboxed floats: a move composes a dozen poses, and the rotated
   vector's sum was an allocation of its own. *)
let pmult a b =
  let v = rotate a.rot b.trans in
  { trans = { x = a.trans.x +. v.x; y = a.trans.y +. v.y; z = a.trans.z +. v.z };
    rot = normalize (omult a.rot b.rot) }
let pinv p = let r = conj p.rot in { trans = scale (-1.) (rotate r p.trans); rot = r }
let pvect p v = add p.trans (rotate p.rot v)

let offs p dx dy dz = { p with trans = add p.trans { x = dx; y = dy; z = dz } }

let rel_tool p dx dy dz ?(rx = 0.) ?(ry = 0.) ?(rz = 0.) () =
  let ex = { x = 1.; y = 0.; z = 0. } and ey = { x = 0.; y = 1.; z = 0. }
  and ez = { x = 0.; y = 0.; z = 1. } in
  let r = omult (of_axis_angle ex (rad rx)) (omult (of_axis_angle ey (rad ry)) (of_axis_angle ez (rad rz))) in
  { trans = pvect p { x = dx; y = dy; z = dz }; rot = normalize (omult p.rot r) }

let mir_pos ~point ~plane ?(wobj = identity) ?(mir_y = false) () =
  let world = pmult wobj point in
  let local = pmult (pinv plane) world in
  let m v = { v with z = -. v.z } in
  let rm = to_matrix local.rot in
  let col j = { x = rm.(j); y = rm.(3 + j); z = rm.(6 + j) } in
  let xa, ya, za =
    if mir_y then
      let y' = m (col 1) and z' = m (col 2) in (cross y' z', y', z')
    else
      let x' = m (col 0) and z' = m (col 2) in (x', cross z' x', z')
  in
  let rot = of_matrix [| xa.x; ya.x; za.x; xa.y; ya.y; za.y; xa.z; ya.z; za.z |] in
  let local' = { trans = m local.trans; rot } in
  pmult (pinv wobj) (pmult plane local')
