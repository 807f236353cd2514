(* The differential fuzzing campaign (lib/fuzz): a bounded campaign runs in every `make test`;
   the long ones belong to `rapid-sem fuzz` (doc/oracle.md). *)

module C = Rapid_fuzz.Campaign
module G = Rapid_fuzz.Program_gen

let whole = { C.index = 1; count = 1 }

let bounded_campaign () =
  (* Both engines on every program (doc/semantics.md, "The second engine"). *)
  let s = C.run ~engines:[ Rapid_fuzz.Fuzz_run.closure ] ~seed:2026 ~count:300 ~shard:whole () in
  List.iter (fun (f : C.failure_found) ->
      Printf.printf "program %d: %s\n%s\n" f.program_index (Rapid_fuzz.Fuzz_run.failure_to_string f.failure) f.source)
    s.failures;
  Alcotest.(check int) "failures" 0 (List.length s.failures);
  Alcotest.(check int) "programs" 300 s.programs;
  (* The campaign reaches the rules of chapters 4, 5 and 7, not only the easy ones. *)
  List.iter (fun rule ->
      Alcotest.(check bool) (rule ^ " applied") true (List.mem_assoc rule s.rules))
    [ "retry"; "trynext"; "raise-propagate"; "longjump-found"; "undo-run"; "goto"; "call-late";
      "call-enter"; "argument-alias"; "test-match"; "for-step"; "while-again"; "function-no-return" ];
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
    let source = G.to_source (G.generate (C.program_seed ~seed:2026 i)) in
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

let suite =
  ("campaign", [
      Alcotest.test_case "a bounded campaign" `Slow bounded_campaign;
      Alcotest.test_case "shards partition the programs" `Quick shards_partition;
      Alcotest.test_case "the seed decides the program" `Quick same_seed_same_program;
      Alcotest.test_case "shrinking" `Quick shrinking_minimises ])
