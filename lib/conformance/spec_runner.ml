open Rapid_syntax

type outcome = { case : Spec_case.t; passed : bool; detail : string }

let class_directive_name = function
  | Diagnostic.Lexical_error -> "lexical-error"
  | Syntax_error -> "syntax-error"
  | Semantic_error -> "semantic-error"
  | Fatal_static_error -> "fatal-error"
  | File_error -> "file-error"

let run_case (case : Spec_case.t) =
  if case.problems <> [] then { case; passed = false; detail = String.concat "; " case.problems }
  else
    let options = { Parse.strict = case.strict } in
    let result = Parse.parse_file ~options case.path in
    let expected = Option.get case.expectation in
    match expected, result with
    | Accepted, Ok _ -> { case; passed = true; detail = "ok" }
    | Accepted, Error d ->
        { case; passed = false; detail = "expected ok, got " ^ Diagnostic.to_string d }
    | Refused _, Ok _ ->
        { case; passed = false;
          detail = Printf.sprintf "expected %s, but the module was accepted"
              (Spec_case.expectation_to_string expected) }
    | Refused { error_class; line; col }, Error d ->
        let p = Source.start d.region in
        let got = class_directive_name d.error_class in
        if got = error_class && p.line = line && p.col = col then
          { case; passed = true; detail = Diagnostic.to_string d }
        else
          { case; passed = false;
            detail = Printf.sprintf "expected %s, got %s %d:%d (%s)"
                (Spec_case.expectation_to_string expected) got p.line p.col
                (Diagnostic.to_string d) }

let find_cases dir =
  let rec walk acc path =
    if Sys.is_directory path then
      Sys.readdir path |> Array.to_list |> List.sort compare
      |> List.fold_left (fun acc name -> walk acc (Filename.concat path name)) acc
    else if Filename.check_suffix path ".mod" then path :: acc
    else acc
  in
  if Sys.file_exists dir then List.rev (walk [] dir) else []

(* Sections sort by their numbers: 2.5 before 2.10 before 10.1. *)
let compare_sections a b =
  let key s = List.map (fun p -> Option.value (int_of_string_opt p) ~default:max_int)
      (String.split_on_char '.' s) in
  compare (key a, a) (key b, b)

let run ?(verbose = false) out dir =
  let outcomes = List.map (fun path -> run_case (Spec_case.read path)) (find_cases dir) in
  let by_section = Hashtbl.create 64 in
  List.iter (fun o ->
      let sections = if o.case.sections = [] then [ "(none)" ] else o.case.sections in
      List.iter (fun s ->
          let p, f = Option.value (Hashtbl.find_opt by_section s) ~default:(0, 0) in
          Hashtbl.replace by_section s (if o.passed then (p + 1, f) else (p, f + 1))) sections;
      if verbose || not o.passed then
        Format.fprintf out "%s %s: %s@." (if o.passed then "PASS" else "FAIL") o.case.path o.detail)
    outcomes;
  let sections = Hashtbl.fold (fun s _ acc -> s :: acc) by_section [] |> List.sort compare_sections in
  Format.fprintf out "@.%-10s %7s %7s@." "section" "passed" "failed";
  List.iter (fun s ->
      let p, f = Hashtbl.find by_section s in
      Format.fprintf out "%-10s %7d %7d@." s p f) sections;
  let passed = List.length (List.filter (fun o -> o.passed) outcomes) in
  let failed = List.length outcomes - passed in
  Format.fprintf out "@.%d passed, %d failed@." passed failed;
  (passed, failed)
