(* The canonical text of values in the events of schema rapid-sem/2 (doc/rulings.md R-4.5-m):
   the examples users met, and as properties: the text reads back to the same value, and no
   text with fewer significant digits does. *)

module O = Rapid_runtime.Observation
module V = Rapid_runtime.Value

let single x = V.Num (V.to_single x)

let examples () =
  List.iter (fun (what, v, text) -> Alcotest.(check string) what text (O.value v)) [
    ("9E+09 (held as 8999999488)", single 9e9, "9000000000");
    ("0.1", single 0.1, "0.1");
    ("1/3", single (1. /. 3.), "0.33333334");
    ("-0", single (-0.), "0");
    ("dnum -0", V.Dnum (-0.), "0");
    ("the largest single", single 3.4028234663852886e38, "3.4028235E+38");
    ("3.4E+38", single 3.4e38, "3.4E+38");
    ("123456789 (held as 123456792)", single 123456789., "123456790");
    ("16777216", single 16777216., "16777216");
    ("1E-05", single 1e-5, "1E-05");
    ("-2.5", single (-2.5), "-2.5");
    ("dnum 1/3", V.Dnum (1. /. 3.), "0.3333333333333333");
    ("dnum 9E+09", V.Dnum 9e9, "9000000000");
    ("dnum 1E+20", V.Dnum 1e20, "1E+20");
    ("a string", V.String "a\"b", "\"a\"\"b\"");
    ("a bool", V.Bool true, "TRUE");
    ("an array of records", V.Array [| V.Record [| single 1.; single 2. |]; V.Record [| single 3.; single 0.5 |] |],
     "[[1,2],[3,0.5]]");
  ]

(* The significant digits of a text in %g or plain form. *)
let digits text =
  let mantissa = match String.index_opt text 'E' with Some i -> String.sub text 0 i | None -> text in
  let ds = String.concat "" (String.split_on_char '.' (String.concat "" (String.split_on_char '-' mantissa))) in
  let n = String.length ds in
  let rec first i = if i < n && ds.[i] = '0' then first (i + 1) else i in
  let rec last i = if i > 0 && ds.[i - 1] = '0' then last (i - 1) else i in
  max 1 (last n - first 0)

let finite_single =
  QCheck.make ~print:(Printf.sprintf "%h")
    QCheck.Gen.(map (fun bits -> Int32.float_of_bits bits) (map Int32.of_int (int_range (-0x7F800000) 0x7F7FFFFF)))

let round_trip_num =
  QCheck.Test.make ~count:3000 ~name:"a num's text reads back to the same single, with no fewer digits possible"
    finite_single (fun x ->
        QCheck.assume (Float.is_finite x);
        let text = O.value (V.Num x) in
        let back = V.to_single (float_of_string text) in
        let d = digits text in
        let shorter = d > 1 && V.to_single (float_of_string (Printf.sprintf "%.*g" (d - 1) x)) = x in
        (back = x || (x = 0. && back = 0.)) && not shorter)

let round_trip_dnum =
  QCheck.Test.make ~count:3000 ~name:"a dnum's text reads back to the same double"
    QCheck.(make ~print:(Printf.sprintf "%h") Gen.(map Int64.float_of_bits ui64)) (fun x ->
        QCheck.assume (Float.is_finite x);
        float_of_string (O.value (V.Dnum x)) = x)

(* A fixed seed: the same values every run. *)
let property t () = QCheck.Test.check_exn ~rand:(Random.State.make [| 11 |]) t

let suite =
  ("observation", [
      Alcotest.test_case "value texts: the examples" `Quick examples;
      Alcotest.test_case "num texts round-trip, shortest" `Quick (property round_trip_num);
      Alcotest.test_case "dnum texts round-trip" `Quick (property round_trip_dnum) ])
