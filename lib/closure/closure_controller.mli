(** What the closure engine ({!Closure_engine}) asks of the controller around the program, through
    the same interfaces as the machine: the run's {!Rapid_controller.World} (virtual clock,
    signals, interrupts) and its motion ({!Motion_routines}). Nothing here knows the engine's
    activations: where the engine must act (serve an interrupt, evaluate WaitUntil's condition,
    raise an error) it is called back (doc/controller.md, doc/semantics.md "The second engine"). *)

val time_limit : Rapid_controller.World.t -> Machine.outcome
(** The end of a run whose virtual time passed [--max-time], in the machine's words. *)

val is_signal : Value.t -> bool
(** A handle of an I/O signal (signaldi, signaldo, ...): assigning to it sets the signal (§2.16). *)

val read_signal : Rapid_controller.World.t -> Value.t -> (Value.t, string) result
(** §2.16: a signal in value context is its value; ERR_NO_ALIASIO_DEF when it is not connected to
    a configured signal. *)

val write_signal : Rapid_controller.World.t -> Value.t -> Value.t -> (unit, string) result
(** §2.16: an assignment to an output signal sets it: ERR_NO_ALIASIO_DEF (not connected),
    ERR_ARGVALERR (a digital signal set to neither 0 nor 1). [Error ""] for a value that is not a
    num (excluded by the static semantics). *)

val argument_label : Ir.program -> Ir.routine -> Ir.argument array -> string -> string option
(** The data object an argument of an installed routine names, for the motion's output ([p10],
    [z10]), or [line N] for another expression; by parameter name. *)

(** How a wait ended. *)
type wait_end =
  | Finished of string option   (** the wait is over; with an error (ERR_ name) to raise *)
  | Halted of Machine.outcome    (** a deadlock, or the time limit *)

val wait :
  ?yield:(wake:float option -> what:string -> pure:bool -> unit) -> Rapid_controller.World.t -> Rapid_controller.World.wait -> first_poll:float option ->
  condition:(unit -> bool) option -> serve:(unit -> bool) -> observe:(unit -> unit) -> spend:(unit -> unit) ->
  wait_end
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
