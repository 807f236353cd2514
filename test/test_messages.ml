(* Each test/messages/NNN-*.mod holds one syntax error; its second line,
   "! @expect-message LINE:COL: CLASS: MESSAGE", is the diagnostic it must get, byte for byte
   after the file name, and its third line, "! @expect-hint HINT", the hint that must follow
   (no such line: the diagnostic has no hint). They pin the wording of
   lib/syntax/parser.messages and of lib/syntax/syntax_hint.ml. *)

open Rapid_syntax

let dir = "messages"
let marker = "! @expect-message "
let hint_marker = "! @expect-hint "

let after marker line =
  let n = String.length marker in
  if String.length line > n && String.sub line 0 n = marker then
    Some (String.sub line n (String.length line - n))
  else None

let expected_message path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      ignore (input_line ic);
      let line = input_line ic in
      let hint = after hint_marker (input_line ic) in
      match after marker line with
      | Some m -> (m, hint)
      | None -> Alcotest.failf "%s: line 2 is not %S" path marker)

let case file =
  Alcotest.test_case file `Quick (fun () ->
      let path = Filename.concat dir file in
      let expected, hint = expected_message path in
      match Parse.parse_file path with
      | Ok _ -> Alcotest.failf "%s parses, but should give: %s" path expected
      | Error d ->
          let got = Diagnostic.headline d in
          let prefix = path ^ ":" in
          let got = String.sub got (String.length prefix) (String.length got - String.length prefix) in
          Alcotest.(check string) file expected got;
          Alcotest.(check (option string)) (file ^ " hint") hint d.hint)

let suite =
  ( "messages",
    Sys.readdir dir |> Array.to_list |> List.filter (fun f -> Filename.check_suffix f ".mod")
    |> List.sort compare |> List.map case )
