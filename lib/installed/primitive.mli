(** The interface of the bodies of installed routines inside lib/installed: the context a body
    is given (the world of its task, where its events go) and what it returns. {!Registry}
    turns each body into an entry of the engines' {!Rapid_runtime.Installed_routine}. *)

type argument = Rapid_runtime.Argument.t =
  | Value of Rapid_runtime.Value.t                   (** an in parameter *)
  | Location of Rapid_runtime.Value.t array * int * Rapid_runtime.Ir.reference_kind
      (** an alias parameter: the container and index of the argument's location, and what it
          denotes (a variable, a persistent, ...) for IsVar and IsPers *)
  | Switch                                           (** a present switch *)
  | Missing                                          (** an absent optional parameter *)

(** An entry of the event log other than ErrWrite's line (§7.5; ABB's ErrLog and SkipWarn). *)
type log_entry = Rapid_runtime.Event.log_entry =
  | Err_log of { id : int; kind : string; arguments : string list }
      (** ErrLog ErrorId [\W]|[\I] Argument1..Argument5: [kind] "error", "warning" (\W) or
          "information" (\I) *)
  | Skip_warning                                     (** SkipWarn (§7.5) *)

type context = {
  output : string -> unit;                           (** a line on the FlexPendant (TPWrite) *)
  erase : unit -> unit;                              (** TPErase *)
  log : string -> unit;                              (** the event log (ErrWrite) *)
  event_log : log_entry -> unit;                     (** ErrLog, SkipWarn (§7.5) *)
  mutable book_error : unit -> int;                  (** BookErrNo: a new error number *)
  mutable error_number : string -> int;
  world : Rapid_controller.World.t;                  (** the controller around the run *)
  mutable parameters : string array;                 (** the routine's parameter names, in order *)
  mutable argument_label : string -> string option;
      (** the name of the data object given for a parameter (by the parameter's name), for the
          motion's output: [p10], [z10]; for any other expression its line, [line 12] *)
}

type outcome =
  | Returned of Rapid_runtime.Value.t option         (** a function's value, or a procedure's end *)
  | Failed of string                                 (** an execution error, by its ERR_ name *)
  | Call_by_name of string                           (** CallByVar: call this procedure (§4.6) *)
  | Stop_requested                                   (** Stop: the task stops *)
  | Exit_cycle_requested                             (** ExitCycle: the next cycle starts *)
  | Not_modelled                                     (** rapid-sem does not model this routine yet *)
  | Wait of Rapid_controller.World.wait              (** a waiting instruction: the engine waits *)
  | Retry_requested                                  (** StartMoveRetry: RETRY, as the statement (§7.1) *)
  | Assertion_failed of string                       (** an assertion of rapid-sem test failed *)
  | Unanswered of string                             (** no scripted answer for a dialogue (R-13-ui2) *)

val named_argument : context -> argument array -> string -> argument
(** The argument of the callee's parameter of this name ([context.parameters]), letter case
    aside (§2.3); [Missing] when there is none. *)

val named_present : context -> argument array -> string -> bool
val named_num : context -> argument array -> string -> float option
(** The num or dnum an argument holds, by value or by reference. *)

val named_store : context -> argument array -> string -> Value.t -> unit
(** Writes a reference argument; does nothing to one passed by value or absent. *)
