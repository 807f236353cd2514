open Motion_data

type velset = { override : float; max : float }

let velset_default = { override = 100.; max = 5000. }

type timing = { speed : speeddata; v : float option; t : float option }

let tcp_speed (r : Robot.t) vs tm =
  let v = Option.value tm.v ~default:tm.speed.v_tcp in
  Float.min (v *. vs.override /. 100.) (Float.min vs.max r.max_tcp_speed)

let check_override vs =
  if not (vs.override > 0.) then Error (Motion_error.Invalid_speed "VelSet override is not positive")
  else Ok ()

let by_time vs t =
  if Float.is_finite t && t >= 0. then Ok (t *. 100. /. vs.override)
  else Error (Motion_error.Invalid_speed "\\T is negative")

(* The time of [amount] at [speed]: none needed when nothing moves, an error when something
   must move at no speed. *)
let need amount speed what =
  if amount <= 0. then Ok 0.
  else if speed > 0. && Float.is_finite speed then Ok (amount /. speed)
  else Error (Motion_error.Invalid_speed (what ^ " is not positive"))

let ( let* ) = Result.bind

let cartesian r vs tm ~length ~angle =
  let* () = check_override vs in
  match tm.t with
  | Some t -> by_time vs t
  | None ->
      let* tl = need length (tcp_speed r vs tm) "v_tcp" in
      let* ta = need angle (tm.speed.v_ori *. vs.override /. 100.) "v_ori" in
      Ok (Float.max tl ta)

let joint (r : Robot.t) vs tm ~deltas ~length ~angle =
  let* () = check_override vs in
  match tm.t with
  | Some t -> by_time vs t
  | None ->
      let* tc = cartesian r vs tm ~length ~angle in
      let slowest = ref tc in
      Array.iteri (fun i d -> slowest := Float.max !slowest (Float.abs d /. r.axes.(i).speed)) deltas;
      Ok !slowest
