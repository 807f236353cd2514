(** How a run ends (doc/semantics.md), in the words both engines give. *)

type t =
  | Running
  | Ended                                  (** end of the entry routine, RETURN in it, EXIT *)
  | Stopped of { name : string; number : int; at : Rapid_syntax.Source.region;
                 chain : string list; about : string option }
      (** the system error handler stopped the task: the error, where it occurred, the call
          chain at that point, innermost first, and the name the error is about (the unknown
          data object or routine of ERR_REFUNKDAT, ERR_REFUNKFUN, ERR_REFUNKPRC, the procedure
          name of ERR_CALLPROC, the function of ERR_FNCNORET), or what it is about (the index and
          the dimension of ERR_OUTOFBND, the retry limit of ERR_EXCRTYMAX) *)
  | Resource_exhausted of string * Rapid_syntax.Source.region option
      (** call depth beyond the limit, or RAPID data or the motion history beyond the memory
          budget, or virtual time beyond --max-time: the reason, and the place when one explains
          it (the declaration or the move beyond the budget; doc/observable.md, R-1.4-small2) *)
  | Unsupported of { name : string; reason : string; at : Rapid_syntax.Source.region }
      (** an installed routine rapid-sem does not model yet was called ([name] is the routine,
          [at] the call) *)
  | Deadlock of string                     (** a wait nothing can ever end (doc/controller.md) *)
  | Stuck of string                        (** no rule applies: a bug of rapid-sem *)

val index_outside : float -> int -> string
(** What ERR_OUTOFBND is about, in both engines' words: the index and the dimension it is
    outside of. *)

val retries_beyond : int -> string
(** What ERR_EXCRTYMAX is about: the retry limit (--retry-limit). *)

val not_modelled : string -> Rapid_syntax.Source.region -> t
(** [Unsupported] for a call of this installed routine at this place. *)

val unanswered : string -> string -> Rapid_syntax.Source.region -> t
(** A dialogue of the FlexPendant the scripted operator has no answer for (R-13-ui2): the
    routine, why, and the call. *)

val unsupported_text : string -> string
(** What the command line says of an [Unsupported] outcome's reason, after its place. *)

val unsupported_what : string -> string
(** The same without the hint of --stub-unmodelled (the debugger, rapid-sem test): "not
    modelled: ..." or, for a dialogue, "no answer from the operator: ...". *)

val time_limit : float -> t
(** The end of a run whose virtual time passed [--max-time] (this many seconds). *)

val motion_history_exhausted : string -> Rapid_syntax.Source.region -> t
(** The history --samples or rapid-sem motion keeps, beyond its budget at the move of this
    call (doc/motion.md): the motion's reason. *)
