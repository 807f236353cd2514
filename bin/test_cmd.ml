(* rapid-sem test: the unit tests of a task buffer (doc/testing.md). How they are found, run and
   reported is lib/unit_test's; here the options and what goes to the terminal. *)

open Cmdliner
module U = Rapid_unit_test

let write_file path text =
  match open_out_bin path with
  | exception Sys_error m -> Error m
  | oc -> output_string oc text; close_out oc; Ok ()

let cmd =
  let files, _, max_steps, allow_unknown, max_depth, retry_limit = Run_args.common_run_args in
  let filter = Arg.(value & opt (some string) None & info [ "filter" ] ~docv:"REGEX"
                      ~doc:"Only the tests whose name the regular expression (OCaml's Str syntax) matches, \
                            anywhere in it.") in
  let jobs = Arg.(value & opt (Run_args.count ~what:"--jobs") 1 & info [ "jobs"; "j" ] ~docv:"N"
                    ~doc:"Run the tests in N child processes; the report keeps the order of the tests.") in
  let junit = Arg.(value & opt (some string) None & info [ "junit" ] ~docv:"FILE"
                     ~doc:"Also write the results as JUnit XML.") in
  let coverage = Arg.(value & opt (some string) None & info [ "coverage" ] ~docv:"FILE"
                        ~doc:"Write the statement and branch coverage of the modules that are not test modules \
                              as an lcov tracefile (genhtml renders it). The tests then run on the machine.") in
  let cobertura = Arg.(value & opt (some string) None & info [ "cobertura" ] ~docv:"FILE"
                         ~doc:"Write the same coverage as Cobertura XML.") in
  let progress = Arg.(value & flag & info [ "progress" ]
                        ~doc:"A progress line on standard error as tests end (by default only on a terminal).") in
  let engine = Arg.(value & opt (some (enum [ ("machine", `Machine); ("closure", `Closure) ])) None
                    & info [ "engine" ] ~docv:"ENGINE"
                        ~doc:"$(b,closure) (the default) or $(b,machine); with --coverage, the machine.") in
  let run files max_steps allow_unknown max_depth retry_limit controller robot filter jobs junit coverage cobertura
      progress engine =
    Cli.guard @@ fun () ->
    let options = Run_args.options ~max_steps ~allow_unknown ~max_depth ~retry_limit ~controller ~robot () in
    let want_coverage = coverage <> None || cobertura <> None in
    let regex = match filter with
      | None -> Ok None
      | Some r -> (match Str.regexp r with re -> Ok (Some re) | exception _ -> Error r) in
    match U.Test_suite.module_files files, regex with
    | Error m, _ -> prerr_endline m; Cli.exit_static_error
    | _, Error r -> Printf.eprintf "rapid-sem: --filter %s: not a regular expression\n" r; Cli.exit_static_error
    | _ when want_coverage && engine = Some `Closure ->
        prerr_endline "rapid-sem: --coverage and --cobertura run on the machine only: leave out --engine closure";
        Cli.exit_static_error
    | Ok files, Ok regex ->
    match U.Test_suite.discover ~notify:Cli.notify options files with
    | Error f -> Cli.failure ~files f
    | Ok suite ->
        let suite = match regex with Some re -> U.Test_suite.filter re suite | None -> suite in
        let total = List.length suite.tests in
        (* No test is no success (R-test-c): a folder or a --filter mistyped in CI would pass. *)
        if total = 0 then begin
          Printf.eprintf "rapid-sem: no test to run: no procedure test_...() without parameters%s in %s\n"
            (match filter with Some r -> " whose name --filter " ^ r ^ " matches" | None -> "")
            (String.concat ", " files);
          1
        end else
        let tty = Unix.isatty Unix.stderr in
        let show_progress = progress || tty in
        let started = Unix.gettimeofday () in
        let finished = ref 0 in
        (* The lines in the order of the tests: a result waits for those before it. *)
        let pending = Hashtbl.create 16 and next = ref 0 in
        let on_result i (r : U.Test_suite.result) =
          Hashtbl.replace pending i r;
          incr finished;
          if show_progress && (progress || Unix.gettimeofday () -. started > 1.) then
            if tty then Printf.eprintf "\r[%d/%d] %s\027[K%!" !finished total r.test.name
            else Printf.eprintf "[%d/%d] %s\n%!" !finished total r.test.name;
          while Hashtbl.mem pending !next do
            if tty && show_progress then prerr_string "\r\027[K";
            List.iter Cli.print_line (U.Test_report.line (Hashtbl.find pending !next));
            Hashtbl.remove pending !next;
            incr next
          done in
        let engine = match engine with Some e -> e | None -> `Closure in
        let results = U.Test_suite.run ~jobs ~coverage:want_coverage ~engine ~on_result suite in
        if tty && show_progress then prerr_string "\r\027[K";
        Cli.print_line (U.Test_report.summary results);
        let written = ref Cli.exit_ok in
        let write what path text =
          match write_file path text with
          | Ok () -> ()
          | Error m -> Printf.eprintf "rapid-sem: %s: %s\n" what m; written := Cli.exit_static_error in
        Option.iter (fun p -> write "--junit" p (U.Test_report.junit results)) junit;
        if want_coverage then begin
          List.iter (fun (r : U.Test_suite.result) -> Option.iter (U.Test_coverage.add suite.coverage) r.hits) results;
          Option.iter (fun p -> write "--coverage" p (U.Test_coverage.lcov suite.coverage)) coverage;
          Option.iter (fun p -> write "--cobertura" p
                          (U.Test_coverage.cobertura suite.coverage ~version:("rapid-sem " ^ Cli.version))) cobertura;
          Printf.eprintf "coverage: %s\n%!" (U.Test_coverage.summary suite.coverage)
        end;
        if !written <> Cli.exit_ok then !written
        else if List.for_all (fun (r : U.Test_suite.result) -> r.verdict = Passed) results then Cli.exit_ok
        else 1
  in
  let doc = "run the unit tests of RAPID modules: every PROC test_...() in a fresh controller" in
  let man = [
    `S Manpage.s_description;
    `P "The FILEs (a folder stands for the .mod, .sys, .modx and .sysx files below it) form one task buffer, \
        checked as $(b,rapid-sem check) does, with the assertions of doc/testing.md installed (AssertEqual, \
        AssertSignal, AssertAtTarget, ...). Every procedure without parameters whose name begins with test_ \
        is a test: each runs from its first statement in a fresh controller (module data, clock, signals, \
        robot). A comment line $(b,!rapid-sem: --io FILE --robot FILE) in a module gives its tests a stimulus, an \
        I/O configuration or a robot.";
    `P "A test passes when it ends; it fails when an assertion fails or an error no handler takes stops it: the \
        line under it says where (FILE:LINE:COL) and what was expected and found. Standard output has a line \
        per test with the virtual time it took, then the summary $(b,N passed, N failed).";
    `S Manpage.s_exit_status;
    `P "0 when every test passes; 1 when one fails or there is no test to run; 2 for a static error or a command \
        line that cannot be used.";
  ] in
  Cmd.v (Cmd.info "test" ~doc ~man)
    Term.(const run $ files $ max_steps $ allow_unknown $ max_depth $ retry_limit $ Run_args.controller_args
          $ Run_args.robot_arg $ filter $ jobs $ junit $ coverage $ cobertura $ progress $ engine)
