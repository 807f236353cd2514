open Value

type result = (Value.t, string) Stdlib.result

let ( let* ) = Result.bind

(* ------------------------------------------------------------------------------ arguments *)

(* R-13-c: positions, lengths and numbers of decimals must be integer values. Huge ones are
   clamped: they are out of every range that follows anyway. *)
let integer v =
  let x = num_value v in
  if Float.is_integer x then Ok (int_of_float (Float.max (-1e9) (Float.min 1e9 x)))
  else Error "ERR_NOTINTVAL"

let decimals v =
  let* d = integer v in
  if d < 0 then Error "ERR_ARGVALERR" else Ok d

let string_result s = if String.length s > 80 then Error "ERR_STRTOOLNG" else Ok (String s)

(* A result of the argument's precision: num rounded to single, dnum as it is. An undefined
   result (NaN) is a domain error, an infinite one an overflow (R-13-e). *)
let like v x =
  if Float.is_nan x then Error "ERR_ARGVALERR"
  else
    match v with
    | Num _ -> Arith.check_num (to_single x)
    | Dnum _ -> Arith.check_dnum x
    | _ -> type_mismatch "a num or dnum"

(* ------------------------------------------------------------------------------ strings *)

let str_len s = Ok (Num (float_of_int (String.length (string_value s))))

let str_part s chpos len =
  let s = string_value s in
  let* p = integer chpos in
  let* l = integer len in
  if p < 1 || l < 0 || p + l - 1 > String.length s then Error "ERR_OUTOFBND"
  else Ok (String (String.sub s (p - 1) l))

(* A search may start just past the end (StrLen + 1), where it finds nothing: programs step
   past the last hit that way. *)
let search_start s chpos =
  let* p = integer chpos in
  if p < 1 || p > String.length s + 1 then Error "ERR_OUTOFBND" else Ok p

let str_find ~not_in_set s chpos set =
  let s = string_value s and set = string_value set in
  let* p = search_start s chpos in
  let n = String.length s in
  let rec from i =
    if i >= n then n + 1
    else if String.contains set s.[i] <> not_in_set then i + 1
    else from (i + 1)
  in
  Ok (Num (float_of_int (from (p - 1))))

let str_match s chpos pattern =
  let s = string_value s and pattern = string_value pattern in
  let* p = search_start s chpos in
  let n = String.length s and m = String.length pattern in
  let matches_at i =
    let rec same j = j >= m || (s.[i + j] = pattern.[j] && same (j + 1)) in
    same 0
  in
  let rec from i = if i + m > n then n + 1 else if matches_at i then i + 1 else from (i + 1) in
  Ok (Num (float_of_int (from (p - 1))))

let str_map s from_map to_map =
  let s = string_value s and from_map = string_value from_map and to_map = string_value to_map in
  Ok
    (String
       (String.map
          (fun c ->
            match String.index_opt from_map c with
            | Some i when i < String.length to_map -> to_map.[i]
            | _ -> c)
          s))

let str_memb s chpos set =
  let s = string_value s and set = string_value set in
  let* p = integer chpos in
  if p < 1 || p > String.length s then Error "ERR_OUTOFBND"
  else Ok (Bool (String.contains set s.[p - 1]))

let str_order s1 s2 order =
  let s1 = string_value s1 and s2 = string_value s2 and order = string_value order in
  let rank c =
    match String.index_opt order c with
    | Some i -> i
    | None -> String.length order + Char.code c
  in
  let n1 = String.length s1 and n2 = String.length s2 in
  let rec before i =
    if i >= n1 then i < n2
    else if i >= n2 then false
    else
      let r1 = rank s1.[i] and r2 = rank s2.[i] in
      if r1 <> r2 then r1 < r2 else before (i + 1)
  in
  Ok (Bool (before 0))

(* ------------------------------------------------------------------------------ numbers and text *)

let to_str v dec ~exp =
  let x = num_value v in
  let* d = decimals dec in
  (* Every result has at least d + 2 characters: refuse before building a huge one. *)
  if d > 80 then Error "ERR_STRTOOLNG"
  else if not (Float.is_finite x) then Error "ERR_OVERFLOW"   (* R-3.12-c: none is infinite *)
  else string_result (if exp then Text_format.scientific x ~decimals:d else Text_format.fixed x ~decimals:d)

let num_to_str v dec ~exp =
  (match v with Num _ -> () | _ -> type_mismatch "a num");
  to_str v dec ~exp

let dnum_to_str v dec ~exp =
  (match v with Dnum _ -> () | _ -> type_mismatch "a dnum");
  to_str v dec ~exp

let val_to_str v = string_result (Text_format.value_text v)

(* StrToVal reads what ValToStr writes, with the literal syntax of §2.5-§2.7. *)
exception No_value

let parse_value text shape =
  let n = String.length text in
  let pos = ref 0 in
  let at i = if i < n then Some text.[i] else None in
  let blanks () = while !pos < n && (text.[!pos] = ' ' || text.[!pos] = '\t') do incr pos done in
  let expect c =
    blanks ();
    if at !pos = Some c then incr pos else raise No_value
  in
  let is_digit = function '0' .. '9' -> true | _ -> false in
  let is_word = function 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_' -> true | _ -> false in
  let skip_while p = while !pos < n && p text.[!pos] do incr pos done in
  (* §2.5: an exponent is part of the literal only when digits follow it. *)
  let exponent () =
    match at !pos with
    | Some ('E' | 'e') ->
        let after_sign = match at (!pos + 1) with Some ('+' | '-') -> !pos + 2 | _ -> !pos + 1 in
        if Option.fold ~none:false ~some:is_digit (at after_sign) then begin
          pos := after_sign;
          skip_while is_digit
        end
    | _ -> ()
  in
  let number () =
    blanks ();
    let negative =
      match at !pos with
      | Some '-' -> incr pos; true
      | Some '+' -> incr pos; false
      | _ -> false
    in
    blanks ();
    let start = !pos in
    let based digit =
      pos := !pos + 2;
      let first = !pos in
      skip_while digit;
      if !pos = first then raise No_value
    in
    (match at !pos, at (!pos + 1) with
     | Some '0', Some ('X' | 'x') ->
         based (function '0' .. '9' | 'A' .. 'F' | 'a' .. 'f' -> true | _ -> false)
     | Some '0', Some ('O' | 'o') -> based (function '0' .. '7' -> true | _ -> false)
     | Some '0', Some ('B' | 'b') -> based (function '0' | '1' -> true | _ -> false)
     | Some '0', Some ('D' | 'd') -> based is_digit; exponent ()
     | _ ->
         let int_start = !pos in
         skip_while is_digit;
         let int_digits = !pos - int_start in
         let frac_digits =
           if at !pos = Some '.' then begin
             incr pos;
             let f = !pos in
             skip_while is_digit;
             !pos - f
           end
           else 0
         in
         if int_digits + frac_digits = 0 then raise No_value;
         exponent ());
    (* R-2.2: a literal runs into no letter, digit or underscore. *)
    if Option.fold ~none:false ~some:is_word (at !pos) then raise No_value;
    match Rapid_syntax.Num_literal.of_text (String.sub text start (!pos - start)) with
    | Ok lit ->
        let q = Rapid_syntax.Num_literal.to_q lit in
        if negative then Q.neg q else q
    | Error _ -> raise No_value
  in
  let hex c =
    match c with
    | '0' .. '9' -> Char.code c - 48
    | 'A' .. 'F' -> Char.code c - 55
    | 'a' .. 'f' -> Char.code c - 87
    | _ -> raise No_value
  in
  let string_lit () =
    expect '"';
    let b = Buffer.create 16 in
    let rec go () =
      match at !pos with
      | None -> raise No_value
      | Some '"' ->
          if at (!pos + 1) = Some '"' then (Buffer.add_char b '"'; pos := !pos + 2; go ())
          else incr pos
      | Some '\\' ->
          (match at (!pos + 1), at (!pos + 2) with
           | Some '\\', _ -> Buffer.add_char b '\\'; pos := !pos + 2
           | Some h, Some l -> Buffer.add_char b (Char.chr ((16 * hex h) + hex l)); pos := !pos + 3
           | _ -> raise No_value);
          go ()
      | Some ('\n' | '\r') -> raise No_value
      | Some c -> Buffer.add_char b c; incr pos; go ()
    in
    go ();
    if Buffer.length b > 80 then raise No_value;
    Buffer.contents b
  in
  let rec value shape =
    match shape with
    | S_num ->
        let x = single_of_q (number ()) in
        if Float.is_finite x then Num x else raise No_value
    | S_dnum -> Dnum (double_of_q (number ()))
    | S_bool ->
        blanks ();
        let start = !pos in
        skip_while is_word;
        (* Reserved words are written in any letter case (§2.3). *)
        (match String.uppercase_ascii (String.sub text start (!pos - start)) with
         | "TRUE" -> Bool true
         | "FALSE" -> Bool false
         | _ -> raise No_value)
    | S_string -> String (string_lit ())
    | S_handle _ -> raise No_value
    | S_record components -> Record (aggregate (Array.to_list components))
    | S_array (count, element) -> Array (aggregate (List.init count (fun _ -> element)))
  and aggregate shapes =
    expect '[';
    let values = List.mapi (fun i s -> if i > 0 then expect ','; value s) shapes in
    expect ']';
    Array.of_list values
  in
  match value shape with
  | v ->
      blanks ();
      if !pos = n then Some v else None
  | exception No_value -> None

let str_to_val s shape = parse_value (string_value s) shape

(* ------------------------------------------------------------------------------ arithmetic *)

let abs_num v = like v (Float.abs (num_value v))

let sqrt_num v =
  let x = num_value v in
  if x < 0. then Error "ERR_ARGVALERR" else like v (Float.sqrt x)

let exp_num v = like v (Float.exp (num_value v))
let pow_num b e = like b (Float.pow (num_value b) (num_value e))

(* Degrees are reduced exactly to a quadrant and an angle below 90 (fmod is exact, and
   subtracting the quadrant's start is exact by Sterbenz's lemma), so that multiples of 90
   give 0, 1 and -1 exactly (R-13-e). *)
let quadrant x =
  let r = Float.rem x 360. in
  let r = if r < 0. then r +. 360. else r in
  let r = if r >= 360. then 0. else r in
  if r < 90. then (0, r)
  else if r < 180. then (1, r -. 90.)
  else if r < 270. then (2, r -. 180.)
  else (3, r -. 270.)

let radians d = d *. (Float.pi /. 180.)
let degrees r = r *. (180. /. Float.pi)
let no_negative_zero x = if x = 0. then 0. else x

let sin_degrees x =
  let q, a = quadrant x in
  let a = radians a in
  no_negative_zero
    (match q with 0 -> Float.sin a | 1 -> Float.cos a | 2 -> -.Float.sin a | _ -> -.Float.cos a)

let cos_degrees x =
  let q, a = quadrant x in
  let a = radians a in
  no_negative_zero
    (match q with 0 -> Float.cos a | 1 -> -.Float.sin a | 2 -> -.Float.cos a | _ -> Float.sin a)

let finite_arg v k =
  let x = num_value v in
  if Float.is_finite x then k x else Error "ERR_ARGVALERR"

let sin_num v = finite_arg v (fun x -> like v (sin_degrees x))
let cos_num v = finite_arg v (fun x -> like v (cos_degrees x))
let tan_num v = finite_arg v (fun x -> like v (sin_degrees x /. cos_degrees x))

let unit_interval v k =
  let x = num_value v in
  if x < -1. || x > 1. then Error "ERR_ARGVALERR" else like v (k x)

let asin_num v = unit_interval v (fun x -> degrees (Float.asin x))
let acos_num v = unit_interval v (fun x -> degrees (Float.acos x))
let atan_num v = like v (degrees (Float.atan (num_value v)))
let atan2_num y x = like y (no_negative_zero (degrees (Float.atan2 (num_value y) (num_value x))))

(* R-13-d: rounding to [d] decimals works on the exact value and rounds the decimal result
   once to the argument's precision. Beyond 1100 decimals every double is exact already. *)
let round_with rounding v dec =
  let* d = match dec with None -> Ok 0 | Some dec -> decimals dec in
  let d = min d 1100 in
  let scale = Text_format.pow10 d in
  let q = Q.div (Q.of_bigint (rounding (Q.mul (Q.of_float (num_value v)) scale))) scale in
  match v with
  | Num _ -> Arith.exact_single q
  | Dnum _ -> Ok (Dnum (double_of_q q))
  | _ -> type_mismatch "a num or dnum"

let round_num v ~dec = round_with Text_format.round_half_away v dec
let trunc_num v ~dec = round_with (fun q -> Z.div (Q.num q) (Q.den q)) v dec

let max_num a b = if num_value a >= num_value b then Ok a else Ok b
let min_num a b = if num_value a <= num_value b then Ok a else Ok b

let num_to_dnum v =
  match v with Num x -> Ok (Dnum x) | _ -> type_mismatch "a num"

let dnum_to_num v ~integer =
  let x = match v with Dnum x -> x | _ -> type_mismatch "a dnum" in
  if integer && not (Float.is_integer x) then Error "ERR_NOTINTVAL"
  else if integer && (x < Arith.num_integer_min || x > Arith.num_integer_max) then
    Error "ERR_NUM_LIMIT"
  else
    let y = to_single x in
    if Float.is_finite y then Ok (Num y) else Error "ERR_NUM_LIMIT"

(* ------------------------------------------------------------------------------ vectors and poses *)

let pos_parts v =
  match v with
  | Record [| Num x; Num y; Num z |] -> (x, y, z)
  | _ -> type_mismatch "a pos"

let orient_parts v =
  match v with
  | Record [| Num a; Num b; Num c; Num d |] -> (a, b, c, d)
  | _ -> type_mismatch "an orient"

let pose_parts v =
  match v with Record [| t; r |] -> (t, r) | _ -> type_mismatch "a pose"

let distance p1 p2 =
  let x1, y1, z1 = pos_parts p1 and x2, y2, z2 = pos_parts p2 in
  let dx = x1 -. x2 and dy = y1 -. y2 and dz = z1 -. z2 in
  Arith.check_num (to_single (Float.sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz))))

let vect_magn p =
  let x, y, z = pos_parts p in
  Arith.check_num (to_single (Float.sqrt ((x *. x) +. (y *. y) +. (z *. z))))

let q = Q.of_float

let dot_prod a b =
  let x1, y1, z1 = pos_parts a and x2, y2, z2 = pos_parts b in
  Arith.exact_single
    (Q.add (Q.mul (q x1) (q x2)) (Q.add (Q.mul (q y1) (q y2)) (Q.mul (q z1) (q z2))))

let cross_prod = Arith.cross

(* R-13-f: the rotation matrix of the quaternion [w, x, y, z] (q1 the scalar part, §2.14), in
   the form that holds for a unit quaternion; entries exact rationals. *)
let rotation (w, x, y, z) =
  let w = q w and x = q x and y = q y and z = q z in
  let two = Q.of_int 2 in
  let ( + ) = Q.add and ( - ) = Q.sub and ( * ) = Q.mul in
  [| [| Q.one - (two * ((y * y) + (z * z))); two * ((x * y) - (w * z)); two * ((x * z) + (w * y)) |];
     [| two * ((x * y) + (w * z)); Q.one - (two * ((x * x) + (z * z))); two * ((y * z) - (w * x)) |];
     [| two * ((x * z) - (w * y)); two * ((y * z) + (w * x)); Q.one - (two * ((x * x) + (y * y))) |] |]

let apply m (x, y, z) =
  Array.map (fun row -> Q.add (Q.mul row.(0) x) (Q.add (Q.mul row.(1) y) (Q.mul row.(2) z))) m

let pos_of_q (v : Q.t array) =
  let* x = Arith.exact_single v.(0) in
  let* y = Arith.exact_single v.(1) in
  let* z = Arith.exact_single v.(2) in
  Ok (Record [| x; y; z |])

let q3 (x, y, z) = (q x, q y, q z)

let transform pose p =
  let t, r = pose_parts pose in
  let tx, ty, tz = q3 (pos_parts t) in
  let v = apply (rotation (orient_parts r)) (q3 (pos_parts p)) in
  [| Q.add v.(0) tx; Q.add v.(1) ty; Q.add v.(2) tz |]

let pose_vect pose p = pos_of_q (transform pose p)

let pose_mult p1 p2 =
  let t2, r2 = pose_parts p2 in
  let _, r1 = pose_parts p1 in
  let* trans = pos_of_q (transform p1 t2) in
  let* rot = Arith.quaternion_product r1 r2 in
  Ok (Record [| trans; rot |])

let pose_inv p =
  let t, r = pose_parts p in
  let w, x, y, z = orient_parts r in
  let conj = (w, -.x, -.y, -.z) in
  let v = apply (rotation conj) (q3 (pos_parts t)) in
  let* trans = pos_of_q (Array.map Q.neg v) in
  Ok (Record [| trans; Record [| Num w; Num (-.x); Num (-.y); Num (-.z) |] |])

let orient_of_floats (w, x, y, z) =
  let* w = Arith.check_num (to_single w) in
  let* x = Arith.check_num (to_single x) in
  let* y = Arith.check_num (to_single y) in
  let* z = Arith.check_num (to_single z) in
  Ok (Record [| w; x; y; z |])

let orient_zyx za ya xa =
  let half v = num_value v /. 2. in
  let all_finite = List.for_all (fun v -> Float.is_finite (num_value v)) [ za; ya; xa ] in
  if not all_finite then Error "ERR_ARGVALERR"
  else
    let cz = cos_degrees (half za) and sz = sin_degrees (half za) in
    let cy = cos_degrees (half ya) and sy = sin_degrees (half ya) in
    let cx = cos_degrees (half xa) and sx = sin_degrees (half xa) in
    orient_of_floats
      ( (cz *. cy *. cx) +. (sz *. sy *. sx),
        (cz *. cy *. sx) -. (sz *. sy *. cx),
        (cz *. sy *. cx) +. (sz *. cy *. sx),
        (sz *. cy *. cx) -. (cz *. sy *. sx) )

let as_num x = like (Num 0.) x

let euler_zyx axis r =
  let w, x, y, z = orient_parts r in
  match axis with
  | None -> Error "ERR_ARGVALERR"
  | Some `Z ->
      as_num (degrees (Float.atan2 (2. *. ((w *. z) +. (x *. y))) (1. -. (2. *. ((y *. y) +. (z *. z))))))
  | Some `Y ->
      let s = 2. *. ((w *. y) -. (z *. x)) in
      as_num (degrees (Float.asin (Float.max (-1.) (Float.min 1. s))))
  | Some `X ->
      as_num (degrees (Float.atan2 (2. *. ((w *. x) +. (y *. z))) (1. -. (2. *. ((x *. x) +. (y *. y))))))

let norient r =
  let w, x, y, z = orient_parts r in
  let sum = List.fold_left (fun acc c -> Q.add acc (Q.mul (q c) (q c))) Q.zero [ w; x; y; z ] in
  if Q.geq (Q.abs (Q.sub sum Q.one)) (Q.make Z.one (Z.of_int 10)) then Error "ERR_ILLQUAT"
  else
    let norm = Float.sqrt (Q.to_float sum) in
    orient_of_floats (w /. norm, x /. norm, y /. norm, z /. norm)

(* ------------------------------------------------------------------------------ bits *)

(* R-13-h: a bit operand is an integer value (ERR_NOTINTVAL) within 0..255 for byte and
   0..2^52-1 for dnum (ERR_ARGVALERR); a bit position within 1..8 or 1..52 and a shift count
   not negative (ERR_ARGVALERR). *)
let byte_width = 8
let dnum_width = 52

let bits ~width v =
  let x = num_value v in
  if not (Float.is_integer x) then Error "ERR_NOTINTVAL"
  else if x < 0. || x >= ldexp 1. width then Error "ERR_ARGVALERR"
  else Ok (int_of_float x)

let bit_position ~width v =
  let* p = integer v in
  if p < 1 || p > width then Error "ERR_ARGVALERR" else Ok p

let shift_count v =
  let* n = integer v in
  if n < 0 then Error "ERR_ARGVALERR" else Ok (min n 62)

let bits_result ~width x =
  let x = float_of_int x in
  if width = dnum_width then Ok (Dnum x) else Ok (Num x)

let mask width = (1 lsl width) - 1

let bit2 ~width f a b =
  let* a = bits ~width a in
  let* b = bits ~width b in
  bits_result ~width (f a b land mask width)

let bit_neg_w ~width a =
  let* a = bits ~width a in
  bits_result ~width (lnot a land mask width)

let shift_w ~width f a n =
  let* a = bits ~width a in
  let* n = shift_count n in
  bits_result ~width (f a n land mask width)

let bit_check_w ~width a p =
  let* a = bits ~width a in
  let* p = bit_position ~width p in
  Ok (Bool ((a lsr (p - 1)) land 1 = 1))

let bit_update_w ~width f a p =
  let* a = bits ~width a in
  let* p = bit_position ~width p in
  bits_result ~width (f a (1 lsl (p - 1)) land mask width)

let bit_and = bit2 ~width:byte_width ( land )
let bit_or = bit2 ~width:byte_width ( lor )
let bit_xor = bit2 ~width:byte_width ( lxor )
let bit_neg = bit_neg_w ~width:byte_width
let bit_lsh = shift_w ~width:byte_width ( lsl )
let bit_rsh = shift_w ~width:byte_width ( lsr )
let bit_check = bit_check_w ~width:byte_width
let bit_set = bit_update_w ~width:byte_width ( lor )
let bit_clear = bit_update_w ~width:byte_width (fun a m -> a land lnot m)
let bit_and_dnum = bit2 ~width:dnum_width ( land )
let bit_or_dnum = bit2 ~width:dnum_width ( lor )
let bit_xor_dnum = bit2 ~width:dnum_width ( lxor )
let bit_neg_dnum = bit_neg_w ~width:dnum_width
let bit_lsh_dnum = shift_w ~width:dnum_width ( lsl )
let bit_rsh_dnum = shift_w ~width:dnum_width ( lsr )
let bit_check_dnum = bit_check_w ~width:dnum_width
let bit_set_dnum = bit_update_w ~width:dnum_width ( lor )
let bit_clear_dnum = bit_update_w ~width:dnum_width (fun a m -> a land lnot m)

(* ------------------------------------------------------------------------------ by name *)

let arg (a : Value.t option array) i =
  match a.(i) with Some v -> v | None -> type_mismatch "a required argument"

(* A function of required parameters only is also known by its number of them, so that an engine
   may call it without the array (Installed_routine.fixed). *)
type implementation = { any : Value.t option array -> result; fixed : Installed_routine.fixed option }

let any f = { any = f; fixed = None }
let f1 f = { any = (fun a -> f (arg a 0)); fixed = Some (One f) }
let f2 f = { any = (fun a -> f (arg a 0) (arg a 1)); fixed = Some (Two f) }
let f3 f = { any = (fun a -> f (arg a 0) (arg a 1) (arg a 2)); fixed = Some (Three f) }
let present (a : Value.t option array) i = Option.is_some a.(i)

(* StrToByte and ByteToStr: the argument, then the switches \Hex, \Okt, \Bin, \Char. *)
let byte_base a =
  Byte_text.base_of_switches ~hex:(present a 1) ~okt:(present a 2) ~bin:(present a 3) ~char:(present a 4)

let implementations =
  [ ("StrLen", 1, { (f1 str_len) with fixed = Some (Length str_len) });
    ("StrPart", 3, f3 str_part);
    ("StrFind", 4, any @@ fun a -> str_find ~not_in_set:(present a 3) (arg a 0) (arg a 1) (arg a 2));
    ("StrMatch", 3, f3 str_match);
    ("StrMap", 3, f3 str_map);
    ("StrMemb", 3, f3 str_memb);
    ("StrOrder", 3, f3 str_order);
    ("NumToStr", 3, any @@ fun a -> num_to_str (arg a 0) (arg a 1) ~exp:(present a 2));
    ("DnumToStr", 3, any @@ fun a -> dnum_to_str (arg a 0) (arg a 1) ~exp:(present a 2));
    ("ValToStr", 1, f1 val_to_str);
    ("Abs", 1, f1 abs_num);
    ("Sqrt", 1, f1 sqrt_num);
    ("Exp", 1, f1 exp_num);
    ("Pow", 2, f2 pow_num);
    ("Sin", 1, f1 sin_num);
    ("Cos", 1, f1 cos_num);
    ("Tan", 1, f1 tan_num);
    ("ASin", 1, f1 asin_num);
    ("ACos", 1, f1 acos_num);
    ("ATan", 1, f1 atan_num);
    ("ATan2", 2, f2 atan2_num);
    ("Round", 2, any @@ fun a -> round_num (arg a 0) ~dec:a.(1));
    ("Trunc", 2, any @@ fun a -> trunc_num (arg a 0) ~dec:a.(1));
    ("Max", 2, f2 max_num);
    ("Min", 2, f2 min_num);
    ("Distance", 2, f2 distance);
    ("DotProd", 2, f2 dot_prod);
    ("CrossProd", 2, f2 cross_prod);
    ("VectMagn", 1, f1 vect_magn);
    ("NumToDnum", 1, f1 num_to_dnum);
    ("DnumToNum", 2, any @@ fun a -> dnum_to_num (arg a 0) ~integer:(present a 1));
    ("AbsDnum", 1, f1 abs_num);
    ("SqrtDnum", 1, f1 sqrt_num);
    ("PowDnum", 2, f2 pow_num);
    ("SinDnum", 1, f1 sin_num);
    ("CosDnum", 1, f1 cos_num);
    ("TanDnum", 1, f1 tan_num);
    ("ASinDnum", 1, f1 asin_num);
    ("ACosDnum", 1, f1 acos_num);
    ("ATanDnum", 1, f1 atan_num);
    ("ATan2Dnum", 2, f2 atan2_num);
    ("RoundDnum", 2, any @@ fun a -> round_num (arg a 0) ~dec:a.(1));
    ("TruncDnum", 2, any @@ fun a -> trunc_num (arg a 0) ~dec:a.(1));
    ("PoseMult", 2, f2 pose_mult);
    ("PoseInv", 1, f1 pose_inv);
    ("PoseVect", 2, f2 pose_vect);
    ("OrientZYX", 3, f3 orient_zyx);
    ( "EulerZYX", 4,
      any @@ fun a ->
        let axis =
          if present a 0 then Some `X else if present a 1 then Some `Y
          else if present a 2 then Some `Z else None
        in
        euler_zyx axis (arg a 3) );
    ("NOrient", 1, f1 norient);
    ("BitAnd", 2, f2 bit_and);
    ("BitOr", 2, f2 bit_or);
    ("BitXOr", 2, f2 bit_xor);
    ("BitNeg", 1, f1 bit_neg);
    ("BitLSh", 2, f2 bit_lsh);
    ("BitRSh", 2, f2 bit_rsh);
    ("BitCheck", 2, f2 bit_check);
    ("BitAndDnum", 2, f2 bit_and_dnum);
    ("BitOrDnum", 2, f2 bit_or_dnum);
    ("BitXOrDnum", 2, f2 bit_xor_dnum);
    ("BitNegDnum", 1, f1 bit_neg_dnum);
    ("BitLShDnum", 2, f2 bit_lsh_dnum);
    ("BitRShDnum", 2, f2 bit_rsh_dnum);
    ("BitCheckDnum", 2, f2 bit_check_dnum);
    ("StrToByte", 5, any @@ fun a -> Byte_text.str_to_byte (byte_base a) (arg a 0));
    ("ByteToStr", 5, any @@ fun a -> Byte_text.byte_to_str (byte_base a) (arg a 0)) ]

let functions = List.map (fun (name, n, i) -> (name, n, i.any)) implementations

let table =
  let t = Hashtbl.create 97 in
  List.iter (fun (name, _, i) -> Hashtbl.replace t (String.lowercase_ascii name) i) implementations;
  t

let find name = Option.map (fun i -> i.any) (Hashtbl.find_opt table (String.lowercase_ascii name))
let find_fixed name = Option.bind (Hashtbl.find_opt table (String.lowercase_ascii name)) (fun i -> i.fixed)
