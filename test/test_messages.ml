(* Each test/messages/NNN-*.mod holds one syntax error; its second line,
   "! @expect-message LINE:COL: CLASS: MESSAGE", is the diagnostic it must get, byte for byte
   after the file name. They pin the wording of lib/syntax/parser.messages. *)

open Rapid_syntax

let dir = "messages"
let marker = "! @expect-message "

let expected_message path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      ignore (input_line ic);
      let line = input_line ic in
      let n = String.length marker in
      if String.length line > n && String.sub line 0 n = marker then
        String.sub line n (String.length line - n)
      else Alcotest.failf "%s: line 2 is not %S" path marker)

let case file =
  Alcotest.test_case file `Quick (fun () ->
      let path = Filename.concat dir file in
      let expected = expected_message path in
      match Parse.parse_file path with
      | Ok _ -> Alcotest.failf "%s parses, but should give: %s" path expected
      | Error d ->
          let got = Diagnostic.to_string d in
          let prefix = path ^ ":" in
          let got = String.sub got (String.length prefix) (String.length got - String.length prefix) in
          Alcotest.(check string) file expected got)

let suite =
  ( "messages",
    Sys.readdir dir |> Array.to_list |> List.filter (fun f -> Filename.check_suffix f ".mod")
    |> List.sort compare |> List.map case )
