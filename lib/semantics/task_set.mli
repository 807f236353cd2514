(** Several tasks on one virtual clock (ch. 14; doc/semantics.md, "Several tasks").

    Each task is its own task buffer and machine ({!Machine.start} [~cooperative:true]), with its
    own entry routine, data, error handling, interrupts and waits; their worlds share the clock,
    the signals and the services ({!Rapid_controller.World.add_task}). System-global persistents
    (PERS declared neither TASK nor LOCAL) with the same name are one data object for every
    task that declares them.

    Turns are deterministic, of one statement each: round robin in the order of the tasks, or,
    with a seed, a pseudo-random order of SplitMix64 that depends on the seed only. *)

type spec = { name : string; files : string list; entry : string }

type t

type failure =
  | Load of string * Session.failure
      (** the task's name and why its buffer was refused; a system-global persistent declared
          with another type than in an earlier task is a semantic error at its declaration *)
  | Refused of string   (** no such entry routine, no such motion task *)

val max_tasks : int
(** The tasks a run may have: 20 (doc/rulings.md R-14-cli3); {!start} refuses more. *)

val task_limits : Machine.limits -> count:int -> Machine.limits
(** The limits of each of [count] tasks: [max_memory] split evenly between them, so that the
    tasks together never hold more RAPID data than the run's budget (R-14-cli3). *)

val start :
  ?limits:Machine.limits -> ?stub_unmodelled:bool -> ?allow_unknown:bool -> ?observe:bool ->
  ?io:Rapid_controller.Io_config.t -> ?seed:int -> ?motion_task:string ->
  world:Rapid_controller.World.t -> motion:Motion_primitives.state -> spec list ->
  (t * Rapid_typing.Report.t list, failure) result
(** The tasks in order, ready to run, and the warnings of their checks. [world] becomes the
    first task's world; [motion] the motion task's robot ([motion_task], default the first
    task). [observe] as {!Machine.start}'s, for every task. [limits] are the run's; each task
    runs with {!task_limits} of them. More than {!max_tasks} tasks are [Refused]. *)

val limits : t -> Machine.limits
(** Each task's limits ({!task_limits} of the run's): what the closure engine's tasks run with
    too. *)

val next : t -> (string * Machine.config) option
(** The task whose turn it is (its name and machine), which {!step} steps next; [None] when the
    run is over. Choosing a task may move the clock (every task waited). *)

val step : t -> (string * string * Machine.event list) option
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
val world : t -> Rapid_controller.World.t
(** The clock of the run (the first task's world). *)

val shared : t -> (int * int * int * int) list
(** The data objects the tasks share (system-global persistents, installed data): task [k]'s
    global slot [i] is task [k']'s slot [j], as [(k, i, k', j)], tasks numbered from 0 in their
    order; [k'] owns the value, and its slot is shared with nothing else. *)

val splitmix : int64 ref -> int64
(** SplitMix64: the next number of the state (the state moves on). *)

type order = Round_robin | Seeded of int64 ref   (** SplitMix64's state *)

val order_of_seed : int option -> order
(** [--schedule SEED]'s order, or round robin without a seed. *)

val next_turn : order -> cursor:int ref -> count:int -> (int -> bool) -> int option
(** The scheduler's rule for both engines ({!Closure_tasks} too): among the [count] tasks (by
    index, in their order) those [eligible] (running, not waiting in vain), the first from
    [cursor] in round robin ([cursor] moves past it), or SplitMix64's pick; [None] when there is
    none. *)

val every_task_waits :
  Rapid_controller.World.t -> (string * string option * float option) list -> Machine.outcome option
(** Every running task waits, each given as (name, what it waits for, the time its wait gave):
    [None] with the clock moved on to the earliest such time; a deadlock when none gave a time;
    the time limit when that time is beyond --max-time. For both engines. *)
