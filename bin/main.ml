let () =
  match Rapid_syntax.Parse.parse_file Sys.argv.(1) with
  | Ok _ -> print_endline "ok"
  | Error d -> prerr_endline (Rapid_syntax.Diagnostic.to_string d); exit 2
