(** Running a generated program and judging the properties of doc/oracle.md ("Fuzzing"). *)

type observed = {
  events : string list;        (** the observable events, one line each, as run --json writes them *)
  outcome : string;            (** how the run ended, with the error's name and place *)
  finished : bool;             (** ended within the step bound (not exhausted) *)
}

type failure =
  | Refused of string          (** the generated program does not pass check: a generator or checker bug *)
  | Exception of string        (** an OCaml exception escaped *)
  | Stuck of string            (** a checked program reached a state with no rule (exit 125) *)
  | Nondeterministic of string (** two runs gave different events *)
  | Engines_differ of string   (** the engines' events differ *)
  | Round_trip of string       (** print (parse s) does not parse to the same tree *)
  | Checker_crashed of string  (** a mutant or hostile text made the front end or the checker
                                   raise, or answer without a place or class (Mutant) *)

val failure_to_string : failure -> string

type engine = {
  engine_name : string;
  run : Rapid_runtime.Ir.program -> max_steps:int -> observed;
}

val io : Rapid_controller.Io_config.t
(** The outside world of every generated program: the signals di1 and do1, and changes of di1
    at fixed times. *)

val io_text : string
(** {!io} as a stimulus file (doc/controller.md). *)

val mentions : string -> string -> bool
(** [mentions word text]: [word] occurs in [text]. *)

val io_text_for : string -> string
(** The stimulus file a program runs with: {!io_text} when the program names di1; else the same
    signals without the stimulus, whose changes such a program cannot react to and which only
    the machine makes (doc/fuzz-campaign.md). Saved beside each failure. *)

val load : Rapid_syntax.Ast.module_declaration -> (Rapid_load.Session.loaded, Rapid_load.Session.failure) result
(** As {!Rapid_load.Session.load_modules} with {!io}, over one installed environment made
    once, so that the checker and the lowering share their work on it between programs. *)

val load_modules :
  ?allow_unknown:bool -> ?io:Rapid_controller.Io_config.t -> Rapid_syntax.Ast.module_declaration list ->
  (Rapid_load.Session.loaded, Rapid_load.Session.failure) result
(** {!load} of several modules of one task buffer, with the checker's [--allow-unknown] and a
    stimulus of the same signals as {!io} (default {!io}). *)

val with_run_options : io:Rapid_controller.Io_config.t -> Fuzz_case.options -> (unit -> 'a) -> 'a
(** [f ()] with {!machine} and {!closure} running in a world of [io] with the case's limits and
    options (max time, memory, call depth, stubs); afterwards as before. *)

val event_text : Rapid_runtime.Event.t -> string
val outcome_text : Rapid_runtime.Outcome.t -> string
(** An event and an outcome as {!observed} holds them. *)

val note_rule : string -> unit
(** Counts one application of a rule ({!rule_counts}): for the runs of several tasks, which step
    the machines themselves. *)

val compare_observed : string -> observed -> observed -> string option
(** The first difference of two observations (events, then outcome), named [what]; [None]
    when they are the same. *)

val machine : engine
(** The small-step machine, the definition. *)

val closure : engine
(** The closure engine ({!Rapid_closure.Closure_engine}), fuel [max_steps]. A run that
    exhausts its fuel or a resource, or reaches the controller or motion (which it leaves to the
    machine), is not finished and so not compared. *)

val round_trip : name:string -> Rapid_syntax.Ast.module_declaration -> (unit, failure) result
(** The printer's round trip of a parsed module: its printed text parses to the same tree,
    locations aside. *)

val refused : Rapid_load.Session.failure -> failure
(** A load's failure as the fuzzer reports it (static errors only, not warnings). *)

val is_stuck : observed -> bool

val judge_runs : engines:engine list -> max_steps:int -> Rapid_runtime.Ir.program -> (observed, failure) result
(** Progress, determinism (the machine runs it twice) and each engine's agreement with the
    machine (when both finished), on a loaded program; [Ok] with the machine's observation. *)

val check_program : ?engines:engine list -> ?max_steps:int -> string -> (observed, failure) result
(** Parses, checks and runs the source with the machine twice and with every other engine;
    [Ok] with the machine's observation when every property holds. *)

val observe : ?max_steps:int -> string -> (observed, string) result
(** The machine's observation of a source, without judging any property. *)

val recording_rules : (unit -> 'a) -> 'a * (string * int) list
(** [f ()], with the rules {!note_rule} counted while it ran, by name. *)

val note_rules : (string * int) list -> unit
(** Counts each rule as many times as it is paired with, as that many {!note_rule} would. *)

val rule_counts : unit -> (string * int) list
(** The machine's rules applied since the last {!reset_rule_counts}, with counts, by name. *)

val reset_rule_counts : unit -> unit
