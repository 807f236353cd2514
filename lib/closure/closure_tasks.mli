(** Several tasks on one virtual clock by the closure engine (ch. 14; doc/semantics.md, "The
    second engine" and "Several tasks").

    The tasks come loaded and linked as for the machine's task set (lib/run's Task_load: the
    same refusals, the same shared data objects, the same initial values); each then runs as a
    {!Closure_engine.run} of its own, on a thread of its own, and exactly one runs at a time.
    Each hands the turn over where the machine's scheduler ends a turn (a statement of a
    statement list in focus, a wait with nothing to do, the end of the task), and the scheduler
    here chooses the next task by {!Task_rules}' rules: round robin in the order of the tasks, or
    with a seed SplitMix64's order; when every running task waits, the clock moves to the
    earliest time one gave; with none, a deadlock. *)

type t

val start :
  ?limits:Limits.t -> ?stub_unmodelled:bool -> ?seed:int -> Task_rules.task list -> Task_rules.link list ->
  (t, string) result
(** The tasks in order, ready to run: nothing runs yet. [limits] are the run's; each task runs
    with {!Limits.for_tasks} of them. *)

type task_result = {
  name : string;
  task_outcome : Outcome.t;
      (** as {!Task_set.task_outcome}: its own end, or the run's deadlock (what it waits for) or
          time limit; [Running] when the run stopped at the fuel limit *)
  fuel_used : int;      (** {!Closure_engine.result}'s, of this task *)
  module_data : (string * string * Value.t) list;
      (** its module data at the end (module, name, value), as {!Machine.module_data} *)
}

type result = {
  outcome : Outcome.t;
      (** as {!Task_set.outcome}: a deadlock or the time limit of the whole run, else the
          outcome of the first task (in order) that did not end normally, else [Ended];
          [Running] when a task ran out of fuel (the run then stops: the step limit) *)
  tasks : task_result list;   (** in the order of the tasks *)
}

val run :
  ?fuel:int -> ?all_events:bool -> ?observe:bool -> ?on_event:(string -> Event.t -> unit) ->
  t -> result
(** Runs every task to its end (or the run's), calling [on_event] with the task's name on each
    observable event as it happens, in the machine's order. [fuel] is each task's
    ({!Closure_engine.run}'s), [all_events] and [observe] as there. Once. An exception that
    [on_event] raises ends the run and is raised again here, every task's thread ended. *)

val names : t -> string list

val clock : t -> Host.t
(** The clock of the run (the first task's host). *)

val thread_budget : unit -> int
(** The native stack budget of a task's thread: {!Native_stack.budget}, at most that of the C
    library's default thread stack (the soft limit, 2 MB when it is unlimited, at most 8 MB
    counted): a thread's stack is not the main thread's. *)
