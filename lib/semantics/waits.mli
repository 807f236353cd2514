(** Interrupts, time and waits (ch. 8; doc/semantics.md, "The controller", and
    doc/controller.md): an interrupt served at a point of response (its trap runs as a routine
    called from there, at trap level), the time limit, and a waiting instruction one step at a
    time (its end, its timeout, WaitUntil's polls, the clock moved on, a deadlock, and with
    several tasks the yield to the scheduler). A module of its own so that the rules of ch. 8
    are in one place; the statements' points of response and settling use it. Each step
    function answers the rule it applied. *)

open Configuration

val serve_interrupt : config -> (Rule.t * Event.t list) option
(** At a point of response, not at trap level: the first queued interrupt (or the one settling
    held) is served, interrupt-serve; [None] when there is none. *)

val interrupt_taken : config -> bool
(** For settling, at a point of response: an interrupt is to be served (taken from the queue and
    held for [serve_interrupt]). *)

val time_exhausted : config -> Rule.t -> Rule.t * Event.t list
(** The virtual time is beyond --max-time: the run ends, with that rule. *)

val wait_step : config -> wait_state -> frame list -> Rule.t * Event.t list
(** One step of a wait (the frame list is the stack below its frame): interrupt-serve,
    async-error (§7.4), wait-poll, wait-done, wait-timeout, wait-yield (ch. 14), wait-deadlock,
    wait-time-limit, wait-advance. *)

val poll_value : config -> wait_state -> frame list -> Value.t -> Rule.t * Event.t list
(** WaitUntil's condition has its value at a poll: wait-poll-true, wait-poll-false. *)
