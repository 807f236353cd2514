(* The rapid-sem command line. Exit statuses are a contract other tools rely on
   (doc/user-guide.md): 0 success, 2 a static error (lexical, syntax, fatal), 1 a failing
   conformance suite, 125 an internal error of rapid-sem. *)

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

let print_line s =
  try print_string s; print_char '\n' with Sys_error m -> raise (Output_failed m)

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
type controller_options = { io : string option; statement_time : float; max_time : float; epoch : float }

let io_arg =
  Arg.(value & opt (some string) None & info [ "io" ] ~docv:"FILE"
         ~doc:"The I/O configuration and the stimulus of the inputs (doc/controller.md): a stimulus file, or a RobotWare EIO.cfg file whose EIO_SIGNAL entries declare the signals.")

(* --epoch YYYY-MM-DDTHH:MM:SS, read as seconds since 1970 (UTC, no leap seconds). *)
let epoch_conv =
  let parse s =
    try Scanf.sscanf s "%4d-%2d-%2dT%2d:%2d:%2d%!" (fun y m d hh mm ss ->
        if m < 1 || m > 12 || d < 1 || d > 31 || hh > 23 || mm > 59 || ss > 59 then Error (`Msg "a date and time out of range")
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
  let print ppf t = let y, m, d, hh, mm, ss, _ = Rapid_semantics.Io_primitives.date_time t in
    Format.fprintf ppf "%04d-%02d-%02dT%02d:%02d:%02d" y m d hh mm ss in
  Arg.conv (parse, print)

let controller_args =
  let module W = Rapid_controller.World in
  let statement_time = Arg.(value & opt float W.default_statement_time & info [ "statement-time" ] ~docv:"SECONDS"
                              ~doc:"Virtual time each executed statement (and each round of a loop) takes.") in
  let max_time = Arg.(value & opt float W.default_max_time & info [ "max-time" ] ~docv:"SECONDS"
                        ~doc:"Stop the run when its virtual time goes beyond SECONDS (exit status 3).") in
  let epoch = Arg.(value & opt epoch_conv W.default_epoch & info [ "epoch" ] ~docv:"YYYY-MM-DDTHH:MM:SS"
                     ~doc:"The wall-clock time at virtual time 0, for CDate, CTime and GetTime (default 2024-01-01T00:00:00).") in
  Term.(const (fun io statement_time max_time epoch -> { io; statement_time; max_time; epoch })
        $ io_arg $ statement_time $ max_time $ epoch)

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
           ~doc:"Refuse what chapter 10 does not print: a %%%% header block, comment lines \
                 before MODULE or alone on their line inside RECORD, a byte-order mark, a file \
                 without a final line break (doc/dialect.md).")
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
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer.") in
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
  let run files allow_unknown strict format io robot =
    guard @@ fun () ->
    match read_io io, Motion_cmd.load_robot robot with
    | Error m, _ | _, Error m -> prerr_endline m; exit_static_error
    | Ok io, Ok _ ->
    let options = { Parse.default_options with strict } in
    let parsed = List.map (fun f -> Parse.parse_file ~options f) files in
    let syntax_errors = List.filter_map (function Error d -> Some d | Ok _ -> None) parsed in
    let print = Check_output.print ~version format in
    if syntax_errors <> [] then begin
      print (List.map Check_output.of_diagnostic syntax_errors);
      exit_static_error
    end
    else
      match Rapid_semantics.Session.installed ~io () with
      | Error d ->
          Printf.eprintf "rapid-sem: internal error: the installed environment does not parse: %s\n"
            (Diagnostic.to_string d);
          exit_internal
      | Ok installed -> (
          (* The whole static semantics, the initial values known before the run included
             (Session: check, lower, evaluate them). *)
          let modules = List.filter_map Result.to_option parsed in
          let result =
            Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
          let reports =
            if Rapid_typing.Check.errors result <> [] then result.reports
            else match Rapid_semantics.Session.lower ~io ~installed ~modules result with
              | Ok _ -> result.reports
              | Error initial_value_errors -> result.reports @ initial_value_errors in
          print (List.map Check_output.of_report reports);
          (* JSON and SARIF carry the warnings themselves: the summary is for people. *)
          if format = Check_output.Text then Option.iter prerr_endline (Rapid_typing.Check.unknown_summary result);
          if List.exists (fun (r : Rapid_typing.Report.t) -> r.severity = Error) reports then exit_static_error
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
    `S Manpage.s_exit_status;
    `P "0 when there is no static error (warnings allowed); 2 when there is one.";
  ] in
  Cmd.v (Cmd.info "check" ~doc ~man) Term.(const run $ files $ allow_unknown $ strict $ format $ io_arg $ Motion_cmd.robot_arg)

(* ------------------------------------------------------------------ run and trace *)

module M = Rapid_semantics.Machine

let exit_stopped = 1
let exit_exhausted = 3
let exit_unsupported = 4

let report_load_failure = function
  | Rapid_semantics.Session.Front_end ds -> List.iter (fun d -> prerr_endline (Diagnostic.to_string d)) ds; exit_static_error
  | Static reports -> List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) reports; exit_static_error
  | Internal m -> Printf.eprintf "rapid-sem: internal error: %s\n" m; exit_internal

(* JSON text is UTF-8: RAPID strings and names are bytes, read as Latin-1 where they are not
   UTF-8 (doc/trace-format.md). *)
let text s = `String (Rapid_semantics.Utf8_text.of_bytes s)

let region_json r =
  let p = Source.start r and q = Source.stop r in
  `Assoc [ ("file", text (match Source.file_of r with Some f -> Source.name f | None -> ""));
           ("line", `Int p.line); ("col", `Int p.col); ("end_line", `Int q.line); ("end_col", `Int q.col) ]

(* A virtual time: seconds to the microsecond, written as such (not as the nearest double). *)
let time_json t = `Intlit (Printf.sprintf "%.6f" t)

let event_json (e : M.event) : Yojson.Safe.t =
  match e with
  | Output s -> `Assoc [ ("event", `String "output"); ("text", text s) ]
  | Erase -> `Assoc [ ("event", `String "erase") ]
  | Log s -> `Assoc [ ("event", `String "log"); ("text", text s) ]
  | Routine_entered r -> `Assoc [ ("event", `String "routine-entered"); ("routine", text r) ]
  | Routine_left r -> `Assoc [ ("event", `String "routine-left"); ("routine", text r) ]
  | Error_raised { name; number; at } ->
      `Assoc [ ("event", `String "error-raised"); ("name", text name); ("number", `Int number);
               ("at", region_json at) ]
  | Error_handled { name; routine } ->
      `Assoc [ ("event", `String "error-handled"); ("name", text name); ("routine", text routine) ]
  | Undo_run r -> `Assoc [ ("event", `String "undo-run"); ("routine", text r) ]
  | Task_ended -> `Assoc [ ("event", `String "task-ended") ]
  | Controller (Signal_changed { time; signal; value }) ->
      `Assoc [ ("event", `String "signal-changed"); ("time", time_json time); ("signal", `String signal);
               ("value", `Float value) ]
  | Controller (Interrupt_occurred { time; number }) ->
      `Assoc [ ("event", `String "interrupt-occurred"); ("time", time_json time); ("number", `Int number) ]
  | Controller (Interrupt_discarded { time; number; reason }) ->
      `Assoc [ ("event", `String "interrupt-discarded"); ("time", time_json time); ("number", `Int number);
               ("reason", `String reason) ]
  | Trap_entered { number; trap; time } ->
      `Assoc [ ("event", `String "trap-entered"); ("time", time_json time); ("number", `Int number);
               ("trap", `String trap) ]
  | Trap_left { trap; time } ->
      `Assoc [ ("event", `String "trap-left"); ("time", time_json time); ("trap", `String trap) ]
  | Stubbed { routine; at } ->
      `Assoc [ ("event", `String "stubbed"); ("routine", `String routine); ("at", region_json at) ]
  | Motion m -> Motion_json.event m

let schema = "rapid-sem/1"

let outcome_json (o : M.outcome) steps : Yojson.Safe.t =
  let base kind extra = `Assoc ([ ("event", `String "end"); ("outcome", `String kind); ("steps", `Int steps) ] @ extra) in
  match o with
  | Running -> base "running" []
  | Ended -> base "ended" []
  | Stopped { name; number; at; chain; about } ->
      base "stopped" ([ ("name", text name); ("number", `Int number); ("at", region_json at);
                        ("chain", `List (List.map text chain)) ]
                      @ (match about with Some a -> [ ("about", text a) ] | None -> []))
  | Resource_exhausted m -> base "exhausted" [ ("reason", text m) ]
  | Unsupported { name; reason; at } ->
      base "unsupported" [ ("name", text name); ("reason", text reason); ("at", region_json at) ]
  | Stuck m -> base "stuck" [ ("reason", text m) ]
  | Deadlock m -> base "deadlock" [ ("reason", text m) ]

let finish (o : M.outcome) steps ~max_steps =
  match o with
  | Ended -> exit_ok
  | Stopped { name; at; chain; about; _ } ->
      Printf.eprintf "%s: execution error: %s%s: the system error handler stopped the task (%s)\n"
        (Source.to_string at) name (match about with Some a -> " (" ^ a ^ ")" | None -> "")
        (String.concat " <- " chain);
      exit_stopped
  | Resource_exhausted m -> Printf.eprintf "rapid-sem: %s\n" m; exit_exhausted
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
  let max_depth = Arg.(value & opt (count ~what:"--max-call-depth") M.default_limits.max_call_depth & info [ "max-call-depth" ] ~docv:"N" ~doc:"The deepest call chain (resource exhaustion beyond).") in
  let retry_limit = Arg.(value & opt (count ~what:"--retry-limit") M.default_limits.retry_limit & info [ "retry-limit" ] ~docv:"N" ~doc:"\"No Of Retry\": RETRYs of one error before ERR_EXCRTYMAX (§7.1).") in
  let max_memory = Arg.(value & opt (count ~what:"--max-memory") M.default_limits.max_memory & info [ "max-memory" ] ~docv:"BYTES" ~doc:"The memory budget of RAPID data (default 256 MiB; doc/user-guide.md): data beyond it ends the run with exit status 3.") in
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
      | M.Stubbed { routine; at } ->
          Printf.eprintf "%s: warning: %s is not modelled; --stub-unmodelled ran it as a no-op\n%!"
            (Source.to_string at) routine
      | _ -> ()) events

let start_machine ?robot files entry (allow_unknown, stub_unmodelled) max_depth retry_limit controller k =
  machine_gc ();
  match read_io controller.io, Motion_cmd.load_robot robot with
  | Error m, _ | _, Error m -> prerr_endline m; exit_static_error
  | Ok io, Ok robot ->
  if controller.statement_time < 0. || controller.max_time < 0. then
    (prerr_endline "rapid-sem: --statement-time and --max-time are not negative"; exit_static_error)
  else
  match Rapid_semantics.Session.load ~allow_unknown ~io files with
  | Error f -> report_load_failure f
  | Ok loaded -> (
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) loaded.warnings;
      Option.iter prerr_endline loaded.unknown_summary;
      let retry_limit, max_memory = retry_limit in
      let world = Rapid_controller.World.create ~statement_time:controller.statement_time
          ~max_time:controller.max_time ~epoch:controller.epoch io in
      let motion = Rapid_semantics.Motion_primitives.create ~robot () in
      match M.start ~limits:{ max_call_depth = max_depth; retry_limit; max_memory } ~world ~stub_unmodelled ~motion
              loaded.program ~entry with
      | Error m -> Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
      | Ok cfg -> k cfg)

(* rapid-sem run --engine closure: the same events and outcome by the closure engine. *)
let run_closure files entry max_steps (allow_unknown, stub_unmodelled) max_depth (retry_limit, max_memory) json print_event =
  match Rapid_semantics.Session.load ~allow_unknown files with
  | Error f -> report_load_failure f
  | Ok loaded -> (
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) loaded.warnings;
      if json then print_endline (Yojson.Safe.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema) ]));
      Option.iter prerr_endline loaded.unknown_summary;
      let limits = { M.max_call_depth = max_depth; retry_limit; max_memory } in
      let stubbed = ref [] in
      let on_event e = (match e with M.Stubbed _ -> stubbed := e :: !stubbed | _ -> ()); print_event e in
      match Rapid_semantics.Closure_engine.run ~limits ~fuel:max_steps ~stub_unmodelled ~all_events:(json || stub_unmodelled)
              ~on_event loaded.program ~entry with
      | Error m -> Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
      | Ok { outcome; fuel_used } ->
          report_stubbed (List.rev !stubbed);
          if json then print_endline (Yojson.Safe.to_string (outcome_json outcome fuel_used));
          match outcome with
          | Unsupported { reason; at; _ } when Rapid_semantics.Closure_engine.machine_only outcome ->
              (* The controller and motion: --stub-unmodelled does not help, the machine does. *)
              Printf.eprintf "%s: not run by the closure engine: %s\n" (Source.to_string at) reason;
              exit_unsupported
          | _ -> finish outcome fuel_used ~max_steps)

let run_cmd =
  let files, entry, max_steps, allow_unknown, max_depth, retry_limit = common_run_args in
  let json = Arg.(value & flag & info [ "json" ] ~doc:"Write one JSON object per observable event (doc/trace-format.md) instead of the program's output.") in
  let engine = Arg.(value & opt (enum [ ("machine", `Machine); ("closure", `Closure) ]) `Machine & info [ "engine" ] ~docv:"ENGINE" ~doc:"$(b,machine) (the small-step machine, the default) or $(b,closure) (the second engine: the same events, faster; --max-steps counts its units of fuel; the programs of chapters 4, 5, 7 and 13 that need no controller, doc/semantics.md).") in
  let run files entry max_steps allow_unknown max_depth retry_limit json controller robot samples engine =
    guard @@ fun () ->
    let print_event (e : M.event) =
      if json then print_line (Yojson.Safe.to_string (event_json e))
      else match e with Output s -> print_line (Rapid_semantics.Format.display s) | _ -> () in
    if engine = `Closure then run_closure files entry max_steps allow_unknown max_depth retry_limit json print_event else
    match Motion_cmd.check_samples samples with Error m -> prerr_endline m; exit_static_error | Ok () ->
    start_machine ?robot files entry allow_unknown max_depth retry_limit controller @@ fun cfg ->
    if json then print_line (Yojson.Safe.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema) ]));
    (* --samples: TCP samples as the clock passes them (JSON only). *)
    let sampler = match samples with Some hz when json -> Some (Motion_cmd.sampler hz) | _ -> None in
    let print_samples l = List.iter (fun j -> print_line (Yojson.Safe.to_string j)) l in
    let rec loop () =
      if M.outcome cfg = Running && M.steps cfg < max_steps then begin
        let _, events = M.step cfg in
        report_stubbed events;
        Option.iter (fun s -> print_samples (Motion_cmd.samples s (M.motion cfg)
                                               ~until:(Rapid_controller.World.now (M.world cfg)))) sampler;
        List.iter (fun (e : M.event) ->
            if json then print_line (Yojson.Safe.to_string (event_json e))
            else match e with Output s -> print_line s | _ -> ()) events;
        loop ()
      end
    in
    loop ();
    Option.iter (fun s -> print_samples (Motion_cmd.final_samples s cfg)) sampler;
    if json then print_line (Yojson.Safe.to_string (outcome_json (M.outcome cfg) (M.steps cfg)));
    flush_output ();
    finish (M.outcome cfg) (M.steps cfg) ~max_steps
  in
  let doc = "run a task: check the modules, then execute the entry routine" in
  let man = [
    `S Manpage.s_description;
    `P "Checks the FILEs as one task buffer (as $(b,rapid-sem check)), then runs the entry routine by the small-step semantics of doc/semantics.md. Standard output carries only the program's output, one line per TPWrite.";
    `S Manpage.s_exit_status;
    `P "0: the task ended (end of the entry routine, RETURN in it, EXIT). 1: the system error handler stopped it; the error's name and the place of the failing statement go to standard error. 2: a static error, before anything ran. 3: the step limit or a resource limit (call depth, the memory budget of --max-memory) was exhausted. 4: the program called an installed routine rapid-sem does not model yet. 141: standard output was closed (a pipe whose reader has gone) or could not be written.";
  ] in
  Cmd.v (Cmd.info "run" ~doc ~man)
    Term.(const run $ files $ entry $ max_steps $ allow_unknown $ max_depth $ retry_limit $ json $ controller_args
          $ Motion_cmd.robot_arg $ Motion_cmd.samples_arg $ engine)

(* The text of a region, for the trace: its first line, cut at 60 characters. Columns count
   characters (§2.1, R-2.1-b): of UTF-8 in a UTF-8 file, bytes in a Latin-1 one. *)
let source_cache = Hashtbl.create 8
let region_text r =
  match Source.file_of r with
  | None -> ""
  | Some f -> (
      let name = Source.name f in
      let lines, latin1 = match Hashtbl.find_opt source_cache name with
        | Some l -> l
        | None ->
            let l =
              if name = Parse.stdin_name then Array.of_list (String.split_on_char '\n' (Parse.source_text "-"))
              else match Rapid_conformance.In_channel_compat.read_lines name with Ok l -> Array.of_list l | Error _ -> [||] in
            let latin1 = not (Array.for_all Rapid_semantics.Utf8_text.is_utf8 l) in
            (* A byte-order mark is not a character of the module. *)
            if (not latin1) && Array.length l > 0 && String.length l.(0) >= 3 && String.sub l.(0) 0 3 = "\xEF\xBB\xBF" then
              l.(0) <- String.sub l.(0) 3 (String.length l.(0) - 3);
            Hashtbl.replace source_cache name (l, latin1); (l, latin1) in
      let p = Source.start r and q = Source.stop r in
      if p.line < 1 || p.line > Array.length lines then ""
      else
        let chars = Rapid_semantics.Utf8_text.characters ~latin1 lines.(p.line - 1) in
        let n = Array.length chars in
        let stop = if q.line = p.line then max 0 (min n (q.col - 1)) else n in
        let start = max 0 (min n (p.col - 1)) in
        let piece = Array.sub chars start (max 0 (stop - start)) in
        let is_blank c = c = " " || c = "\t" || c = "\r" || c = "\n" || c = "\012" in
        let first = ref 0 and last = ref (Array.length piece) in
        while !first < !last && is_blank piece.(!first) do incr first done;
        while !last > !first && is_blank piece.(!last - 1) do decr last done;
        let piece = Array.sub piece !first (!last - !first) in
        if Array.length piece > 60 then String.concat "" (Array.to_list (Array.sub piece 0 57)) ^ "..."
        else String.concat "" (Array.to_list piece))

let trace_cmd =
  let files, entry, max_steps, allow_unknown, max_depth, retry_limit = common_run_args in
  let format = Arg.(value & opt (enum [ ("human", `Human); ("jsonl", `Jsonl) ]) `Human & info [ "format" ] ~docv:"FORMAT" ~doc:"$(b,human) or $(b,jsonl) (doc/trace-format.md).") in
  let from_ = Arg.(value & opt (count ~what:"--from") 1 & info [ "from" ] ~docv:"N" ~doc:"First step printed.") in
  let to_ = Arg.(value & opt (count ~what:"--to") max_int & info [ "to" ] ~docv:"N" ~doc:"Last step printed.") in
  let rules = Arg.(value & opt (some string) None & info [ "rules" ] ~docv:"PATTERN" ~doc:"Print only the steps whose rule name contains PATTERN.") in
  let run files entry max_steps allow_unknown max_depth retry_limit format from_ to_ rules controller robot samples =
    guard @@ fun () ->
    match Motion_cmd.check_samples samples with Error m -> prerr_endline m; exit_static_error | Ok () ->
    start_machine ?robot files entry allow_unknown max_depth retry_limit controller @@ fun cfg ->
    let sampler = match samples with Some hz when format = `Jsonl -> Some (Motion_cmd.sampler hz) | _ -> None in
    let contains s p =
      let n = String.length p and m = String.length s in
      let rec go i = i + n <= m && (String.sub s i n = p || go (i + 1)) in
      n = 0 || go 0 in
    if format = `Jsonl then print_line (Yojson.Safe.to_string (`Assoc [ ("schema", `String schema); ("kind", `String "trace") ]));
    let rec loop () =
      if M.outcome cfg = Running && M.steps cfg < max_steps then begin
        let region = M.focus_region cfg and kind = M.focus_kind cfg and stack = M.stack_view cfg in
        let depth = M.depth cfg in
        let rule, events = M.step cfg in
        report_stubbed events;
        let n = M.steps cfg in
        if n >= from_ && n <= to_ && (match rules with None -> true | Some p -> contains rule p) then begin
          match format with
          | `Human ->
              print_line (Printf.sprintf "%6d %-24s %s %-10s %s | %s" n rule (Source.to_string region) kind
                (Rapid_semantics.Format.display (region_text region)) (String.concat " " stack));
              List.iter (function
                  | M.Output s -> print_line (Printf.sprintf "       > %s" s)
                  | M.Controller (Signal_changed { time; signal; value }) ->
                      print_line (Printf.sprintf "       ~ %.6f s: %s = %g" time signal value)
                  | M.Controller (Interrupt_occurred { time; number }) ->
                      print_line (Printf.sprintf "       ~ %.6f s: interrupt %d occurred" time number)
                  | M.Controller (Interrupt_discarded { time; number; reason }) ->
                      print_line (Printf.sprintf "       ~ %.6f s: interrupt %d discarded (%s)" time number reason)
                  | M.Trap_entered { time; number; trap } ->
                      print_line (Printf.sprintf "       ~ %.6f s: trap %s serves interrupt %d" time trap number)
                  | M.Trap_left { time; trap } -> print_line (Printf.sprintf "       ~ %.6f s: trap %s left" time trap)
                  | M.Motion m -> print_line (Printf.sprintf "       ~ %s" (Rapid_semantics.Motion_primitives.event_to_string m))
                  | _ -> ()) events
          | `Jsonl ->
              print_line (Yojson.Safe.to_string (`Assoc [
                  ("step", `Int n); ("rule", `String rule); ("depth", `Int depth);
                  ("focus", `Assoc [ ("kind", `String kind); ("at", region_json region); ("text", text (region_text region)) ]);
                  ("stack", `List (List.map (fun s -> `String s) stack));
                  ("events", `List (List.map event_json events
                                    @ (match sampler with
                                        | Some s -> Motion_cmd.samples s (M.motion cfg) ~until:(Rapid_controller.World.now (M.world cfg))
                                        | None -> []))) ]))
        end;
        loop ()
      end
    in
    loop ();
    Option.iter (fun s -> List.iter (fun j -> print_line (Yojson.Safe.to_string j)) (Motion_cmd.final_samples s cfg)) sampler;
    if format = `Jsonl then print_line (Yojson.Safe.to_string (outcome_json (M.outcome cfg) (M.steps cfg)))
    else print_line @@ Printf.sprintf "end: %s after %d steps" (match M.outcome cfg with
        | Ended -> "the task ended" | Stopped { name; _ } -> "stopped by the system error handler (" ^ name ^ ")"
        | Resource_exhausted m | Unsupported { reason = m; _ } | Stuck m | Deadlock m -> m | Running -> "step limit") (M.steps cfg);
    finish (M.outcome cfg) (M.steps cfg) ~max_steps
  in
  let doc = "print the reductions of a run one by one" in
  let man = [
    `S Manpage.s_description;
    `P "Runs the task like $(b,rapid-sem run) and prints each reduction: the step number, the rule applied (doc/semantics.md), the focus (its location, kind and source text) and the topmost continuation frames. $(b,--format jsonl) writes one JSON object per step in the schema of doc/trace-format.md.";
    `S Manpage.s_exit_status; `P "As $(b,rapid-sem run).";
  ] in
  Cmd.v (Cmd.info "trace" ~doc ~man)
    Term.(const run $ files $ entry $ max_steps $ allow_unknown $ max_depth $ retry_limit $ format $ from_ $ to_ $ rules $ controller_args
          $ Motion_cmd.robot_arg $ Motion_cmd.samples_arg)

let spec_cmd =
  let dir = Arg.(value & pos 0 dir "spec" & info [] ~docv:"DIR" ~doc:"The suite's folder.") in
  let verbose = Arg.(value & flag & info [ "verbose"; "v" ] ~doc:"List passing cases too.") in
  let engine = Arg.(value & opt (enum [ ("machine", Rapid_conformance.Spec_runner.Machine); ("closure", Closure) ]) Machine & info [ "engine" ] ~docv:"ENGINE" ~doc:"The engine that runs the cases of format 3: $(b,machine) (default) or $(b,closure).") in
  let run dir verbose engine =
    guard @@ fun () ->
    let _, failed = Rapid_conformance.Spec_runner.run ~verbose ~engine Format.std_formatter dir in
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
  Cmd.v (Cmd.info "spec" ~doc ~man) Term.(const run $ dir $ verbose $ engine)

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
                                                     guard @@ fun () -> start_machine ?robot files entry allow_unknown max_depth retry_limit controller k)
                                                   ~finish ~common_run_args ~controller_args;
                                                 Oracle_cmd.cmd; Fuzz_cmd.cmd; Mem_cmd.cmd ]) in
  (* A command line that cannot be read (an unknown option, a negative limit) is refused like a
     static error, with cmdliner's message saying what is wrong. *)
  exit (if status = Cmd.Exit.cli_error then exit_static_error else status)
