(** Errors and error recovery (ch. 7; doc/semantics.md, "Errors" and "The user level"): what
    happens to an error in flight (its handler, the system error handler, propagation, the long
    jump's search for an error recovery point), leaving routines (UNDO handlers, abandoned
    activations), RaiseToUser (§7.3), and the asynchronous errors of the motion (§7.4, §7.6).
    A module of its own so that the rules of ch. 7 are in one place; it comes before the calls
    (RaiseToUser is an installed routine that needs it) and the statements, whose RAISE, RETRY,
    TRYNEXT and EXIT (ch. 4) use what is here. Each function answers the rule it applied. *)

open Configuration

(** {1 An error in flight (§7.1, §7.2)} *)

val raise_step : config -> err -> Rule.t * Event.t list
(** The error in focus in the current activation: its handler takes it (raise-handle), or the
    system error handler (raise-in-handler, raise-unhandled, raise-in-trap, raise-in-backward:
    §6.1), or it leaves the routine (raise-propagate, longjump-search-start). *)

val search_step : config -> err -> activation option -> Rule.t * Event.t list
(** One step of the long jump's search (§7.2): longjump-found, longjump-search, raise-propagate,
    raise-in-trap. *)

val abandon_step : config -> after_abandon -> Rule.t * Event.t list
(** Leaving the current activation (EXIT, propagation, long jump): undo-run, abandon,
    abandon-entry (§7.2, §1.2). *)

val leave_abandoned : config -> after_abandon -> Rule.t -> Rule.t -> Rule.t * Event.t list
(** The abandoned activation is popped: the first rule, or the second when it is the entry
    routine's (the task ends). *)

val handler_end : config -> Rule.t * Event.t list
(** The end of an error handler (§7.1): handler-end. *)

val stop : config -> err -> Rule.t -> Rule.t * Event.t list
(** The system error handler stops the task, reporting the error at the user level (§7.3). *)

val waits_left : config -> unit
(** The waits on the stack are abandoned (a move's path with it, doc/motion.md M-abandon). *)

(** {1 RETRY and TRYNEXT (§4.13, §4.14, §7.3)} *)

val statement_point : frame list -> frame list
(** "The statement that caused the error": an ELSEIF's is its IF statement's. *)

val resume_nostepin : config -> bool
(** In a handler at user level that RaiseToUser \Continue entered, RETRY and TRYNEXT go on in
    the NOSTEPIN routine (§7.3): that routine becomes current; true then. *)

(** {1 Asynchronous errors (§7.4, §7.6)} *)

val serve_async_error : config -> (Rule.t * Event.t list) option
(** An asynchronous error of the motion, raised while the program pointer waits: async-error,
    async-error-unhandled; [None] when there is none (or at trap level). *)

val kept_exit : config -> Ir.stmt -> (Rule.t * Event.t list) option
(** RETRY, TRYNEXT, RAISE, RETURN or EXIT in the handler of an asynchronous error with the
    program pointer kept elsewhere: async-retry-resume, async-trynext-resume, async-exit,
    async-handler-leave; [None] when the statement runs as in any handler. *)

(** {1 The user level (§7.3)} *)

val raise_to_user : config -> call_state -> Rule.t * Event.t list
(** RaiseToUser, with its arguments bound: raise-to-user-continue, raise-to-user-break-off,
    raise-to-user-no-user-level, raise-to-user-unhandled, raise-to-user-illegal,
    raise-to-user-misplaced. *)
