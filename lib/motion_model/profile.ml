open Motion_data

type velset = { override : float; max : float }

let velset_default = { override = 100.; max = 5000. }

type speed_limit = { check_point : float option; axes : (int * float) list }

let no_speed_limit = { check_point = None; axes = [] }

let limited_time lim ~length ~deltas =
  let t_tcp = match lim.check_point with Some v when v > 0. -> length /. v | _ -> 0. in
  List.fold_left (fun acc (i, v) ->
      if i >= 1 && i <= Array.length deltas && v > 0. then Float.max acc (Float.abs deltas.(i - 1) /. v) else acc)
    t_tcp lim.axes

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
