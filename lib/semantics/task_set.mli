(** Several tasks on one virtual clock (ch. 14; doc/semantics.md, "Several tasks").

    Each task is its own task buffer and machine ({!Machine.start} [~cooperative:true]), with its
    own entry routine, data, error handling, interrupts and waits; their worlds share the clock,
    the signals and the services ({!Rapid_controller.World.add_task}). System-global persistents
    (PERS declared neither TASK nor LOCAL) with the same name are one data object for every
    task that declares them.

    Turns are deterministic, of one statement each: round robin in the order of the tasks, or,
    with a seed, a pseudo-random order of SplitMix64 that depends on the seed only. *)

type t

val start :
  ?limits:Limits.t -> ?stub_unmodelled:bool -> ?observe:bool -> ?seed:int -> Task_rules.task list ->
  Task_rules.link list -> (t, string) result
(** The tasks in order, loaded and linked ({!Rapid_run.Task_load}), each a machine ready to run
    ({!Machine.start} [~cooperative:true]); the data objects they share made one. [observe] as
    {!Machine.start}'s, for every task. [limits] are the run's; each task runs with
    {!Limits.for_tasks} of them. [Error]: a task that cannot start ("task T1: no procedure
    main without parameters to run"). *)

val limits : t -> Limits.t
(** Each task's limits ({!Limits.for_tasks} of the run's). *)

val next : t -> (string * Machine.config) option
(** The task whose turn it is (its name and machine), which {!step} steps next; [None] when the
    run is over. Choosing a task may move the clock (every task waited). *)

val step : t -> (string * string * Event.t list) option
(** One reduction step of the task whose turn it is: its name, the rule, the events. [None]
    when the run is over (every task ended, or {!outcome} says why not). *)

val outcome : t -> Machine.outcome
(** [Running] while a task runs; then a deadlock or the time limit of the whole run, else the
    outcome of the first task (in order) that did not end normally, else [Ended]. *)

val task_outcome : t -> Machine.config -> Machine.outcome
(** The outcome of one task of the run: its own, once it ended; a task still running when the
    scheduler ended the run is in a [Deadlock] that says what the task waits for, or in the
    run's [Resource_exhausted] (its time limit); [Running] only while the run goes on or after
    the step limit. *)

val tasks : t -> (string * Machine.config) list
val steps : t -> int
val clock : t -> Host.t
(** The clock of the run (the first task's host). *)
