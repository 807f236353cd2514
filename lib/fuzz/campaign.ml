type shard = { index : int; count : int }

type failure_found = {
  program_index : int;
  failure : Fuzz_run.failure;
  source : string;
  original_size : int;
  minimal_size : int;
  case : Fuzz_case.t option;
}

type summary = {
  programs : int;
  failures : failure_found list;
  outcomes : (string * int) list;
  rules : (string * int) list;
  seconds : float;
  cpu_seconds : float;
}

(* A campaign's process keeps a large heap that does not change (the installed environment,
   checked and lowered once) beside a stream of short-lived programs: major collections that
   mark the former again and again, and minor ones that promote what a program still holds,
   were a quarter of the time (bench/README.md, "Fuzzing throughput"). Next-fit allocation
   promotes faster than best-fit; its fragmentation is left to compaction (the default
   max_overhead of 500 %: without it the heap grew to 250 MB in 10,000 programs, with it it
   stays below 60 MB). The heap grows by 15 % at a time, the runtime's default, not in the steps
   of 8 MB a single run takes (Installed_image): 1.5 % fewer instructions over 300 programs. *)
let tune_gc () =
  Gc.set { (Gc.get ()) with minor_heap_size = 1 lsl 20; space_overhead = 400; allocation_policy = 0;
                            max_overhead = 500; major_heap_increment = 15 }

let program_seed ~seed i = Seed_state.make [| seed; i |]

(* A refusal's message without its place: a smaller program refused for another reason (a BREAK
   left outside its loop by the shrinking) is not the same failure. *)
let without_place m =
  let rec skip m n = if n = 0 then m else match String.index_opt m ':' with
      | Some i -> skip (String.sub m (i + 1) (String.length m - i - 1)) (n - 1)
      | None -> m in
  let first = match String.index_opt m ';' with Some i -> String.sub m 0 i | None -> m in
  skip first 3

let same_class (a : Fuzz_run.failure) (b : Fuzz_run.failure) =
  match a, b with
  | Refused a, Refused b -> without_place a = without_place b
  | Exception _, Exception _ | Stuck _, Stuck _
  | Nondeterministic _, Nondeterministic _ | Engines_differ _, Engines_differ _
  | Round_trip _, Round_trip _ -> true
  | _ -> false

(* Greedy shrinking: take the first smaller program that fails in the same way, until none
   does. A candidate that no longer checks is not a smaller failure of the same kind (unless
   the failure is itself a refusal). *)
let minimise_by shrink judge program failure =
  let rec go program failure budget =
    if budget = 0 then (program, failure)
    else
      let next = Seq.filter_map (fun candidate ->
          match judge candidate with
          | Error f when same_class f failure -> Some (candidate, f)
          | _ -> None) (shrink program) in
      match next () with
      | Seq.Nil -> (program, failure)
      | Seq.Cons ((smaller, f), _) -> go smaller f (budget - 1)
  in
  go program failure 500

let minimise judge program failure = minimise_by Program_gen.shrink judge program failure

(* The same for a scenario: its modules shrunk one at a time (Fuzz_case.shrink). *)
let minimise_case judge case failure = minimise_by Fuzz_case.shrink judge case failure

(* Whether program [i] is a scenario (Scenario_gen): drawn from a state apart from the
   program's, so that the other programs are those of a campaign without scenarios. *)
let is_scenario ~seed ~scenarios i =
  scenarios > 0 && Random.State.int (Seed_state.make [| seed; i; 104729 |]) scenarios = 0

(* What one text gives: the failure it shows, shrunk, if any. *)
let judge_text i text =
  match Mutant.check_text text with
  | Ok () -> None
  | Error m ->
      let fails t = Result.is_error (Mutant.check_text t) in
      let minimal = Mutant.shrink_text fails text in
      let m = match Mutant.check_text minimal with Error m' -> m' | Ok () -> m in
      let lines t = List.length (String.split_on_char '\n' t) in
      Some { program_index = i; failure = Fuzz_run.Checker_crashed m; source = minimal;
             original_size = lines text; minimal_size = lines minimal; case = None }

(* Most hostile texts are one of some fifty fixed texts (Mutant.hostile: a kind and a depth,
   drawn), the large ones 20 KB to 600 KB, and one in 14 a module of 10,000 procedures: checking
   the same bytes again in every tenth program was a fifth of the default configuration's time
   (bench/README.md, "What each program re-did"). The verdict of a text is a function of its
   bytes (the machine that runs it is deterministic, which every program tests), so a large one
   is judged once per process, and its verdict and the rules its run applied counted again at
   each repetition. The random texts (bytes, words) are under 4 KB and rarely repeat: not kept. *)
let judged_hostile : (string, failure_found option * (string * int) list) Hashtbl.t = Hashtbl.create 64
(* The same verdicts by the texts' addresses: Mutant.hostile hands out one string for each large
   text, and hashing it for the table read all of its bytes (up to 600 KB) at every repetition. *)
let judged_here : (string * (failure_found option * (string * int) list)) list ref = ref []
let kept_from = 4096
let forget_texts () = Hashtbl.reset judged_hostile; judged_here := []

let judge_hostile i text =
  if String.length text < kept_from then judge_text i text
  else
    let known = match List.assq_opt text !judged_here with
      | Some _ as known -> known
      | None -> Hashtbl.find_opt judged_hostile text in
    match known with
    | Some (verdict, rules) ->
        Fuzz_run.note_rules rules;
        Option.map (fun f -> { f with program_index = i }) verdict
    | None ->
        let verdict, rules = Fuzz_run.recording_rules (fun () -> judge_text i text) in
        if Hashtbl.length judged_hostile < 256 then begin
          Hashtbl.replace judged_hostile text (verdict, rules);
          judged_here := (text, (verdict, rules)) :: !judged_here
        end;
        verdict

(* The mutants of program [i] and, every [hostile_every] programs, a hostile text: each failing
   text is shrunk by lines and characters. Their random states are apart from the program's, so
   that a campaign's programs do not change with the number of mutants. *)
let check_texts ~seed ~mutants ~hostile_every i source =
  let hostile = hostile_every > 0 && i mod hostile_every = 0 in
  (* Making a random state digests its seed some hundred times: not done for no text. *)
  if mutants = 0 && not hostile then []
  else
    let rs = Seed_state.make [| seed; i; 7919 |] in
    (* the hostile text drawn first, then the mutants, as they always were *)
    let hostile_text = if hostile then Some (Mutant.hostile rs) else None in
    let found = List.filter_map (judge_text i) (List.init mutants (fun _ -> Mutant.mutate rs source)) in
    found @ Option.to_list (Option.bind hostile_text (judge_hostile i))

let run ?(options = Program_gen.default_options) ?(engines = []) ?external_check ?progress
    ?(max_steps = 200_000) ?(mutants = 1) ?(hostile_every = 10) ?(scenarios = 10) ?max_failures ~seed ~count ~shard () =
  let started = Unix.gettimeofday () and cpu_started = Sys.time () in
  let outcomes = Hashtbl.create 8 in
  Fuzz_run.reset_rule_counts ();
  (* [source] is [Program_gen.to_source program], printed once for the texts and the judge. *)
  let judge_source source =
    match Fuzz_run.check_program ~engines ~max_steps source with
    | Error f -> Error f
    | Ok observed -> (
        match external_check with
        | None -> Ok observed
        | Some check -> (
            match check source with
            | Ok () -> Ok observed
            | Error m -> Error (Fuzz_run.Engines_differ ("the implementation: " ^ m))))
  in
  let judge program = judge_source (Program_gen.to_source program) in
  let failures = ref [] and programs = ref 0 in
  for i = 0 to count - 1 do
    let enough = match max_failures with Some k -> List.length !failures >= k | None -> false in
    if i mod shard.count = shard.index - 1 && not enough then begin
      incr programs;
      let count_outcome (observed : Fuzz_run.observed) =
        let kind = List.hd (String.split_on_char ' ' observed.outcome) in
        Hashtbl.replace outcomes kind (1 + Option.value (Hashtbl.find_opt outcomes kind) ~default:0) in
      if is_scenario ~seed ~scenarios i then begin
        (* a scenario: its options and stimulus are its own, so no external check (the
           oracle's protocol passes one program alone); its first module is mutated *)
        let case = Scenario_gen.generate (program_seed ~seed i) in
        let first = match case.tasks with
          | { modules = m :: _; _ } :: _ -> Program_gen.to_source m | _ -> "" in
        failures := List.rev_append (check_texts ~seed ~mutants ~hostile_every i first) !failures;
        let judge c = Case_run.check_case ~engines ~max_steps c in
        match judge case with
        | Ok observed -> count_outcome observed
        | Error failure ->
            let minimal, failure = minimise_case judge case failure in
            failures := { program_index = i; failure; source = Fuzz_case.to_text minimal;
                          original_size = Fuzz_case.size case; minimal_size = Fuzz_case.size minimal;
                          case = Some minimal } :: !failures
      end
      else begin
      let program = Program_gen.generate ~options (program_seed ~seed i) in
      let source = Program_gen.to_source program in
      failures := List.rev_append (check_texts ~seed ~mutants ~hostile_every i source) !failures;
      (match judge_source source with
       | Ok observed -> count_outcome observed
       | Error failure ->
           let minimal, failure = minimise judge program failure in
           failures := { program_index = i; failure; source = Program_gen.to_source minimal;
                         original_size = Program_gen.size program; minimal_size = Program_gen.size minimal;
                         case = None }
                       :: !failures)
      end;
      match progress with
      | Some f -> f ~done_:!programs ~total:((count - shard.index) / shard.count + 1)
                    ~failures:(List.length !failures) ~rules_seen:(List.length (Fuzz_run.rule_counts ()))
      | None -> ()
    end
  done;
  { programs = !programs; failures = List.rev !failures;
    outcomes = List.sort compare (Hashtbl.fold (fun k v acc -> (k, v) :: acc) outcomes []);
    rules = Fuzz_run.rule_counts (); seconds = Unix.gettimeofday () -. started;
    cpu_seconds = Sys.time () -. cpu_started }

let write path text =
  let oc = open_out_bin path in
  Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text)

(* A scenario: a folder fuzz-I.case with its modules (a folder per task when there are
   several), the stimulus fuzz.io and the command that runs it (run.sh). *)
let save_case ~base f (c : Fuzz_case.t) =
  let folder = base ^ ".case" in
  if not (Sys.file_exists folder) then Sys.mkdir folder 0o755;
  let several = List.length c.tasks > 1 in
  List.iter (fun (t : Fuzz_case.task) ->
      let sub = if several then Filename.concat folder t.task_name else folder in
      if not (Sys.file_exists sub) then Sys.mkdir sub 0o755;
      List.iter (fun m -> write (Filename.concat sub (Fuzz_case.module_file m)) (Program_gen.to_source m)) t.modules)
    c.tasks;
  write (Filename.concat folder "fuzz.io") c.io_text;
  let command =
    if several then
      (* the files of each task are in its folder *)
      String.concat " " ([ "rapid-sem run" ] @ Fuzz_case.arguments c.options @ [ "--io fuzz.io" ]
                         @ (match c.schedule with Some s -> [ "--schedule"; string_of_int s ] | None -> [])
                         @ List.map (fun (t : Fuzz_case.task) ->
                             Printf.sprintf "--task %s=%s" t.task_name
                               (String.concat ","
                                  (List.map (fun m -> t.task_name ^ "/" ^ Fuzz_case.module_file m) t.modules)))
                             c.tasks)
    else Fuzz_case.command c in
  write (Filename.concat folder "run.sh") ("#!/bin/sh\ncd \"$(dirname \"$0\")\"\n" ^ command ^ " \"$@\"\n");
  write (base ^ ".failure") (Fuzz_run.failure_to_string f.failure ^ "\n");
  let expected =
    match Case_run.observe c with
    | Ok o -> String.concat "\n" (o.events @ [ "end " ^ o.outcome ]) ^ "\n"
    | Error m -> m ^ "\n" in
  write (base ^ ".expected") expected;
  folder

let save ~dir f =
  if not (Sys.file_exists dir) then Sys.mkdir dir 0o755;
  let base = Filename.concat dir (Printf.sprintf "fuzz-%d" f.program_index) in
  match f.case with
  | Some c -> save_case ~base f c
  | None ->
  write (base ^ ".mod") f.source;
  (* the signals the program may use: rapid-sem run --io fuzz-I.io fuzz-I.mod runs it again *)
  write (base ^ ".io") (Fuzz_run.io_text_for f.source);
  write (base ^ ".failure") (Fuzz_run.failure_to_string f.failure ^ "\n");
  let expected =
    match Fuzz_run.observe f.source with
    | Ok o -> String.concat "\n" (o.events @ [ "end " ^ o.outcome ]) ^ "\n"
    | Error m -> m ^ "\n" in
  write (base ^ ".expected") expected;
  base ^ ".mod"
