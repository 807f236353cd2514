(* The rapid-sem command line: its commands' options and what they print. Exit statuses are a
   contract other tools rely on (doc/user-guide.md): 0 success, 2 a static error (lexical,
   syntax, fatal), 1 a failing conformance suite, 125 an internal error of rapid-sem (Cli). How a
   run is put together is lib/run's (Run_setup, Run_drive, Machine_steps); the JSON of its events
   is the oracle's (Rapid_oracle.Event_json). *)

module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
module EJ = Rapid_oracle.Event_json
module Drive = Rapid_run.Run_drive
open Cmdliner
open Rapid_syntax

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
           ~doc:"Refuse what chapter 10 does not print: a %%% header block, comment lines \
                 before MODULE or alone on their line inside RECORD, a byte-order mark, a file \
                 without a final line break, \\\\Continue as an argument (doc/dialect.md).")
  in
  let run files print ast strict robotware =
    Cli.guard @@ fun () ->
    let robotware = Option.value robotware ~default:Rapid_syntax.Robotware.default in
    let options = { Parse.default_options with strict; robotware } in
    let ok = List.fold_left (fun ok file ->
        match Parse.parse_file ~options file with
        | Ok m ->
            if print then print_string (Printer.module_declaration m);
            if ast then print_string (Ast_dump.module_declaration m);
            ok
        | Error d -> prerr_endline (Diagnostic.to_string d); false) true files
    in
    if ok then Cli.exit_ok else Cli.exit_static_error
  in
  let doc = "read RAPID modules and report every lexical and syntax error" in
  let man = [
    `S Manpage.s_description;
    `P "Reads each FILE as one RAPID module (chapter 10 of the RAPID kernel manual); a FILE \
        $(b,-) is standard input. A file that is refused gets one diagnostic on standard error, \
        $(b,FILE:LINE:COL: CLASS: MESSAGE), where CLASS is lexical error, syntax error or \
        fatal error (§1.4) and columns count characters, and where one helps a hint on an \
        indented next line.";
    `S Manpage.s_exit_status;
    `P "0 when every file parses; 2 when one does not.";
  ] in
  Cmd.v (Cmd.info "parse" ~doc ~man) Term.(const run $ files $ print $ ast $ strict $ Run_args.robotware_arg)

(* What rapid-sem run writes of a run as it goes: with --json every event as a JSON object (each
   naming its task, with several), else the program's output. The closure engine's run of one
   task shows the control characters of an output line as the pendant does, and leaves its start
   and end lines in the buffer until the next line goes out; the others write an output line as
   it is, and flush every line. *)
(* A controller backup's summary, on standard error at the end of a run without --json: what
   ran, and how each task ended. *)
let outcome_text (o : Rapid_runtime.Outcome.t) = match o with
  | Running -> "still running at the step limit"
  | Ended -> "ended"
  | Stopped { name; at; about; _ } ->
      Printf.sprintf "stopped by %s%s at %s" name (match about with Some a -> " (" ^ a ^ ")" | None -> "")
        (Rapid_syntax.Source.to_string at)
  | Resource_exhausted (m, _) -> "exhausted: " ^ m
  | Unsupported { name; at; _ } ->
      Printf.sprintf "stopped at %s, not modelled, at %s" name (Rapid_syntax.Source.to_string at)
  | Deadlock _ -> "waiting forever (deadlock)"
  | Stuck m -> "stuck: " ^ m

let print_summary (s : Rapid_run.Backup_setup.summary) ends =
  Printf.eprintf "rapid-sem: the backup %s ran %d task%s; I/O configuration %s (%d signals); %d warning%s above\n"
    s.dir (List.length s.tasks) (if List.length s.tasks = 1 then "" else "s")
    (Option.value s.io ~default:"none") s.signals s.warned (if s.warned = 1 then "" else "s");
  List.iter (fun (t : Rapid_run.Backup_setup.task_summary) ->
      let robot = match t.robot, t.reads with
        | Some r, _ -> Printf.sprintf "robot %s%s" r (match t.robot_type with
            | Some ty when ty <> "" && t.stand_in <> None ->
                Printf.sprintf " in place of %s (%s)" ty (Option.get t.stand_in)
            | Some ty when ty <> "" -> " (" ^ ty ^ ")"
            | _ -> "")
        | None, Some m -> "reads " ^ m ^ "'s robot"
        | None, None -> "no robot" in
      let events = match t.event_routines with
        | [] -> ""
        | l -> ", event routines " ^ String.concat ", " (List.map (fun (r, e) -> Printf.sprintf "%s (%s)" r e) l) in
      Printf.eprintf "  %s (%s): entry %s%s, %d module%s, %s: %s\n" t.task t.kind t.entry events t.modules
        (if t.modules = 1 then "" else "s") robot
        (match List.assoc_opt t.task ends with Some o -> outcome_text o | None -> "not started")) s.tasks;
  flush stderr

let run_sink ~json ~closure_single : Drive.sink =
  let encoder = EJ.create () in
  let summary = ref None and ends = ref [] in
  let line j = Cli.print_line (Json_text.to_string j) in
  let framing j = if closure_single then print_endline (Json_text.to_string j) else line j in
  let named task j = match task with Some name -> EJ.with_task name j | None -> j in
  let output s = Cli.print_line (if closure_single then Rapid_runtime.Text_format.display s else s) in
  { start = (fun tasks -> if json then framing (EJ.start ?tasks ()));
    event = (fun task e ->
        if json then line (named task (EJ.event encoder e)) else match e with Output s -> output s | _ -> ());
    stubbed = Cli.report_stubbed;
    samples = (fun task -> List.iter (fun (s : Rapid_run.Tcp_samples.sample) ->
        line (named task (EJ.sample s.time s.pose s.joints))));
    cell = (fun (s : Rapid_run.Backup_setup.summary) ->
        if json then
          line (EJ.cell ~backup:s.dir ~io:s.io ~signals:s.signals ~warnings:s.warned
                  (List.map (fun (t : Rapid_run.Backup_setup.task_summary) ->
                       { EJ.name = t.task; kind = t.kind; entry = t.entry; motion = t.motion; robot = t.robot;
                         robot_type = t.robot_type; stand_in = t.stand_in; reads = t.reads;
                         modules = t.modules; event_routines = t.event_routines }) s.tasks))
        else summary := Some s);
    task_end = (fun name o steps -> if json then line (EJ.task_end name o steps) else ends := (name, o) :: !ends);
    run_end = (fun ?entry_at o steps ->
        if json then framing (EJ.outcome ?entry_at o steps)
        else match !summary with
          | Some s -> Cli.flush_output (); print_summary s !ends
          | None -> Cli.report_task_stops (List.rev !ends) o);
    flush = Cli.flush_output }

let run_cmd =
  let _files, _entry, max_steps, allow_unknown, max_depth, retry_limit = Run_args.common_run_args in
  let json = Arg.(value & flag & info [ "json" ]
                    ~doc:"Write one JSON object per observable event (doc/trace-format.md) instead of the program's \
                          output.") in
  let save = Arg.(value & opt (some string) None & info [ "save" ] ~docv:"DIR"
                    ~doc:"At the end of the run, write each module to DIR (made if missing) with every PERS \
                          declaration's initial value replaced by the persistent's current value; the rest \
                          of the text is kept byte for byte, and each file is replaced atomically \
                          (doc/services.md).") in
  let engine = Arg.(value & opt (some (enum [ ("machine", `Machine); ("closure", `Closure) ])) None
                    & info [ "engine" ] ~docv:"ENGINE"
                        ~doc:"$(b,closure) (the second engine, the default: the same events as the machine's, \
                              faster; --max-steps counts its units of fuel, each task's with --task) or \
                              $(b,machine) (the small-step machine, the definition, which $(b,trace) and \
                              $(b,debug) run). Without this option, a run with --samples runs on the machine, \
                              which alone has it (doc/semantics.md, \"The second engine\").") in
  let run (tasks : Rapid_run.Run_options.tasks) max_steps allow_unknown max_depth retry_limit json controller
      (robot, base_frames) samples save engine =
    Cli.guard @@ fun () ->
    let options = Run_args.options ~base_frames ~max_steps ~allow_unknown ~max_depth ~retry_limit ~controller ~robot ()
    in
    let engine = Drive.engine ?requested:engine ~samples () in
    let sink = run_sink ~json ~closure_single:(engine = `Closure && tasks.tasks = []) in
    match Drive.run ~notify:Cli.notify sink ~engine ~json ~samples ~save options tasks with
    | Error f -> Cli.failure ~json ~files:tasks.files f
    | Ok { outcome; work } -> Cli.finish outcome work ~max_steps
  in
  let doc = "run a task: check the modules, then execute the entry routine" in
  let man = [
    `S Manpage.s_description;
    `P "Checks the FILEs as one task buffer (as $(b,rapid-sem check)), then runs the entry routine by the semantics \
        of doc/semantics.md (the second engine unless $(b,--engine) or what only the machine has asks for the \
        small-step machine). Standard output carries only the program's output, one line per TPWrite.";
    `P "With $(b,--task NAME=FILE,...) (repeated), runs several tasks instead, each its own task buffer and entry \
        routine, on one virtual clock, in turns of one statement (round robin, or the order of \
        $(b,--schedule SEED)); system-global persistents are shared between them (chapter 14; doc/user-guide.md, \
        \"Several tasks\"). With $(b,--json), each event names its task.";
    `S Manpage.s_exit_status;
    `P "0: the task ended (end of the entry routine, RETURN in it, EXIT). 1: the system error handler stopped it; \
        the error's name and the place of the failing statement go to standard error. 2: a static error, before \
        anything ran. 3: the step limit or a resource limit (call depth, the memory budget of --max-memory) was \
        exhausted. 4: the program called an installed routine rapid-sem does not model yet. 141: standard output \
        was closed (a pipe whose reader has gone) or could not be written.";
  ] in
  Cmd.v (Cmd.info "run" ~doc ~man)
    Term.(const run $ Run_args.tasks_args $ max_steps $ allow_unknown $ max_depth $ retry_limit $ json
          $ Run_args.controller_args $ Run_args.robot_and_base_frames $ Run_args.samples_arg $ save $ engine)

let spec_cmd =
  let dir = Arg.(value & pos 0 dir "spec" & info [] ~docv:"DIR" ~doc:"The suite's folder.") in
  let verbose = Arg.(value & flag & info [ "verbose"; "v" ] ~doc:"List passing cases too.") in
  let impl = Arg.(value & opt (some string) None & info [ "impl" ] ~docv:"CMD"
                    ~doc:"Run the suite against another implementation through the oracle's protocol \
                          (doc/oracle.md): $(b,{mode}) is parse, check or run, $(b,{options}) the \
                          case's options, $(b,{files}) its files. With $(b,{tasks}) in CMD, the cases of \
                          several tasks (format 4) run too, {tasks} standing for their $(b,--task) NAME=FILE,..., \
                          $(b,--entry) TASK=ROUTINE, $(b,--schedule) SEED and $(b,--motion-task) NAME as \
                          $(b,rapid-sem run) spells them ({files} then empty), and their events are compared \
                          task by task; without it they are skipped.") in
  let junit = Arg.(value & opt (some string) None & info [ "junit" ] ~docv:"FILE"
                     ~doc:"With --impl: also write the results as JUnit XML.") in
  let report = Arg.(value & opt (some string) None & info [ "report-json" ] ~docv:"FILE"
                      ~doc:"With --impl: also write the results as JSON.") in
  let engines = [ ("machine", Rapid_conformance.Spec_runner.Machine); ("closure", Closure) ] in
  let engine = Arg.(value & opt (enum engines) Machine & info [ "engine" ] ~docv:"ENGINE"
                        ~doc:"The engine that runs the run-time cases (formats 3 and 4, one task or several): \
                              $(b,machine) (default) or $(b,closure).") in
  let ignore_kinds = Arg.(value & opt_all string [] & info [ "ignore" ] ~docv:"KIND"
                            ~doc:"With --impl: leave the events of this kind out of the comparison of the events \
                                  (repeatable).") in
  let timeout = Arg.(value & opt float 60. & info [ "timeout" ] ~docv:"SECONDS"
                       ~doc:"With --impl: the time allowed to each run of a case (either tool's).") in
  let run dir verbose impl junit report engine ignore_kinds timeout =
    Cli.guard @@ fun () ->
    if timeout <= 0. || Float.is_nan timeout then (prerr_endline "rapid-sem: --timeout must be positive"; 2) else
    let _, failed = match impl with
      | None -> Rapid_conformance.Spec_runner.run ~verbose ~engine Format.std_formatter dir
      | Some template ->
          ignore (Rapid_oracle.Oracle.self_reference ());
          (* Run cases compare the events with rapid-sem's own too. *)
          let reference = Filename.quote Sys.executable_name ^ " run --json {options} {tasks} {files}" in
          Rapid_conformance.Impl_runner.run ~verbose ~timeout ~reference ~ignore:ignore_kinds ?junit ?json:report
            ~template
            Format.std_formatter dir in
    if failed = 0 then Cli.exit_ok else Cli.exit_spec_failed
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
  Cmd.v (Cmd.info "spec" ~doc ~man)
    Term.(const run $ dir $ verbose $ impl $ junit $ report $ engine $ ignore_kinds $ timeout)

let () =
  (* A closed pipe is then an error of the write (EPIPE), which ends the run with its status. *)
  Sys.set_signal Sys.sigpipe Sys.Signal_ignore;
  let doc = "the executable semantics of ABB's RAPID robot programming language" in
  let info = Cmd.info "rapid-sem" ~version:Cli.version ~doc in
  (* cmdliner reads "--max-steps -1" as an option "-1": joined as "--max-steps=-1", the value
     reaches [count], whose message says what is wrong with it. *)
  let count_options = [ "--max-steps"; "--max-call-depth"; "--retry-limit"; "--from"; "--to"; "--max-memory" ] in
  let rec join = function
    | opt :: value :: rest
      when List.mem opt count_options && String.length value > 1 && value.[0] = '-'
           && int_of_string_opt value <> None ->
        (opt ^ "=" ^ value) :: join rest
    | a :: rest -> a :: join rest
    | [] -> []
  in
  let argv = Array.of_list (join (Array.to_list Sys.argv)) in
  let commands = [ parse_cmd; Check_cmd.cmd; run_cmd; Trace_cmd.cmd; spec_cmd; Motion_cmd.cmd; Debug_cmd.cmd;
                   Lsp_cmd.cmd; Oracle_cmd.cmd; Fuzz_cmd.cmd; Mem_cmd.cmd; Verdict.cmd; Test_cmd.cmd ] in
  let status = Cmd.eval' ~argv (Cmd.group info commands) in
  (* A command line that cannot be read (an unknown option, a negative limit) is refused like a
     static error, with cmdliner's message saying what is wrong. *)
  exit (if status = Cmd.Exit.cli_error then Cli.exit_static_error else status)
