(* rapid-sem fuzz: a differential fuzzing campaign (doc/oracle.md, "Fuzzing"). *)

open Cmdliner
module C = Rapid_fuzz.Campaign
module R = Rapid_fuzz.Shard_report

let shard_conv =
  let parse s =
    match String.split_on_char '/' s with
    | [ k; n ] -> (
        match int_of_string_opt k, int_of_string_opt n with
        | Some k, Some n when n >= 1 && k >= 1 && k <= n -> Ok { C.index = k; count = n }
        | _ -> Error (`Msg (Printf.sprintf "%S: a shard is K/N with 1 <= K <= N" s)))
    | _ -> Error (`Msg (Printf.sprintf "%S: a shard is K/N, for example 2/8" s))
  in
  Arg.conv (parse, fun ppf s -> Format.fprintf ppf "%d/%d" s.C.index s.count)

let positive_int what =
  let parse s = match int_of_string_opt s with
    | Some n when n >= 0 -> Ok n
    | _ -> Error (`Msg (Printf.sprintf "%s must be a whole number >= 0, not %S" what s)) in
  Arg.conv (parse, Format.pp_print_int)

(* On a terminal, one line rewritten in place; elsewhere nothing until the summary. *)
let progress_line started ~done_ ~total ~failures ~rules_seen =
  if done_ = total || done_ mod 25 = 0 then begin
    let elapsed = Unix.gettimeofday () -. started in
    let width = 30 in
    let filled = if total = 0 then width else done_ * width / total in
    Printf.eprintf "\r[%s%s] %d/%d  %.0f programs/s  %d failures  %d rules%!"
      (String.make filled '#') (String.make (width - filled) '.') done_ total
      (if elapsed > 0. then float done_ /. elapsed else 0.) failures rules_seen
  end

let write_file path text =
  match open_out_bin path with
  | oc -> Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text); Ok ()
  | exception Sys_error m -> Error m

(* --merge-report: the shards' reports into one (Shard_report.merge), written beside their
   coverage. *)
let merge_reports ~out files =
  let dir = Option.value out ~default:"fuzz-report" in
  let reports = List.map R.read files in
  match List.find_map (function Error m -> Some m | Ok _ -> None) reports with
  | Some m -> Printf.eprintf "rapid-sem: %s\n" m; 2
  | None ->
  match R.merge (List.filter_map Result.to_option reports) with
  | Error m -> Printf.eprintf "rapid-sem: %s\n" m; 2
  | Ok m ->
  match
    (try if not (Sys.file_exists dir) then Sys.mkdir dir 0o755; Ok () with Sys_error e -> Error e)
    |> Fun.flip Result.bind (fun () ->
        write_file (Filename.concat dir "report.json")
          (Rapid_runtime.Json_text.pretty_to_string (R.merged_to_json m) ^ "\n"))
    |> Fun.flip Result.bind (fun () -> write_file (Filename.concat dir "report.md") (R.merged_to_markdown m))
    |> Fun.flip Result.bind (fun () ->
        try Rapid_fuzz.Coverage.write ~dir (R.coverage m); Ok () with Sys_error e -> Error e)
  with
  | Error e -> Printf.eprintf "rapid-sem: %s\n" e; 2
  | Ok () ->
      print_string (R.merged_to_markdown m);
      Printf.printf "\nreport: %s, %s\n" (Filename.concat dir "report.md") (Filename.concat dir "report.json");
      if m.m_failures = [] then 0 else 1

let cmd =
  let count = Arg.(value & opt (positive_int "--count") 1000 & info [ "count" ] ~docv:"N"
                     ~doc:"Programs in the whole campaign.") in
  let seed = Arg.(value & opt int 1 & info [ "seed" ] ~docv:"S"
                    ~doc:"The campaign's seed: the same seed gives the same programs.") in
  let shard = Arg.(value & opt shard_conv { C.index = 1; count = 1 } & info [ "shard" ] ~docv:"K/N"
                     ~doc:"Run only shard K of N: program I belongs to shard (I mod N) + 1.") in
  let out = Arg.(value & opt (some string) None & info [ "out" ] ~docv:"DIR"
                   ~doc:"Where each failure is saved as a minimal .mod with its expected events (without \
                         $(b,--out): fuzz-failures), and where the rule coverage is written: coverage.json and \
                         coverage.md (doc/fuzz-campaign.md).") in
  let merge = Arg.(value & opt_all file [] & info [ "merge" ] ~docv:"FILE"
                     ~doc:"Add the coverage.json of another shard to this run's (repeatable); with $(b,--count 0) \
                           only merges, as bench/fuzz-campaign.sh does.") in
  let impl = Arg.(value & opt (some string) None & info [ "impl" ] ~docv:"CMD"
                    ~doc:"Also check another implementation on each program, as $(b,rapid-sem oracle --impl) does. \
                          The protocol passes the program alone, without an I/O configuration, so no program then \
                          uses the controller (as with $(b,--no-controller)).") in
  let mismatching = Arg.(value & flag & info [ "mismatching" ]
                           ~doc:"Generate late-bound calls with wrong arguments too (the default; kept for older \
                                 scripts).") in
  let matching_only = Arg.(value & flag & info [ "matching-only" ]
                             ~doc:"Generate no late-bound call with wrong arguments.") in
  let no_controller = Arg.(value & flag & info [ "no-controller" ]
                             ~doc:"Generate no program that uses the controller (waits, signals, interrupts, \
                                   moves).") in
  let signal_stores = Arg.(value & flag & info [ "no-signal-stores" ]
                             ~doc:"Generate no assignments to signal variables (do1 := 1).") in
  let mutants = Arg.(value & opt (positive_int "--mutants") 1 & info [ "mutants" ] ~docv:"M"
                       ~doc:"Ill-typed mutants of each program, for the property that the checker never crashes.") in
  let hostile_every = Arg.(value & opt (positive_int "--hostile-every") 10 & info [ "hostile-every" ] ~docv:"K"
                             ~doc:"A hostile text (random bytes, deep nesting, huge names and numbers) every K \
                                   programs; 0: none.") in
  let scenarios = Arg.(value & opt (positive_int "--scenarios") 10 & info [ "scenarios" ] ~docv:"K"
                         ~doc:"One program in K on average is a scenario: several modules, a NOSTEPIN module, two \
                               tasks, a collision, or run with $(b,--allow-unknown), $(b,--stub-unmodelled) or small \
                               limits (doc/fuzz-campaign.md, \"Scenarios\"); 0: none. Not with $(b,--impl).") in
  let break_rule =
    let names = List.map (fun m -> (Rapid_fuzz.Mutation.name m, m)) Rapid_fuzz.Mutation.all in
    Arg.(value & opt (some (enum names)) None & info [ "break-rule" ] ~docv:"MUTATION"
           ~doc:(Printf.sprintf "The mutation check: run the closure engine with one rule deliberately broken \
                                 (%s), and stop at the first failure, which a working harness finds (exit 1 then; \
                                 0 would mean the harness missed it)."
                   (String.concat ", " (List.map fst names)))) in
  let json = Arg.(value & opt (some string) None & info [ "json" ] ~docv:"FILE"
                    ~doc:"Also write this shard's results to FILE as JSON: its settings, shard, host, programs, \
                          failures with their reproducers and minimal programs, outcomes, rule counts and times, \
                          for $(b,--merge-report) (doc/fuzz-campaign.md, \"Campaigns across machines\").") in
  let merge_report = Arg.(value & opt_all file [] & info [ "merge-report" ] ~docv:"FILE"
                            ~doc:"Merge the shard reports FILE (written with $(b,--json); repeatable, every shard of \
                                  one campaign once) into one report, and run no program: DIR/report.json, \
                                  DIR/report.md, DIR/coverage.json and DIR/coverage.md with DIR from $(b,--out) \
                                  (default fuzz-report). Exit 0 without failures, 1 with, 2 when the reports are \
                                  not the shards of one campaign.") in
  let coverage = Arg.(value & flag & info [ "coverage" ]
                        ~doc:"List every rule of the machine with how often it applied, and the rules never \
                              applied.") in
  let run count seed shard (out, merge, break_rule) impl (mismatching, matching_only, no_controller, signal_stores)
      (mutants, hostile_every, scenarios) (json, merge_report) coverage =
    if merge_report <> [] then merge_reports ~out merge_report else begin
    C.tune_gc ();
    let started = Unix.gettimeofday () in
    let progress = if Unix.isatty Unix.stderr then Some (progress_line started) else None in
    let external_check = Option.map (fun template ->
        let reference = Rapid_oracle.Oracle.self_reference () in
        fun source ->
        let file = Filename.temp_file "rapid-fuzz" ".mod" in
        Fun.protect ~finally:(fun () -> try Sys.remove file with Sys_error _ -> ()) (fun () ->
            let oc = open_out_bin file in
            output_string oc source; close_out oc;
            match Rapid_oracle.Oracle.check ~reference ~impl:template { name = file; files = [ file ] } with
            | Agree _ -> Ok ()
            | v -> Error (Rapid_oracle.Oracle.verdict_report { name = "program"; files = [] } v))) impl in
    let options = { Rapid_fuzz.Program_gen.default_options with
                    mismatching = mismatching || not matching_only; controller = not no_controller && impl = None;
                    signal_stores = not signal_stores } in
    (* Every program runs under both engines (doc/semantics.md, "The second engine"). *)
    let engine = match break_rule with
      | Some m -> Rapid_fuzz.Mutation.engine m Rapid_fuzz.Fuzz_run.closure
      | None -> Rapid_fuzz.Fuzz_run.closure in
    let max_failures = Option.map (fun _ -> 1) break_rule in
    let scenarios = if impl = None then scenarios else 0 in
    let s = C.run ~options ~engines:[ engine ] ?external_check ?progress ~mutants ~hostile_every ~scenarios
        ?max_failures ~seed ~count ~shard () in
    if progress <> None then prerr_newline ();
    let saved = List.map (fun (f : C.failure_found) ->
        let path = C.save ~dir:(Option.value out ~default:"fuzz-failures") f in
        Printf.printf "FAIL program %d: %s\n  minimal program (%d statements, from %d): %s\n" f.program_index
          (Rapid_fuzz.Fuzz_run.failure_to_string f.failure) f.minimal_size f.original_size path;
        (* the minimal program itself, when it is short enough to read here *)
        let lines = String.split_on_char '\n' f.source in
        if List.length lines <= 40 && String.length f.source <= 4000 then
          List.iter (fun l ->
              let printable = String.for_all (fun c -> c >= ' ' && c <= '~') l in
              if l <> "" then Printf.printf "    | %s\n" (if printable then l else String.escaped l)) lines;
        (f, Filename.basename path)) s.failures in
    let json_written = match json with
      | None -> Ok ()
      | Some file ->
          let bool b = if b then "true" else "false" in
          let settings = [ ("seed", string_of_int seed); ("count", string_of_int count);
                           ("mutants", string_of_int mutants); ("hostile_every", string_of_int hostile_every);
                           ("scenarios", string_of_int scenarios); ("mismatching", bool options.mismatching);
                           ("controller", bool options.controller); ("signal_stores", bool options.signal_stores);
                           ("break_rule", (match break_rule with
                                | Some m -> Rapid_fuzz.Mutation.name m | None -> "none"));
                           ("impl", Option.value impl ~default:"none") ] in
          let reproducer f = List.assq f saved in
          let r = R.of_summary ~settings ~shard ~host:(Unix.gethostname ()) ~reproducer s in
          write_file file (Rapid_runtime.Json_text.pretty_to_string (R.to_json r) ^ "\n") in
    match json_written with
    | Error m -> Printf.eprintf "rapid-sem: %s\n" m; 2
    | Ok () ->
    let merged = List.map Rapid_fuzz.Coverage.read merge in
    match List.find_map (function Error m -> Some m | Ok _ -> None) merged with
    | Some m -> Printf.eprintf "rapid-sem: %s\n" m; 2
    | None ->
    let cov = Rapid_fuzz.Coverage.merge
        (Rapid_fuzz.Coverage.of_summary s :: List.filter_map Result.to_option merged) in
    Option.iter (fun dir -> Rapid_fuzz.Coverage.write ~dir cov) out;
    Printf.printf "%d programs (shard %d/%d, seed %d) in %.1f s: %.0f programs/s (%.0f per second of processor time)\n"
      s.programs shard.index shard.count seed s.seconds (if s.seconds > 0. then float s.programs /. s.seconds else 0.)
      (if s.cpu_seconds > 0. then float s.programs /. s.cpu_seconds else 0.);
    Printf.printf "outcomes: %s\n"
      (String.concat ", " (List.map (fun (k, n) -> Printf.sprintf "%s %d" k n) s.outcomes));
    if merge <> [] then
      Printf.printf "merged with %d other shard%s: %d programs, %d failures\n" (List.length merge)
        (if List.length merge = 1 then "" else "s") cov.programs cov.failures;
    Printf.printf "rules applied: %d of %d\n" (Rapid_fuzz.Coverage.applied cov)
      (List.length Rapid_fuzz.Coverage.rule_names);
    if coverage then
      List.iter (fun (r, n) -> Printf.printf "  %-28s %d\n" r n) cov.rules;
    Printf.printf "%d passed, %d failed\n" (s.programs - List.length s.failures) (List.length s.failures);
    if s.failures = [] && cov.failures = 0 then 0 else 1
    end
  in
  let doc = "generate well-typed RAPID programs and check the semantics' properties on each" in
  let man = [
    `S Manpage.s_description;
    `P "Generates COUNT programs type-directed (lib/fuzz), and for each: the printer's round \
        trip, the static semantics accepts it, progress (no state without a rule, no OCaml \
        exception), determinism (two runs give the same events), the engines agree, and with \
        $(b,--impl) another implementation agrees (doc/oracle.md). Each failure is shrunk to a \
        minimal program, saved in DIR with its expected events.";
    `S Manpage.s_exit_status; `P "0 when every program passes; 1 when one fails.";
  ] in
  let pair a b = (a, b) and triple a b c = (a, b, c) and quadruple a b c d = (a, b, c, d) in
  Cmd.v (Cmd.info "fuzz" ~doc ~man)
    Term.(const run $ count $ seed $ shard $ (const triple $ out $ merge $ break_rule) $ impl
          $ (const quadruple $ mismatching $ matching_only $ no_controller $ signal_stores)
          $ (const triple $ mutants $ hostile_every $ scenarios) $ (const pair $ json $ merge_report) $ coverage)
