(* Run-time values (lib/semantics): rounding of literals to num and dnum, the operators of
   §3.12, the controller's number formats and the pure installed functions. Expected values
   are written from the manual, installed-facts.md (its examples) and doc/rulings.md, or
   computed by hand where a comment says how; the random properties check against oracles
   that do not share the code under test (neighbouring floats, strtod, exact rationals).

   Every random test has a fixed seed. *)

module V = Rapid_runtime.Value
module A = Rapid_runtime.Arith
module F = Rapid_runtime.Text_format
module L = Rapid_installed.Library
module NL = Rapid_syntax.Num_literal

(* ---------------------------------------------------------------- helpers *)

let literal precision text =
  match NL.of_text text with
  | Ok t -> V.of_literal t precision
  | Error e -> Alcotest.failf "literal %s: %s" text e

(* A num or dnum from the text of a RAPID literal, rounded as the program would round it. *)
let n text = literal `Num text
let d text = literal `Dnum text
let nf x = V.num x
let str s = V.String s
let b x = V.Bool x
let pos x y z = V.pos x y z
let orient a b c d = V.orient a b c d

(* Numbers compare by IEEE equality (0 = -0), everything else structurally. *)
let rec same (a : V.t) (b : V.t) =
  match a, b with
  | Num x, Num y | Dnum x, Dnum y -> x = y
  | Bool x, Bool y -> x = y
  | String x, String y -> x = y
  | Record x, Record y | Array x, Array y ->
      Array.length x = Array.length y && Array.for_all2 same x y
  | _ -> false

let value = Alcotest.testable (fun ppf v -> Stdlib.Format.pp_print_string ppf (V.to_debug_string v)) same
let outcome = Alcotest.result value Alcotest.string

let ok name expected actual = Alcotest.check outcome name (Ok expected) actual
let err name error actual = Alcotest.check outcome name (Error error) actual

let single_bits = function
  | V.Num x -> Int32.bits_of_float x
  | v -> Alcotest.failf "not a num: %s" (V.to_debug_string v)

let check_bits name expected v = Alcotest.(check int32) name expected (single_bits v)

let near name ~tolerance expected = function
  | Ok (V.Num x) | Ok (V.Dnum x) ->
      if Float.abs (x -. expected) > tolerance then
        Alcotest.failf "%s: %.9g is not within %g of %.9g" name x tolerance expected
  | Ok v -> Alcotest.failf "%s: %s is not a number" name (V.to_debug_string v)
  | Error e -> Alcotest.failf "%s: %s" name e

let run_property ~seed ~count ~name arb prop =
  QCheck.Test.check_exn ~rand:(Random.State.make [| seed |]) (QCheck.Test.make ~count ~name arb prop)

(* ---------------------------------------------------------------- literals *)

(* 1 + 2^-24 lies halfway between the singles 1 and 1 + 2^-23; adding 10^-35 puts the literal
   just above that midpoint. Its nearest double is the midpoint itself, so rounding through
   double precision ends on the tie and picks the even 1.0: the wrong single. *)
let above_midpoint = "1.00000005960464477539062500000000001"

let test_literal_rounding () =
  check_bits "0.1 (§2.13, single)" 0x3DCCCCCDl (n "0.1");
  check_bits "16777217 ties to even" 0x4B800000l (n "16777217");
  check_bits "16777219 ties to even (up)" 0x4B800002l (n "16777219");
  check_bits "just above a midpoint" 0x3F800001l (n above_midpoint);
  Alcotest.(check int32) "the same through double precision rounds twice" 0x3F800000l
    (Int32.bits_of_float (V.to_single (float_of_string above_midpoint)));
  check_bits "largest single" 0x7F7FFFFFl (n "3.4028234663852886E38");
  check_bits "smallest subnormal single" 0x00000001l (n "1.4E-45");
  check_bits "below half the smallest subnormal: 0" 0l (n "7.0E-46");
  check_bits "above half the smallest subnormal" 0x00000001l (n "7.1E-46");
  (* 2^-150 written exactly (5^150 * 10^-150): a tie between 0 and 2^-149, to even: 0. *)
  let half_subnormal = Z.to_string (Z.pow (Z.of_int 5) 150) ^ "E-150" in
  check_bits "exactly half the smallest subnormal: 0" 0l (n half_subnormal);
  let three_halves = Z.to_string (Z.mul (Z.of_int 3) (Z.pow (Z.of_int 5) 150)) ^ "E-150" in
  check_bits "three halves of it: 2^-148 (even)" 0x00000002l (n three_halves);
  (match n "3.5E38" with
   | Num x when x = infinity -> ()
   | v -> Alcotest.failf "3.5E38 as num: %s" (V.to_debug_string v));
  Alcotest.check value "0.1 as dnum" (V.Dnum 0.1) (d "0.1");
  Alcotest.check value "2E+43 as dnum (§2.13)" (V.Dnum 2e43) (d "2E+43");
  Alcotest.check value "0x7F" (V.Num 127.) (n "0x7F");
  Alcotest.check value "9007199254740993 as dnum ties to even" (V.Dnum 9007199254740992.)
    (d "9007199254740993")

(* Oracle: r is the nearest single when neither neighbour is nearer, and on a tie its last
   significand bit is 0. *)
let is_nearest_single q r =
  let bits = Int32.bits_of_float r in
  let neighbour k = Int32.float_of_bits (Int32.add bits k) in
  let dist x = Q.abs (Q.sub q (Q.of_float x)) in
  let dr = dist r in
  let check k =
    let x = neighbour k in
    (not (Float.is_finite x)) || Q.lt dr (dist x) || (Q.equal dr (dist x) && Int32.logand bits 1l = 0l)
  in
  check 1l && check (-1l)

let decimal_gen =
  QCheck.Gen.(
    map3
      (fun digits frac e -> Printf.sprintf "%s.%sE%d" digits frac e)
      (string_size ~gen:(char_range '0' '9') (int_range 1 20))
      (string_size ~gen:(char_range '0' '9') (int_range 0 20))
      (int_range (-60) 38))

let test_literal_property () =
  run_property ~seed:2024 ~count:3000 ~name:"num literals round to the nearest single"
    (QCheck.make ~print:Fun.id decimal_gen) (fun text ->
      match NL.of_text text with
      | Error _ -> QCheck.assume_fail ()
      | Ok t -> (
          let q = NL.to_q t in
          match V.of_literal t `Num with
          | Num r when Float.is_finite r -> is_nearest_single q r
          | _ -> QCheck.assume_fail ()));
  run_property ~seed:2025 ~count:3000 ~name:"dnum literals round as strtod does"
    (QCheck.make ~print:Fun.id decimal_gen) (fun text ->
      match NL.of_text text with
      | Error _ -> QCheck.assume_fail ()
      | Ok t -> same (V.of_literal t `Dnum) (V.Dnum (float_of_string text)))

(* ---------------------------------------------------------------- values *)

let test_copy_equal_default () =
  let original = V.Array [| pos 1. 2. 3.; pos 4. 5. 6. |] in
  let copy = V.copy original in
  (match copy with
   | Array [| Record c; _ |] -> c.(0) <- V.Num 99.
   | _ -> Alcotest.fail "copy has another shape");
  Alcotest.check value "updating a copy leaves the original" (V.Array [| pos 1. 2. 3.; pos 4. 5. 6. |])
    original;
  Alcotest.(check bool) "0 = -0 (IEEE)" true (V.equal (V.Num 0.) (V.Num (-0.)));
  Alcotest.(check bool) "arrays element-wise" true
    (V.equal (V.Array [| n "1"; n "2" |]) (V.Array [| n "1"; n "2" |]));
  Alcotest.(check bool) "arrays element-wise, different" false
    (V.equal (V.Array [| n "1"; n "2" |]) (V.Array [| n "1"; n "3" |]));
  Alcotest.check value "initial value of a record with an array (§2.22)"
    (V.Record [| V.Num 0.; V.Dnum 0.; V.Bool false; V.String ""; V.Array [| V.Num 0.; V.Num 0. |] |])
    (V.default_of (S_record [| S_num; S_dnum; S_bool; S_string; S_array (2, S_num) |]));
  let open Rapid_typing.Types in
  let r = { record_id = new_record_id (); record_name = "r"; components = [ ("a", Num); ("b", String) ] } in
  Alcotest.check value "shape of a num{2,3}"
    (V.Array (Array.init 2 (fun _ -> V.Array [| V.Num 0.; V.Num 0.; V.Num 0. |])))
    (V.default_of (V.shape_of_type { base = Num; dims = Sized [ 2; 3 ] }));
  Alcotest.check value "shape of a record" (V.Record [| V.Num 0.; V.String "" |])
    (V.default_of (V.shape_of_type (scalar (Record r))))

(* ---------------------------------------------------------------- §3.12 *)

let bin op a b = A.binary op a b

let test_num_arithmetic () =
  (* single(0.1) + single(0.2) = 0.300000004470348...; the singles around it are
     0.29999998211860657 and 0.30000001192092896, and the second is nearer: single(0.3). *)
  ok "0.1 + 0.2 = 0.3 in single precision" (n "0.3") (bin Num_add (n "0.1") (n "0.2"));
  ok "0.1 + 0.2 in double precision is not 0.3" (V.Bool false)
    (Result.bind (bin Dnum_add (d "0.1") (d "0.2")) (fun s -> bin Equal s (d "0.3")));
  ok "8388607 + 1 (exact, §2.13)" (n "8388608") (bin Num_add (n "8388607") (n "1"));
  ok "16777216 + 1 is rounded" (n "16777216") (bin Num_add (n "16777216") (n "1"));
  ok "num - num" (n "-1.5") (bin Num_sub (n "1") (n "2.5"));
  ok "num * num" (n "6") (bin Num_mul (n "2") (n "3"));
  check_bits "1 / 3 rounded to single" 0x3EAAAAABl
    (Result.get_ok (bin Num_div (n "1") (n "3")));
  err "1 / 0" "ERR_DIVZERO" (bin Num_div (n "1") (n "0"));
  err "0 / 0" "ERR_DIVZERO" (bin Num_div (n "0") (n "0"));
  err "dnum / 0" "ERR_DIVZERO" (bin Dnum_div (d "1") (d "0"));
  ok "dnum / dnum" (V.Dnum (1. /. 3.)) (bin Dnum_div (d "1") (d "3"));
  ok "dnum keeps integers to 2^52" (d "4503599627370496")
    (bin Dnum_add (d "4503599627370495") (d "1"));
  err "num overflow (R-3.12-c)" "ERR_OVERFLOW" (bin Num_mul (n "1E38") (n "10"));
  err "num overflow by addition" "ERR_OVERFLOW"
    (bin Num_add (n "3.4028234663852886E38") (n "3.4028234663852886E38"));
  err "dnum overflow" "ERR_OVERFLOW" (bin Dnum_mul (d "1E300") (d "1E300"));
  ok "unary minus" (n "-3") (A.unary Num_neg (n "3"));
  ok "unary plus" (n "3") (A.unary Num_plus (n "3"));
  ok "dnum unary minus" (d "-3") (A.unary Dnum_neg (d "3"));
  ok "dnum unary plus" (d "3") (A.unary Dnum_plus (d "3"));
  ok "dnum - dnum" (V.Dnum (0.3 -. 0.1)) (bin Dnum_sub (d "0.3") (d "0.1"));
  ok "dnum * dnum keeps what num loses" (d "16777217") (bin Dnum_mul (d "16777217") (d "1"));
  ok "num * num loses it" (n "16777216") (bin Num_mul (nf 16777217.) (n "1"));
  ok "comparison <" (b true) (bin Num_lt (n "1") (n "2"));
  ok "comparison <=" (b true) (bin Num_le (n "2") (n "2"));
  ok "comparison >" (b false) (bin Num_gt (n "2") (n "2"));
  ok "comparison >=" (b true) (bin Dnum_ge (d "3") (d "2"));
  ok "dnum <" (b false) (bin Dnum_lt (d "3") (d "2"));
  ok "dnum >" (b true) (bin Dnum_gt (d "3") (d "2"));
  ok "dnum <=" (b false) (bin Dnum_le (d "3") (d "2"));
  ok "num >=" (b false) (bin Num_ge (n "1") (n "2"))

(* R-3.12 (truncation toward zero) and R-3.12-b (operand errors). *)
let test_div_mod () =
  ok "7 DIV 2" (n "3") (bin Num_intdiv (n "7") (n "2"));
  ok "-7 DIV 2" (n "-3") (bin Num_intdiv (n "-7") (n "2"));
  ok "7 DIV -2" (n "-3") (bin Num_intdiv (n "7") (n "-2"));
  ok "-7 MOD 2" (n "-1") (bin Num_mod (n "-7") (n "2"));
  ok "7 MOD -2" (n "1") (bin Num_mod (n "7") (n "-2"));
  ok "8388608 DIV 2 (top of the sub-domain)" (n "4194304") (bin Num_intdiv (n "8388608") (n "2"));
  err "DIV by zero" "ERR_DIVZERO" (bin Num_intdiv (n "7") (n "0"));
  err "MOD by zero" "ERR_DIVZERO" (bin Num_mod (n "7") (n "0"));
  err "non-integer left operand" "ERR_NOTINTVAL" (bin Num_intdiv (n "7.5") (n "2"));
  err "non-integer right operand" "ERR_NOTINTVAL" (bin Num_mod (n "2") (n "0.5"));
  err "a non-integer operand is found before a zero divisor" "ERR_NOTINTVAL"
    (bin Num_intdiv (n "1.5") (n "0"));
  err "integer beyond the sub-domain" "ERR_MAXINTVAL" (bin Num_intdiv (n "16777216") (n "2"));
  err "below the sub-domain" "ERR_MAXINTVAL" (bin Num_mod (n "-8388608") (n "2"));
  ok "dnum DIV" (d "3") (bin Dnum_intdiv (d "7") (d "2"));
  ok "dnum MOD at 2^52 (2^52 = 4^26 = 1 mod 3)" (d "1") (bin Dnum_mod (d "4503599627370496") (d "3"));
  err "negative dnum operand (§3.12 note c)" "ERR_NOTINTVAL" (bin Dnum_intdiv (d "-7") (d "2"));
  err "negative dnum divisor" "ERR_NOTINTVAL" (bin Dnum_mod (d "7") (d "-2"));
  err "dnum beyond 2^52" "ERR_MAXINTVAL" (bin Dnum_intdiv (d "9007199254740992") (d "2"));
  err "dnum MOD by zero" "ERR_DIVZERO" (bin Dnum_mod (d "7") (d "0"))

let test_div_mod_property () =
  let gen = QCheck.(pair (int_range (-8388607) 8388608) (int_range (-8388607) 8388608)) in
  run_property ~seed:7 ~count:2000 ~name:"a = (a DIV b) * b + a MOD b, |a MOD b| < |b|" gen
    (fun (a, b) ->
      QCheck.assume (b <> 0);
      match bin Num_intdiv (nf (float a)) (nf (float b)), bin Num_mod (nf (float a)) (nf (float b)) with
      | Ok (Num q), Ok (Num r) ->
          let q = int_of_float q and r = int_of_float r in
          q * b + r = a && abs r < abs b && (r = 0 || (r < 0) = (a < 0))
      | _ -> false)

let test_strings_and_logic () =
  ok "string + string" (str "abcd") (bin String_concat (str "ab") (str "cd"));
  let s40 = String.make 40 'x' in
  ok "80 bytes" (str (s40 ^ s40)) (bin String_concat (str s40) (str s40));
  err "81 bytes" "ERR_STRTOOLNG" (bin String_concat (str s40) (str (s40 ^ "y")));
  err "bytes, not characters: 40 two-byte letters and one more" "ERR_STRTOOLNG"
    (bin String_concat (str (String.concat "" (List.init 40 (fun _ -> "\xc3\xa9")))) (str "a"));
  ok "XOR" (b true) (bin Xor (b true) (b false));
  ok "XOR equal" (b false) (bin Xor (b true) (b true));
  ok "NOT" (b false) (A.unary Not (b true));
  ok "= on strings" (b true) (bin Equal (str "a") (str "a"));
  ok "<> on strings" (b true) (bin Not_equal (str "a") (str "b"));
  ok "= on records" (b true) (bin Equal (pos 1. 2. 3.) (pos 1. 2. 3.));
  ok "<> on records" (b true) (bin Not_equal (pos 1. 2. 3.) (pos 1. 2. 4.));
  ok "= on arrays" (b true) (bin Equal (V.Array [| n "1"; n "2" |]) (V.Array [| n "1"; n "2" |]));
  err "= on arrays of different sizes (R-3.12-e)" "ERR_NOTEQDIM"
    (bin Equal (V.Array [| n "1"; n "2" |]) (V.Array [| n "1" |]));
  err "<> on 2-dimensional arrays of different inner sizes" "ERR_NOTEQDIM"
    (bin Not_equal (V.Array [| V.Array [| n "1" |] |]) (V.Array [| V.Array [| n "1"; n "2" |] |]));
  ok "0 = -0" (b true) (bin Equal (n "0") (A.unary Num_neg (n "0") |> Result.get_ok))

let test_geometry_operators () =
  ok "pos + pos" (pos 5. 7. 9.) (bin Pos_add (pos 1. 2. 3.) (pos 4. 5. 6.));
  ok "pos - pos" (pos (-3.) (-3.) (-3.)) (bin Pos_sub (pos 1. 2. 3.) (pos 4. 5. 6.));
  ok "num * pos" (pos 2. 4. 6.) (bin Num_pos_mul (n "2") (pos 1. 2. 3.));
  ok "pos * num" (pos 2. 4. 6.) (bin Pos_num_mul (pos 1. 2. 3.) (n "2"));
  ok "pos / num" (pos 1. 2. 3.) (bin Pos_num_div (pos 2. 4. 6.) (n "2"));
  ok "pos / num rounds each component" (V.Record [| n "0.1"; n "0.2"; n "0.3" |])
    (bin Pos_num_div (pos 1. 2. 3.) (n "10"));
  err "pos / 0" "ERR_DIVZERO" (bin Pos_num_div (pos 2. 4. 6.) (n "0"));
  err "pos component overflow" "ERR_OVERFLOW" (bin Pos_num_mul (pos 1e38 0. 0.) (n "10"));
  ok "x * y = z" (pos 0. 0. 1.) (bin Pos_cross (pos 1. 0. 0.) (pos 0. 1. 0.));
  (* [2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4] *)
  ok "[1,2,3] * [4,5,6]" (pos (-3.) 6. (-3.)) (bin Pos_cross (pos 1. 2. 3.) (pos 4. 5. 6.));
  ok "-pos" (pos (-1.) 2. (-3.)) (A.unary Pos_neg (pos 1. (-2.) 3.));
  ok "+pos" (pos 1. 2. 3.) (A.unary Pos_plus (pos 1. 2. 3.));
  ok "i * j = k" (orient 0. 0. 0. 1.) (bin Orient_mul (orient 0. 1. 0. 0.) (orient 0. 0. 1. 0.));
  ok "j * i = -k" (orient 0. 0. 0. (-1.)) (bin Orient_mul (orient 0. 0. 1. 0.) (orient 0. 1. 0. 0.));
  ok "k * i = j" (orient 0. 0. 1. 0.) (bin Orient_mul (orient 0. 0. 0. 1.) (orient 0. 1. 0. 0.));
  ok "identity * q" (orient 0.5 0.5 0.5 0.5) (bin Orient_mul (orient 1. 0. 0. 0.) (orient 0.5 0.5 0.5 0.5));
  (* Two rotations of 120 degrees about (1,1,1): [0.5,0.5,0.5,0.5]^2 = [-0.5,0.5,0.5,0.5]. *)
  ok "q * q" (orient (-0.5) 0.5 0.5 0.5) (bin Orient_mul (orient 0.5 0.5 0.5 0.5) (orient 0.5 0.5 0.5 0.5))

(* Each num result is the exact result rounded once (R-3.12-d): compared with exact rational
   arithmetic on random singles. *)
let test_rounding_property () =
  let single = QCheck.map (fun x -> V.to_single x) QCheck.(float_range (-1e6) 1e6) in
  let exact op a b =
    let qa = Q.of_float a and qb = Q.of_float b in
    match op with
    | A.Num_add -> Q.add qa qb
    | Num_sub -> Q.sub qa qb
    | Num_mul -> Q.mul qa qb
    | _ -> Q.div qa qb
  in
  run_property ~seed:11 ~count:3000 ~name:"num + - * / are correctly rounded" (QCheck.pair single single)
    (fun (a, b) ->
      List.for_all
        (fun op ->
          if op = A.Num_div && b = 0. then true
          else
            match bin op (V.Num a) (V.Num b) with
            | Ok (Num r) -> is_nearest_single (exact op a b) r
            | _ -> false)
        [ A.Num_add; Num_sub; Num_mul; Num_div ]);
  run_property ~seed:12 ~count:500 ~name:"cross product components are correctly rounded"
    (QCheck.pair (QCheck.triple single single single) (QCheck.triple single single single))
    (fun ((x1, y1, z1), (x2, y2, z2)) ->
      let q = Q.of_float in
      let det a b c e = Q.sub (Q.mul (q a) (q b)) (Q.mul (q c) (q e)) in
      match bin Pos_cross (pos x1 y1 z1) (pos x2 y2 z2) with
      | Ok (Record [| Num x; Num y; Num z |]) ->
          is_nearest_single (det y1 z2 z1 y2) x && is_nearest_single (det z1 x2 x1 z2) y
          && is_nearest_single (det x1 y2 y1 x2) z
      | _ -> false)

(* ---------------------------------------------------------------- formatting *)

let test_num_to_str () =
  ok "NumToStr(0.38521,3) (installed-facts §1)" (str "0.385") (L.num_to_str (n "0.38521") (n "3") ~exp:false);
  ok "NumToStr(0.38521,2\\Exp) (R-13-a)" (str "3.85E-01") (L.num_to_str (n "0.38521") (n "2") ~exp:true);
  ok "NumToStr(1,2)" (str "1.00") (L.num_to_str (n "1") (n "2") ~exp:false);
  ok "NumToStr(2.5,0): ties away from zero" (str "3") (L.num_to_str (n "2.5") (n "0") ~exp:false);
  ok "NumToStr(-2.5,0)" (str "-3") (L.num_to_str (n "-2.5") (n "0") ~exp:false);
  ok "NumToStr(0.125,2): the exact value is a tie" (str "0.13") (L.num_to_str (n "0.125") (n "2") ~exp:false);
  (* single(1.005) = 1.00499999523..., below the tie. *)
  ok "NumToStr(1.005,2): the exact single is below 1.005" (str "1.00")
    (L.num_to_str (n "1.005") (n "2") ~exp:false);
  ok "NumToStr(-0.001,2): no minus before zero" (str "0.00") (L.num_to_str (n "-0.001") (n "2") ~exp:false);
  ok "NumToStr(123456,1)" (str "123456.0") (L.num_to_str (n "123456") (n "1") ~exp:false);
  ok "NumToStr(0,2\\Exp)" (str "0.00E+00") (L.num_to_str (n "0") (n "2") ~exp:true);
  ok "NumToStr(9.999,2\\Exp) carries" (str "1.00E+01") (L.num_to_str (n "9.999") (n "2") ~exp:true);
  ok "NumToStr(-1E30,1\\Exp)" (str "-1.0E+30") (L.num_to_str (n "-1E30") (n "1") ~exp:true);
  ok "NumToStr(1E-5,0\\Exp)" (str "1E-05") (L.num_to_str (n "1E-5") (n "0") ~exp:true);
  err "Dec not an integer" "ERR_NOTINTVAL" (L.num_to_str (n "1") (n "1.5") ~exp:false);
  err "Dec negative" "ERR_ARGVALERR" (L.num_to_str (n "1") (n "-1") ~exp:false);
  err "over 80 characters" "ERR_STRTOOLNG" (L.num_to_str (n "1E38") (n "60") ~exp:false);
  ok "DnumToStr(val,15)" (str "0.100000000000000") (L.dnum_to_str (d "0.1") (n "15") ~exp:false);
  ok "DnumToStr of a large integer" (str "4503599627370496") (L.dnum_to_str (d "4503599627370496") (n "0") ~exp:false);
  ok "DnumToStr \\Exp" (str "1.234567890E+09") (L.dnum_to_str (d "1234567890") (n "9") ~exp:true)

let test_num_text () =
  let text v = F.value_text v in
  Alcotest.(check string) "ValToStr(1.234567890123456789) (installed-facts §1)" "1.23457"
    (text (n "1.234567890123456789"));
  Alcotest.(check string) "0.1" "0.1" (text (n "0.1"));
  Alcotest.(check string) "integers" "250" (text (n "250"));
  Alcotest.(check string) "negative" "-3" (text (n "-3"));
  Alcotest.(check string) "8388608 in full" "8388608" (text (n "8388608"));
  Alcotest.(check string) "beyond the exact sub-domain: 6 digits" "1.67772E+07" (text (n "16777216"));
  Alcotest.(check string) "decimal part below 0.000005: an integer" "2" (text (n "2.000001"));
  Alcotest.(check string) "decimal part above 0.999995: an integer" "2" (text (n "1.999999"));
  Alcotest.(check string) "decimal part 0.00001: 6 digits" "2.00001" (text (n "2.00001"));
  Alcotest.(check string) "tiny: 0" "0" (text (n "0.0000001"));
  Alcotest.(check string) "tiny negative: 0, no sign" "0" (text (n "-0.0000001"));
  Alcotest.(check string) "small: exponent" "1.234E-05" (text (n "0.00001234"));
  Alcotest.(check string) "0.0001234: positional" "0.0001234" (text (n "0.0001234"));
  Alcotest.(check string) "6 digits" "123457" (text (n "123456.7"));
  Alcotest.(check string) "7 digits: exponent" "1.23457E+06" (text (n "1234567.5"));
  Alcotest.(check string) "1E10" "1E+10" (text (n "1E10"));
  Alcotest.(check string) "-0.5" "-0.5" (text (n "-0.5"));
  Alcotest.(check string) "dnum: 15 digits" "0.333333333333333" (text (V.Dnum (1. /. 3.)));
  Alcotest.(check string) "dnum 0.1" "0.1" (text (d "0.1"));
  Alcotest.(check string) "dnum integer" "4503599627370496" (text (d "4503599627370496"));
  Alcotest.(check string) "dnum 1E20" "1E+20" (text (d "1E20"));
  Alcotest.(check string) "dnum 0.0001: positional" "0.0001" (text (d "0.0001"));
  Alcotest.(check string) "dnum 0.000001: exponent" "1E-06" (text (d "0.000001"));
  Alcotest.(check string) "bool" "TRUE" (text (b true));
  Alcotest.(check string) "pos, no spaces" "[0.5,-1.25,100]" (text (pos 0.5 (-1.25) 100.));
  Alcotest.(check string) "pose" "[[1,2,3],[1,0,0,0]]" (text (V.pose (pos 1. 2. 3.) (orient 1. 0. 0. 0.)));
  Alcotest.(check string) "string in quotes (R-13-b)" "\"a\"\"b\\\\c\\07\"" (text (str "a\"b\\c\007"));
  Alcotest.(check string) "record with a string" "[FALSE,\"\"]" (text (V.Record [| b false; str "" |]))

let test_val_to_str_tpwrite () =
  ok "ValToStr(TRUE)" (str "TRUE") (L.val_to_str (b true));
  ok "ValToStr(pos)" (str "[100,200,300]") (L.val_to_str (pos 100. 200. 300.));
  ok "ValToStr of a string" (str "\"Robot\"") (L.val_to_str (str "Robot"));
  err "ValToStr over 80 bytes" "ERR_STRTOOLNG" (L.val_to_str (str (String.make 79 'x')));
  Alcotest.(check string) "TPWrite \\Num" "Value: 3" (F.tpwrite "Value: " (Some (n "3")));
  Alcotest.(check string) "TPWrite \\Num 6 digits" "r = 0.333333" (F.tpwrite "r = " (Some (nf (1. /. 3.))));
  Alcotest.(check string) "TPWrite \\Bool" "ok: FALSE" (F.tpwrite "ok: " (Some (b false)));
  Alcotest.(check string) "TPWrite \\Pos" "p: [1,2,3]" (F.tpwrite "p: " (Some (pos 1. 2. 3.)));
  Alcotest.(check string) "TPWrite \\Orient" "[1,0,0,0]" (F.tpwrite "" (Some (orient 1. 0. 0. 0.)));
  Alcotest.(check string) "TPWrite \\Dnum" "d=123456789012" (F.tpwrite "d=" (Some (d "123456789012")));
  Alcotest.(check string) "TPWrite alone" "Hello" (F.tpwrite "Hello" None)

(* The fixed format is within half a unit of its last digit of the exact value (an oracle that
   reads the text back as a rational). *)
let test_fixed_property () =
  let gen = QCheck.(pair (map V.to_single (float_range (-1e7) 1e7)) (int_range 0 8)) in
  run_property ~seed:5 ~count:2000 ~name:"fixed is within half a unit" gen (fun (x, dec) ->
      let text = F.fixed x ~decimals:dec in
      let digits = String.concat "" (String.split_on_char '.' text) in
      let shown = Q.div (Q.of_string digits) (F.pow10 dec) in
      Q.leq (Q.abs (Q.sub shown (Q.of_float x))) (Q.div (F.pow10 (-dec)) (Q.of_int 2)))

(* ---------------------------------------------------------------- strings *)

let robotics = str "Robotics"

let test_string_functions () =
  ok "StrLen(\"Robotics\")" (n "8") (L.str_len robotics);
  ok "StrPart(\"Robotics\",1,5)" (str "Robot") (L.str_part robotics (n "1") (n "5"));
  ok "StrPart at the end" (str "s") (L.str_part robotics (n "8") (n "1"));
  ok "StrPart empty past the end" (str "") (L.str_part robotics (n "9") (n "0"));
  err "StrPart from 0" "ERR_OUTOFBND" (L.str_part robotics (n "0") (n "1"));
  err "StrPart past the end" "ERR_OUTOFBND" (L.str_part robotics (n "6") (n "4"));
  err "StrPart negative length" "ERR_OUTOFBND" (L.str_part robotics (n "1") (n "-1"));
  err "StrPart non-integer" "ERR_NOTINTVAL" (L.str_part robotics (n "1.5") (n "1"));
  ok "StrFind(\"Robotics\",1,\"aeiou\")" (n "2") (L.str_find ~not_in_set:false robotics (n "1") (str "aeiou"));
  ok "StrFind \\NotInSet" (n "1") (L.str_find ~not_in_set:true robotics (n "1") (str "aeiou"));
  ok "StrFind(\"IRB 6400\",1,STR_DIGIT)" (n "5")
    (L.str_find ~not_in_set:false (str "IRB 6400") (n "1") (str "0123456789"));
  ok "StrFind from 3" (n "4") (L.str_find ~not_in_set:false robotics (n "3") (str "aeiou"));
  ok "StrFind nothing: StrLen + 1" (n "9") (L.str_find ~not_in_set:false robotics (n "1") (str "xyz"));
  ok "StrFind from StrLen + 1" (n "9") (L.str_find ~not_in_set:false robotics (n "9") (str "s"));
  err "StrFind from StrLen + 2" "ERR_OUTOFBND" (L.str_find ~not_in_set:false robotics (n "10") (str "s"));
  ok "StrMatch(\"Robotics\",1,\"bo\")" (n "3") (L.str_match robotics (n "1") (str "bo"));
  ok "StrMatch not found" (n "9") (L.str_match robotics (n "1") (str "box"));
  ok "StrMatch from after the hit" (n "9") (L.str_match robotics (n "4") (str "bo"));
  ok "StrMatch the empty pattern" (n "2") (L.str_match robotics (n "2") (str ""));
  ok "StrMap(\"Robotics\",\"aeiou\",\"AEIOU\")" (str "RObOtIcs")
    (L.str_map robotics (str "aeiou") (str "AEIOU"));
  ok "StrMap STR_LOWER STR_UPPER" (str "ROBOTICS 2")
    (L.str_map (str "Robotics 2") (str "abcdefghijklmnopqrstuvwxyz") (str "ABCDEFGHIJKLMNOPQRSTUVWXYZ"));
  ok "StrMap with a short ToMap (R-13-c)" (str "RObOtics") (L.str_map robotics (str "oi") (str "O"));
  ok "StrMemb(\"Robotics\",2,\"aeiou\")" (b true) (L.str_memb robotics (n "2") (str "aeiou"));
  ok "StrMemb(\"Robotics\",3,\"aeiou\")" (b false) (L.str_memb robotics (n "3") (str "aeiou"));
  err "StrMemb past the end" "ERR_OUTOFBND" (L.str_memb robotics (n "9") (str "aeiou"));
  let upper = str "ABCDEFGHIJKLMNOPQRSTUVWXYZ" in
  ok "StrOrder(\"FIRST\",\"SECOND\",STR_UPPER)" (b true) (L.str_order (str "FIRST") (str "SECOND") upper);
  ok "StrOrder(\"FIRST\",\"FIRSTB\",STR_UPPER)" (b true) (L.str_order (str "FIRST") (str "FIRSTB") upper);
  ok "StrOrder(\"FIRSTB\",\"FIRST\",STR_UPPER)" (b false) (L.str_order (str "FIRSTB") (str "FIRST") upper);
  ok "StrOrder of equal strings" (b false) (L.str_order (str "AB") (str "AB") upper);
  ok "StrOrder by the order given" (b true) (L.str_order (str "B") (str "A") (str "BA"));
  ok "StrOrder: bytes not in Order after it (R-13-c)" (b false) (L.str_order (str "A1") (str "AB") upper);
  ok "StrOrder: among themselves by code" (b true) (L.str_order (str "1") (str "2") upper)

let test_str_to_val () =
  let check name expected text shape =
    Alcotest.(check (option value)) name expected (L.str_to_val (str text) shape)
  in
  check "StrToVal(\"3.85\",nval)" (Some (n "3.85")) "3.85" S_num;
  check "blanks and a sign" (Some (n "-2.5E-3")) "  -2.5E-3 " S_num;
  check "hexadecimal" (Some (n "31")) "0x1F" S_num;
  check ".5" (Some (n "0.5")) ".5" S_num;
  check "38." (Some (n "38")) "38." S_num;
  check "a pos" (Some (pos 1. 2. 3.)) "[1,2,3]" V.pos_shape;
  check "a pos with blanks" (Some (pos 1. 2. 3.)) "[ 1 , 2 , 3 ]" V.pos_shape;
  check "a pose" (Some (V.pose (pos 1. 2. 3.) (orient 1. 0. 0. 0.))) "[[1,2,3],[1,0,0,0]]" V.pose_shape;
  check "too few components" None "[1,2]" V.pos_shape;
  check "too many components" None "[1,2,3,4]" V.pos_shape;
  check "not a number" None "abc" S_num;
  check "trailing text" None "12abc" S_num;
  check "an exponent without digits" None "2E" S_num;
  check "two points" None "1.5.2" S_num;
  check "nothing" None "" S_num;
  check "too large for num" None "1E39" S_num;
  check "not too large for dnum" (Some (V.Dnum 1e39)) "1E39" S_dnum;
  check "TRUE" (Some (b true)) "TRUE" S_bool;
  check "true, any letter case" (Some (b true)) "true" S_bool;
  check "not a bool" None "yes" S_bool;
  check "a string literal" (Some (str "a\"b\\c\007")) "\"a\"\"b\\\\c\\07\"" S_string;
  check "a string without quotes" None "abc" S_string;
  check "an array" (Some (V.Array [| b true; b false |])) "[TRUE,FALSE]" (S_array (2, S_bool));
  check "a handle has no text" None "0" (S_handle "iodev")

let test_str_to_val_property () =
  let gen = QCheck.(string_gen_of_size (Gen.int_range 0 30) Gen.char) in
  run_property ~seed:3 ~count:2000 ~name:"StrToVal reads back what ValToStr writes" gen (fun s ->
      match L.val_to_str (str s) with
      | Ok text -> (
          match L.str_to_val text S_string with Some v -> same v (str s) | None -> false)
      | Error _ -> QCheck.assume_fail ())

(* ---------------------------------------------------------------- arithmetic functions *)

let test_math () =
  ok "Round(0.3852138\\Dec:=3) (installed-facts §1)" (n "0.385") (L.round_num (n "0.3852138") ~dec:(Some (n "3")));
  ok "Round(0.3852138\\Dec:=1)" (n "0.4") (L.round_num (n "0.3852138") ~dec:(Some (n "1")));
  ok "Round(0.3852138)" (n "0") (L.round_num (n "0.3852138") ~dec:None);
  ok "Trunc(0.3852138\\Dec:=3)" (n "0.385") (L.trunc_num (n "0.3852138") ~dec:(Some (n "3")));
  ok "Round(2.5): ties away from zero (R-13-d)" (n "3") (L.round_num (n "2.5") ~dec:None);
  ok "Round(-2.5)" (n "-3") (L.round_num (n "-2.5") ~dec:None);
  ok "Trunc(-2.7)" (n "-2") (L.trunc_num (n "-2.7") ~dec:None);
  ok "RoundDnum" (d "0.333") (L.round_num (V.Dnum (1. /. 3.)) ~dec:(Some (n "3")));
  err "Round with a negative \\Dec" "ERR_ARGVALERR" (L.round_num (n "1") ~dec:(Some (n "-1")));
  err "Round with a non-integer \\Dec" "ERR_NOTINTVAL" (L.round_num (n "1") ~dec:(Some (n "0.5")));
  ok "Abs" (n "3") (L.abs_num (n "-3"));
  ok "AbsDnum" (d "3") (L.abs_num (d "-3"));
  ok "Sqrt(2) rounded to single" (nf (sqrt 2.)) (L.sqrt_num (n "2"));
  ok "SqrtDnum(2)" (V.Dnum (sqrt 2.)) (L.sqrt_num (d "2"));
  err "Sqrt(-1) (R-13-e)" "ERR_ARGVALERR" (L.sqrt_num (n "-1"));
  ok "Exp(0)" (n "1") (L.exp_num (n "0"));
  err "Exp(100) overflows single" "ERR_OVERFLOW" (L.exp_num (n "100"));
  ok "Pow(2,10)" (n "1024") (L.pow_num (n "2") (n "10"));
  err "Pow(-8,0.5)" "ERR_ARGVALERR" (L.pow_num (n "-8") (n "0.5"));
  err "Pow(0,-1)" "ERR_OVERFLOW" (L.pow_num (n "0") (n "-1"));
  ok "Sin(30)" (n "0.5") (L.sin_num (n "30"));
  ok "Sin(90)" (n "1") (L.sin_num (n "90"));
  ok "Sin(180) is 0 exactly" (n "0") (L.sin_num (n "180"));
  ok "Sin(-90)" (n "-1") (L.sin_num (n "-90"));
  ok "Sin(720)" (n "0") (L.sin_num (n "720"));
  ok "Cos(90) is 0 exactly" (n "0") (L.cos_num (n "90"));
  ok "Cos(180)" (n "-1") (L.cos_num (n "180"));
  ok "Cos(-270)" (n "0") (L.cos_num (n "-270"));
  ok "Tan(45)" (n "1") (L.tan_num (n "45"));
  err "Tan(90)" "ERR_OVERFLOW" (L.tan_num (n "90"));
  ok "ASin(1)" (n "90") (L.asin_num (n "1"));
  ok "ASin(0.5)" (n "30") (L.asin_num (n "0.5"));
  err "ASin(2)" "ERR_ARGVALERR" (L.asin_num (n "2"));
  ok "ACos(-1)" (n "180") (L.acos_num (n "-1"));
  err "ACos(-1.5)" "ERR_ARGVALERR" (L.acos_num (n "-1.5"));
  ok "ATan(1)" (n "45") (L.atan_num (n "1"));
  ok "ATan2(1,-1)" (n "135") (L.atan2_num (n "1") (n "-1"));
  ok "ATan2(-1,-1)" (n "-135") (L.atan2_num (n "-1") (n "-1"));
  ok "ATan2(0,0)" (n "0") (L.atan2_num (n "0") (n "0"));
  ok "SinDnum(30)" (V.Dnum (Float.sin (30. *. Float.pi /. 180.))) (L.sin_num (d "30"));
  ok "Max" (n "3") (L.max_num (n "3") (n "-4"));
  ok "Min" (n "-4") (L.min_num (n "3") (n "-4"));
  ok "NumToDnum" (V.Dnum (V.to_single 0.1)) (L.num_to_dnum (n "0.1"));
  ok "DnumToNum" (n "0.1") (L.dnum_to_num (d "0.1") ~integer:false);
  err "DnumToNum beyond num (R-13-g)" "ERR_NUM_LIMIT" (L.dnum_to_num (d "1E39") ~integer:false);
  ok "DnumToNum \\Integer" (n "5") (L.dnum_to_num (d "5") ~integer:true);
  err "DnumToNum \\Integer of 2.5" "ERR_NOTINTVAL" (L.dnum_to_num (d "2.5") ~integer:true);
  err "DnumToNum \\Integer beyond the sub-domain" "ERR_NUM_LIMIT" (L.dnum_to_num (d "10000000") ~integer:true)

let test_vectors_and_poses () =
  ok "Distance" (n "5") (L.distance (pos 0. 0. 0.) (pos 3. 4. 0.));
  ok "DotProd" (n "32") (L.dot_prod (pos 1. 2. 3.) (pos 4. 5. 6.));
  ok "CrossProd" (pos (-3.) 6. (-3.)) (L.cross_prod (pos 1. 2. 3.) (pos 4. 5. 6.));
  ok "VectMagn" (n "13") (L.vect_magn (pos 3. 4. 12.));
  (* [0,0,0,1] turns 180 degrees about z: R = diag(-1,-1,1). *)
  let half_turn = V.pose (pos 10. 0. 0.) (orient 0. 0. 0. 1.) in
  ok "PoseVect" (pos 9. (-2.) 3.) (L.pose_vect half_turn (pos 1. 2. 3.));
  ok "PoseMult" (V.pose (pos 9. (-2.) 3.) (orient 0. 0. 1. 0.))
    (L.pose_mult half_turn (V.pose (pos 1. 2. 3.) (orient 0. 1. 0. 0.)));
  let p = V.pose (pos 10. 20. 30.) (orient 0. 0. 0. 1.) in
  ok "PoseInv" (V.pose (pos 10. 20. (-30.)) (orient 0. 0. 0. (-1.))) (L.pose_inv p);
  ok "PoseMult(p, PoseInv(p)) = identity" (V.pose (pos 0. 0. 0.) (orient 1. 0. 0. 0.))
    (Result.bind (L.pose_inv p) (L.pose_mult p));
  ok "OrientZYX(0,0,0)" (orient 1. 0. 0. 0.) (L.orient_zyx (n "0") (n "0") (n "0"));
  ok "OrientZYX(180,0,0)" (orient 0. 0. 0. 1.) (L.orient_zyx (n "180") (n "0") (n "0"));
  ok "OrientZYX(0,0,180)" (orient 0. 1. 0. 0.) (L.orient_zyx (n "0") (n "0") (n "180"));
  let r = Result.get_ok (L.orient_zyx (n "30") (n "20") (n "10")) in
  near "EulerZYX(\\Z, OrientZYX(30,20,10))" ~tolerance:1e-4 30. (L.euler_zyx (Some `Z) r);
  near "EulerZYX(\\Y, ...)" ~tolerance:1e-4 20. (L.euler_zyx (Some `Y) r);
  near "EulerZYX(\\X, ...)" ~tolerance:1e-4 10. (L.euler_zyx (Some `X) r);
  err "EulerZYX without a switch (R-13-f)" "ERR_ARGVALERR" (L.euler_zyx None r);
  (* The orient of OrientZYX(90,0,0) is [cos 45, 0, 0, sin 45]. *)
  near "OrientZYX(90,0,0).q4" ~tolerance:1e-7 (sqrt 0.5)
    (Result.map (fun o -> (V.components o).(3)) (L.orient_zyx (n "90") (n "0") (n "0")));
  ok "NOrient of a slightly long quaternion" (orient 1. 0. 0. 0.) (L.norient (orient 1.02 0. 0. 0.));
  ok "NOrient([0.7,0,0,0.7])" (orient (sqrt 0.5) 0. 0. (sqrt 0.5)) (L.norient (orient 0.7 0. 0. 0.7));
  err "NOrient beyond 0.1 (installed-facts §3)" "ERR_ILLQUAT" (L.norient (orient 2. 0. 0. 0.));
  err "NOrient of a short quaternion" "ERR_ILLQUAT" (L.norient (orient 0.9 0. 0. 0.))

let test_bits () =
  ok "BitAnd" (n "8") (L.bit_and (n "12") (n "10"));
  ok "BitOr" (n "14") (L.bit_or (n "12") (n "10"));
  ok "BitXOr" (n "6") (L.bit_xor (n "12") (n "10"));
  ok "BitNeg" (n "255") (L.bit_neg (n "0"));
  ok "BitLSh drops bits past 8" (n "0") (L.bit_lsh (n "128") (n "1"));
  ok "BitLSh" (n "8") (L.bit_lsh (n "1") (n "3"));
  ok "BitRSh" (n "1") (L.bit_rsh (n "8") (n "3"));
  ok "BitCheck bit 1" (b true) (L.bit_check (n "5") (n "1"));
  ok "BitCheck bit 2" (b false) (L.bit_check (n "5") (n "2"));
  ok "BitSet bit 8" (n "128") (L.bit_set (n "0") (n "8"));
  ok "BitClear bit 1" (n "254") (L.bit_clear (n "255") (n "1"));
  err "a byte of 256 (R-13-h)" "ERR_ARGVALERR" (L.bit_and (n "256") (n "1"));
  err "bit position 9" "ERR_ARGVALERR" (L.bit_check (n "1") (n "9"));
  err "a byte of 1.5" "ERR_NOTINTVAL" (L.bit_or (n "1.5") (n "1"));
  ok "BitCheckDnum bit 52" (b true) (L.bit_check_dnum (d "2251799813685248") (n "52"));
  ok "BitNegDnum" (d "4503599627370495") (L.bit_neg_dnum (d "0"));
  ok "BitSetDnum" (d "4294967296") (L.bit_set_dnum (d "0") (n "33"));
  err "bit position 53" "ERR_ARGVALERR" (L.bit_check_dnum (d "1") (n "53"))

(* ---------------------------------------------------------------- the table by name *)

(* The installed FUNC declarations, with their parameters counted one per alternative. *)
let installed_functions () =
  let open Rapid_syntax.Ast in
  match Rapid_typing.Installed_env.modules () with
  | Error _ -> Alcotest.fail "the installed environment does not parse"
  | Ok modules ->
      List.concat_map
        (fun m ->
          List.filter_map
            (fun (r : routine_declaration) ->
              match r.it with
              | Function_declaration { name = { it = Ident name; _ }; parameters; _ } ->
                  let count (p : parameter) =
                    match p.it with
                    | Required_parameter _ -> 1
                    | Optional_parameter alternatives -> List.length alternatives
                    | PAR_placeholder -> 1
                  in
                  let module_name = match m.module_name.it with Ident s -> s | ID_placeholder -> "" in
                  Some (module_name, name, List.fold_left (fun acc p -> acc + count p) 0 parameters)
              | _ -> None)
            m.routine_declarations)
        modules

let test_table () =
  let installed = installed_functions () in
  List.iter
    (fun (name, arity, _) ->
      match List.find_opt (fun (_, n, _) -> String.lowercase_ascii n = String.lowercase_ascii name) installed with
      | None -> Alcotest.failf "%s is not an installed function" name
      | Some (_, _, count) -> Alcotest.(check int) (name ^ ": parameters") count arity)
    L.functions;
  (* Every function of the string and math modules is here, and the geometry functions of
     the motion module (StrToVal apart: its Val is INOUT), or in System_routines (DecToHex). *)
  let geometry = [ "PoseMult"; "PoseInv"; "PoseVect"; "OrientZYX"; "EulerZYX"; "NOrient" ] in
  List.iter
    (fun (m, name, _) ->
      let wanted =
        (m = "Installed_string" || m = "Installed_math" || List.mem name geometry) && name <> "StrToVal"
      in
      if wanted && L.find name = None && not (Rapid_installed.System_routines.modelled name) then
        Alcotest.failf "%s (%s) has no implementation" name m)
    installed;
  let call name args = (Option.get (L.find name)) args in
  ok "StrFind by name, \\NotInSet present" (n "1")
    (call "strfind" [| Some robotics; Some (n "1"); Some (str "aeiou"); Some (b true) |]);
  ok "Round by name, \\Dec absent" (n "0") (call "Round" [| Some (n "0.3852138"); None |]);
  near "EulerZYX by name, \\Y" ~tolerance:1e-4 20.
    (call "EulerZYX" [| None; Some (b true); None; Some (Result.get_ok (L.orient_zyx (n "30") (n "20") (n "10"))) |]);
  ok "NumToStr by name, \\Exp" (str "3.85E-01") (call "NumToStr" [| Some (n "0.38521"); Some (n "2"); Some (b true) |])

(* ---------------------------------------------------------------- suite *)

let suite =
  ( "values",
    [ Alcotest.test_case "literals round once to single or double" `Quick test_literal_rounding;
      Alcotest.test_case "literal rounding, random" `Quick test_literal_property;
      Alcotest.test_case "copy, equality, initial values" `Quick test_copy_equal_default;
      Alcotest.test_case "num and dnum operators" `Quick test_num_arithmetic;
      Alcotest.test_case "DIV and MOD" `Quick test_div_mod;
      Alcotest.test_case "DIV and MOD, random" `Quick test_div_mod_property;
      Alcotest.test_case "strings, logic, equality" `Quick test_strings_and_logic;
      Alcotest.test_case "pos and orient operators" `Quick test_geometry_operators;
      Alcotest.test_case "correct rounding, random" `Quick test_rounding_property;
      Alcotest.test_case "NumToStr and DnumToStr" `Quick test_num_to_str;
      Alcotest.test_case "number text of ValToStr and TPWrite" `Quick test_num_text;
      Alcotest.test_case "ValToStr and TPWrite" `Quick test_val_to_str_tpwrite;
      Alcotest.test_case "fixed format, random" `Quick test_fixed_property;
      Alcotest.test_case "string functions" `Quick test_string_functions;
      Alcotest.test_case "StrToVal" `Quick test_str_to_val;
      Alcotest.test_case "StrToVal of ValToStr, random" `Quick test_str_to_val_property;
      Alcotest.test_case "arithmetic functions" `Quick test_math;
      Alcotest.test_case "vectors and poses" `Quick test_vectors_and_poses;
      Alcotest.test_case "bit functions" `Quick test_bits;
      Alcotest.test_case "functions by name" `Quick test_table ] )
