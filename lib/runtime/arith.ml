open Value

type binary =
  | Num_add | Dnum_add | Pos_add | String_concat
  | Num_sub | Dnum_sub | Pos_sub
  | Num_mul | Dnum_mul
  | Num_pos_mul
  | Pos_num_mul
  | Pos_cross
  | Orient_mul
  | Num_div | Dnum_div
  | Pos_num_div
  | Num_intdiv | Dnum_intdiv
  | Num_mod | Dnum_mod
  | Num_lt | Num_le | Num_ge | Num_gt
  | Dnum_lt | Dnum_le | Dnum_ge | Dnum_gt
  | Equal | Not_equal
  | Xor

type unary =
  | Num_neg | Dnum_neg | Pos_neg
  | Num_plus | Dnum_plus | Pos_plus
  | Not

(* §2.13 *)
let num_integer_min = -8388607.
let num_integer_max = 8388608.
let dnum_integer_min = -4503599627370496.
let dnum_integer_max = 4503599627370496.

let divzero = Error "ERR_DIVZERO"

(* R-3.12-c: a result beyond the finite range is the execution error "overflow" of §7.1, not
   an infinity that would travel on through the program. *)
let check_num x = if Float.is_finite x then Ok (Num x) else Error "ERR_OVERFLOW"
let check_dnum x = if Float.is_finite x then Ok (Dnum x) else Error "ERR_OVERFLOW"

(* With single operands, one operation of + - * / computed in double and rounded to single is
   the correctly rounded single result: double has more than 2 * 24 + 2 bits. *)
let num_op f a b = check_num (to_single (f (num_value a) (num_value b)))
let dnum_op f a b = check_dnum (f (num_value a) (num_value b))

let exact_single q = check_num (single_of_q q)

let ( let* ) = Result.bind

let pos_parts = function
  | Record [| Num x; Num y; Num z |] -> (x, y, z)
  | _ -> type_mismatch "a pos"

let orient_parts = function
  | Record [| Num a; Num b; Num c; Num d |] -> (a, b, c, d)
  | _ -> type_mismatch "an orient"

let make_pos x y z =
  let* x = check_num x in
  let* y = check_num y in
  let* z = check_num z in
  Ok (Record [| x; y; z |])

let pos_map f p =
  let x, y, z = pos_parts p in
  make_pos (to_single (f x)) (to_single (f y)) (to_single (f z))

let pos_zip f p q =
  let x1, y1, z1 = pos_parts p and x2, y2, z2 = pos_parts q in
  make_pos (to_single (f x1 x2)) (to_single (f y1 y2)) (to_single (f z1 z2))

(* R-3.12-d: the cross and quaternion products are sums of products; each component is
   computed exactly (as a rational) and rounded once, so that the result does not depend on the
   order of the operations. *)
let q = Q.of_float

let cross a b =
  let x1, y1, z1 = pos_parts a and x2, y2, z2 = pos_parts b in
  let det u v s t = Q.sub (Q.mul (q u) (q v)) (Q.mul (q s) (q t)) in
  let* x = exact_single (det y1 z2 z1 y2) in
  let* y = exact_single (det z1 x2 x1 z2) in
  let* z = exact_single (det x1 y2 y1 x2) in
  Ok (Record [| x; y; z |])

let quaternion_product a b =
  let a1, a2, a3, a4 = orient_parts a and b1, b2, b3, b4 = orient_parts b in
  let sum terms =
    exact_single
      (List.fold_left (fun acc (sign, u, v) ->
           let p = Q.mul (q u) (q v) in
           if sign > 0 then Q.add acc p else Q.sub acc p) Q.zero terms)
  in
  let* w = sum [ (1, a1, b1); (-1, a2, b2); (-1, a3, b3); (-1, a4, b4) ] in
  let* x = sum [ (1, a1, b2); (1, a2, b1); (1, a3, b4); (-1, a4, b3) ] in
  let* y = sum [ (1, a1, b3); (-1, a2, b4); (1, a3, b1); (1, a4, b2) ] in
  let* z = sum [ (1, a1, b4); (1, a2, b3); (-1, a3, b2); (1, a4, b1) ] in
  Ok (Record [| w; x; y; z |])

(* §3.12 notes b and c, ruling R-3.12-b: an operand of DIV or MOD must be an integer value
   (ERR_NOTINTVAL), inside the exact integer sub-domain (ERR_MAXINTVAL: beyond it a num no
   longer represents one integer exactly), and for dnum not negative. *)
let integer_operand ~dnum x =
  let lo, hi =
    if dnum then (dnum_integer_min, dnum_integer_max) else (num_integer_min, num_integer_max)
  in
  if Float.is_nan x then Error "ERR_NOTINTVAL"
  else if Float.is_integer x then
    if x < lo || x > hi then Error "ERR_MAXINTVAL"
    else if dnum && x < 0. then Error "ERR_NOTINTVAL"
    else Ok x
  else if Float.is_finite x then Error "ERR_NOTINTVAL"
  else Error "ERR_MAXINTVAL"

(* Truncation toward zero (R-3.12). Both results are computed exactly: fmod is exact, and
   a - r is a multiple of b with no more bits than a, so the division is exact. *)
let integer_division ~dnum ~modulo a b =
  let* a = integer_operand ~dnum (num_value a) in
  let* b = integer_operand ~dnum (num_value b) in
  if b = 0. then divzero
  else
    let r = Float.rem a b in
    let result = if modulo then r else (a -. r) /. b in
    (* An integer result has no sign of zero. *)
    let result = if result = 0. then 0. else result in
    Ok (if dnum then Dnum result else Num result)

let compare_op f a b = Ok (Bool (f (num_value a) (num_value b)))

let rec same_sizes a b =
  match a, b with
  | Array x, Array y ->
      Array.length x = Array.length y
      && (let rec from i = i >= Array.length x || (same_sizes x.(i) y.(i) && from (i + 1)) in
          from 0)
  | Record x, Record y ->
      (* Records of different lengths are of different types: [Value.equal] refuses them. *)
      Array.length x <> Array.length y
      || (let rec from i = i >= Array.length x || (same_sizes x.(i) y.(i) && from (i + 1)) in
          from 0)
  | _ -> true

(* R-3.12-e: arrays of equal types have equal sizes (§2.17), which for {*} parameters only the
   values show; two of different sizes are the "mixed array dimensions" of ch. 12. *)
let equality a b =
  if same_sizes a b then Ok (Bool (Value.equal a b)) else Error "ERR_NOTEQDIM"

let binary op a b =
  match op with
  | Num_add -> num_op ( +. ) a b
  | Num_sub -> num_op ( -. ) a b
  | Num_mul -> num_op ( *. ) a b
  | Num_div -> if num_value b = 0. then divzero else num_op ( /. ) a b
  | Dnum_add -> dnum_op ( +. ) a b
  | Dnum_sub -> dnum_op ( -. ) a b
  | Dnum_mul -> dnum_op ( *. ) a b
  | Dnum_div -> if num_value b = 0. then divzero else dnum_op ( /. ) a b
  | Pos_add -> pos_zip ( +. ) a b
  | Pos_sub -> pos_zip ( -. ) a b
  | Num_pos_mul ->
      let k = num_value a in
      pos_map (fun c -> k *. c) b
  | Pos_num_mul ->
      let k = num_value b in
      pos_map (fun c -> c *. k) a
  | Pos_num_div ->
      let k = num_value b in
      if k = 0. then divzero else pos_map (fun c -> c /. k) a
  | Pos_cross -> cross a b
  | Orient_mul -> quaternion_product a b
  | String_concat ->
      let s = string_value a ^ string_value b in
      if String.length s > 80 then Error "ERR_STRTOOLNG" else Ok (String s)
  | Num_intdiv -> integer_division ~dnum:false ~modulo:false a b
  | Num_mod -> integer_division ~dnum:false ~modulo:true a b
  | Dnum_intdiv -> integer_division ~dnum:true ~modulo:false a b
  | Dnum_mod -> integer_division ~dnum:true ~modulo:true a b
  | Num_lt | Dnum_lt -> compare_op ( < ) a b
  | Num_le | Dnum_le -> compare_op ( <= ) a b
  | Num_ge | Dnum_ge -> compare_op ( >= ) a b
  | Num_gt | Dnum_gt -> compare_op ( > ) a b
  | Equal -> equality a b
  | Not_equal -> Result.map (fun eq -> Bool (not (bool_value eq))) (equality a b)
  | Xor -> Ok (Bool (bool_value a <> bool_value b))

let unary op a =
  match op, a with
  | (Num_neg | Num_plus), Num x -> Ok (Num (if op = Num_neg then -.x else x))
  | (Dnum_neg | Dnum_plus), Dnum x -> Ok (Dnum (if op = Dnum_neg then -.x else x))
  | Pos_neg, _ -> pos_map ( ~-. ) a
  | Pos_plus, _ ->
      ignore (pos_parts a);
      Ok (Value.copy a)
  | Not, Bool b -> Ok (Bool (not b))
  | _ -> type_mismatch "an operand of a unary operator (§3.12)"

let binary_name = function
  | Num_add -> "num + num" | Dnum_add -> "dnum + dnum" | Pos_add -> "pos + pos"
  | String_concat -> "string + string"
  | Num_sub -> "num - num" | Dnum_sub -> "dnum - dnum" | Pos_sub -> "pos - pos"
  | Num_mul -> "num * num" | Dnum_mul -> "dnum * dnum"
  | Num_pos_mul -> "num * pos" | Pos_num_mul -> "pos * num" | Pos_cross -> "pos * pos"
  | Orient_mul -> "orient * orient"
  | Num_div -> "num / num" | Dnum_div -> "dnum / dnum" | Pos_num_div -> "pos / num"
  | Num_intdiv -> "num DIV num" | Dnum_intdiv -> "dnum DIV dnum"
  | Num_mod -> "num MOD num" | Dnum_mod -> "dnum MOD dnum"
  | Num_lt -> "num < num" | Num_le -> "num <= num" | Num_ge -> "num >= num"
  | Num_gt -> "num > num"
  | Dnum_lt -> "dnum < dnum" | Dnum_le -> "dnum <= dnum" | Dnum_ge -> "dnum >= dnum"
  | Dnum_gt -> "dnum > dnum"
  | Equal -> "=" | Not_equal -> "<>" | Xor -> "bool XOR bool"

let unary_name = function
  | Num_neg -> "-num" | Dnum_neg -> "-dnum" | Pos_neg -> "-pos"
  | Num_plus -> "+num" | Dnum_plus -> "+dnum" | Pos_plus -> "+pos"
  | Not -> "NOT bool"
