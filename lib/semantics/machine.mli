(** The small-step machine of RAPID's dynamic semantics (chapters 2-7 and 9).

    A configuration holds the control (an expression, statement or place in focus, a value, or an
    error in flight), the store (module data and the activations of routines), and a flat stack of
    continuation frames, one per pending piece of work, in the style of CompCert's Csem. [step]
    reduces one redex and names the rule it applies; every step costs O(1), whatever the nesting
    or the depth of recursion: no rule walks the stack or rebuilds the path to the focus. Errors,
    long jumps and UNDO handlers unwind the stack one frame or one activation per step.

    A step is a redex a programmer would name; the administrative moves between two of them
    (a literal becoming a value, an argument bound, a completed statement popped, the next
    statement of a list put in focus, ...) are made at the end of the step that leads to them,
    so that between two steps the configuration is always settled (doc/semantics.md,
    "Settling"). Settling passes through the points of response to interrupts (ch. 8) and
    charges the statement time where a statement is entered; where something happens there (an
    interrupt to serve, the time limit), it stops and that is the next step. The views at the
    end of this interface are for the trace only: a run never computes them.

    The configuration holds the controller around the program (a {!Rapid_controller.World}: the
    virtual clock, the signals, the interrupt queue; doc/controller.md); traps run at trap level.
    It is ready for what later issues add: the user level, a motion queue, and several tasks. *)

type config

type event = Event.t
type outcome = Outcome.t
type limits = Limits.t

val start :
  ?limits:limits -> ?stub_unmodelled:bool -> ?cooperative:bool -> ?observe:bool -> ?before:string list ->
  ?after:string list -> host:Host.t -> Ir.program -> entry:string -> (config, string) result
(** The configuration that runs the entry routine, after the module data has been initialised
    (§2.21: static data initialised on load). [Error] when there is no such procedure.
    [~stub_unmodelled] (default false): an installed routine rapid-sem does not model runs as a
    no-op (a function gives its type's initial value) instead of ending the run as
    [Unsupported].
    [~cooperative] (default false): the task is one of several on one clock (ch. 14); a waiting
    instruction with nothing to do now steps by "wait-yield" ({!wake_time}) and leaves moving the
    clock to the scheduler ({!Task_set}).
    [~observe] (default false): the steps also say the store writes, the
    arguments of calls and the values functions return ({!Observation.t}: texts built only then,
    schema rapid-sem/2).
    [~before], [~after] (default none): a controller backup's event routines (doc/rulings.md
    R-bk-8), run one after the other in a new activation each, those of [before] before the
    entry routine, those of [after] once it has returned; each a procedure without parameters
    ([Error] otherwise). A routine of the sequence that ends by its end or RETURN is followed by
    the next; ExitCycle in an event routine ends that routine as its end does; an error the
    system error handler takes, EXIT or Stop ends the task. *)

val interpose : config -> string list -> (event list, string) result
(** The debugger's events of a controller backup (a step, a start, a restart, a stop;
    doc/rulings.md R-bk-11): these routines, each a procedure without parameters, run from
    here one after the other, each in a new activation; when the last has ended (its end,
    RETURN, ExitCycle) the control comes back as it stood, the program pointer where it was.
    An error the system error handler takes, EXIT or Stop in one ends the task. The events
    are those of entering the first. *)

val in_event_routine : config -> bool
(** Whether the task runs an event routine: one of its sequence other than the entry routine
    (R-bk-8), or one interposed. *)

val interposed : config -> int
(** How many {!interpose}d sequences are running (their control not yet given back). *)

val step_rule : config -> Rule.t * event list
(** One reduction: the rule applied and what it made observable. Only valid while [outcome] is
    [Running]. *)

val step : config -> string * event list
(** [step_rule], with the rule's name ({!Rule.name}): the string the trace prints. *)

val outcome : config -> outcome

val host : config -> Host.t
(** The world around the run (its controller and motion), as the run was started with. *)

val trap_level : config -> bool
(** Whether the task executes at trap level (a trap, or a routine called from one; §7.2). *)

val steps : config -> int

(** {1 A view of the configuration, for the trace} *)

val focus_region : config -> Rapid_syntax.Source.region
val focus_kind : config -> string
(** "expression", "statement", "place", "value", "error", "next", ... *)

val stack_view : config -> string list
(** The kinds of the topmost continuation frames, top first (at most 8). *)

val depth : config -> int
(** Call depth: the number of active routines. *)

(** {2 The redex, for [rapid-sem trace]}

    What is in focus and what the topmost frame waits for, in the machine's terms. These are
    computed only when called: running never builds them. *)

type location
(** The storage of an entire data object, a component of a record or an element of an array. *)

type focus_view =
  | Statement of Ir.stmt                   (** a statement begins *)
  | Expression of Ir.expr                  (** an expression to evaluate *)
  | Place of Ir.place                      (** a reference being located *)
  | Location of location                   (** a located reference *)
  | Value of Value.t
  | Next                                   (** a statement, an argument or a list has completed *)
  | Error of { name : string; number : int; at : Rapid_syntax.Source.region }
  | Search of string option                (** the long jump looks at this routine (§7.2) *)
  | Abandon                                (** the current routine is left (UNDO first) *)
  | End

type argument_view =
  | Bound_value of Value.t                 (** an [in] parameter's copy *)
  | Bound_alias of location                (** a reference parameter's location *)
  | Absent_argument
  | Switch_argument
  | Not_bound                              (** not yet reached *)

type frame_view =
  | Binary_right of Arith.binary * Value.t (** the left operand's value; the right one in focus *)
  | Unary_operand of Arith.unary
  | And_right                              (** the left operand of AND is in focus *)
  | Or_right
  | Aggregate_member of Ir.aggregate_kind * Value.t array * int
      (** the members so far, and the index of the one in focus *)
  | Store of location * Ir.stmt option     (** the target; the assignment (None: routine data) *)
  | Assign_target of Ir.stmt option        (** the target with indexes is being located *)
  | Condition of Ir.stmt option            (** of this IF, compact IF or WHILE *)
  | For_bound of Ir.for_loop * Value.t list
      (** the bounds evaluated so far (FROM, then TO); the next one is in focus *)
  | For_body of Ir.for_loop                (** the body is running *)
  | While_body of Ir.expr                  (** the body is running; the condition *)
  | Test_value of Value.t option           (** the TEST expression's value once known *)
  | Return_value
  | Raise_value
  | Late_name                              (** the name of a late-bound call (§4.6) *)
  | Element_index of location * int * int * bool
      (** the array (or the row so far), the index in focus (from 0), the number of indexes,
          and whether the element is then read *)
  | Call_arguments of { callee : Ir.routine; call : Ir.call; arguments : argument_view array;
                        next : int }
  | Routine_end
  | Local_init of (int * Ir.init) list     (** routine data still to initialise *)
  | Other_frame of string                  (** a frame's kind, as in {!stack_view} *)

val focus_view : config -> focus_view
val frame_view : config -> frame_view
(** The topmost frame. *)

val location_value : location -> Value.t

type path_step = Observation.step = Index of int | Component_of of int
(** [Index] from 1, [Component_of] from 0. *)

val location_path : config -> location -> (Ir.slot * path_step list) option
(** Where a location is: a slot of the current activation or of the module data, and the path
    from that data object to it. Searches the store: for the trace only. *)

val place_value : config -> Ir.place -> Value.t option
(** The value of a place without index expressions ([None] for another place, or an absent
    parameter). *)

val slot_value : config -> Ir.slot -> Value.t option
val current_routine : config -> Ir.routine
val current_statement : config -> Ir.stmt option
(** The innermost statement in progress. *)

val program : config -> Ir.program

val computed_values : config -> (Rapid_syntax.Source.region * Value.t) list
(** The values computed so far within the innermost statement in progress, each with the
    region of the expression it is the value of (the statement as it stands). *)

val rule_names : string list
(** Every rule of the machine, as doc/semantics.md lists them: the names of the {!Rule.listed}
    rules of {!Rule.all}, in its order. *)

val module_data : config -> (string * string * Value.t) list
(** Each module data object of the task (and installed datum): its module, its name and its
    current value (--save). *)

(** {1 The debugger's views (doc/debugger.md)} *)

val pointer_statement : config -> Ir.stmt option
(** The statement the program pointer is at, when the machine stands before a statement of a
    statement list (not the simple statement of a compact IF, which is part of its IF). *)

val test_case : config -> int option
(** While a TEST compares its test values: the index (from 0) of the case whose value is in
    focus; the next step's rule, test-match, selects that case. For rapid-sem test's branch
    coverage (doc/testing.md). *)

val empty_loop_round : config -> bool
(** After a step of rule while-again or for-step: whether the loop's body has no statement
    (where a turn of several tasks ends, doc/rulings.md R-14-o). *)

val call_chain_view : config -> (Ir.routine * Rapid_syntax.Source.region) list
(** The active routines, innermost first, each with where it stands: the innermost at the
    focus, a caller at its call. *)

val read_data : config -> Ir.slot -> Value.t option
(** The value of a data object of the current routine ([Local]) or module data ([Global]);
    [None] for an absent optional parameter. *)

val write_data : config -> Ir.slot -> Value.t -> bool

(** {1 Backward execution (ch. 6)} *)

val backward : config -> (string, string) result
(** One statement backward, when the program pointer is at a statement (§6.1-§6.3): [Ok rule]
    with rule "backward-noop" (the pointer moved back over a label, assignment or CONNECT) or
    "backward-call" (a procedure call's BACKWARD handler is set to run: [step] runs it, and
    when it has ended, "backward-end", the pointer is at the call); [Error message] when
    backward execution is refused: nothing changed. *)

val backward_rule : config -> (Rule.t, string) result
(** [backward], with the rule as a constructor. *)

val backward_running : config -> bool
(** A BACKWARD handler is running: an error now goes to the system error handler
    ("raise-in-backward", §6.1). *)

val backward_rule_names : string list
(** The rules of backward execution (doc/semantics.md, "Backward execution"): the names of the
    {!Rule.backward} rules of {!Rule.all}. *)

val global_slot : config -> string -> Ir.slot option
(** The module data object (or installed data object) of that name, case-insensitively (§2.2). *)

(** {1 Several tasks (ch. 14)} *)

val wake_time : config -> float option
(** After a "wait-yield" step: the earliest time at which the wait can end by itself (a timed
    event, its deadline, its next poll); [None]: only another task can end it. *)

val waiting_for : config -> string option
(** What the task waits for, when a waiting instruction is in progress (for a deadlock's
    message). *)

val share_global : config -> int -> with_:config * int -> unit
(** Before the run: the module data object of global slot [i] becomes the one of slot [j] of the
    other task: a system-global persistent shared by both (ch. 14). *)
