(** What a run makes observable, as both engines emit it, in order (doc/observable.md,
    doc/trace-format.md). The oracle writes them as JSON ({!Rapid_oracle}'s encoder). *)

(** An entry of the event log other than ErrWrite's line (§7.5; ABB's ErrLog and SkipWarn). *)
type log_entry =
  | Err_log of { id : int; kind : string; arguments : string list }
      (** ErrLog ErrorId [\W]|[\I] Argument1..Argument5: [kind] "error", "warning" (\W) or
         "information" (\I) *)
  | Skip_warning                                     (** SkipWarn (§7.5) *)

type t =
  | Output of string                       (** a line written by TPWrite *)
  | Erase                                  (** TPErase *)
  | Event_log of log_entry                 (** ErrLog and SkipWarn: the event log (§7.5) *)
  | Log of string                          (** ErrWrite and the like: the event log *)
  | Routine_entered of string
  | Routine_left of string
  | Error_raised of { name : string; number : int; at : Rapid_syntax.Source.region }
  | Error_handled of { name : string; routine : string }
  | Undo_run of string
  | Task_ended
  | Controller of Rapid_observable.Controller_observation.t
      (** a signal changed, an interrupt occurred or was discarded (doc/controller.md) *)
  | Trap_entered of { number : int; trap : string; time : float }
      (** an interrupt is served: its trap runs (ch. 8) *)
  | Trap_left of { trap : string; time : float }
  | Stubbed of { routine : string; at : Rapid_syntax.Source.region }
      (** --stub-unmodelled ran an unmodelled installed routine as a no-op: once per routine,
          at its first call *)
  | Motion of Rapid_observable.Motion_event.t
      (** a move planned, begun, ended; a path command (doc/motion.md, doc/trace-format.md) *)
  | Observed of Observation.t
      (** what schema rapid-sem/2 adds (doc/observable.md): errors propagated, RETRY, TRYNEXT,
          and with [~observe] store writes, arguments and returned values *)

val world_event : t -> bool
(** An event of the world (signal changes, interrupts, motion) rather than of the program: the
    two engines order each stream alike, but may interleave the two differently within a step
    (doc/semantics.md, "What is compared"). *)
