open Geom

let is_world (b : pose) =
  b.trans.x = 0. && b.trans.y = 0. && b.trans.z = 0.
  && b.rot.q1 = 1. && b.rot.q2 = 0. && b.rot.q3 = 0. && b.rot.q4 = 0.

(* Law F-base with law X-track (R-bk-12): a track translates the base frame it carries along its
   direction of the world. *)
let in_world (r : Robot.t) e =
  match Ext_axes.base r.externals e with
  | None -> if is_world r.base_frame then None else Some r.base_frame
  | Some t -> Some (pmult t r.base_frame)

let max_offset = 1e7

let orientation q1 q2 q3 q4 =
  let n = sqrt ((q1 *. q1) +. (q2 *. q2) +. (q3 *. q3) +. (q4 *. q4)) in
  if not (List.for_all Float.is_finite [ q1; q2; q3; q4 ]) then Error "a quaternion component is not finite"
  else if not (Float.abs (n -. 1.) <= 1e-3) then
    Error (Printf.sprintf "the quaternion [%g,%g,%g,%g] is not a unit quaternion (its norm is %g)" q1 q2 q3 q4 n)
  else
    let s = if q1 < 0. then -1. /. n else 1. /. n in
    (* +. 0. makes a -0 component 0 *)
    Ok { q1 = (s *. q1) +. 0.; q2 = (s *. q2) +. 0.; q3 = (s *. q3) +. 0.; q4 = (s *. q4) +. 0. }

let position x y z =
  if List.for_all (fun v -> Float.is_finite v && Float.abs v <= max_offset) [ x; y; z ] then Ok { x; y; z }
  else Error (Printf.sprintf "the origin [%g,%g,%g] mm is not within %g mm of the world's" x y z max_offset)

let of_text text =
  let parts = List.map String.trim (String.split_on_char ',' text) in
  (* decimal numbers only: no hexadecimal, no nan or infinity words, no underscores *)
  let number s = if Rapid_syntax.Decimal.is_decimal s then float_of_string_opt s else None in
  match List.map number parts with
  | [ Some x; Some y; Some z; Some q1; Some q2; Some q3; Some q4 ] ->
      Result.bind (position x y z) (fun trans -> Result.map (fun rot -> { trans; rot }) (orientation q1 q2 q3 q4))
  | l when List.length l <> 7 ->
      Error (Printf.sprintf "expected X,Y,Z,Q1,Q2,Q3,Q4 (seven numbers), got %d" (List.length l))
  | _ -> Error "expected X,Y,Z,Q1,Q2,Q3,Q4: each a decimal number"

let to_text (b : pose) =
  String.concat "," (List.map (Printf.sprintf "%.9g")
                       [ b.trans.x; b.trans.y; b.trans.z; b.rot.q1; b.rot.q2; b.rot.q3; b.rot.q4 ])
