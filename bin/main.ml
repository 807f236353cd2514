(* The rapid-sem command line. Exit statuses are a contract other tools rely on
   (doc/user-guide.md): 0 success, 2 a static error (lexical, syntax, fatal), 1 a failing
   conformance suite, 125 an internal error of rapid-sem. *)

module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
open Cmdliner
open Rapid_syntax

let exit_ok = 0
let exit_static_error = 2
let exit_spec_failed = 1
let exit_internal = 125
let version = "0.1.0"

(* Standard output closed (a pipe whose reader has gone) or not writable (a full disk): the run
   ends at once with this status, 128 + SIGPIPE as a shell reports a process that a closed pipe
   ended (doc/user-guide.md). *)
let exit_output_failed = 141

exception Output_failed of string

(* Each line leaves the process as it is written: a reader waiting for it (a client before the
   program's SocketAccept) would otherwise wait for the buffer to fill, and a run killed by a
   timeout (SIGKILL) would lose every line still in the buffer (doc/services.md). *)
let print_line s =
  try print_string s; print_char '\n'; flush stdout with Sys_error m -> raise (Output_failed m)

let flush_output () = try flush stdout with Sys_error m -> raise (Output_failed m)

let contains_sub s p =
  let n = String.length p and m = String.length s in
  let rec go i = if i + n > m then raise Not_found else if String.sub s i n = p then i else go (i + 1) in
  go 0

let contains_sub_bool s p = match contains_sub s p with _ -> true | exception Not_found -> false

(* No OCaml exception may reach a user as such: anything that escapes is a bug of rapid-sem,
   reported as one. *)
let stdout_broken m =
  contains_sub_bool m "Broken pipe" || (try flush stdout; false with Sys_error _ -> true)

let guard f =
  try
    try let status = f () in flush_output (); status
    with Sys_error m when stdout_broken m -> raise (Output_failed m)
  with
  | Output_failed m ->
      (* A closed pipe is the reader's choice: quiet. Anything else is said once. *)
      let broken_pipe = contains_sub_bool m "Broken pipe" in
      if not broken_pipe then (try Printf.eprintf "rapid-sem: cannot write the standard output: %s\n%!" m with _ -> ());
      (* What is left in the buffer cannot be written either: closing drops it, so that the
         flushes at exit have nothing to fail on. *)
      close_out_noerr stdout;
      exit_output_failed
  | Stack_overflow ->
      prerr_endline "rapid-sem: internal error: stack overflow (please report this input)";
      exit_internal
  | Out_of_memory ->
      (* The machine's memory, not a rule of rapid-sem: a resource exhausted (§1.4). The RAPID
         data of a run is bounded by --max-memory, so this means a budget beyond the memory the
         machine has. *)
      prerr_endline "rapid-sem: out of memory (resource exhaustion, §1.4): try a smaller --max-memory";
      3
  | e ->
      Printf.eprintf "rapid-sem: internal error: %s (please report this input)\n"
        (Printexc.to_string e);
      exit_internal

(* The controller around the run (doc/controller.md): --io, --statement-time, --max-time,
   --epoch. *)
type controller_options = { io : string option; statement_time : float; max_time : float; epoch : float;
                            services : Services_args.t }

let io_arg =
  Arg.(value & opt (some string) None & info [ "io" ] ~docv:"FILE"
         ~doc:"The I/O configuration and the stimulus of the inputs (doc/controller.md): a stimulus file, or a RobotWare EIO.cfg file whose EIO_SIGNAL entries declare the signals.")

(* --epoch YYYY-MM-DDTHH:MM:SS, read as seconds since 1970 (UTC, no leap seconds). A date that
   does not exist (February 30, a year before 0001) is refused rather than carried over. *)
let epoch_conv =
  let days_in_month y m =
    if m = 2 then (if (y mod 4 = 0 && y mod 100 <> 0) || y mod 400 = 0 then 29 else 28)
    else if m = 4 || m = 6 || m = 9 || m = 11 then 30 else 31 in
  let parse s =
    try Scanf.sscanf s "%4u-%2u-%2uT%2u:%2u:%2u%!" (fun y m d hh mm ss ->
        if y < 1 || m < 1 || m > 12 || d < 1 || d > days_in_month y m || hh > 23 || mm > 59 || ss > 59 then
          Error (`Msg "a date and time that does not exist")
        else
          let y' = if m <= 2 then y - 1 else y in
          let era = (if y' >= 0 then y' else y' - 399) / 400 in
          let yoe = y' - (era * 400) in
          let mp = if m > 2 then m - 3 else m + 9 in
          let doy = ((153 * mp) + 2) / 5 + d - 1 in
          let doe = (yoe * 365) + (yoe / 4) - (yoe / 100) + doy in
          let days = (era * 146097) + doe - 719468 in
          Ok (float_of_int ((days * 86400) + (hh * 3600) + (mm * 60) + ss)))
    with _ -> Error (`Msg "expected YYYY-MM-DDTHH:MM:SS") in
  let print ppf t = let y, m, d, hh, mm, ss, _ = Rapid_installed.Io_routines.date_time t in
    Format.fprintf ppf "%04d-%02d-%02dT%02d:%02d:%02d" y m d hh mm ss in
  Arg.conv (parse, print)

(* A number of seconds of virtual time: never NaN (it compares false with every time, so a limit of
   NaN would be no limit and a statement of NaN would stop the clock), never negative, and at most
   [most] (a statement time of 1e308 would take the clock past every time it can represent). *)
let seconds_conv ~most =
  let parse s =
    match float_of_string_opt (String.trim s) with
    | None -> Error (`Msg (Printf.sprintf "%S is not a number of seconds" s))
    | Some v when Float.is_nan v -> Error (`Msg "not a number (nan) is not a time")
    | Some v when v < 0. -> Error (`Msg "a time is not negative")
    | Some v when v > most -> Error (`Msg (Printf.sprintf "at most %g s" most))
    | Some v -> Ok v in
  Arg.conv (parse, fun ppf v -> Format.fprintf ppf "%g" v)

(* The longest statement: a day of virtual time. *)
let most_statement_time = 86400.

let controller_args =
  let module W = Rapid_controller.World in
  let statement_time =
    Arg.(value & opt (seconds_conv ~most:most_statement_time) W.default_statement_time
         & info [ "statement-time" ] ~docv:"SECONDS"
             ~doc:"Virtual time each executed statement (and each round of a loop) takes (at most 86400).") in
  let max_time = Arg.(value & opt (seconds_conv ~most:infinity) W.default_max_time & info [ "max-time" ]
                        ~docv:"SECONDS"
                        ~doc:"Stop the run when its virtual time goes beyond SECONDS (exit status 3; inf: never).") in
  let epoch = Arg.(value & opt epoch_conv W.default_epoch & info [ "epoch" ] ~docv:"YYYY-MM-DDTHH:MM:SS"
                     ~doc:"The wall-clock time at virtual time 0, for CDate, CTime and GetTime (default 2024-01-01T00:00:00).") in
  Term.(const (fun io statement_time max_time epoch services -> { io; statement_time; max_time; epoch; services })
        $ io_arg $ statement_time $ max_time $ epoch $ Services_args.term)

let read_io = function
  | None -> Ok Rapid_controller.Io_config.empty
  | Some file -> Rapid_controller.Io_config.read_file file

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
    `P "Reads each FILE as one RAPID module (chapter 10 of the RAPID kernel manual); a FILE \
        $(b,-) is standard input. A file that is refused gets one diagnostic on standard error, \
        $(b,FILE:LINE:COL: CLASS: MESSAGE), where CLASS is lexical error, syntax error or \
        fatal error (§1.4) and columns count characters, and where one helps a hint on an \
        indented next line.";
    `S Manpage.s_exit_status;
    `P "0 when every file parses; 2 when one does not.";
  ] in
  Cmd.v (Cmd.info "parse" ~doc ~man) Term.(const run $ files $ print $ ast $ strict)

let check_cmd =
  let files = Arg.(value & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer (without --task).") in
  let tasks = Arg.(value & opt_all string [] & info [ "task" ] ~docv:"NAME=FILE[,FILE...]"
                     ~doc:"A task buffer of its own (ch. 14): its name and its module files. Repeat for several tasks, checked each on its own and then together: a system-global persistent has one type in every task (doc/user-guide.md, \"Several tasks\").") in
  let allow_unknown =
    Arg.(value & flag & info [ "allow-unknown" ]
           ~doc:"Report a name that is neither declared nor installed as a warning, and go on: \
                 real programs call installed routines beyond rapid-sem's environment.")
  in
  let strict =
    Arg.(value & flag & info [ "strict" ] ~doc:"Refuse the dialect extensions of doc/dialect.md.")
  in
  let format =
    Arg.(value & opt (enum [ ("text", Check_output.Text); ("json", Check_output.Json);
                             ("sarif", Check_output.Sarif) ]) Check_output.Text
         & info [ "format" ] ~docv:"FORMAT"
             ~doc:"$(b,text) (standard error, the default), $(b,json) or $(b,sarif) (SARIF 2.1.0), \
                   both on standard output: every diagnostic with its file, region, class, \
                   sections, message and hint (doc/user-guide.md).")
  in
  let run files tasks allow_unknown strict format io robot =
    guard @@ fun () ->
    (* One buffer, or one per --task (its name and files). *)
    let buffers =
      if tasks = [] then Ok [ ("", files) ]
      else if files <> [] then Error "rapid-sem: with --task, the files are named in each --task NAME=FILE,..."
      else
        List.fold_left (fun acc t -> Result.bind acc (fun l ->
            match String.index_opt t '=' with
            | Some i when i > 0 && i < String.length t - 1 ->
                let name = String.sub t 0 i in
                if List.exists (fun (n, _) -> String.lowercase_ascii n = String.lowercase_ascii name) l then
                  Error (Printf.sprintf "rapid-sem: --task %s is given twice: task names are unique" name)
                else Ok (l @ [ (name, String.split_on_char ',' (String.sub t (i + 1) (String.length t - i - 1))) ])
            | _ -> Error (Printf.sprintf "rapid-sem: --task %s: expected NAME=FILE[,FILE...]" t))) (Ok []) tasks in
    match buffers, read_io io, Motion_cmd.load_robot robot with
    | Error m, _, _ | _, Error m, _ | _, _, Error m -> prerr_endline m; exit_static_error
    | Ok [ (_, []) ], _, _ -> prerr_endline "rapid-sem: required argument FILE is missing (or give --task NAME=FILE)"; exit_static_error
    | Ok buffers, Ok io, Ok _ ->
    let options = { Parse.default_options with strict } in
    let parsed = List.map (fun (name, files) -> (name, List.map (fun f -> Parse.parse_file ~options f) files)) buffers in
    let syntax_errors = List.concat_map (fun (_, p) -> List.filter_map (function Error d -> Some d | Ok _ -> None) p) parsed in
    let print = Check_output.print ~version format in
    if syntax_errors <> [] then begin
      print (List.map Check_output.of_diagnostic syntax_errors);
      exit_static_error
    end
    else
      match Rapid_load.Session.installed ~io () with
      | Error d ->
          Printf.eprintf "rapid-sem: internal error: the installed environment does not parse: %s\n"
            (Diagnostic.to_string d);
          exit_internal
      | Ok installed -> (
          (* The whole static semantics, the initial values known before the run included
             (Session: check, lower, evaluate them). *)
          let checked = List.map (fun (name, p) ->
              let modules = List.filter_map Result.to_option p in
              let result =
                Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
              let reports =
                if Rapid_typing.Check.errors result <> [] then result.reports
                else match Rapid_load.Session.lower ~io ~installed ~modules result with
                  | Ok _ -> result.reports
                  | Error initial_value_errors -> result.reports @ initial_value_errors in
              (name, modules, result, reports)) parsed in
          let is_error (r : Rapid_typing.Report.t) = r.severity = Error in
          (* ch. 14: the buffers together, once each is sound on its own. *)
          let across =
            if tasks = [] || List.exists (fun (_, _, _, reports) -> List.exists is_error reports) checked then []
            else Rapid_load.Task_check.shared_persistents
                (List.map (fun (name, modules, (result : Rapid_typing.Check.result), _) ->
                     { Rapid_load.Task_check.name; modules; elaboration = result.elaboration }) checked) in
          let reports = List.map (Rapid_load.Session.at_io_place io)
              (List.concat_map (fun (_, _, _, reports) -> reports) checked @ across) in
          print (List.map Check_output.of_report reports);
          (* JSON and SARIF carry the warnings themselves: the summary is for people. *)
          if format = Check_output.Text then
            List.iter (fun (name, _, result, _) ->
                Option.iter (fun s -> prerr_endline (if name = "" then s else "task " ^ name ^ ": " ^ s))
                  (Rapid_typing.Check.unknown_summary result)) checked;
          if List.exists is_error reports then exit_static_error
          else exit_ok)
  in
  let doc = "check RAPID modules, as one task buffer, against the static semantics" in
  let man = [
    `S Manpage.s_description;
    `P "Reads each FILE as a module and checks them together as one task buffer (§9.1) \
        against the rules of chapters 2-5 and 9 of the RAPID kernel manual, with the installed \
        environment of types, data and routines that real programs use. Each error is reported \
        on standard error as $(b,FILE:LINE:COL: semantic error: MESSAGE (§x.y)), with a hint \
        on an indented next line where one helps; independent errors are all reported in one \
        run. $(b,--format json) and $(b,--format sarif) write them all to standard output \
        instead. A FILE $(b,-) is standard input.";
    `P "With $(b,--task NAME=FILE,...) (repeated), checks several task buffers instead, as \
        $(b,rapid-sem run --task) loads them: each on its own, then, when none has an error, \
        together: a system-global persistent declared with another type than in an earlier \
        task is an error at the later declaration (chapter 14).";
    `S Manpage.s_exit_status;
    `P "0 when there is no static error (warnings allowed); 2 when there is one.";
  ] in
  Cmd.v (Cmd.info "check" ~doc ~man) Term.(const run $ files $ tasks $ allow_unknown $ strict $ format $ io_arg $ Motion_cmd.robot_arg)

(* ------------------------------------------------------------------ run and trace *)

module M = Rapid_semantics.Machine

let exit_stopped = 1
let exit_exhausted = 3
let exit_unsupported = 4

let report_load_failure ?(json = false) failure =
  (* With --json, a program refused before it runs still gives an event stream: the start line
     and an end object naming the first error (doc/oracle.md). *)
  if json then Option.iter (fun j -> List.iter (fun l -> print_endline (Json_text.to_string l)) j)
      (Verdict.stream_of_failure failure);
  match failure with
  | Rapid_load.Session.Front_end ds -> List.iter (fun d -> prerr_endline (Diagnostic.to_string d)) ds; exit_static_error
  | Static reports -> List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) reports; exit_static_error
  | Internal m -> Printf.eprintf "rapid-sem: internal error: %s\n" m; exit_internal

module EJ = Rapid_oracle.Event_json

let schema = EJ.schema

(* The events of the run this process makes (one a process). *)
let encoder = EJ.create ()

let event_json e = EJ.event encoder e

(* Schema rapid-sem/2: every end object has [at]. An ended task is at its entry routine (the
   place both engines know; R-4.12-m); an end no source place explains has [null]. *)
let entry_region (program : Rapid_runtime.Ir.program) entry =
  let lower = String.lowercase_ascii entry in
  Array.fold_left (fun found (r : Rapid_runtime.Ir.routine) ->
      match found with
      | Some _ -> found
      | None -> if String.lowercase_ascii r.name = lower && r.kind = Procedure then Some r.at else None)
    None program.routines

let finish (o : Rapid_runtime.Outcome.t) steps ~max_steps =
  match o with
  | Ended -> exit_ok
  | Stopped { name; at; chain; about; _ } ->
      Printf.eprintf "%s: execution error: %s%s: the system error handler stopped the task (%s)\n"
        (Source.to_string at) name (match about with Some a -> " (" ^ a ^ ")" | None -> "")
        (EJ.chain_text chain);
      exit_stopped
  | Resource_exhausted (m, _) -> Printf.eprintf "rapid-sem: %s\n" m; exit_exhausted
  | Deadlock m -> Printf.eprintf "rapid-sem: %s\n" m; exit_exhausted
  | Unsupported { reason; at; _ } ->
      Printf.eprintf "%s: not modelled: %s (run with --stub-unmodelled to run it as a no-op)\n"
        (Source.to_string at) reason;
      exit_unsupported
  | Stuck m -> Printf.eprintf "rapid-sem: internal error: no rule applies (%s) after %d steps; please report this program\n" m steps; exit_internal
  | Running -> Printf.eprintf "rapid-sem: the step limit (%d) is exhausted\n" max_steps; exit_exhausted

(* A count given on the command line: a whole number from 0 to the largest integer; a negative
   one is refused as a usage error (exit status 2) that says so. *)
let count ~what =
  let parse s =
    match int_of_string_opt (String.trim s) with
    | Some n when n >= 0 -> Ok n
    | Some _ -> Error (`Msg (Printf.sprintf "%s must be 0 or more, not %s" what s))
    | None ->
        Error (`Msg (Printf.sprintf "%s must be a whole number from 0 to %d, not %S" what max_int s))
  in
  Arg.conv (parse, Format.pp_print_int)

let common_run_args =
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer.") in
  let entry = Arg.(value & opt string "main" & info [ "entry" ] ~docv:"NAME" ~doc:"The entry routine (default main).") in
  let max_steps = Arg.(value & opt (count ~what:"--max-steps") 100_000_000 & info [ "max-steps" ] ~docv:"N" ~doc:"Stop after N reduction steps (exit status 3).") in
  let allow_unknown = Arg.(value & flag & info [ "allow-unknown" ] ~doc:"Names neither declared nor installed are warnings; reaching one is an execution error.") in
  let max_depth = Arg.(value & opt (count ~what:"--max-call-depth") Rapid_runtime.Limits.default.max_call_depth & info [ "max-call-depth" ] ~docv:"N" ~doc:"The deepest call chain (resource exhaustion beyond).") in
  let retry_limit = Arg.(value & opt (count ~what:"--retry-limit") Rapid_runtime.Limits.default.retry_limit & info [ "retry-limit" ] ~docv:"N" ~doc:"\"No Of Retry\": RETRYs of one error before ERR_EXCRTYMAX (§7.1).") in
  let max_memory = Arg.(value & opt (count ~what:"--max-memory") Rapid_runtime.Limits.default.max_memory & info [ "max-memory" ] ~docv:"BYTES" ~doc:"The memory budget of RAPID data (default 256 MiB; doc/user-guide.md): data beyond it ends the run with exit status 3.") in
  let stub = Arg.(value & flag & info [ "stub-unmodelled" ] ~doc:"Run an installed routine whose behaviour rapid-sem does not model as a no-op (a function returns its type's initial value; VAR and INOUT arguments are left as they are), with one warning per routine, instead of ending the run with exit status 4.") in
  (files, entry, max_steps, Term.(const (fun a b -> (a, b)) $ allow_unknown $ stub), max_depth,
   Term.(const (fun r m -> (r, m)) $ retry_limit $ max_memory))

(* A run allocates frames that live as long as their routine: with deep recursion the live heap
   grows with the call depth, and the collector's default pace makes each step cost more the
   deeper it is. A lazier pace keeps the cost of a step nearly independent of depth
   (bench/README.md, "The machine"). *)
let machine_gc () = Gc.set { (Gc.get ()) with space_overhead = 400 }

(* --stub-unmodelled: each stubbed routine once, at its first call. *)
let report_stubbed events =
  List.iter (function
      | Rapid_runtime.Event.Stubbed { routine; at } ->
          Printf.eprintf "%s: warning: %s is not modelled; --stub-unmodelled ran it as a no-op\n%!"
            (Source.to_string at) routine
      | _ -> ()) events

(* R-13-aa: under --allow-unknown --stub-unmodelled, the undeclared names a program passes as
   signals become virtual signals at 0, reported once each on standard error. *)
let with_inferred_signals (allow_unknown, stub_unmodelled) files io =
  if not (allow_unknown && stub_unmodelled) then io
  else
    let modules = List.filter_map (fun f -> Result.to_option (Rapid_syntax.Parse.parse_file f)) files in
    let io, added = Rapid_load.Signal_inference.for_run ~allow_unknown ~stub_unmodelled modules io in
    List.iter (fun (s : Rapid_controller.Io_config.signal) ->
        Printf.eprintf "warning: %s is not declared; --stub-unmodelled made it a virtual %s at 0\n%!" s.name
          (Rapid_controller.Io_config.type_name s.kind)) added;
    io

(* The task buffer loaded, in the controller of the options (signals, stimulus, clock, services,
   robot), which both engines run it in; its warnings on standard error. *)
let in_controller ?json ?robot ?history files (allow_unknown, stub_unmodelled) controller k =
  match read_io controller.io, Motion_cmd.load_robot robot with
  | Error m, _ | _, Error m -> prerr_endline m; exit_static_error
  | Ok io, Ok robot ->
  let io = with_inferred_signals (allow_unknown, stub_unmodelled) files io in
  if controller.statement_time < 0. || controller.max_time < 0. then
    (prerr_endline "rapid-sem: --statement-time and --max-time are not negative"; exit_static_error)
  else
  match Rapid_load.Session.load ~allow_unknown ~io files with
  | Error f -> report_load_failure ?json f
  | Ok loaded ->
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) loaded.warnings;
      Option.iter prerr_endline loaded.unknown_summary;
      let world = Rapid_controller.World.create ~statement_time:controller.statement_time
          ~max_time:controller.max_time ~epoch:controller.epoch io in
      let motion = Rapid_installed.Motion_routines.create ~robot ?history () in
      match Services_args.install controller.services world with
      | Error m -> Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
      | Ok () -> k loaded world motion

(* [history]: the motion history is kept, within --max-memory (--samples, rapid-sem motion). *)
let start_machine ?json ?(observe = false) ?(history = false) ?robot files entry (allow_unknown, stub_unmodelled)
    max_depth
    retry_limit controller k =
  machine_gc ();
  let history = if history then Some (snd retry_limit) else None in
  in_controller ?json ?robot ?history files (allow_unknown, stub_unmodelled) controller @@ fun loaded world motion ->
  let retry_limit, max_memory = retry_limit in
  let w = Rapid_run.Run.setup ~controller:world ~motion () in
  match M.start ~limits:{ max_call_depth = max_depth; retry_limit; max_memory } ~host:w.host ~stub_unmodelled
          ~observe loaded.program ~entry with
  | Error m ->
      if json = Some true then
        List.iter (fun j -> print_endline (Json_text.to_string j)) [ Verdict.start_line; EJ.refused_entry ~files ~entry ];
      Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
  | Ok cfg -> k cfg w

(* rapid-sem run --engine closure: the same events and outcome by the closure engine, in the same
   controller (signals, stimulus, clock, services, robot) as the machine's. *)
let run_closure ?robot ?save files entry max_steps (allow_unknown, stub_unmodelled) max_depth (retry_limit, max_memory) json
    controller print_event =
  in_controller ~json ?robot files (allow_unknown, stub_unmodelled) controller @@ fun loaded world motion ->
  if json then print_endline (Json_text.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema) ]));
  let limits = { Rapid_runtime.Limits.max_call_depth = max_depth; retry_limit; max_memory } in
  let stubbed = ref [] in
  let on_event e = (match e with Rapid_runtime.Event.Stubbed _ -> stubbed := e :: !stubbed | _ -> ()); print_event e in
  let data = ref [] in
  let module_data = Option.map (fun _ d -> data := d) save in
  match Rapid_closure.Closure_engine.run ~limits ~fuel:max_steps ~stub_unmodelled ~all_events:(json || stub_unmodelled)
          ~observe:json ~on_event ~host:(Rapid_run.Run.setup ~controller:world ~motion ()).host ?module_data
          loaded.program ~entry with
  | Error m ->
      if json then print_endline (Json_text.to_string (EJ.refused_entry ~files ~entry));
      Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
  | Ok { outcome; fuel_used } ->
      report_stubbed (List.rev !stubbed);
      if json then print_endline (Json_text.to_string
                                    (EJ.outcome ?entry_at:(entry_region loaded.program entry) outcome fuel_used));
      (* --save: as the machine's run writes them (Persistent_save). *)
      let saved = match save with
        | None -> Ok []
        | Some dir ->
            flush_output ();
            Rapid_run.Persistent_save.save_modules ~dir ~files:(List.filter (( <> ) "-") files) !data in
      match saved with
      | Error m -> Printf.eprintf "rapid-sem: --save: %s\n%!" m; exit_static_error
      | Ok _ -> finish outcome fuel_used ~max_steps

(* rapid-sem run --task NAME=FILE,... (ch. 14): every task on one clock, turns of a statement
   (Task_set); each event of --json names its task. [start] loads them for one engine. *)
let prepare_tasks ?history ~tasks ~entries (allow_unknown, stub_unmodelled) controller robot start =
  machine_gc ();
  let parse_task s =
    match String.index_opt s '=' with
    | Some i when i > 0 && i < String.length s - 1 ->
        Ok (String.sub s 0 i, List.filter (( <> ) "") (String.split_on_char ',' (String.sub s (i + 1) (String.length s - i - 1))))
    | _ -> Error (Printf.sprintf "rapid-sem: --task %s: expected NAME=FILE[,FILE...]" s) in
  let parse_entry s =
    match String.index_opt s '=' with
    | Some i when i > 0 && i < String.length s - 1 -> Ok (String.sub s 0 i, String.sub s (i + 1) (String.length s - i - 1))
    | _ -> Error (Printf.sprintf "rapid-sem: --entry %s: with --task, expected NAME=ROUTINE" s) in
  let all f l = List.fold_right (fun x acc -> match f x, acc with Ok v, Ok vs -> Ok (v :: vs) | Error m, _ | _, Error m -> Error m) l (Ok []) in
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  match all parse_task tasks, all parse_entry entries, read_io controller.io, Motion_cmd.load_robot robot with
  | Error m, _, _, _ | _, Error m, _, _ | _, _, Error m, _ | _, _, _, Error m -> prerr_endline m; exit_static_error
  | Ok tasks, Ok entries, Ok io, Ok robot ->
  let names = List.map fst tasks in
  let duplicate = List.find_opt (fun n -> List.length (List.filter (same n) names) > 1) names in
  let unknown_entry = List.find_opt (fun (n, _) -> not (List.exists (same n) names)) entries in
  match duplicate, unknown_entry with
  | Some n, _ -> Printf.eprintf "rapid-sem: --task %s is given twice: task names are unique\n" n; exit_static_error
  | _, Some (n, _) -> Printf.eprintf "rapid-sem: --entry %s=...: there is no task %s\n" n n; exit_static_error
  | None, None ->
  (* R-13-aa: the signals are the controller's, shared by every task. *)
  let io = with_inferred_signals (allow_unknown, stub_unmodelled) (List.concat_map snd tasks) io in
  let specs = List.map (fun (name, files) ->
      let entry = match List.find_opt (fun (n, _) -> same n name) (List.rev entries) with Some (_, r) -> r | None -> "main" in
      { Rapid_run.Task_load.name; files; entry }) tasks in
  let world = Rapid_controller.World.create ~statement_time:controller.statement_time
      ~max_time:controller.max_time ~epoch:controller.epoch io in
  let motion = Rapid_installed.Motion_routines.create ~robot ?history () in
  match Services_args.install controller.services world with
  | Error m -> Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
  | Ok () -> start ~io ~world ~motion specs names

let refused_tasks ~json (failure : Rapid_run.Task_load.failure) =
  match failure with
  | Load (name, f) -> Printf.eprintf "rapid-sem: task %s is refused:\n%!" name; report_load_failure ~json f
  | Refused m -> prerr_endline ("rapid-sem: " ^ m); exit_static_error

let start_tasks ?(history = false) ~tasks ~entries ~seed ~motion_task ~json (allow_unknown, stub_unmodelled) max_depth
    (retry_limit, max_memory) controller robot k =
  let history = if history then Some max_memory else None in
  prepare_tasks ?history ~tasks ~entries (allow_unknown, stub_unmodelled) controller robot
  @@ fun ~io ~world ~motion specs names ->
  let module TS = Rapid_semantics.Task_set in
  match Rapid_run.Run.machine_tasks ~limits:{ max_call_depth = max_depth; retry_limit; max_memory } ~stub_unmodelled
          ~allow_unknown ~io ~observe:json ?seed ?motion_task ~controller:world ~motion specs with
  | Error f -> refused_tasks ~json f
  | Ok (ts, loaded) ->
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) loaded.warnings;
      k ts names loaded

(* One task-end object per task (as the end object of one task), before the run's end. *)
let task_ends ts =
  List.iter (fun (name, cfg) ->
      print_line (Json_text.to_string (EJ.task_end name (Rapid_semantics.Task_set.task_outcome ts cfg) (M.steps cfg))))
    (Rapid_semantics.Task_set.tasks ts)

(* run --task by the closure engine (Closure_tasks): the same events, in the same order, as
   run_tasks's; --max-steps is each task's fuel. *)
let run_tasks_closure ~tasks ~entries ~seed ~motion_task ~json ~max_steps (allow_unknown, stub_unmodelled) max_depth
    (retry_limit, max_memory) controller robot =
  prepare_tasks ~tasks ~entries (allow_unknown, stub_unmodelled) controller robot @@ fun ~io ~world ~motion specs names ->
  let module CT = Rapid_closure.Closure_tasks in
  match Rapid_run.Run.closure_tasks ~limits:{ max_call_depth = max_depth; retry_limit; max_memory } ~stub_unmodelled
          ~allow_unknown ~io ?seed ?motion_task ~controller:world ~motion specs with
  | Error f -> refused_tasks ~json f
  | Ok (ct, loaded) ->
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) loaded.warnings;
      if json then print_line (Json_text.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema);
                                                                 ("tasks", `List (List.map (fun n -> `String n) names)) ]));
      let on_event name (e : Rapid_runtime.Event.t) =
        report_stubbed [ e ];
        if json then print_line (Json_text.to_string (EJ.with_task name (event_json e)))
        else match e with Output s -> print_line s | _ -> () in
      let r = CT.run ~fuel:max_steps ~all_events:(json || stub_unmodelled) ~observe:json ~on_event ct in
      let steps = List.fold_left (fun n (t : CT.task_result) -> n + t.fuel_used) 0 r.tasks in
      if json then begin
        List.iter (fun (t : CT.task_result) ->
            print_line (Json_text.to_string
                          (EJ.task_end t.name t.task_outcome t.fuel_used))) r.tasks;
        print_line (Json_text.to_string (EJ.outcome r.outcome steps))
      end;
      flush_output ();
      finish r.outcome steps ~max_steps

let run_tasks ?samples ~tasks ~entries ~seed ~motion_task ~json ~max_steps allow_unknown max_depth retry_limit controller robot =
  let module TS = Rapid_semantics.Task_set in
  start_tasks ~history:(samples <> None && json) ~tasks ~entries ~seed ~motion_task ~json allow_unknown max_depth
    retry_limit controller robot @@ fun ts names loaded ->
      if json then print_line (Json_text.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema);
                                                                 ("tasks", `List (List.map (fun n -> `String n) names)) ]));
      (* --samples: the motion task's robot, as the one clock passes the samples; each
         tcp-sample names the motion task. *)
      let robot_task = Option.map (fun (t : Rapid_run.Task_load.task) ->
          (t.rules.name, List.assoc t.rules.name (TS.tasks ts), Rapid_run.Run.task_world t)) (Rapid_run.Run.motion_task loaded) in
      let sampler = match samples, robot_task with Some hz, Some _ when json -> Some (Motion_cmd.sampler hz) | _ -> None in
      let print_samples l =
        Option.iter (fun (name, _, _) -> List.iter (fun j -> print_line (Json_text.to_string (EJ.with_task name j))) l) robot_task in
      let rec loop () =
        if TS.steps ts < max_steps then
          match TS.step ts with
          | None -> ()
          | Some (name, _, events) ->
              report_stubbed events;
              Option.iter (fun s -> Option.iter (fun (_, _, (w : Rapid_run.Run.world)) ->
                  print_samples (Motion_cmd.samples s w.motion ~until:((TS.clock ts).now ()))) robot_task) sampler;
              List.iter (fun (e : Rapid_runtime.Event.t) ->
                  if json then print_line (Json_text.to_string (EJ.with_task name (event_json e)))
                  else match e with Output s -> print_line s | _ -> ()) events;
              loop ()
      in
      loop ();
      Option.iter (fun s -> Option.iter (fun (_, cfg, w) -> print_samples (Motion_cmd.final_samples s cfg w)) robot_task)
        sampler;
      let outcome = TS.outcome ts in
      if json then begin
        task_ends ts;
        print_line (Json_text.to_string (EJ.outcome outcome (TS.steps ts)))
      end;
      flush_output ();
      finish outcome (TS.steps ts) ~max_steps

(* --task, --schedule, --motion-task, and FILE and --entry as they are with them (run, trace). *)
let tasks_args =
  let files = Arg.(value & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer (without --task).") in
  let entry = Arg.(value & opt_all string [] & info [ "entry" ] ~docv:"[TASK=]ROUTINE"
                     ~doc:"The entry routine (default main); with --task, TASK=ROUTINE for each task whose entry is not main.") in
  let tasks = Arg.(value & opt_all string [] & info [ "task" ] ~docv:"NAME=FILE[,FILE...]"
                     ~doc:"A task of its own (ch. 14): its name and the module files of its task buffer. Repeat for several tasks, all on one virtual clock (doc/user-guide.md, \"Several tasks\"); the first is the motion task unless --motion-task names another.") in
  let schedule = Arg.(value & opt (some (count ~what:"--schedule")) None & info [ "schedule" ] ~docv:"SEED"
                        ~doc:"With --task: turns in a pseudo-random order that depends on SEED only (SplitMix64), instead of round robin.") in
  let motion_task = Arg.(value & opt (some string) None & info [ "motion-task" ] ~docv:"NAME"
                           ~doc:"With --task: the task that has the robot (default the first task).") in
  Term.(const (fun files entries tasks schedule motion_task -> (files, entries, tasks, schedule, motion_task))
        $ files $ entry $ tasks $ schedule $ motion_task)

(* Without --task: the files are required, and --entry names a routine. *)
let single_task files entries schedule motion_task k =
  if files = [] then (prerr_endline "rapid-sem: required argument FILE is missing (or give --task NAME=FILE)"; exit_static_error)
  else if schedule <> None || motion_task <> None then (prerr_endline "rapid-sem: --schedule and --motion-task go with --task"; exit_static_error)
  else match List.find_opt (fun e -> String.contains e '=') entries with
    | Some e -> Printf.eprintf "rapid-sem: --entry %s: TASK=ROUTINE goes with --task\n" e; exit_static_error
    | None -> k (match List.rev entries with e :: _ -> e | [] -> "main")

let run_cmd =
  let _files, _entry, max_steps, allow_unknown, max_depth, retry_limit = common_run_args in

  let json = Arg.(value & flag & info [ "json" ] ~doc:"Write one JSON object per observable event (doc/trace-format.md) instead of the program's output.") in
  let save = Arg.(value & opt (some string) None & info [ "save" ] ~docv:"DIR"
                    ~doc:"At the end of the run, write each module to DIR (made if missing) with every PERS \
                          declaration's initial value replaced by the persistent's current value; the rest \
                          of the text is kept byte for byte, and each file is replaced atomically (doc/services.md).") in
  
  let engine = Arg.(value & opt (some (enum [ ("machine", `Machine); ("closure", `Closure) ])) None & info [ "engine" ] ~docv:"ENGINE" ~doc:"$(b,closure) (the second engine, the default: the same events as the machine's, faster; --max-steps counts its units of fuel, each task's with --task) or $(b,machine) (the small-step machine, the definition, which $(b,trace) and $(b,debug) run). Without this option, a run with --samples runs on the machine, which alone has it (doc/semantics.md, \"The second engine\").") in
  let run (files, entries, tasks, schedule, motion_task) max_steps allow_unknown max_depth retry_limit json controller robot samples save engine =
    guard @@ fun () ->
    (* The closure engine by default, once the differential campaign passed (doc/fuzz-campaign.md);
       what only the machine has selects it. *)
    let engine = match engine with
      | Some e -> e
      | None -> if samples <> None then `Machine else `Closure in
    if tasks <> [] then begin
      if files <> [] then (prerr_endline "rapid-sem: with --task, the files are named in each --task NAME=FILE,..."; exit_static_error)
      else if save <> None then (prerr_endline "rapid-sem: --save runs one task: not with --task"; exit_static_error)
      else if engine = `Closure && samples <> None then
        (prerr_endline "rapid-sem: --samples runs on the machine only: use --engine machine"; exit_static_error)
      else if engine = `Closure then
        run_tasks_closure ~tasks ~entries ~seed:schedule ~motion_task ~json ~max_steps allow_unknown max_depth retry_limit controller robot
      else match Motion_cmd.check_samples samples with Error m -> prerr_endline m; exit_static_error | Ok () ->
      run_tasks ?samples ~tasks ~entries ~seed:schedule ~motion_task ~json ~max_steps allow_unknown max_depth retry_limit controller robot
    end
    else let saved_files = List.filter (( <> ) "-") files in
    match Option.map (fun dir -> Rapid_run.Persistent_save.check ~dir ~files:saved_files) save with
    | Some (Error m) -> Printf.eprintf "rapid-sem: --save: %s\n%!" m; exit_static_error
    | _ ->
    (* A module read from standard input has no file to write back: say so rather than drop it. *)
    if save <> None && List.mem "-" files then
      prerr_endline "rapid-sem: --save: warning: the module read from standard input (-) is not saved: \
                     it has no file to write back to";
    single_task files entries schedule motion_task @@ fun entry ->
    let print_event (e : Rapid_runtime.Event.t) =
      if json then print_line (Json_text.to_string (event_json e))
      else match e with Output s -> print_line (Rapid_runtime.Text_format.display s) | _ -> () in
    if engine = `Closure && samples <> None then
      (prerr_endline "rapid-sem: --samples runs on the machine only: use --engine machine"; exit_static_error)
    else if engine = `Closure then
      run_closure ?robot ?save files entry max_steps allow_unknown max_depth retry_limit json controller print_event else
    match Motion_cmd.check_samples samples with Error m -> prerr_endline m; exit_static_error | Ok () ->
    start_machine ~json ~observe:json ~history:(samples <> None && json) ?robot files entry allow_unknown max_depth
      retry_limit controller @@ fun cfg w ->
    if json then print_line (Json_text.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema) ]));
    (* --samples: TCP samples as the clock passes them (JSON only). *)
    let sampler = match samples with Some hz when json -> Some (Motion_cmd.sampler hz) | _ -> None in
    let print_samples l = List.iter (fun j -> print_line (Json_text.to_string j)) l in
    let rec loop () =
      if M.outcome cfg = Running && M.steps cfg < max_steps then begin
        let _, events = M.step cfg in
        report_stubbed events;
        Option.iter (fun s -> print_samples (Motion_cmd.samples s w.motion
                                               ~until:(Rapid_controller.World.now w.controller))) sampler;
        List.iter (fun (e : Rapid_runtime.Event.t) ->
            if json then print_line (Json_text.to_string (event_json e))
            else match e with Output s -> print_line s | _ -> ()) events;
        loop ()
      end
    in
    loop ();
    Option.iter (fun s -> print_samples (Motion_cmd.final_samples s cfg w)) sampler;
    if json then print_line (Json_text.to_string (EJ.outcome ?entry_at:(entry_region (M.program cfg) entry)
                                                      (M.outcome cfg) (M.steps cfg)));
    flush_output ();
    let saved = match save with
      | None -> Ok []
      | Some dir ->
          Rapid_run.Persistent_save.save_modules ~dir
            ~files:(List.filter (( <> ) "-") files) (M.module_data cfg) in
    match saved with
    | Error m -> Printf.eprintf "rapid-sem: --save: %s\n%!" m; exit_static_error
    | Ok _ -> finish (M.outcome cfg) (M.steps cfg) ~max_steps
  in
  let doc = "run a task: check the modules, then execute the entry routine" in
  let man = [
    `S Manpage.s_description;
    `P "Checks the FILEs as one task buffer (as $(b,rapid-sem check)), then runs the entry routine by the semantics of doc/semantics.md (the second engine unless $(b,--engine) or what only the machine has asks for the small-step machine). Standard output carries only the program's output, one line per TPWrite.";
    `P "With $(b,--task NAME=FILE,...) (repeated), runs several tasks instead, each its own task buffer and entry routine, on one virtual clock, in turns of one statement (round robin, or the order of $(b,--schedule SEED)); system-global persistents are shared between them (chapter 14; doc/user-guide.md, \"Several tasks\"). With $(b,--json), each event names its task.";
    `S Manpage.s_exit_status;
    `P "0: the task ended (end of the entry routine, RETURN in it, EXIT). 1: the system error handler stopped it; the error's name and the place of the failing statement go to standard error. 2: a static error, before anything ran. 3: the step limit or a resource limit (call depth, the memory budget of --max-memory) was exhausted. 4: the program called an installed routine rapid-sem does not model yet. 141: standard output was closed (a pipe whose reader has gone) or could not be written.";
  ] in
  Cmd.v (Cmd.info "run" ~doc ~man)
    Term.(const run $ tasks_args $ max_steps $ allow_unknown $ max_depth $ retry_limit $ json $ controller_args
          $ Motion_cmd.robot_arg $ Motion_cmd.samples_arg $ save $ engine)

module TV = Rapid_tools.Trace_view

let write_json (w : TV.change) =
  match w with
  | Write { place; value } -> Some (`Assoc [ ("place", EJ.text place); ("value", EJ.text value) ])
  | _ -> None

(* The changes other than writes, as the events of run --json, with two more kinds. *)
let change_json (c : TV.change) : Yojson.Safe.t option =
  let ev (e : Rapid_runtime.Event.t) = Some (event_json e) in
  match c with
  | Write _ -> None
  | Output s -> ev (Output s)
  | Erase -> ev Erase
  | Log s -> ev (Log s)
  | Raised { name; number; at } -> ev (Error_raised { name; number; at })
  | Handled { name; routine } -> ev (Error_handled { name; routine })
  | Undo_run r -> ev (Undo_run r)
  | Routine_entered r -> ev (Routine_entered r)
  | Routine_left r -> ev (Routine_left r)
  | Task_ended -> ev Task_ended
  | Retried -> Some (`Assoc [ ("event", `String "retry") ])
  | Next_tried -> Some (`Assoc [ ("event", `String "trynext") ])
  | Controller_event e -> ev e

(* What the controller and the motion did, as the human trace writes it after "~ ". *)
let controller_text (e : Rapid_runtime.Event.t) =
  match e with
  | Controller (Signal_changed { time; signal; value }) -> Some (Printf.sprintf "%.6f s: %s = %g" time signal value)
  | Controller (Interrupt_occurred { time; number }) -> Some (Printf.sprintf "%.6f s: interrupt %d occurred" time number)
  | Controller (Interrupt_discarded { time; number; reason }) ->
      Some (Printf.sprintf "%.6f s: interrupt %d discarded (%s)" time number reason)
  | Trap_entered { time; number; trap } -> Some (Printf.sprintf "%.6f s: trap %s serves interrupt %d" time trap number)
  | Trap_left { time; trap } -> Some (Printf.sprintf "%.6f s: trap %s left" time trap)
  | Motion m -> Some (Rapid_observable.Motion_event.to_string m)
  | _ -> None

(* An entry of the event log other than ErrWrite's (§7.5), as the debugger shows it. *)
let event_log_text : Rapid_installed.Primitive.log_entry -> string = function
  | Err_log { id; kind; arguments } -> Printf.sprintf "%s %d: %s" kind id (String.concat " | " arguments)
  | Skip_warning -> "SkipWarn"

(* A change as the statement-level trace writes it after the statement. *)
let change_text (c : TV.change) =
  match c with
  | Controller_event (Event_log l) -> Some ("log: " ^ event_log_text l)
  | Write { place; value } -> Some (place ^ " := " ^ value)
  | Output s -> Some ("> " ^ s)
  | Erase -> Some "(erased)"
  | Log s -> Some ("log: " ^ s)
  | Raised { name; number; at } -> Some (Printf.sprintf "%s (%d) raised at %s" name number (Source.to_string at))
  | Handled { routine; _ } -> Some ("handled by " ^ routine)
  | Retried | Next_tried -> None  (* the statement says it *)
  | Undo_run r -> Some ("UNDO of " ^ r)
  | Controller_event (Observed (Propagated { name; number; routine; _ })) ->
      Some (Printf.sprintf "%s (%d) propagated from %s" name number routine)
  | Controller_event e -> Option.map (fun t -> "~ " ^ t) (controller_text e)
  | Routine_entered _ | Routine_left _ | Task_ended -> None

(* What a reduction line adds under it: output, errors and handlers, UNDO. *)
let change_line (c : TV.change) =
  match c with
  | Controller_event (Event_log l) -> Some ("log: " ^ event_log_text l)
  | Output s -> Some ("> " ^ s)
  | Erase -> Some "> (erased)"
  | Log s -> Some ("log: " ^ s)
  | Undo_run r -> Some ("! the UNDO handler of " ^ r ^ " runs")
  | Controller_event e -> Option.map (fun t -> "~ " ^ t) (controller_text e)
  | Raised _ | Handled _ (* the error's own step says it *) | Write _ | Retried | Next_tried | Routine_entered _ | Routine_left _ | Task_ended -> None

let trace_cmd =
  let _files, _entry, max_steps, allow_unknown, max_depth, retry_limit = common_run_args in
  let format = Arg.(value & opt (enum [ ("human", `Human); ("jsonl", `Jsonl) ]) `Human & info [ "format" ] ~docv:"FORMAT" ~doc:"$(b,human) or $(b,jsonl) (doc/trace-format.md).") in
  let level = Arg.(value & opt (enum [ ("reduction", `Reduction); ("statement", `Statement) ]) `Reduction & info [ "level" ] ~docv:"LEVEL" ~doc:"$(b,reduction): one line per reduction step (the default); $(b,statement): one line per statement executed, with the changes it made.") in
  let from_ = Arg.(value & opt (count ~what:"--from") 1 & info [ "from" ] ~docv:"N" ~doc:"First step printed.") in
  let to_ = Arg.(value & opt (count ~what:"--to") max_int & info [ "to" ] ~docv:"N" ~doc:"Last step printed.") in
  let rules = Arg.(value & opt (some string) None & info [ "rules" ] ~docv:"PATTERN" ~doc:"Print only the steps whose rule name contains PATTERN (reduction level).") in
  let run (files, entries, tasks, schedule, motion_task) max_steps allow_unknown max_depth retry_limit format level from_ to_ rules controller robot samples =
    guard @@ fun () ->
    match Motion_cmd.check_samples samples with Error m -> prerr_endline m; exit_static_error | Ok () ->
    (* One task, or several (--task): [next] the task about to step (its name with
       several), [do_step] its step, [single] the task whose robot --samples samples (the one
       task, or the motion task). *)
    let body ~next ~do_step ~outcome ~steps ~single ~entry_at =
    let sampler = match samples, single with Some hz, Some _ when format = `Jsonl -> Some (Motion_cmd.sampler hz) | _ -> None in
    let contains s p =
      let n = String.length p and m = String.length s in
      let rec go i = i + n <= m && (String.sub s i n = p || go (i + 1)) in
      n = 0 || go 0 in
    let views = Hashtbl.create 4 in
    let view_of task =
      match Hashtbl.find_opt views task with
      | Some v -> v
      | None ->
          let v = TV.create ~read:(fun name -> if name = Parse.stdin_name then Some (Parse.source_text "-") else None) () in
          Hashtbl.replace views task v; v in
    let view = view_of None in
    let json j = print_line (Json_text.to_string j) in
    if format = `Jsonl then
      json (`Assoc [ ("schema", `String schema); ("kind", `String "trace");
                     ("level", `String (match level with `Reduction -> "reduction" | `Statement -> "statement")) ]);
    (* Source text and values as JSON strings: valid UTF-8 whatever the file's encoding. *)
    let text_json = EJ.text in
    let writes (st : TV.step) = List.filter_map write_json st.changes in
    let events (st : TV.step) = List.filter_map change_json st.changes in
    (* The statement level: one line per statement, its changes after it. A change made after a
       nested statement printed (the store of [x := f(y)] after f's statements) continues its
       statement on a line of its own. *)
    (* A line is a statement's, or, before a routine's first statement, its routine data's. *)
    let module Ir = Rapid_runtime.Ir in
    let line : (int * Ir.routine * Ir.stmt option * int * TV.change list) option ref = ref None in
    (* With several tasks: the task of the line being built; a step of another task ends it. *)
    let line_task : string option ref = ref None in
    let flush () =
      match !line with
      | None -> ()
      | Some (first, routine, s, depth, changes) ->
          line := None;
          if first >= from_ && first <= to_ then begin
            let changes = List.rev changes in
            let place, text, at = match s with
              | Some s -> (TV.place_of_statement view routine s, TV.statement_text view s, s.sat)
              | None ->
                  (Printf.sprintf "%s:%d" routine.module_name (Source.start routine.at).line,
                   "(routine data of " ^ routine.name ^ ")", routine.at) in
            match format with
            | `Human ->
                let shown = List.filter_map change_text changes in
                let place = match !line_task with Some t -> t ^ " " ^ place | None -> place in
                print_line @@ Printf.sprintf "%s%s%s%s%s" place (String.make (max 2 (20 - String.length place)) ' ')
                  (String.make (2 * min 10 (depth - 1)) ' ') (Rapid_runtime.Text_format.display text)
                  (if shown = [] then "" else "   " ^ Rapid_runtime.Text_format.display (String.concat "; " shown))
            | `Jsonl ->
                json (`Assoc ((match !line_task with Some t -> [ ("task", `String t) ] | None -> []) @ [
                    ("statement", `String place);
                    ("step", `Int first); ("depth", `Int depth); ("routine", `String routine.name);
                    ("at", EJ.region at); ("text", text_json text);
                    ("writes", `List (List.filter_map write_json changes));
                    ("events", `List (List.filter_map change_json changes)) ]))
          end
    in
    let statement_step (st : TV.step) =
      let owner = match st.statement with Some s -> Some s | None -> st.in_statement in
      let printable = List.exists (fun c -> change_text c <> None) st.changes in
      (match st.statement, !line, owner with
       | Some s, _, _ -> flush (); line := Some (st.number, st.routine, Some s, st.depth, [])
       | None, Some (_, _, Some s, _, _), Some o when s == o -> ()
       | None, _, Some o when printable -> flush (); line := Some (st.number, st.routine, Some o, st.depth, [])
       | None, Some (_, r, None, _, _), None when r == st.routine -> ()
       (* An interrupt served between statements, a trap left: what the controller did goes
          on the line printed last, in the order it happened. *)
       | None, Some _, None when List.for_all (function
           | TV.Controller_event _ | Routine_entered _ | Routine_left _ -> true | _ -> false) st.changes -> ()
       | None, _, None when printable -> flush (); line := Some (st.number, st.routine, None, st.depth, [])
       | _ -> ());
      match !line with
      | Some (first, r, s, d, changes) ->
          line := Some (first, r, s, d, List.rev_append st.changes changes)
      | None -> ()
    in
    let last_state = ref None in
    let reduction_step task (st : TV.step) region kind stack samples =
      if st.number >= from_ && st.number <= to_ && (match rules with None -> true | Some p -> contains st.rule p) then
        match format with
        | `Human ->
            let shown_writes = List.filter_map (function
                | TV.Write { place; value } ->
                    let w = place ^ " := " ^ value in if w = st.redex then None else Some w
                | _ -> None) st.changes in
            let results = (match st.result with Some r -> [ r ] | None -> []) @ shown_writes in
            let step = Printf.sprintf "%s%s%s" (String.make (2 * min 10 (st.depth - 1)) ' ') st.redex
                (if results = [] then "" else " -> " ^ String.concat "; " results) in
            (* The statement as it stands, when this step changed it. *)
            let state = match st.state with
              | Some s when Some s <> !last_state -> last_state := st.state; "   | " ^ s
              | Some _ -> ""
              | None -> last_state := None; "" in
            let step = Rapid_runtime.Text_format.display step and state = Rapid_runtime.Text_format.display state in
            let number = match task with Some t -> Printf.sprintf "%s %d" t st.number | None -> Printf.sprintf "%6d" st.number in
            if state = "" then print_line (Printf.sprintf "%s %-22s %-24s %s" number st.rule (Source.to_string st.at) step)
            else print_line (Printf.sprintf "%s %-22s %-24s %-44s%s" number st.rule (Source.to_string st.at) step state);
            List.iter (fun c -> match change_line c with
                | Some l -> print_line ("       " ^ Rapid_runtime.Text_format.display l) | None -> ()) st.changes
        | `Jsonl ->
            json (`Assoc ((match task with Some t -> [ ("task", `String t) ] | None -> []) @ [
                ("step", `Int st.number); ("rule", `String st.rule); ("depth", `Int st.depth);
                ("at", EJ.region st.at); ("redex", text_json st.redex);
                ("result", (match st.result with Some r -> text_json r | None -> `Null));
                ("writes", `List (writes st));
                ("state", (match st.state with Some s -> text_json s | None -> `Null));
                ("focus", `Assoc [ ("kind", `String kind); ("at", EJ.region region);
                                   ("text", text_json (TV.source_text view region)) ]);
                ("stack", `List (List.map (fun s -> `String s) stack));
                ("events", `List (events st @ samples ())) ]))
    in
    let rec loop () =
      match next () with
      | None -> ()
      | Some (task, cfg) ->
        let view = view_of task in
        let region = M.focus_region cfg and kind = M.focus_kind cfg and stack = M.stack_view cfg in
        let before = TV.before view cfg in
        let (_, events) as answer = do_step () in
        report_stubbed events;
        (* The error in flight, for error-handled, also from the steps --from and --to leave out. *)
        List.iter (EJ.note encoder) events;
        let st = TV.after view before cfg answer in
        (* The robot sampled is [single]'s: the one task's, or with several the motion task's. *)
        let samples () = match sampler, single with
          | Some s, Some (_, (w : Rapid_run.Run.world)) -> Motion_cmd.samples s w.motion ~until:(Rapid_controller.World.now w.controller)
          | _ -> [] in
        (match level with
         | `Reduction -> reduction_step task st region kind stack samples
         | `Statement ->
             ignore (samples ());
             if task <> !line_task then (flush (); line_task := task);
             statement_step st);
        loop ()
    in
    loop ();
    flush ();
    Option.iter (fun s -> Option.iter (fun (cfg, w) ->
        List.iter (fun j -> print_line (Json_text.to_string j)) (Motion_cmd.final_samples s cfg w)) single) sampler;
    let outcome = outcome () and steps = steps () in
    if format = `Jsonl then print_line (Json_text.to_string (EJ.outcome ?entry_at:(entry_at ()) outcome steps))
    else print_line @@ Printf.sprintf "end: %s after %d steps" (match outcome with
        | Ended -> "the task ended" | Stopped { name; _ } -> "stopped by the system error handler (" ^ name ^ ")"
        | Resource_exhausted (m, _) | Unsupported { reason = m; _ } | Stuck m | Deadlock m -> m
        | Running -> "step limit") steps;
    finish outcome steps ~max_steps
    in
    if tasks <> [] then begin
        let module TS = Rapid_semantics.Task_set in
        start_tasks ~history:(samples <> None && format = `Jsonl) ~tasks ~entries ~seed:schedule ~motion_task
          ~json:false
          allow_unknown max_depth retry_limit controller robot
        @@ fun ts _ loaded ->
        (* --samples: the motion task's robot. *)
        let robot_task = Option.map (fun (t : Rapid_run.Task_load.task) ->
            (List.assoc t.rules.name (TS.tasks ts), Rapid_run.Run.task_world t)) (Rapid_run.Run.motion_task loaded) in
        body ~next:(fun () -> if TS.steps ts < max_steps then Option.map (fun (n, c) -> (Some n, c)) (TS.next ts) else None)
          ~do_step:(fun () -> match TS.step ts with Some (_, rule, events) -> (rule, events) | None -> ("", []))
          ~outcome:(fun () -> TS.outcome ts) ~steps:(fun () -> TS.steps ts) ~single:robot_task
          ~entry_at:(fun () -> None)
    end
    else
      single_task files entries schedule motion_task @@ fun entry ->
      start_machine ~history:(samples <> None && format = `Jsonl) ?robot files entry allow_unknown max_depth retry_limit
        controller @@ fun cfg w ->
      body ~next:(fun () -> if M.outcome cfg = Running && M.steps cfg < max_steps then Some (None, cfg) else None)
        ~do_step:(fun () -> M.step cfg) ~outcome:(fun () -> M.outcome cfg) ~steps:(fun () -> M.steps cfg)
        ~single:(Some (cfg, w))
        ~entry_at:(fun () -> entry_region (M.program cfg) entry)
  in
  let doc = "print the reductions of a run one by one, or the statements it executes" in
  let man = [
    `S Manpage.s_description;
    `P "Runs the task like $(b,rapid-sem run --engine machine) (the small-step machine) and prints each reduction: the step number, the rule applied (doc/semantics.md), where in the source, the redex with the values it works on and what it became (errors raised and where they went included), and the statement as it stands after |; output and UNDO handlers follow on lines of their own. $(b,--level statement) prints one line per statement executed, as a programmer steps through it on the FlexPendant: MODULE:LINE, the statement, and the changes it made (store writes, output, errors). $(b,--format jsonl) writes one JSON object per line in the schema of doc/trace-format.md.";
    `S Manpage.s_exit_status; `P "As $(b,rapid-sem run).";
  ] in
  Cmd.v (Cmd.info "trace" ~doc ~man)
    Term.(const run $ tasks_args $ max_steps $ allow_unknown $ max_depth $ retry_limit $ format $ level $ from_ $ to_ $ rules $ controller_args
          $ Motion_cmd.robot_arg $ Motion_cmd.samples_arg)

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
  let junit = Arg.(value & opt (some string) None & info [ "junit" ] ~docv:"FILE" ~doc:"With --impl: also write the results as JUnit XML.") in
  let report = Arg.(value & opt (some string) None & info [ "report-json" ] ~docv:"FILE" ~doc:"With --impl: also write the results as JSON.") in
  let engine = Arg.(value & opt (enum [ ("machine", Rapid_conformance.Spec_runner.Machine); ("closure", Closure) ]) Machine & info [ "engine" ] ~docv:"ENGINE" ~doc:"The engine that runs the run-time cases (formats 3 and 4, one task or several): $(b,machine) (default) or $(b,closure).") in
  let ignore_kinds = Arg.(value & opt_all string [] & info [ "ignore" ] ~docv:"KIND"
                            ~doc:"With --impl: leave the events of this kind out of the comparison of the events (repeatable).") in
  let timeout = Arg.(value & opt float 60. & info [ "timeout" ] ~docv:"SECONDS"
                       ~doc:"With --impl: the time allowed to each run of a case (either tool's).") in
  let run dir verbose impl junit report engine ignore_kinds timeout =
    guard @@ fun () ->
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
  Cmd.v (Cmd.info "spec" ~doc ~man)
    Term.(const run $ dir $ verbose $ impl $ junit $ report $ engine $ ignore_kinds $ timeout)

let () =
  (* A closed pipe is then an error of the write (EPIPE), which ends the run with its status. *)
  Sys.set_signal Sys.sigpipe Sys.Signal_ignore;
  let doc = "the executable semantics of ABB's RAPID robot programming language" in
  let info = Cmd.info "rapid-sem" ~version ~doc in
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
  let status = Cmd.eval' ~argv (Cmd.group info [ parse_cmd; check_cmd; run_cmd; trace_cmd; spec_cmd;
                                                 Motion_cmd.cmd ~start_machine:(fun ?robot files entry allow_unknown max_depth retry_limit controller k ->
                                                     guard @@ fun () ->
                                                     start_machine ~history:true ?robot files entry allow_unknown
                                                       max_depth retry_limit controller k)
                                                   ~finish ~common_run_args ~controller_args;
                                                 Debug_cmd.cmd ~start_machine:(fun ?robot files entry allow_unknown max_depth retry_limit controller k ->
                                                     guard @@ fun () -> start_machine ?robot files entry allow_unknown max_depth retry_limit controller k)
                                                   ~finish ~common_run_args ~controller_args;
                                                 Oracle_cmd.cmd; Fuzz_cmd.cmd; Mem_cmd.cmd;
                                                 Verdict.cmd ~read_io ~io_arg ]) in
  (* A command line that cannot be read (an unknown option, a negative limit) is refused like a
     static error, with cmdliner's message saying what is wrong. *)
  exit (if status = Cmd.Exit.cli_error then exit_static_error else status)
