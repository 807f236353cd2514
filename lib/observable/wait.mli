(** A wait of a waiting instruction (WaitTime, WaitDI, WaitUntil, a move until its ready time...),
    engine-neutral: the engine checks [satisfied] and the deadline at every step of the wait, lets
    interrupts in, and moves the clock on to the next event, the deadline or the next poll
    (doc/controller.md). *)

(** An execution error a wait ends with. *)
type raised = {
  error : string;                             (** its ERR_ name *)
  at_move : bool;
      (** a \SyncLastMoveInst error of the motion, raised at the move instruction the program
          pointer waits in: asynchronous, TRYNEXT in its handler executes as RETRY (§7.4) *)
}

val error : string -> raised option
(** An error that is not the motion's asynchronous one. *)

type t = {
  what : string;                              (** for the deadlock message *)
  satisfied : unit -> bool;                   (** unused when [poll] is set *)
  deadline : float option;                    (** absolute virtual time *)
  finish : timed_out:bool -> raised option;   (** at the end: an error to raise *)
  poll : float option;                        (** WaitUntil: the engine re-evaluates a condition *)
}

val default_poll_rate : float
(** WaitUntil's \PollRate when absent: 0.1 s (installed-facts.md section 4, UNCERTAIN). *)

val first_poll : t -> now:float -> float option -> float
(** When a wait begun [now] first evaluates its condition (WaitUntil, §4 of ABB's WaitUntil): one
    poll period on, or later when the motion gives a later time (\InPos: when the robot stands
    still, R-4.1-f). Both engines start their waits with it. *)
