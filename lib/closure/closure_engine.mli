(** The second evaluator of RAPID's dynamic semantics: a definitional interpreter written from
    doc/semantics.md and the manual, independent of the small-step {!Machine}.

    It shares with the machine only what lib/runtime holds: the checked, lowered program
    ({!Ir}), values and their operators ({!Value}, {!Arith}, {!Late_binding}), the observable
    events and outcomes, and the host through which both reach the world ({!Host}: the
    controller, the motion and the installed routines' registry); {!Closure_controller} carries
    out waits. Its library cannot name the machine (test/test_layers.ml). Each routine is
    compiled once, when it is first called, to OCaml closures: an expression to a function from
    the activation to a value, a place to a function giving its location (a container and an
    index), a statement to a function from the activation that says whether execution goes on
    after it or the routine returns (RETURN). Any other control that leaves a statement (GOTO,
    BREAK, CONTINUE, EXIT, an error in flight, a long jump, RETRY and TRYNEXT) is an OCaml
    exception caught where the manual sends it.

    It is the machine's first differential partner: on every program both must make the same
    observable {!Event.t}s in the same order and end with the same {!Outcome.t}
    (doc/semantics.md, "The second engine"). It is also the fast path of
    [rapid-sem run --engine closure]. *)

val default_fuel : int
(** 100,000,000, the default of [--max-steps]. *)

type result = {
  outcome : Outcome.t;
      (** as the machine's; [Running] when the fuel ran out (the machine's "step limit") *)
  fuel_used : int;
      (** units of fuel spent: one per statement started, per loop iteration (each test of a
          WHILE condition, each FOR iteration), per routine entered, and per poll, move of the
          clock and yield of a wait (doc/rulings.md R-8-waits1) *)
}

type cooperation = {
  share : Value.t array -> unit;
      (** the task's module data, once initialised (§2.21), before the entry routine runs: the
          slots of the persistents shared with other tasks are set here *)
  mutable entered : bool;
      (** whether the entry routine's first statement was entered: [false] when the task's
          start took that entry already (its statement time, as {!Task_set.start}'s machines
          do when made); the engine then goes on without taking it again *)
  turn : unit -> unit;
      (** a statement of a statement list comes into focus, its time charged and the interrupts
          served (where the machine's turn ends): returns when it is this task's turn again *)
  yield : wake:float option -> what:string -> pure:bool -> unit;
      (** a wait with nothing to do now (the machine's wait-yield): the earliest time the clock
          can end it, what it waits for, and whether nothing else happened in this turn;
          returns at the task's next turn *)
  native_budget : int;
      (** the native stack budget of the thread it runs on ({!Native_stack.budget}'s units) *)
}
(** One task of several ({!Closure_tasks}; doc/semantics.md, "The second engine"): the run
    hands the turn over where the machine's scheduler ends a turn. *)

val run :
  ?limits:Limits.t -> ?fuel:int -> ?stub_unmodelled:bool -> ?all_events:bool -> ?observe:bool ->
  ?on_event:(Event.t -> unit) -> ?before:string list -> ?after:string list -> host:Host.t ->
  ?cooperation:cooperation -> ?module_data:((string * string * Value.t) list -> unit) ->
  Ir.program -> entry:string -> (result, string) Stdlib.result
(** Initialises the module data (§2.21), then runs the entry routine to its end, calling
    [on_event] on each observable event as it happens; with [all_events:false] only on [Output],
    [Erase] and [Log] (what [rapid-sem run] without [--json] shows), which spares building the
    others. [~observe] (default false, with [all_events]): also the store writes, the arguments
    of calls and the values functions return, as [Machine.start ~observe] (schema rapid-sem/2;
    their texts are built only then). [Error] when there is no procedure
    [entry] without parameters (nothing runs).

    The program runs in the world of [host] (its controller and robot), as the machine runs it: virtual time, the
    time limit ([Resource_exhausted]), deadlocks of waits ([Deadlock]), interrupts and traps,
    the asynchronous errors of moves with the program pointer kept (§7.4, §7.6), and the user
    level of NOSTEPIN routines (§7.3, RaiseToUser). One task; with [cooperation], one of several
    ({!Closure_tasks}), whose waits yield instead of moving the clock. [module_data] is given the
    module data at the end of a run that started (module, name, value, as
    {!Machine.module_data}: [run --save]).

    [before], [after] (default none): a controller backup's event routines run before the entry
    routine and after it has returned, as {!Machine.start}'s (doc/rulings.md R-bk-8).

    Resources are bounded: the call depth by [limits.max_call_depth] (beyond it,
    [Resource_exhausted], as the machine), the work by [fuel]. A call chain deeper than the
    native stack of the running thread can hold also ends as [Resource_exhausted] (the default
    depth of 10,000 needs far less than the usual 8 MB stack; bench/README.md). No OCaml
    exception escapes: one that is not part of the semantics ends the run as [Stuck]. *)

val events :
  ?limits:Limits.t -> ?fuel:int -> ?stub_unmodelled:bool -> ?all_events:bool -> ?observe:bool ->
  host:Host.t -> Ir.program -> entry:string -> (Event.t list * result, string) Stdlib.result
(** [run], collecting the events in order. *)
