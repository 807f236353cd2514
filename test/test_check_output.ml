(* The machine-readable output of `rapid-sem check --format json|sarif`: its shape, against the
   fields that SARIF 2.1.0 requires and that CI systems and editors read (version,
   runs[].tool.driver.name, results[].message.text, locations[].physicalLocation
   .artifactLocation.uri, region.startLine/startColumn), and its completeness: every diagnostic
   of the text format is there, with the same place. The exact text is pinned by the golden
   tests (the test/golden/check-format cases). *)

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

(* Standard output and standard error of rapid-sem run on [args] in test/golden. *)
let run args =
  let out = Filename.temp_file "rapid-sem" ".out" and err = Filename.temp_file "rapid-sem" ".err" in
  let command = Printf.sprintf "cd golden && %s %s > %s 2> %s" (Filename.quote binary) args
      (Filename.quote out) (Filename.quote err) in
  ignore (Sys.command command);
  let read f =
    let ic = open_in_bin f in
    Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
        really_input_string ic (in_channel_length ic)) in
  let o = read out and e = read err in
  Sys.remove out; Sys.remove err;
  (o, e)

(* The places (FILE:LINE:COL) of the text format's headlines: the lines not indented, but for
   --allow-unknown's closing summary, which is no diagnostic. *)
let summary_line l =
  let suffix = "they are warnings under --allow-unknown" in
  let n = String.length l and k = String.length suffix in
  n >= k && String.sub l (n - k) k = suffix

let text_places args =
  let _, err = run args in
  String.split_on_char '\n' err
  |> List.filter (fun l -> l <> "" && l.[0] <> ' ' && not (summary_line l))
  |> List.map (fun l ->
      match String.split_on_char ':' l with
      | f :: line :: col :: _ -> (f, int_of_string line, int_of_string col)
      | _ -> Alcotest.failf "not a diagnostic: %s" l)

let member k = function
  | `Assoc fields -> (
      match List.assoc_opt k fields with Some v -> v | None -> Alcotest.failf "no field %s" k)
  | _ -> Alcotest.failf "not an object where %s was wanted" k

let string_field k j = match member k j with `String s -> s | _ -> Alcotest.failf "%s: not a string" k
let int_field k j = match member k j with `Int n -> n | _ -> Alcotest.failf "%s: not an integer" k
let list_field k j = match member k j with `List l -> l | _ -> Alcotest.failf "%s: not an array" k

(* RFC 3986 relative references: what the file names of these tests become as URIs. *)
let uri f =
  String.concat "" (List.map (fun c ->
      match c with
      | 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '-' | '.' | '_' | '~' | '/' -> String.make 1 c
      | c -> Printf.sprintf "%%%02X" (Char.code c)) (List.of_seq (String.to_seq f)))

let files = [ "hints.mod"; "double-equal.mod"; "unknown-names.mod"; "--allow-unknown unknown-names.mod";
              "semantic-errors.mod"; "../../examples/weldcell.mod" ]

let sarif_shape () =
  List.iter (fun file ->
      let out, _ = run ("check --format sarif " ^ file) in
      let doc = Yojson.Safe.from_string out in
      Alcotest.(check string) "version" "2.1.0" (string_field "version" doc);
      let runs = list_field "runs" doc in
      Alcotest.(check int) "one run" 1 (List.length runs);
      let run = List.hd runs in
      Alcotest.(check string) "driver name" "rapid-sem"
        (string_field "name" (member "driver" (member "tool" run)));
      let places = List.map (fun r ->
          if string_field "text" (member "message" r) = "" then Alcotest.fail "empty message";
          (match string_field "level" r with
           | "error" | "warning" -> ()
           | l -> Alcotest.failf "level %s" l);
          match list_field "locations" r with
          | [ loc ] ->
              let physical = member "physicalLocation" loc in
              let uri = string_field "uri" (member "artifactLocation" physical) in
              let region = member "region" physical in
              let line = int_field "startLine" region and col = int_field "startColumn" region in
              if line < 1 || col < 1 then Alcotest.failf "region %d:%d" line col;
              if int_field "endLine" region < line then Alcotest.fail "region ends before it starts";
              (uri, line, col)
          | _ -> Alcotest.fail "one location per result") (list_field "results" run) in
      let expected = List.map (fun (f, l, c) -> (uri f, l, c)) (text_places ("check " ^ file)) in
      Alcotest.(check (list (triple string int int))) ("results of " ^ file) expected places)
    files

let json_shape () =
  List.iter (fun file ->
      let out, _ = run ("check --format json " ^ file) in
      let doc = Yojson.Safe.from_string out in
      let items = list_field "diagnostics" doc in
      let places = List.map (fun d ->
          ignore (string_field "class" d); ignore (string_field "message" d);
          ignore (string_field "rule" d); ignore (list_field "sections" d);
          (match member "severity" d with `String ("error" | "warning") -> () | _ -> Alcotest.fail "severity");
          let r = member "region" d in
          ignore (int_field "end_line" r); ignore (int_field "end_column" r);
          (string_field "file" d, int_field "start_line" r, int_field "start_column" r)) items in
      Alcotest.(check (list (triple string int int))) ("diagnostics of " ^ file)
        (text_places ("check " ^ file)) places;
      let count sev = List.length (List.filter (fun d -> member "severity" d = `String sev) items) in
      Alcotest.(check int) "errors" (count "error") (int_field "errors" doc);
      Alcotest.(check int) "warnings" (count "warning") (int_field "warnings" doc))
    files

(* "did you mean": the distance, the limit, ties, letter case (§2.3). *)
let suggestions () =
  let open Rapid_syntax in
  Alcotest.(check int) "substitution" 1 (Suggest.distance "tool0" "tool1");
  Alcotest.(check int) "transposition" 1 (Suggest.distance "WObj" "wboj");
  Alcotest.(check int) "letter case" 0 (Suggest.distance "TPWRITE" "TPWrite");
  Alcotest.(check int) "insertion" 1 (Suggest.distance "countr" "counter");
  Alcotest.(check int) "two edits" 2 (Suggest.distance "cnter" "counter");
  Alcotest.(check (list string)) "nearest only" [ "tool0" ]
    (Suggest.closest "tol0" [ "tool0"; "tooldata"; "wobj0"; "tol00x" ]);
  Alcotest.(check (list string)) "ties, at most three, in the order given" [ "p10"; "p11"; "p12" ]
    (Suggest.closest "p1x" [ "p10"; "p11"; "p12"; "p13"; "v100" ]);
  Alcotest.(check (list string)) "too far" [] (Suggest.closest "pHome" [ "pStart"; "pHomePosition" ]);
  Alcotest.(check (list string)) "short names get none" [] (Suggest.closest "p" [ "a"; "p1" ]);
  Alcotest.(check (list string)) "the same name in another case is no suggestion" []
    (Suggest.closest "reg1" [ "REG1" ]);
  Alcotest.(check (option string)) "hint" (Some "did you mean a12, a13 or a14?")
    (Suggest.hint "a1x" [ "a12"; "a13"; "a14" ])

(* "did you mean" against its plain definition (bench/README.md: Suggest tests a candidate's
   length first and its spelling's repetition only when near, and keeps its table between
   calls): every candidate in lower case, once, not the name itself, its distance computed on a
   fresh table; the nearest, at most three, in the order given. Random names over a small
   alphabet in both cases, so that repeated spellings, ties and every length difference occur. *)
let suggestions_as_defined () =
  let open Rapid_syntax in
  let plain_distance a b =
    let a = String.lowercase_ascii a and b = String.lowercase_ascii b in
    let n = String.length a and m = String.length b in
    let d = Array.make_matrix (n + 1) (m + 1) 0 in
    for i = 0 to n do d.(i).(0) <- i done;
    for j = 0 to m do d.(0).(j) <- j done;
    for i = 1 to n do
      for j = 1 to m do
        let cost = if a.[i - 1] = b.[j - 1] then 0 else 1 in
        let best = List.fold_left Stdlib.min max_int [ d.(i - 1).(j) + 1; d.(i).(j - 1) + 1; d.(i - 1).(j - 1) + cost ] in
        d.(i).(j) <- (if i > 1 && j > 1 && a.[i - 1] = b.[j - 2] && a.[i - 2] = b.[j - 1]
                      then Stdlib.min best (d.(i - 2).(j - 2) + 1) else best)
      done
    done;
    d.(n).(m) in
  let plain_closest name candidates =
    if String.length name < 3 then [] else
    let limit = max 1 (Stdlib.min 3 (String.length name / 3)) in
    let lower = String.lowercase_ascii name in
    let rec scan seen acc = function
      | [] -> List.rev acc
      | c :: rest ->
          let k = String.lowercase_ascii c in
          if List.mem k seen || k = lower then scan seen acc rest
          else
            let d = plain_distance name c in
            scan (k :: seen) (if d <= limit then (d, c) :: acc else acc) rest in
    let scored = scan [] [] candidates in
    match List.sort compare (List.map fst scored) with
    | [] -> []
    | best :: _ -> List.filteri (fun i _ -> i < 3) (List.filter_map (fun (d, c) -> if d = best then Some c else None) scored) in
  let rs = Random.State.make [| 11 |] in
  let name () = String.init (1 + Random.State.int rs 12) (fun _ ->
      let c = "abp1".[Random.State.int rs 4] in
      if Random.State.bool rs then Char.uppercase_ascii c else c) in
  for _ = 1 to 3000 do
    let n = name () and cs = List.init (Random.State.int rs 30) (fun _ -> name ()) in
    Alcotest.(check (list string)) (String.concat " " (n :: cs)) (plain_closest n cs) (Suggest.closest n cs);
    let c = name () in
    Alcotest.(check int) (n ^ " " ^ c) (plain_distance n c) (Suggest.distance n c)
  done

let suite =
  ( "check-output",
    [ Alcotest.test_case "SARIF 2.1.0 required fields, one result per diagnostic" `Quick sarif_shape;
      Alcotest.test_case "JSON fields, one item per diagnostic" `Quick json_shape;
      Alcotest.test_case "did you mean" `Quick suggestions;
      Alcotest.test_case "did you mean, as defined, on random names" `Quick suggestions_as_defined ] )
