type t = { mantissa : Z.t; exponent : int }

let zero = { mantissa = Z.zero; exponent = 0 }

let to_q { mantissa; exponent } =
  if exponent >= 0 then Q.of_bigint (Z.mul mantissa (Z.pow (Z.of_int 10) exponent))
  else Q.make mantissa (Z.pow (Z.of_int 10) (-exponent))

(* IEEE 754 double precision: a value rounds to a finite non-zero double exactly when its
   magnitude lies strictly between half the smallest subnormal (2^-1075) and the midpoint
   between the largest finite double and 2^1024 (2^1024 - 2^970). *)
let underflow_bound = Q.make Z.one (Z.shift_left Z.one 1075)
let overflow_bound = Q.of_bigint (Z.sub (Z.shift_left Z.one 1024) (Z.shift_left Z.one 970))

let out_of_range = "numeric literal out of the range of IEEE 754 (§2.5)"

let strip_leading_zeros s =
  let n = String.length s in
  let i = ref 0 in
  while !i < n && s.[!i] = '0' do incr i done;
  String.sub s !i (n - !i)

let check { mantissa; exponent } digits =
  if Z.equal mantissa Z.zero then Ok zero
  else
    (* The decimal exponent of the leading digit decides all but the borderline cases without
       building a huge number. *)
    let adjusted = exponent + digits - 1 in
    if adjusted > 309 then Error out_of_range
    else if adjusted < -325 then Error out_of_range
    else
      let q = Q.abs (to_q { mantissa; exponent }) in
      if Q.geq q overflow_bound || Q.leq q underflow_bound then Error out_of_range
      else Ok { mantissa; exponent }

let of_based base digits =
  let z = Z.of_string_base base digits in
  let t = { mantissa = z; exponent = 0 } in
  check t (String.length (Z.to_string z))

(* The first 'e' or 'E', without a lowered copy of every literal. *)
let rec exponent_mark s i =
  if i >= String.length s then None
  else match String.unsafe_get s i with 'e' | 'E' -> Some i | _ -> exponent_mark s (i + 1)

let split_exponent s =
  match exponent_mark s 0 with
  | None -> (s, Z.zero)
  | Some i ->
      let e = String.sub s (i + 1) (String.length s - i - 1) in
      let e = if e <> "" && e.[0] = '+' then String.sub e 1 (String.length e - 1) else e in
      (String.sub s 0 i, Z.of_string e)

let of_decimal s =
  let body, exponent = split_exponent s in
  let int_part, frac_part =
    match String.index_opt body '.' with
    | None -> (body, "")
    | Some i -> (String.sub body 0 i, String.sub body (i + 1) (String.length body - i - 1))
  in
  let digits = strip_leading_zeros (int_part ^ frac_part) in
  if digits = "" then Ok zero
  else
    let exponent = Z.sub exponent (Z.of_int (String.length frac_part)) in
    (* An exponent beyond any int is out of range unless the mantissa is zero (handled). *)
    if not (Z.fits_int exponent) || abs (Z.to_int exponent) > 1_000_000_000 then Error out_of_range
    else check { mantissa = Z.of_string digits; exponent = Z.to_int exponent } (String.length digits)

let of_text text =
  let n = String.length text in
  if n >= 2 && text.[0] = '0' then
    let rest () = String.sub text 2 (n - 2) in
    match text.[1] with
    | 'X' | 'x' -> of_based 16 (rest ())
    | 'O' | 'o' -> of_based 8 (rest ())
    | 'B' | 'b' -> of_based 2 (rest ())
    | 'D' | 'd' -> of_decimal (rest ())
    | _ -> of_decimal text
  else of_decimal text

let value text =
  match of_text text with
  | Ok t -> to_q t
  | Error message -> invalid_arg message
