(** Calls and routines (§3.11, §4.6, ch. 5; doc/semantics.md, "Calls"): a call's arguments bound
    to the parameters one by one, a RAPID routine entered (a new activation) and left, an
    installed routine run through the host (with what it answers: a value, an error, a wait, a
    stop, a call by name, not modelled), late binding, and routine data initialised at each
    call. A module of its own so that the rules of calls are in one place; the statements and
    expressions that make calls, and settling, use it. Each step function answers the rule it
    applied. *)

open Configuration

val routines_named : (string, int list) Hashtbl.t * (string, int list) Hashtbl.t -> string -> int list option
(** The routines of a lower-case name in a program's table ([by_name] of {!Configuration}), in
    increasing order; [None] when none has it. *)

(** {1 Starting and ending calls} *)

val begin_call : config -> Ir.call -> Rule.t
(** A call starts evaluating its arguments (call-arguments), or names no routine
    (call-unknown). *)

val next_argument : config -> call_state -> frame list -> Rule.t * Event.t list
(** The call waits for a reference argument (argument-reference, argument-alias), an argument
    that cannot be bound quietly (argument-pass-on-duplicate, memory-exhausted), or, every
    argument bound, the call itself: call-enter (call-depth-exceeded, memory-exhausted) for a
    RAPID routine, an installed routine's rule (call-primitive, wait-start, ...) else. The
    frame list is the stack below the call's frame. *)

val return_from : config -> Value.t option -> Rule.t * Event.t list
(** RETURN, or the end of a procedure or trap (§4.10, ch. 8): return-procedure,
    return-function, return-entry, trap-end. *)

val routine_end : config -> Rule.t * Event.t list
(** The end of a routine's body: function-no-return (§5.5), or as [return_from]. *)

val exec_ref : (config -> Ir.stmt -> Rule.t * Event.t list) ref
(** [Statements.exec], set there: StartMoveRetry runs the RETRY statement (R-7.6-b), and the
    statements come after the calls. *)

(** {1 The frames of calls} *)

val bind_alias : config -> call_state -> frame list -> loc -> Rule.t * Event.t list
(** A reference argument located: argument-alias, or argument-alias-refused (§5.2). *)

val local_init : config -> activation -> (int * Ir.init) list -> frame list -> Rule.t * Event.t list
(** Routine data still to initialise: local-initial-value, or memory-exhausted. *)

val late_name : config -> Ir.late_argument array -> Rapid_syntax.Source.region -> frame list -> Value.t ->
  Rule.t * Event.t list
(** The name of a late-bound call has its value (§4.6): call-late-unknown, call-late-mismatch,
    or the call begins. *)

val fit : config -> Value.shape -> frame list -> Value.t -> Rule.t * Event.t list
(** An aggregate argument of a late-bound call takes its parameter's type (§3.10): argument-fit,
    argument-fit-refused. *)

val copy_exhausted : config -> call_state -> frame list -> Rule.t * Event.t list
(** An in argument's copy the memory budget does not hold: memory-exhausted. *)

(** {1 For settling and the statements} *)

val args_room : config -> call_state -> int
(** The bytes the memory budget still holds for the arguments of a call in progress. *)

val bind_value : config -> call_state -> Value.t -> bool
(** An in argument's value bound to its parameter (a copy, §5.2); false when the budget does not
    hold it. *)

val settle_arguments : config -> call_state -> unit
(** The arguments that need no step of their own are bound (§5.2): absent ones, switches,
    conditional arguments, literals. *)

val reference_kind : config -> Ir.place -> Ir.reference_kind -> Ir.reference_kind
(** The binding an alias argument has: a parameter passes on its own (§5.2). *)

val denotes_module_data : config -> Ir.place -> bool
(** The place denotes module data, seen through the parameters it goes through (§4.15). *)
