let z10 = Z.of_int 10

let pow10 e =
  if e >= 0 then Q.of_bigint (Z.pow z10 e) else Q.make Z.one (Z.pow z10 (-e))

(* floor(|q| + 1/2) with the sign of q. *)
let round_half_away q =
  let a = Q.abs q in
  let n = Z.fdiv (Z.add (Z.shift_left (Q.num a) 1) (Q.den a)) (Z.shift_left (Q.den a) 1) in
  if Q.sign q < 0 then Z.neg n else n

(* The digits of n >= 0 with a point before the last [decimals] of them. *)
let with_point n decimals =
  let s = Z.to_string n in
  if decimals = 0 then s
  else
    let s =
      if String.length s <= decimals then String.make (decimals + 1 - String.length s) '0' ^ s
      else s
    in
    let k = String.length s - decimals in
    String.sub s 0 k ^ "." ^ String.sub s k decimals

let signed negative text = if negative then "-" ^ text else text

(* R-3.12-c: no num or dnum value is infinite or NaN; were one to reach these functions, the
   digit loops below would not end, so it is refused as the bug it would be. *)
let finite x = if not (Float.is_finite x) then Value.type_mismatch "a finite number (R-3.12-c)"

let fixed x ~decimals =
  finite x;
  let n = round_half_away (Q.mul (Q.of_float x) (pow10 decimals)) in
  signed (Z.sign n < 0) (with_point (Z.abs n) decimals)

(* floor(log10 a) for a > 0: the float logarithm is a guess that the exact comparisons
   correct near powers of ten. *)
let decimal_exponent a =
  let guess = int_of_float (Float.floor (Float.log10 (Q.to_float a))) in
  let rec adjust e =
    if Q.lt a (pow10 e) then adjust (e - 1)
    else if Q.geq a (pow10 (e + 1)) then adjust (e + 1)
    else e
  in
  adjust guess

(* a > 0 rounded to [digits] significant digits: (n, e) with n of exactly [digits] digits and
   a ~ n * 10^(e - digits + 1). Rounding up may carry into a new digit (9.9999996 -> 10.0000),
   which moves the exponent. *)
let significant a digits =
  let e = decimal_exponent a in
  let n = round_half_away (Q.div a (pow10 (e - digits + 1))) in
  if Z.equal n (Z.pow z10 digits) then (Z.div n z10, e + 1) else (n, e)

let exponent_text e = Printf.sprintf "E%c%02d" (if e < 0 then '-' else '+') (abs e)

let scientific x ~decimals =
  finite x;
  if x = 0. then with_point Z.zero decimals ^ exponent_text 0
  else
    let n, e = significant (Q.abs (Q.of_float x)) (decimals + 1) in
    signed (x < 0.) (with_point n decimals ^ exponent_text e)

let strip_zeros s =
  if not (String.contains s '.') then s
  else
    let k = ref (String.length s) in
    while s.[!k - 1] = '0' do decr k done;
    if s.[!k - 1] = '.' then decr k;
    String.sub s 0 !k

(* The %g notation of C with [digits] significant digits: positional for decimal exponents
   from -4 to digits - 1, otherwise one digit before the point and an exponent. *)
let general a digits =
  let n, e = significant a digits in
  if e < -4 || e >= digits then
    let d = Z.to_string n in
    strip_zeros (String.sub d 0 1 ^ "." ^ String.sub d 1 (digits - 1)) ^ exponent_text e
  else strip_zeros (with_point n (digits - 1 - e))

(* installed-facts.md §1 (UNCERTAIN): TPWrite writes "up to 6 significant digits", and "if the
   decimal part is less than 0.000005 or greater than 0.999995 the number is rounded to an
   integer"; ruling R-13-a. *)
let integer_tolerance = Q.make (Z.of_int 5) (Z.of_int 1_000_000)

let num_text x =
  finite x;
  if x = 0. then "0"
  else
    let a = Q.abs (Q.of_float x) in
    let whole = Z.fdiv (Q.num a) (Q.den a) in
    let frac = Q.sub a (Q.of_bigint whole) in
    let nearest =
      if Q.lt frac integer_tolerance then Some whole
      else if Q.gt frac (Q.sub Q.one integer_tolerance) then Some (Z.succ whole)
      else None
    in
    match nearest with
    | Some n when Z.leq n (Z.of_int 8388608) -> signed (Z.sign n > 0 && x < 0.) (Z.to_string n)
    | _ -> signed (x < 0.) (general a 6)

let dnum_text x =
  finite x;
  if x = 0. then "0"
  else if Float.is_integer x && Float.abs x <= 4503599627370496. then
    Z.to_string (Z.of_float x)
  else signed (x < 0.) (general (Q.abs (Q.of_float x)) 15)

let string_literal s =
  let b = Buffer.create (String.length s + 2) in
  Buffer.add_char b '"';
  String.iter
    (fun c ->
      match c with
      | '"' -> Buffer.add_string b "\"\""
      | '\\' -> Buffer.add_string b "\\\\"
      | c when Char.code c < 32 || Char.code c = 127 ->
          Buffer.add_string b (Printf.sprintf "\\%02X" (Char.code c))
      | c -> Buffer.add_char b c)
    s;
  Buffer.add_char b '"';
  Buffer.contents b

let display s =
  if not (String.exists (fun c -> Char.code c < 32 || Char.code c = 127) s) then s
  else begin
    let b = Buffer.create (String.length s + 8) in
    String.iter (fun c ->
        if Char.code c < 32 || Char.code c = 127 then Buffer.add_string b (Printf.sprintf "\\%02X" (Char.code c))
        else Buffer.add_char b c) s;
    Buffer.contents b
  end

let rec value_text (v : Value.t) =
  match v with
  | Num x -> num_text x
  | Dnum x -> dnum_text x
  | Bool b -> if b then "TRUE" else "FALSE"
  | String s -> string_literal s
  | Record a | Array a ->
      "[" ^ String.concat "," (Array.to_list (Array.map value_text a)) ^ "]"
  | Handle _ -> Value.type_mismatch "a value of a value type (a handle has no text)"

let tpwrite text = function None -> text | Some v -> text ^ value_text v
