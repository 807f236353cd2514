(** What the controller makes observable (doc/controller.md), each with its virtual time
    (seconds). *)

type t =
  | Signal_changed of { time : float; signal : string; value : float }
  | Interrupt_occurred of { time : float; number : int }
      (** the interrupt is queued for its trap (ch. 8) *)
  | Interrupt_discarded of { time : float; number : int; reason : string }
      (** sleeping (ISleep), deleted, or the queue was full *)
