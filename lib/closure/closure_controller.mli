(** What the closure engine ({!Closure_engine}) asks of the world around the program, through
    the run's {!Rapid_runtime.Host}, as the machine asks it. Nothing here knows the engine's
    activations: where the engine must act (serve an interrupt, evaluate WaitUntil's condition,
    raise an error) it is called back (doc/controller.md, doc/semantics.md "The second engine"). *)

val is_signal : Value.t -> bool
(** A handle of an I/O signal (signaldi, signaldo, ...): assigning to it sets the signal (§2.16). *)

(** How a wait ended. *)
type wait_end =
  | Finished of Rapid_observable.Wait.raised option   (** the wait is over; with an error to raise *)
  | Halted of Outcome.t                               (** a deadlock, or the time limit *)

val wait :
  ?yield:(wake:float option -> what:string -> pure:bool -> unit) -> Host.t -> Rapid_observable.Wait.t ->
  first_poll:float option -> condition:(unit -> bool) option -> serve:(unit -> bool) -> observe:(unit -> unit) ->
  spend:(unit -> unit) -> wait_end
(** A waiting instruction carried out (doc/controller.md): at each turn, [serve ()] lets an
    interrupt (or an asynchronous error) in, [true] when it ran a trap, and the turn is taken
    again; then the wait ends when [condition] (WaitUntil, at each poll) or the wait's own test
    holds, or at its deadline; otherwise the clock moves on to the next timed event, the deadline
    or the next poll, and [observe ()] passes on what happened meanwhile. With nothing to come,
    a deadlock. [first_poll]: the motion's time of WaitUntil \InPos's first evaluation.
    [spend ()] is called at each poll, each move of the clock and each yield, before it: the
    engine's unit of work, which may end the run (its fuel).

    [yield] (one of several tasks, ch. 14): instead of moving the clock or ending in a deadlock,
    the wait yields its turn ({!Closure_engine.cooperation}) and is taken again when the task's
    turn comes back. *)
