(* The differential fuzzing campaign (lib/fuzz): a bounded campaign runs in every `make test`;
   the long ones belong to `rapid-sem fuzz` (doc/oracle.md). *)

module C = Rapid_fuzz.Campaign
module G = Rapid_fuzz.Program_gen

let whole = { C.index = 1; count = 1 }

let bounded_campaign () =
  (* Both engines on every program (doc/semantics.md, "The second engine"). *)
  let s = C.run ~engines:[ Rapid_fuzz.Fuzz_run.closure ] ~seed:2030 ~count:300 ~shard:whole () in
  List.iter (fun (f : C.failure_found) ->
      Printf.printf "program %d: %s\n%s\n" f.program_index (Rapid_fuzz.Fuzz_run.failure_to_string f.failure) f.source)
    s.failures;
  Alcotest.(check int) "failures" 0 (List.length s.failures);
  Alcotest.(check int) "programs" 300 s.programs;
  (* The campaign reaches the rules of chapters 4, 5 and 7, not only the easy ones. *)
  List.iter (fun rule ->
      Alcotest.(check bool) (rule ^ " applied") true (List.mem_assoc rule s.rules))
    [ "retry"; "trynext"; "raise-propagate"; "longjump-found"; "undo-run"; "goto"; "call-late";
      "call-enter"; "argument-alias"; "test-match"; "for-step"; "while-again"; "function-no-return";
      (* the controller, and the forms added for the rules one statement rarely reaches *)
      "interrupt-serve"; "trap-end"; "execute-placeholder"; "argument-reference"; "index-not-integer";
      "call-by-var-mismatch"; "call-late-mismatch"; "connect-inomax"; "wait-start";
      (* and its scenarios, one program in ten: the user level, asynchronous errors, two tasks,
         a memory budget *)
      "raise-to-user-continue"; "async-error"; "wait-yield"; "memory-exhausted" ];
  (* A conditional argument [\p ? x] (§3.11) is bound by settling, within the step that enters
     the call (doc/semantics.md, "Settling"): no rule of its own to count. The campaign's
     programs have them, and the campaign runs them (call-enter above). *)
  let conditional source =
    (* [\name?name], as the generator writes them *)
    let n = String.length source in
    let ident c = c = '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') in
    let rec word j = if j < n && ident source.[j] then word (j + 1) else j in
    let rec go i =
      i < n
      && ((source.[i] = '\\' && (let j = word (i + 1) in j > i + 1 && j + 1 < n && source.[j] = '?' && ident source.[j + 1]))
          || go (i + 1)) in
    go 0 in
  let with_conditional = ref 0 in
  for i = 0 to 299 do
    let source = G.to_source (G.generate (C.program_seed ~seed:2030 i)) in
    if conditional source then incr with_conditional
  done;
  Alcotest.(check bool) (Printf.sprintf "programs with conditional arguments (%d)" !with_conditional)
    true (!with_conditional >= 10)

let shards_partition () =
  let indexes shard = (C.run ~seed:5 ~count:20 ~shard ()).programs in
  let total = List.fold_left (fun n k -> n + indexes { C.index = k; count = 3 }) 0 [ 1; 2; 3 ] in
  Alcotest.(check int) "three shards run every program once" 20 total

let same_seed_same_program () =
  let a = G.to_source (G.generate (C.program_seed ~seed:9 4)) in
  let b = G.to_source (G.generate (C.program_seed ~seed:9 4)) in
  let c = G.to_source (G.generate (C.program_seed ~seed:9 5)) in
  Alcotest.(check string) "reproducible" a b;
  Alcotest.(check bool) "programs differ" true (a <> c)

(* Shrinking keeps the failure and makes the program smaller: a property that fails on every
   program with an output line shrinks to one statement that writes. *)
let shrinking_minimises () =
  let failing = Rapid_fuzz.Fuzz_run.{ engine_name = "no-output";
                                      run = (fun p ~max_steps ->
                                          let o = machine.run p ~max_steps in
                                          { o with events = List.filter (fun e -> String.sub e 0 6 <> "output") o.events }) } in
  let s = C.run ~engines:[ failing ] ~seed:11 ~count:40 ~shard:whole () in
  Alcotest.(check bool) "the broken engine is caught" true (s.failures <> []);
  List.iter (fun (f : C.failure_found) ->
      Alcotest.(check bool) "smaller" true (f.minimal_size <= f.original_size);
      Alcotest.(check bool) (Printf.sprintf "at most 3 statements left, got %d:\n%s" f.minimal_size f.source)
        true (f.minimal_size <= 3)) s.failures

(* The mutation check (doc/fuzz-campaign.md): with one rule broken in the closure engine, a
   campaign finds a failure within a bounded number of programs, and shrinks it to a small
   program that uses the broken rule. *)
let mutation_caught mutation ~keyword () =
  let engine = Rapid_fuzz.Mutation.engine mutation Rapid_fuzz.Fuzz_run.closure in
  List.iter (fun seed ->
      let s = C.run ~engines:[ engine ] ~mutants:0 ~hostile_every:0 ~max_failures:1 ~seed ~count:200 ~shard:whole () in
      match s.failures with
      | [] -> Alcotest.failf "%s not caught within 200 programs (seed %d)" (Rapid_fuzz.Mutation.name mutation) seed
      | f :: _ ->
          (match f.failure with
           | Engines_differ _ -> ()
           | other -> Alcotest.failf "caught as %s" (Rapid_fuzz.Fuzz_run.failure_to_string other));
          let contains word =
            let n = String.length word and m = String.length f.source in
            let rec go i = i + n <= m && (String.sub f.source i n = word || go (i + 1)) in go 0 in
          Alcotest.(check bool) (Printf.sprintf "the minimal program (%d statements) uses %s:\n%s" f.minimal_size keyword f.source)
            true (contains keyword);
          Alcotest.(check bool) "at most 5 statements" true (f.minimal_size <= 5))
    [ 1; 2; 3 ]

(* The same engine, unbroken, passes the same programs: the mutation check tests the harness,
   not a difference the engines always have. *)
let mutation_identity () =
  (* the first program of seed 3 with a TRYNEXT *)
  let rec with_trynext i =
    let source = G.to_source (G.generate (C.program_seed ~seed:3 i)) in
    if Rapid_fuzz.Fuzz_run.mentions "TRYNEXT" source then source else with_trynext (i + 1) in
  match Rapid_fuzz.Fuzz_run.load (Result.get_ok (Rapid_syntax.Parse.parse_string ~name:"fuzz.mod" (with_trynext 0))) with
  | Error _ -> Alcotest.fail "the program does not load"
  | Ok loaded ->
      let count_trynext (p : Rapid_runtime.Ir.program) =
        let n = ref 0 in
        let rec block (b : Rapid_runtime.Ir.block) = Array.iter stmt b.body
        and stmt (s : Rapid_runtime.Ir.stmt) = match s.s with
          | Trynext -> incr n
          | If (_, a, b) | Elseif (_, a, b) -> block a; block b
          | For f -> block f.loop_body
          | While (_, b) -> block b
          | Compact_if (_, s) -> stmt s
          | Test (_, cs, d) -> Array.iter (fun (_, b) -> block b) cs; block d
          | _ -> () in
        Array.iter (fun (r : Rapid_runtime.Ir.routine) ->
            block r.body; Option.iter (fun (h : Rapid_runtime.Ir.error_handler) -> block h.handler) r.error) p.routines;
        !n in
      let before = count_trynext loaded.program in
      Alcotest.(check bool) "the program has TRYNEXT" true (before > 0);
      Alcotest.(check int) "none left" 0 (count_trynext (Rapid_fuzz.Mutation.apply Trynext_as_retry loaded.program));
      Alcotest.(check int) "the other mutation leaves them" before
        (count_trynext (Rapid_fuzz.Mutation.apply For_skips_last loaded.program))

(* Mutants and hostile texts: the property holds on them (it is what the campaign checks), the
   mutants are mostly refused (ill-typed or ill-formed) but not all, and every kind of hostile
   text is answered. *)
let mutants_answered () =
  let rs = Random.State.make [| 42 |] in
  let refused = ref 0 and accepted = ref 0 in
  for i = 0 to 199 do
    let source = G.to_source (G.generate (C.program_seed ~seed:42 i)) in
    let m = Rapid_fuzz.Mutant.mutate rs source in
    Alcotest.(check bool) "a mutant differs from its program" true (m <> source || String.length source = 0);
    (match Rapid_fuzz.Mutant.check_text m with
     | Ok () -> ()
     | Error e -> Alcotest.failf "mutant %d: %s\n%s" i e m);
    match Rapid_syntax.Parse.parse_string ~name:"fuzz.mod" m with
    | Error _ -> incr refused
    | Ok tree -> (match Rapid_fuzz.Fuzz_run.load tree with Ok _ -> incr accepted | Error _ -> incr refused)
  done;
  Alcotest.(check bool) (Printf.sprintf "most mutants refused (%d of 200)" !refused) true (!refused >= 100);
  Alcotest.(check bool) (Printf.sprintf "some mutants accepted and run (%d)" !accepted) true (!accepted >= 5);
  for _ = 1 to 60 do
    let h = Rapid_fuzz.Mutant.hostile rs in
    match Rapid_fuzz.Mutant.check_text h with
    | Ok () -> ()
    | Error e -> Alcotest.failf "hostile text (%d bytes): %s" (String.length h) e
  done

let text_shrinking () =
  let text = "MODULE m\n  PROC main()\n    x := 1;\n    BAD;\n    y := 2;\n  ENDPROC\nENDMODULE\n" in
  let contains t w = let n = String.length w in
    let rec go i = i + n <= String.length t && (String.sub t i n = w || go (i + 1)) in go 0 in
  Alcotest.(check string) "down to the word" "BAD" (Rapid_fuzz.Mutant.shrink_text (fun t -> contains t "BAD") text)

(* Coverage: every named rule with its count, merged across shards, read back from its JSON. *)
let coverage_merges () =
  let cov seedless_shard = Rapid_fuzz.Coverage.of_summary
      (C.run ~engines:[] ~mutants:0 ~hostile_every:0 ~seed:7 ~count:30 ~shard:{ C.index = seedless_shard; count = 2 } ()) in
  let a = cov 1 and b = cov 2 in
  let whole = Rapid_fuzz.Coverage.of_summary (C.run ~engines:[] ~mutants:0 ~hostile_every:0 ~seed:7 ~count:30 ~shard:whole ()) in
  let merged = Rapid_fuzz.Coverage.merge [ a; b ] in
  Alcotest.(check int) "programs" 30 merged.programs;
  Alcotest.(check (list (pair string int))) "two shards count what the whole campaign counts" whole.rules merged.rules;
  Alcotest.(check int) "every named rule listed" (List.length Rapid_fuzz.Coverage.rule_names) (List.length merged.rules);
  Alcotest.(check bool) "not done, not stuck" false
    (List.mem "done" Rapid_fuzz.Coverage.rule_names || List.mem "stuck" Rapid_fuzz.Coverage.rule_names);
  (match Rapid_fuzz.Coverage.of_json (Rapid_fuzz.Coverage.to_json merged) with
   | Ok back -> Alcotest.(check (list (pair string int))) "JSON round trip" merged.rules back.rules
   | Error m -> Alcotest.fail m);
  let md = Rapid_fuzz.Coverage.to_markdown merged in
  let headline = Printf.sprintf "%d of %d named rules" (Rapid_fuzz.Coverage.applied merged) (List.length Rapid_fuzz.Coverage.rule_names) in
  let contains t w = let n = String.length w in
    let rec go i = i + n <= String.length t && (String.sub t i n = w || go (i + 1)) in go 0 in
  Alcotest.(check bool) headline true (contains md headline);
  Alcotest.(check bool) "a row per rule" true (contains md "| call-enter |")

(* The generator reaches the forms of issue 11's list: every operator row of §3.12 (pos, orient,
   dnum included), the controller (interrupts, waits, signals, moves), mismatching late-bound
   calls. *)
let generator_forms () =
  let sources = List.init 300 (fun i -> G.to_source (G.generate (C.program_seed ~seed:2030 i))) in
  let all = String.concat "\n" sources in
  let contains w = let n = String.length w in
    let rec go i = i + n <= String.length all && (String.sub all i n = w || go (i + 1)) in go 0 in
  List.iter (fun form -> Alcotest.(check bool) form true (contains form))
    [ "\\Pos:="; "\\Orient:="; "gor1 := "; "gpos1 := ["; "(gpos"; " DIV gd1"; "gd1 MOD"; "(gor"; "(garr = garr)";
      "(gpt <> gpt)"; "ITimer"; "ISignalDI"; "WaitTime"; "WaitDI"; "WaitUntil"; "SetDO do1"; "PulseDO";
      "MoveL"; "MoveJ"; "CONNECT gint WITH fztrap"; "CallByVar"; "\\nosuch:=1"; "<SMT>" ]

(* Scenarios (doc/fuzz-campaign.md, "Scenarios"): a campaign of scenarios only reaches each rule
   the one-module programs cannot, with every property holding. *)
let scenarios_reach_rules () =
  let s = C.run ~engines:[ Rapid_fuzz.Fuzz_run.closure ] ~scenarios:1 ~seed:2031 ~count:300 ~shard:whole () in
  List.iter (fun (f : C.failure_found) ->
      Printf.printf "scenario %d: %s\n%s\n" f.program_index (Rapid_fuzz.Fuzz_run.failure_to_string f.failure) f.source)
    s.failures;
  Alcotest.(check int) "failures" 0 (List.length s.failures);
  List.iter (fun rule ->
      Alcotest.(check bool) (rule ^ " applied") true (List.mem_assoc rule s.rules))
    [ "argument-pass-on-duplicate"; "connect-not-variable"; "memory-exhausted"; "call-not-modelled"; "call-stubbed"; "place-unknown";
      "call-unknown"; "call-unknown-function"; "call-depth-exceeded"; "time-limit"; "wait-yield";
      "wait-time-limit"; "wait-deadlock"; "async-error"; "async-error-unhandled"; "async-retry-resume";
      "async-trynext-resume"; "async-exit"; "async-handler-leave"; "async-error-at-move";
      "raise-to-user-continue"; "raise-to-user-break-off"; "raise-to-user-no-user-level";
      "raise-to-user-unhandled"; "raise-to-user-illegal"; "raise-to-user-misplaced"; "resume-retry";
      "resume-trynext" ];
  (* the default campaign has them too, one program in ten *)
  let scenario_indexes = List.filter (fun i -> C.is_scenario ~seed:2030 ~scenarios:10 i) (List.init 300 Fun.id) in
  let n = List.length scenario_indexes in
  Alcotest.(check bool) (Printf.sprintf "scenarios in the bounded campaign (%d of 300)" n) true (n >= 15 && n <= 45)

(* A scenario saved with a failure runs again as saved: run.sh in its folder (the options, the
   stimulus, the modules, the tasks) ends as the campaign's run of it did. *)
let scenario_reproduces () =
  let dir = Filename.temp_file "rapid-fuzz-saved" "" in
  Sys.remove dir;
  let bin = Filename.temp_file "rapid-fuzz-bin" "" in
  Sys.remove bin; Sys.mkdir bin 0o755;
  Unix.symlink (Filename.concat (Sys.getcwd ()) "../bin/main.exe") (Filename.concat bin "rapid-sem");
  let status = function
    | "ended" -> 0 | "stopped" -> 1 | "exhausted" | "deadlock" -> 3 | "unsupported" -> 4 | o -> Alcotest.failf "outcome %s" o in
  List.iteri (fun i kind ->
      let case = Rapid_fuzz.Scenario_gen.generate_kind kind (Random.State.make [| 17; i |]) in
      match Rapid_fuzz.Case_run.observe case with
      | Error m -> Alcotest.failf "%s: %s" kind m
      | Ok o ->
          let f = { C.program_index = i; failure = Rapid_fuzz.Fuzz_run.Stuck "(a test)"; source = Rapid_fuzz.Fuzz_case.to_text case;
                    original_size = 0; minimal_size = 0; case = Some case } in
          let folder = C.save ~dir f in
          let expected = status (List.hd (String.split_on_char ' ' o.outcome)) in
          let code = Sys.command (Printf.sprintf "PATH=%s:$PATH sh %s >/dev/null 2>&1" (Filename.quote bin)
                                    (Filename.quote (Filename.concat folder "run.sh"))) in
          Alcotest.(check int) (Printf.sprintf "%s (%s): %s" kind o.outcome (Rapid_fuzz.Fuzz_case.command case)) expected code)
    Rapid_fuzz.Scenario_gen.kinds;
  ignore (Sys.command (Printf.sprintf "rm -rf %s %s" (Filename.quote dir) (Filename.quote bin)))

(* Shard reports (rapid-sem fuzz --json, bench/slurm): the merge of shards 1/3, 2/3 and 3/3 has
   the totals and failures of one unsharded run of the same programs. An engine that drops the
   output events makes failures (each shrunk) to merge; mutants and hostile texts are on. *)
module R = Rapid_fuzz.Shard_report

let has text part =
  let n = String.length part in
  let rec at i = i + n <= String.length text && (String.sub text i n = part || at (i + 1)) in
  at 0

let read file =
  let ic = open_in_bin file in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))

let no_output =
  Rapid_fuzz.Fuzz_run.{ engine_name = "no-output";
                        run = (fun p ~max_steps ->
                            let o = machine.run p ~max_steps in
                            { o with events = List.filter (fun e -> String.sub e 0 6 <> "output") o.events }) }

let settings = [ ("seed", "11"); ("count", "30"); ("engine", "no-output") ]

let shard_report shard =
  let s = C.run ~engines:[ no_output ] ~seed:11 ~count:30 ~shard () in
  let reproducer (f : C.failure_found) = Printf.sprintf "fuzz-%d.mod" f.program_index in
  let r = R.of_summary ~settings ~shard ~host:"test" ~reproducer s in
  (* through its JSON, as the merge reads it *)
  match R.of_json (Yojson.Safe.from_string (Yojson.Safe.to_string (R.to_json r))) with
  | Ok r' ->
      Alcotest.(check string) "the JSON reads back" (Yojson.Safe.to_string (R.to_json r))
        (Yojson.Safe.to_string (R.to_json r'));
      r'
  | Error m -> Alcotest.failf "its own report: %s" m

let shard_reports = lazy (List.map (fun k -> shard_report { C.index = k; count = 3 }) [ 3; 1; 2 ])
let whole_report = lazy (shard_report whole)

let merged_or_fail reports = match R.merge reports with Ok m -> m | Error e -> Alcotest.failf "merge: %s" e

(* what an unsharded run and a merge must share: all but the shards' hosts and times *)
let comparable (j : Yojson.Safe.t) =
  match j with
  | `Assoc l -> Yojson.Safe.to_string (`Assoc (List.filter (fun (k, _) -> k <> "shards") l))
  | _ -> Alcotest.fail "a report is an object"

let merge_is_unsharded () =
  let sharded = merged_or_fail (Lazy.force shard_reports) and one = merged_or_fail [ Lazy.force whole_report ] in
  Alcotest.(check bool) "there are failures to merge" true (List.length one.m_failures >= 3);
  Alcotest.(check int) "programs" 30 sharded.m_programs;
  (* the unsharded run's own report, not its merge: the same failures in the same order *)
  let run = Lazy.force whole_report in
  Alcotest.(check (list int)) "failures in the order of the unsharded run"
    (List.map (fun (f : R.failure_entry) -> f.program) run.failures)
    (List.map (fun (f : R.failure_entry) -> f.program) sharded.m_failures);
  Alcotest.(check (list (pair string int))) "rule counts" run.rules sharded.m_rules;
  Alcotest.(check (list (pair string int))) "outcomes" run.outcomes sharded.m_outcomes;
  Alcotest.(check bool) "the failures themselves" true (run.failures = sharded.m_failures);
  Alcotest.(check string) "the report but its shards' figures" (comparable (R.merged_to_json one))
    (comparable (R.merged_to_json sharded));
  Alcotest.(check int) "shards listed" 3 (List.length sharded.shards);
  let md = R.merged_to_markdown sharded in
  List.iter (fun (f : R.failure_entry) ->
      let where = Printf.sprintf "shard-%d/fuzz-%d.mod" (f.program mod 3 + 1) f.program in
      Alcotest.(check bool) (where ^ " in the report") true (has md where)) sharded.m_failures;
  (* the coverage of the merge is that of the unsharded run too *)
  let coverage m = Yojson.Safe.to_string (Rapid_fuzz.Coverage.to_json { (R.coverage m) with cpu_seconds = 0. }) in
  Alcotest.(check string) "coverage" (coverage one) (coverage sharded)

let merge_refuses () =
  let reports = Lazy.force shard_reports in
  let refused what reports fragment =
    match R.merge reports with
    | Ok _ -> Alcotest.failf "%s: merged" what
    | Error m -> Alcotest.(check bool) (Printf.sprintf "%s: %s" what m) true (has m fragment) in
  refused "a shard missing" (List.tl reports) "missing";
  refused "a shard twice" (List.hd reports :: reports) "more than once";
  refused "another campaign" ({ (List.hd reports) with settings = [ ("seed", "12") ] } :: List.tl reports)
    "same campaign";
  refused "nothing" [] "no shard";
  List.iter (fun text ->
      match R.of_json (Yojson.Safe.from_string text) with
      | Ok _ -> Alcotest.failf "read %s" text
      | Error m -> Alcotest.(check bool) m true (has m "not a shard report"))
    [ "[]"; "{}"; {|{"format": "rapid-sem fuzz shard 0"}|};
      Yojson.Safe.to_string (match R.to_json (List.hd reports) with
          | `Assoc l -> `Assoc (List.remove_assoc "rules" l) | j -> j) ]

(* The scripts of bench/slurm without Slurm: merge.sh on shard reports written here, and
   rapid-sem fuzz --json as a task runs it, its usual output unchanged. *)
let merge_script () =
  let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe" in
  let script = Filename.concat (Sys.getcwd ()) "../bench/slurm/merge.sh" in
  let dir = Filename.temp_file "rapid-fuzz-merge" "" in
  Sys.remove dir; Sys.mkdir dir 0o755;
  let write name text = let oc = open_out_bin (Filename.concat dir name) in output_string oc text; close_out oc in
  List.iter (fun (r : R.t) ->
      write (Printf.sprintf "shard-%d.json" r.shard.index) (Yojson.Safe.to_string (R.to_json r)))
    (Lazy.force shard_reports);
  let merge () =
    Sys.command (Printf.sprintf "RAPID_SEM=%s bash %s %s 3 > %s 2>&1" (Filename.quote binary) (Filename.quote script)
                   (Filename.quote dir) (Filename.quote (Filename.concat dir "out"))) in
  Alcotest.(check int) "exit 1: failures" 1 (merge ());
  let report = Yojson.Safe.from_file (Filename.concat dir "report.json") in
  let unsharded = R.merged_to_json (merged_or_fail [ Lazy.force whole_report ]) in
  Alcotest.(check string) "report.json is the unsharded run's" (comparable unsharded) (comparable report);
  List.iter (fun f -> Alcotest.(check bool) f true (Sys.file_exists (Filename.concat dir f)))
    [ "report.md"; "coverage.json"; "coverage.md" ];
  Sys.remove (Filename.concat dir "shard-2.json");
  Alcotest.(check int) "exit 2: a shard missing" 2 (merge ());
  let out = read (Filename.concat dir "out") in
  Alcotest.(check bool) ("names the shard: " ^ out) true (has out "shard 2 of 3");
  (* --json beside the usual output, which it leaves as it was *)
  let fuzz extra = Sys.command (Printf.sprintf "%s fuzz --count 20 --seed 4 --shard 2/2 --out %s %s > %s 2>&1"
                                  (Filename.quote binary) (Filename.quote (Filename.concat dir "f")) extra
                                  (Filename.quote (Filename.concat dir "log"))) in
  let log () =
    read (Filename.concat dir "log")
    |> String.split_on_char '\n' |> List.filter (fun l -> not (has l " programs/s ")) in
  Alcotest.(check int) "plain" 0 (fuzz "");
  let plain = log () in
  Alcotest.(check int) "with --json" 0 (fuzz ("--json " ^ Filename.quote (Filename.concat dir "s.json")));
  Alcotest.(check (list string)) "the same output" plain (log ());
  (match R.read (Filename.concat dir "s.json") with
   | Ok r -> Alcotest.(check (pair int int)) "shard 2/2, 10 programs" (2, 10) (r.shard.index, r.programs)
   | Error m -> Alcotest.fail m);
  ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir)))

(* Seed_state.make stands for Random.State.make in every campaign: the same state for seeds of
   one, two and three elements, negative, large and empty ones among them, and the same draws. *)
let seed_states () =
  let seeds = [ [||]; [| 0 |]; [| -1; max_int |]; [| min_int; 3; 7919 |]; [| 1; 2; 3; 4; 5; 6 |];
                Array.init 60 (fun i -> i * 7 - 100) ] in
  let seeds = seeds @ List.concat (List.init 2000 (fun i ->
      [ [| i |]; [| 20261203 - i; i |]; [| i; i * 31; 104729 |]; [| -i; i; 7919 |] ])) in
  List.iter (fun seed ->
      let a = Random.State.make seed and b = Rapid_fuzz.Seed_state.make seed in
      if a <> b then Alcotest.failf "seed [%s]: another state"
          (String.concat "; " (Array.to_list (Array.map string_of_int seed)));
      for _ = 1 to 5 do
        Alcotest.(check int) "a draw" (Random.State.bits a) (Random.State.bits b)
      done) seeds

(* The mutants made from a program's text do not change with the way they are made: a digest of
   1,000 of them, five from each of the first 200 programs of seed 5, as the lines' list made
   them (bench/README.md, "What each program still re-did"). *)
let mutants_pinned () =
  let d = Buffer.create 16 in
  for i = 0 to 199 do
    let t = G.to_source (G.generate (C.program_seed ~seed:5 i)) in
    for k = 0 to 4 do Buffer.add_string d (Digest.string (Rapid_fuzz.Mutant.mutate (Random.State.make [| i; k |]) t)) done
  done;
  Alcotest.(check string) "digest" "1055d01149443ae514cf1da9b3c09a8b" (Digest.to_hex (Digest.string (Buffer.contents d)))

let suite =
  ("campaign", [
      Alcotest.test_case "mutants pinned" `Quick mutants_pinned;
      Alcotest.test_case "seed states as Random.State.make" `Quick seed_states;
      Alcotest.test_case "a bounded campaign" `Slow bounded_campaign;
      Alcotest.test_case "shards partition the programs" `Quick shards_partition;
      Alcotest.test_case "the seed decides the program" `Quick same_seed_same_program;
      Alcotest.test_case "shrinking" `Quick shrinking_minimises;
      Alcotest.test_case "mutation check: trynext-as-retry" `Quick (mutation_caught Trynext_as_retry ~keyword:"TRYNEXT");
      Alcotest.test_case "mutation check: for-skips-last" `Quick (mutation_caught For_skips_last ~keyword:"FOR");
      Alcotest.test_case "mutations rewrite what they name" `Quick mutation_identity;
      Alcotest.test_case "mutants and hostile texts" `Quick mutants_answered;
      Alcotest.test_case "text shrinking" `Quick text_shrinking;
      Alcotest.test_case "coverage merges" `Quick coverage_merges;
      Alcotest.test_case "generator forms" `Quick generator_forms;
      Alcotest.test_case "scenarios reach every rule" `Slow scenarios_reach_rules;
      Alcotest.test_case "a saved scenario runs again" `Quick scenario_reproduces;
      Alcotest.test_case "shard reports merge to the unsharded run's" `Quick merge_is_unsharded;
      Alcotest.test_case "shard reports of another campaign refused" `Quick merge_refuses;
      Alcotest.test_case "bench/slurm/merge.sh and fuzz --json" `Quick merge_script ])
