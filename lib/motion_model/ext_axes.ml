open Geom

type kind = Linear | Rotating

type axis = {
  name : string; index : int; kind : kind; min : float; max : float; speed : float;
  track : pos option;
}

let names = [| "eax_a"; "eax_b"; "eax_c"; "eax_d"; "eax_e"; "eax_f" |]

(* A num holds 9E9 in single precision: 8999999488, a little below the double 9e9. *)
let unused = Int32.float_of_bits (Int32.bits_of_float 9e9)

let is_unused v = v >= unused

let initial axes =
  let e = Array.make 6 unused in
  List.iter (fun a -> e.(a.index) <- Float.max a.min (Float.min a.max 0.)) axes;
  e

let ( let* ) = Result.bind

let resolve axes ~from target =
  let e = Array.make 6 unused in
  List.fold_left (fun acc a ->
      let* () = acc in
      let v = if Array.length target > a.index then target.(a.index) else unused in
      if is_unused v then (e.(a.index) <- from.(a.index); Ok ())
      else if Float.is_nan v || v < a.min -. 1e-9 || v > a.max +. 1e-9 then
        Error (Motion_error.External_out_of_range a.name)
      else (e.(a.index) <- v; Ok ()))
    (Ok ()) axes
  |> Result.map (fun () -> e)

let base axes e =
  List.fold_left (fun acc a ->
      match a.track with
      | None -> acc
      | Some dir ->
          let b = Option.value acc ~default:identity in
          Some { b with trans = add b.trans (scale e.(a.index) dir) })
    None axes

let time axes ~override ~v_leax ~v_reax ~from e =
  List.fold_left (fun acc a ->
      let* t = acc in
      let d = Float.abs (e.(a.index) -. from.(a.index)) in
      if d <= 0. then Ok t
      else
        let v = (match a.kind with Linear -> v_leax | Rotating -> v_reax) *. override /. 100. in
        let v = Float.min v a.speed in
        if v > 0. && Float.is_finite (d /. v) then Ok (Float.max t (d /. v))
        else Error (Motion_error.Invalid_speed
                      ((match a.kind with Linear -> "v_leax" | Rotating -> "v_reax") ^ " is not positive")))
    (Ok 0.) axes
