(** A fuzzing campaign: generate, check and run programs, shrink each failure to a minimal
    program and save it (doc/oracle.md, "Fuzzing"). *)

type shard = { index : int; count : int }
(** Shard [index] of [count] (1-based): program [i] of the campaign belongs to shard
    [i mod count + 1], so that shards split the programs and together cover them all. *)

type failure_found = {
  program_index : int;
  failure : Fuzz_run.failure;
  source : string;                       (** the minimal program *)
  original_size : int;
  minimal_size : int;
  case : Fuzz_case.t option;             (** a scenario's minimal case ([source] is its text) *)
}

type summary = {
  programs : int;                        (** programs of this shard run *)
  failures : failure_found list;
  outcomes : (string * int) list;        (** how runs ended: ended, stopped, exhausted ... *)
  rules : (string * int) list;           (** the machine's rules, with how often each applied *)
  seconds : float;                       (** wall-clock time *)
  cpu_seconds : float;                   (** processor time of this process: programs per
                                             second per core is [programs / cpu_seconds] *)
}

val tune_gc : unit -> unit
(** Sets the garbage collector of this process for a campaign: a larger minor heap, a higher
    space overhead and next-fit allocation, for a heap that never changes beside many
    short-lived programs. Changes only speed and memory use. *)

val program_seed : seed:int -> int -> Random.State.t
(** The random state of program [i] of a campaign: the same for every shard layout. *)

val is_scenario : seed:int -> scenarios:int -> int -> bool
(** Whether program [i] of a campaign is a scenario: one in [scenarios] on average, drawn from
    a random state of its own. *)

val run :
  ?options:Program_gen.options ->
  ?engines:Fuzz_run.engine list ->
  ?external_check:(string -> (unit, string) result) ->
  ?progress:(done_:int -> total:int -> failures:int -> rules_seen:int -> unit) ->
  ?max_steps:int -> ?mutants:int -> ?hostile_every:int -> ?scenarios:int -> ?max_failures:int ->
  seed:int -> count:int -> shard:shard -> unit -> summary
(** Each program also gives [mutants] (default 1) ill-typed mutants ({!Mutant.mutate}), and every
    [hostile_every]-th program (default 10; 0: none) a hostile text ({!Mutant.hostile}), each
    judged by {!Mutant.check_text} and shrunk by lines and characters when it fails.
    One program in [scenarios] (default 10; 0: none), drawn from the seed, is a scenario of
    {!Scenario_gen} instead, judged by {!Case_run.check_case} with its own options and stimulus
    (doc/fuzz-campaign.md, "Scenarios"); its first module is mutated as a program is.
    With [max_failures], the campaign stops once it has found that many failures.
    [external_check source] compares another implementation on a program that passed every
    property (the oracle); an [Error] is a failure too. *)

val forget_texts : unit -> unit
(** Forgets the verdicts of the large hostile texts judged so far: {!run} judges each such text
    once per process and counts its verdict and rules again when it recurs. *)

val save : dir:string -> failure_found -> string
(** A scenario's failure is written as a folder [fuzz-I.case] (its modules, [fuzz.io] and
    [run.sh], the command that runs it) with [fuzz-I.failure] and [fuzz-I.expected]; returns
    the folder. Otherwise: writes [fuzz-I.mod] (the minimal program), [fuzz-I.io] (the signals
    it may use, for [rapid-sem run --io]), [fuzz-I.failure] (what went wrong) and
    [fuzz-I.expected] (the machine's events and outcome for it) into [dir], created if missing;
    returns the .mod's path. *)
