(** The store, and the moves every part of the machine makes on a configuration: reading and
    writing locations, locating a place without index, making and raising errors, making
    activations and charging the memory budget, and reading numbers and booleans off values.
    A module of its own because every chapter's rules use them: Recovery, Calls, Waits,
    Statements and Backward all come after it. *)

open Configuration

(** {1 Locations} *)

val fresh_loc : Value.t -> loc
val get : loc -> Value.t
val set : loc -> Value.t -> unit
(** A copy of the value is stored. *)

val no_loc : loc
(** The answer of [static_loc] for a place it cannot locate, compared by identity ([==]). *)

val static_loc : config -> Ir.place -> loc
(** A place without an index expression (a data object, or a component of one), located in one
    step: its path is part of the program's text. [no_loc] for an absent optional parameter
    (§5.2) and for a place with indexes, which take steps of their own. *)

val observed_store : config -> loc -> Value.t -> Event.t list
(** Schema rapid-sem/2: the store write as RAPID names it, when the run observes; [] else. *)

val push : config -> frame -> unit

(** {1 Errors} *)

val error_number : config -> string -> int
val call_chain : activation -> string list
(** The routines from this activation up, innermost first. *)

val error : ?about:string -> config -> string -> Rapid_syntax.Source.region -> err
(** The error of that name (an ERR_ constant) at that place; its call chain computed only when
    the system error handler reports it. *)

val error_of_number : config -> int -> Rapid_syntax.Source.region -> err
(** The error of that number: named by its ERR_ constant, or by the number (a user error). *)

val region_of_focus_stmt : config -> Rapid_syntax.Source.region
(** The innermost statement in progress, or the routine. *)

val initialising : config -> activation -> bool
(** The routine's data are being initialised (R-7.1-w: its body has not started). *)

val raise_ : ?about:string -> config -> string -> unit
(** The error of that name is in flight, at the innermost statement in progress. *)

val set_errno : config -> int -> unit

(** {1 Activations and the memory budget} *)

val has_recovery_point : activation -> bool
(** The routine's error handler has an error recovery point (§7.2). *)

val activation :
  routine:Ir.routine -> slots:loc array -> present:bool array -> kinds:Ir.reference_kind array ->
  module_data:bool array -> caller:activation option -> return_to:frame list -> caller_mark:frame list ->
  activation

val memory_exhausted : config -> string -> Rapid_syntax.Source.region -> Outcome.t

val charge : config -> activation -> int -> bool
(** Charges bytes of RAPID data to the activation; false when the budget does not hold them. *)

val release : config -> activation -> unit
(** Gives back the activation's bytes, and those of the NOSTEPIN routines a handler at user
    level could have gone on in (R-7.3-p). *)

val next_phase : config -> Ir.routine option
(** The routine at the bottom of the stack has ended and the task's sequence (a controller
    backup's event routines and the entry routine, doc/rulings.md R-bk-8) has another: it is
    made current, in a new activation at its first statement; [None] when none follows. *)

val resume : config -> bool
(** The last routine of a sequence the debugger interposed has ended: the control it found comes
    back (R-bk-11); [false] when none was interposed. *)

(** {1 Values the rules read} *)

val bool_of : Value.t -> bool option
val num_of : Value.t -> float option
val to_int : float -> int option
(** A whole number of any size is an integer (R-3.6), clamped beyond OCaml's ints. *)

val frame_kind : frame -> string
(** The kind of a frame, as the trace ({!Machine.stack_view}) and the stuck messages name it. *)
