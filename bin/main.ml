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

(* ------------------------------------------------------------------ run and trace *)

module M = Rapid_semantics.Machine

let exit_stopped = 1
let exit_exhausted = 3
let exit_unsupported = 4

let report_load_failure = function
  | Rapid_semantics.Session.Front_end ds -> List.iter (fun d -> prerr_endline (Diagnostic.to_string d)) ds; exit_static_error
  | Static reports -> List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) reports; exit_static_error
  | Internal m -> Printf.eprintf "rapid-sem: internal error: %s\n" m; exit_internal

let region_json r =
  let p = Source.start r and q = Source.stop r in
  `Assoc [ ("file", `String (match Source.file_of r with Some f -> Source.name f | None -> ""));
           ("line", `Int p.line); ("col", `Int p.col); ("end_line", `Int q.line); ("end_col", `Int q.col) ]

let event_json (e : M.event) : Yojson.Safe.t =
  match e with
  | Output s -> `Assoc [ ("event", `String "output"); ("text", `String s) ]
  | Erase -> `Assoc [ ("event", `String "erase") ]
  | Log s -> `Assoc [ ("event", `String "log"); ("text", `String s) ]
  | Routine_entered r -> `Assoc [ ("event", `String "routine-entered"); ("routine", `String r) ]
  | Routine_left r -> `Assoc [ ("event", `String "routine-left"); ("routine", `String r) ]
  | Error_raised { name; number; at } ->
      `Assoc [ ("event", `String "error-raised"); ("name", `String name); ("number", `Int number);
               ("at", region_json at) ]
  | Error_handled { name; routine } ->
      `Assoc [ ("event", `String "error-handled"); ("name", `String name); ("routine", `String routine) ]
  | Undo_run r -> `Assoc [ ("event", `String "undo-run"); ("routine", `String r) ]
  | Task_ended -> `Assoc [ ("event", `String "task-ended") ]

let schema = "rapid-sem/1"

let outcome_json (o : M.outcome) steps : Yojson.Safe.t =
  let base kind extra = `Assoc ([ ("event", `String "end"); ("outcome", `String kind); ("steps", `Int steps) ] @ extra) in
  match o with
  | Running -> base "running" []
  | Ended -> base "ended" []
  | Stopped { name; number; at; chain } ->
      base "stopped" [ ("name", `String name); ("number", `Int number); ("at", region_json at);
                       ("chain", `List (List.map (fun r -> `String r) chain)) ]
  | Resource_exhausted m -> base "exhausted" [ ("reason", `String m) ]
  | Unsupported m -> base "unsupported" [ ("reason", `String m) ]
  | Stuck m -> base "stuck" [ ("reason", `String m) ]

let finish (o : M.outcome) steps ~max_steps =
  match o with
  | Ended -> exit_ok
  | Stopped { name; at; chain; _ } ->
      Printf.eprintf "%s: execution error: %s: the system error handler stopped the task (%s)\n"
        (Source.to_string at) name (String.concat " <- " chain);
      exit_stopped
  | Resource_exhausted m -> Printf.eprintf "rapid-sem: %s\n" m; exit_exhausted
  | Unsupported m -> Printf.eprintf "rapid-sem: %s\n" m; exit_unsupported
  | Stuck m -> Printf.eprintf "rapid-sem: internal error: no rule applies (%s) after %d steps; please report this program\n" m steps; exit_internal
  | Running -> Printf.eprintf "rapid-sem: the step limit (%d) is exhausted\n" max_steps; exit_exhausted

let common_run_args =
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer.") in
  let entry = Arg.(value & opt string "main" & info [ "entry" ] ~docv:"NAME" ~doc:"The entry routine (default main).") in
  let max_steps = Arg.(value & opt int 100_000_000 & info [ "max-steps" ] ~docv:"N" ~doc:"Stop after N reduction steps (exit status 3).") in
  let allow_unknown = Arg.(value & flag & info [ "allow-unknown" ] ~doc:"Names neither declared nor installed are warnings; reaching one is an execution error.") in
  let max_depth = Arg.(value & opt int M.default_limits.max_call_depth & info [ "max-call-depth" ] ~docv:"N" ~doc:"The deepest call chain (resource exhaustion beyond).") in
  let retry_limit = Arg.(value & opt int M.default_limits.retry_limit & info [ "retry-limit" ] ~docv:"N" ~doc:"\"No Of Retry\": RETRYs of one error before ERR_EXCRTYMAX (§7.1).") in
  (files, entry, max_steps, allow_unknown, max_depth, retry_limit)

(* A run allocates frames that live as long as their routine: with deep recursion the live heap
   grows with the call depth, and the collector's default pace makes each step cost more the
   deeper it is. A lazier pace keeps the cost of a step nearly independent of depth
   (bench/README.md, "The machine"). *)
let machine_gc () = Gc.set { (Gc.get ()) with space_overhead = 400 }

let start_machine files entry allow_unknown max_depth retry_limit k =
  machine_gc ();
  match Rapid_semantics.Session.load ~allow_unknown files with
  | Error f -> report_load_failure f
  | Ok loaded -> (
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) loaded.warnings;
      match M.start ~limits:{ max_call_depth = max_depth; retry_limit } loaded.program ~entry with
      | Error m -> Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
      | Ok cfg -> k cfg)

(* rapid-sem run --engine closure: the same events and outcome by the closure engine. *)
let run_closure files entry max_steps allow_unknown max_depth retry_limit json print_event =
  match Rapid_semantics.Session.load ~allow_unknown files with
  | Error f -> report_load_failure f
  | Ok loaded -> (
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) loaded.warnings;
      if json then print_endline (Yojson.Safe.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema) ]));
      let limits = { M.max_call_depth = max_depth; retry_limit } in
      match Rapid_semantics.Closure_engine.run ~limits ~fuel:max_steps ~all_events:json ~on_event:print_event loaded.program ~entry with
      | Error m -> Printf.eprintf "rapid-sem: %s\n" m; exit_static_error
      | Ok { outcome; fuel_used } ->
          if json then print_endline (Yojson.Safe.to_string (outcome_json outcome fuel_used));
          finish outcome fuel_used ~max_steps)

let run_cmd =
  let files, entry, max_steps, allow_unknown, max_depth, retry_limit = common_run_args in
  let json = Arg.(value & flag & info [ "json" ] ~doc:"Write one JSON object per observable event (doc/trace-format.md) instead of the program's output.") in
  let engine = Arg.(value & opt (enum [ ("machine", `Machine); ("closure", `Closure) ]) `Machine & info [ "engine" ] ~docv:"ENGINE" ~doc:"$(b,machine) (the small-step machine, the default) or $(b,closure) (the second engine: the same events, faster; --max-steps counts its units of fuel, doc/semantics.md).") in
  let run files entry max_steps allow_unknown max_depth retry_limit json engine =
    guard @@ fun () ->
    let print_event (e : M.event) =
      if json then print_endline (Yojson.Safe.to_string (event_json e))
      else match e with Output s -> print_endline s | _ -> () in
    if engine = `Closure then run_closure files entry max_steps allow_unknown max_depth retry_limit json print_event else
    start_machine files entry allow_unknown max_depth retry_limit @@ fun cfg ->
    if json then print_endline (Yojson.Safe.to_string (`Assoc [ ("event", `String "start"); ("schema", `String schema) ]));
    let rec loop () =
      if M.outcome cfg = Running && M.steps cfg < max_steps then begin
        let _, events = M.step cfg in
        List.iter (fun (e : M.event) ->
            if json then print_endline (Yojson.Safe.to_string (event_json e))
            else match e with Output s -> print_endline s | _ -> ()) events;
        loop ()
      end
    in
    loop ();
    if json then print_endline (Yojson.Safe.to_string (outcome_json (M.outcome cfg) (M.steps cfg)));
    finish (M.outcome cfg) (M.steps cfg) ~max_steps
  in
  let doc = "run a task: check the modules, then execute the entry routine" in
  let man = [
    `S Manpage.s_description;
    `P "Checks the FILEs as one task buffer (as $(b,rapid-sem check)), then runs the entry routine by the small-step semantics of doc/semantics.md. Standard output carries only the program's output, one line per TPWrite.";
    `S Manpage.s_exit_status;
    `P "0: the task ended (end of the entry routine, RETURN in it, EXIT). 1: the system error handler stopped it; the error's name and the place of the failing statement go to standard error. 2: a static error, before anything ran. 3: the step limit or a resource limit (call depth) was exhausted. 4: the program called an installed routine rapid-sem does not model yet.";
  ] in
  Cmd.v (Cmd.info "run" ~doc ~man)
    Term.(const run $ files $ entry $ max_steps $ allow_unknown $ max_depth $ retry_limit $ json $ engine)

(* The text of a region, for the trace: its first line, cut at 60 characters. *)
let source_cache = Hashtbl.create 8
let region_text r =
  match Source.file_of r with
  | None -> ""
  | Some f -> (
      let name = Source.name f in
      let lines = match Hashtbl.find_opt source_cache name with
        | Some l -> l
        | None ->
            let l = match Rapid_conformance.In_channel_compat.read_lines name with Ok l -> Array.of_list l | Error _ -> [||] in
            Hashtbl.replace source_cache name l; l in
      let p = Source.start r and q = Source.stop r in
      if p.line < 1 || p.line > Array.length lines then ""
      else
        let line = lines.(p.line - 1) in
        let stop = if q.line = p.line then min (String.length line) (q.col - 1) else String.length line in
        let start = min (String.length line) (p.col - 1) in
        let text = String.trim (String.sub line start (max 0 (stop - start))) in
        if String.length text > 60 then String.sub text 0 57 ^ "..." else text)

let trace_cmd =
  let files, entry, max_steps, allow_unknown, max_depth, retry_limit = common_run_args in
  let format = Arg.(value & opt (enum [ ("human", `Human); ("jsonl", `Jsonl) ]) `Human & info [ "format" ] ~docv:"FORMAT" ~doc:"$(b,human) or $(b,jsonl) (doc/trace-format.md).") in
  let from_ = Arg.(value & opt int 1 & info [ "from" ] ~docv:"N" ~doc:"First step printed.") in
  let to_ = Arg.(value & opt int max_int & info [ "to" ] ~docv:"N" ~doc:"Last step printed.") in
  let rules = Arg.(value & opt (some string) None & info [ "rules" ] ~docv:"PATTERN" ~doc:"Print only the steps whose rule name contains PATTERN.") in
  let run files entry max_steps allow_unknown max_depth retry_limit format from_ to_ rules =
    guard @@ fun () ->
    start_machine files entry allow_unknown max_depth retry_limit @@ fun cfg ->
    let contains s p =
      let n = String.length p and m = String.length s in
      let rec go i = i + n <= m && (String.sub s i n = p || go (i + 1)) in
      n = 0 || go 0 in
    if format = `Jsonl then print_endline (Yojson.Safe.to_string (`Assoc [ ("schema", `String schema); ("kind", `String "trace") ]));
    let rec loop () =
      if M.outcome cfg = Running && M.steps cfg < max_steps then begin
        let region = M.focus_region cfg and kind = M.focus_kind cfg and stack = M.stack_view cfg in
        let depth = M.depth cfg in
        let rule, events = M.step cfg in
        let n = M.steps cfg in
        if n >= from_ && n <= to_ && (match rules with None -> true | Some p -> contains rule p) then begin
          match format with
          | `Human ->
              Printf.printf "%6d %-24s %s %-10s %s | %s\n" n rule (Source.to_string region) kind
                (region_text region) (String.concat " " stack);
              List.iter (function M.Output s -> Printf.printf "       > %s\n" s | _ -> ()) events
          | `Jsonl ->
              print_endline (Yojson.Safe.to_string (`Assoc [
                  ("step", `Int n); ("rule", `String rule); ("depth", `Int depth);
                  ("focus", `Assoc [ ("kind", `String kind); ("at", region_json region); ("text", `String (region_text region)) ]);
                  ("stack", `List (List.map (fun s -> `String s) stack));
                  ("events", `List (List.map event_json events)) ]))
        end;
        loop ()
      end
    in
    loop ();
    if format = `Jsonl then print_endline (Yojson.Safe.to_string (outcome_json (M.outcome cfg) (M.steps cfg)))
    else Printf.printf "end: %s after %d steps\n" (match M.outcome cfg with
        | Ended -> "the task ended" | Stopped { name; _ } -> "stopped by the system error handler (" ^ name ^ ")"
        | Resource_exhausted m | Unsupported m | Stuck m -> m | Running -> "step limit") (M.steps cfg);
    finish (M.outcome cfg) (M.steps cfg) ~max_steps
  in
  let doc = "print the reductions of a run one by one" in
  let man = [
    `S Manpage.s_description;
    `P "Runs the task like $(b,rapid-sem run) and prints each reduction: the step number, the rule applied (doc/semantics.md), the focus (its location, kind and source text) and the topmost continuation frames. $(b,--format jsonl) writes one JSON object per step in the schema of doc/trace-format.md.";
    `S Manpage.s_exit_status; `P "As $(b,rapid-sem run).";
  ] in
  Cmd.v (Cmd.info "trace" ~doc ~man)
    Term.(const run $ files $ entry $ max_steps $ allow_unknown $ max_depth $ retry_limit $ format $ from_ $ to_ $ rules)

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
  let doc = "the executable semantics of ABB's RAPID robot programming language" in
  let info = Cmd.info "rapid-sem" ~version:"0.1.0" ~doc in
  exit (Cmd.eval' (Cmd.group info [ parse_cmd; check_cmd; run_cmd; trace_cmd; spec_cmd ]))
