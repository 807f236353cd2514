(* rapid-sem oracle: another implementation's events against rapid-sem's (doc/oracle.md). *)

open Cmdliner

let cmd =
  let impl =
    Arg.(required & opt (some string) None & info [ "impl" ] ~docv:"CMD"
           ~doc:"The implementation under test, as a shell command; $(b,{file}) stands for the \
                 program's file, $(b,{files}) for all files of a task buffer (appended when \
                 neither is given). It must write the events of doc/observable.md on standard \
                 output.")
  in
  let ignore =
    Arg.(value & opt_all string [] & info [ "ignore" ] ~docv:"KIND"
           ~doc:"Leave events of this kind out of the comparison (repeatable), so that a partial \
                 implementation can be checked on what it does.")
  in
  let timeout =
    Arg.(value & opt float 60. & info [ "timeout" ] ~docv:"SECONDS" ~doc:"Time allowed to each run.")
  in
  let paths =
    Arg.(non_empty & pos_all string [] & info [] ~docv:"PROGRAM"
           ~doc:"Module files, $(b,*.task) folders, or folders searched for both.")
  in
  let run impl ignore timeout paths =
    if timeout <= 0. || Float.is_nan timeout then (prerr_endline "rapid-sem: --timeout must be positive"; 2)
    else
    match Rapid_oracle.Oracle.programs_of_paths paths with
    | Error m -> Printf.eprintf "rapid-sem: %s\n" m; 2
    | Ok [] -> prerr_endline "rapid-sem: no program found"; 2
    | Ok programs ->
        (* An implementation that wraps rapid-sem (as the tests' deliberately wrong one does)
           finds it here. *)
        let reference = Rapid_oracle.Oracle.self_reference () in
        let agree = ref 0 and differ = ref 0 in
        List.iter (fun p ->
            let v = Rapid_oracle.Oracle.check ~ignore ~timeout ~reference ~impl p in
            (match v with Agree _ -> incr agree | Diverge _ | Broken _ -> incr differ);
            print_string (Rapid_oracle.Oracle.verdict_report p v)) programs;
        Printf.printf "%d agree, %d diverge\n" !agree !differ;
        if !differ = 0 then 0 else 1
  in
  let doc = "check another RAPID implementation's observable events against rapid-sem's" in
  let man = [
    `S Manpage.s_description;
    `P "Runs each PROGRAM with $(b,rapid-sem run --json) and with CMD, compares the two event \
        streams (doc/observable.md) and reports, per program, the first divergence: the \
        event's index, the source place, the events agreed just before, and the expected and \
        actual event. The field $(b,steps) of the end event is rapid-sem's own and is not \
        compared.";
    `S Manpage.s_exit_status;
    `P "0 when every program agrees; 1 when one diverges or the implementation writes no \
        usable stream; 2 when a PROGRAM cannot be read.";
  ] in
  Cmd.v (Cmd.info "oracle" ~doc ~man) Term.(const run $ impl $ ignore $ timeout $ paths)
