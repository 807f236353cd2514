(** Several tasks on one virtual clock (ch. 14; doc/semantics.md, "Several tasks"): what the
    machine's task set ({!Rapid_semantics.Task_set}) and the closure engine's
    ({!Rapid_closure.Closure_tasks}) share: the tasks as loaded, the data objects they share,
    and the scheduler's rules. *)

type task = {
  name : string;
  program : Ir.program;        (** checked and lowered, its shared persistents initialised *)
  entry : string;              (** the entry routine, a procedure without parameters *)
  host : Host.t;               (** the task's world: its controller shares the clock *)
  before : string list;
      (** a controller backup's event routines the task runs before its entry routine, in order
          (doc/rulings.md R-bk-8); each a procedure without parameters *)
  after : string list;         (** those it runs once the entry routine has returned *)
}

val first_routine : task -> string
(** The routine the task starts in: its first event routine, else its entry routine. *)

type link = { task : int; slot : int; owner : int; owner_slot : int }
(** A data object the tasks share (system-global persistents, installed data): task [task]'s
    global slot [slot] is task [owner]'s slot [owner_slot], tasks numbered from 0 in their
    order; [owner] owns the value, and its slot is shared with nothing else. *)

val max_tasks : int
(** The tasks a run may have: 20 (doc/rulings.md R-14-cli3). *)

type order = Round_robin | Seeded of int64 ref   (** SplitMix64's state *)

val order_of_seed : int option -> order
(** [--schedule SEED]'s order, or round robin without a seed. *)

val splitmix : int64 ref -> int64
(** SplitMix64: the next number of the state (the state moves on). *)

val next_turn : order -> cursor:int ref -> count:int -> (int -> bool) -> int option
(** The scheduler's rule for both engines: among the [count] tasks (by index, in their order)
    those [eligible] (running, not waiting in vain), the first from [cursor] in round robin
    ([cursor] moves past it), or SplitMix64's pick; [None] when there is none. *)

val every_task_waits : Host.t -> (string * string option * float option) list -> Outcome.t option
(** Every running task waits, each given as (name, what it waits for, the time its wait gave):
    [None] with the clock moved on to the earliest such time; a deadlock when none gave a time;
    the time limit when that time is beyond --max-time. The host is the run's clock (the first
    task's). *)

val no_entry : Ir.program -> string -> string
(** The message for a task without the procedure [entry]: what to do, with the task's procedures
    without parameters that --entry can run (§9.1). *)

val not_an_event_routine : Ir.program -> string -> string
(** Why the event routine of this name does not run (doc/rulings.md R-bk-8): the task has no
    procedure so named, or it has parameters or is not a procedure; both engines' words. *)

val sequence :
  find:(is_entry:bool -> string -> ('a, string) result) -> before:string list -> entry:string -> after:string list ->
  ('a list, string) result
(** The routines a task runs one after the other (R-bk-8): the event routines [before], the
    entry routine, the event routines [after], each found by [find] (its own way of each engine),
    or the first error in that order. *)

val entry_routine : Ir.program -> string -> (int, string) result
(** The entry routine of this name (letter case aside): the first routine so named, which must
    be a procedure without parameters (§9.1); [Error] says why there is none, in the words both
    engines give. *)

val initial_value : Ir.program -> int -> Value.t option
(** The value module data object [j] has before the run, when the program knows it: a literal
    (computed by {!Initial_values}) or its type's initial value; [None] for an expression left to
    the run (a placeholder, an unknown name), which fails when the task starts. *)
