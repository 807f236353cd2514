(* The rapid-sem command line. Exit statuses are a contract other tools rely on
   (doc/user-guide.md): 0 success, 2 a static error (lexical, syntax, fatal), 1 a failing
   conformance suite, 125 an internal error of rapid-sem. *)

open Cmdliner
open Rapid_syntax

let exit_ok = 0
let exit_static_error = 2
let exit_spec_failed = 1
let exit_internal = 125

(* No OCaml exception may reach a user as such: anything that escapes is a bug of rapid-sem,
   reported as one. *)
let guard f =
  try f () with
  | Stack_overflow ->
      prerr_endline "rapid-sem: internal error: stack overflow (please report this input)";
      exit_internal
  | Out_of_memory ->
      prerr_endline "rapid-sem: internal error: out of memory";
      exit_internal
  | e ->
      Printf.eprintf "rapid-sem: internal error: %s (please report this input)\n"
        (Printexc.to_string e);
      exit_internal

let parse_cmd =
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files.") in
  let print =
    Arg.(value & flag & info [ "print" ] ~doc:"Write each module back as canonical RAPID source.")
  in
  let ast =
    Arg.(value & flag & info [ "ast" ]
           ~doc:"Write each module's syntax tree without locations, in a stable text form: two \
                 files that parse to the same tree give byte-identical output.")
  in
  let strict =
    Arg.(value & flag & info [ "strict" ]
           ~doc:"Refuse what chapter 10 does not print: a %%%% header block, a byte-order \
                 mark, a file without a final line break (doc/dialect.md).")
  in
  let run files print ast strict =
    guard @@ fun () ->
    let options = { Parse.default_options with strict } in
    let ok = List.fold_left (fun ok file ->
        match Parse.parse_file ~options file with
        | Ok m ->
            if print then print_string (Printer.module_declaration m);
            if ast then print_string (Ast_dump.module_declaration m);
            ok
        | Error d -> prerr_endline (Diagnostic.to_string d); false) true files
    in
    if ok then exit_ok else exit_static_error
  in
  let doc = "read RAPID modules and report every lexical and syntax error" in
  let man = [
    `S Manpage.s_description;
    `P "Reads each FILE as one RAPID module (chapter 10 of the RAPID kernel manual). A file \
        that is refused gets one diagnostic on standard error, \
        $(b,FILE:LINE:COL: CLASS: MESSAGE), where CLASS is lexical error, syntax error or \
        fatal error (§1.4) and columns count characters.";
    `S Manpage.s_exit_status;
    `P "0 when every file parses; 2 when one does not.";
  ] in
  Cmd.v (Cmd.info "parse" ~doc ~man) Term.(const run $ files $ print $ ast $ strict)

let check_cmd =
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer.") in
  let allow_unknown =
    Arg.(value & flag & info [ "allow-unknown" ]
           ~doc:"Report a name that is neither declared nor installed as a warning, and go on: \
                 real programs call installed routines beyond rapid-sem's environment.")
  in
  let strict =
    Arg.(value & flag & info [ "strict" ] ~doc:"Refuse the dialect extensions of doc/dialect.md.")
  in
  let run files allow_unknown strict =
    guard @@ fun () ->
    let options = { Parse.default_options with strict } in
    let parsed = List.map (fun f -> Parse.parse_file ~options f) files in
    let syntax_errors = List.filter_map (function Error d -> Some d | Ok _ -> None) parsed in
    List.iter (fun d -> prerr_endline (Diagnostic.to_string d)) syntax_errors;
    if syntax_errors <> [] then exit_static_error
    else
      match Rapid_typing.Installed_env.modules () with
      | Error d ->
          Printf.eprintf "rapid-sem: internal error: the installed environment does not parse: %s\n"
            (Diagnostic.to_string d);
          exit_internal
      | Ok installed ->
          let modules = List.filter_map Result.to_option parsed in
          let result =
            Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
          List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) result.reports;
          if Rapid_typing.Check.errors result = [] then exit_ok else exit_static_error
  in
  let doc = "check RAPID modules, as one task buffer, against the static semantics" in
  let man = [
    `S Manpage.s_description;
    `P "Reads each FILE as a module and checks them together as one task buffer (§9.1) \
        against the rules of chapters 2-5 and 9 of the RAPID kernel manual, with the installed \
        environment of types, data and routines that real programs use. Each error is reported \
        on standard error as $(b,FILE:LINE:COL: semantic error: MESSAGE (§x.y)); independent \
        errors are all reported in one run.";
    `S Manpage.s_exit_status;
    `P "0 when there is no static error (warnings allowed); 2 when there is one.";
  ] in
  Cmd.v (Cmd.info "check" ~doc ~man) Term.(const run $ files $ allow_unknown $ strict)

let spec_cmd =
  let dir = Arg.(value & pos 0 dir "spec" & info [] ~docv:"DIR" ~doc:"The suite's folder.") in
  let verbose = Arg.(value & flag & info [ "verbose"; "v" ] ~doc:"List passing cases too.") in
  let run dir verbose =
    guard @@ fun () ->
    let _, failed = Rapid_conformance.Spec_runner.run ~verbose Format.std_formatter dir in
    if failed = 0 then exit_ok else exit_spec_failed
  in
  let doc = "run the conformance suite" in
  let man = [
    `S Manpage.s_description;
    `P "Runs every .mod file below DIR against the expectations written in its comments \
        (spec/README.md), prints each failure, a summary per manual section and the line \
        $(b,N passed, N failed).";
    `S Manpage.s_exit_status;
    `P "0 when every case passes; 1 otherwise.";
  ] in
  Cmd.v (Cmd.info "spec" ~doc ~man) Term.(const run $ dir $ verbose)

let () =
  let doc = "the executable semantics of ABB's RAPID robot programming language" in
  let info = Cmd.info "rapid-sem" ~version:"0.1.0" ~doc in
  exit (Cmd.eval' (Cmd.group info [ parse_cmd; check_cmd; spec_cmd ]))
