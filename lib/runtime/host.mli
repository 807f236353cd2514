(** The host: everything an engine may ask of the world around the program, and nothing else
    (doc/architecture.md). One host per task; lib/installed's {!Rapid_installed.World_host}
    makes it from the run's controller (virtual clock, signals, interrupts, services) and motion
    (the robot and its planner). Both engines reach the world only through it, so that the
    definition (lib/semantics) and the second engine (lib/closure) link neither. *)

type motion_error = { error : string; move : int option; handled : bool }
(** An asynchronous error of the motion to raise now in the routine of a move (ProcerrRecovery
    \SyncOrgMoveInst, a collision): its ERR_ name, the move the robot executed, and whether an
    error handler may take it (false: a collision while the program has switched Collision Error
    Handling off, §7.6). *)

type t = {
  routine : string -> Installed_routine.entry option;
      (** the installed routine of this name (letter case aside) that rapid-sem models; [None]
          for one it does not model yet *)

  book_error : unit -> int;
      (** BookErrNo: a new error number of the task, from 2001 on (R-4.11-b) *)
  booked : int -> bool;                          (** whether BookErrNo gave this number *)

  (* The virtual clock (doc/controller.md). *)
  now : unit -> float;
  max_time : float;                              (** --max-time, seconds *)
  reached : float -> bool;
      (** whether the clock has reached this time, at its resolution (a microsecond) *)
  statement : unit -> unit;                      (** the time of one statement passes *)
  statement_within : unit -> bool;
      (** [statement], then whether the clock is still within [max_time] *)
  statements : int -> unit;                      (** the time of this many statements passes *)
  statements_left : unit -> int;
      (** how many statements' time can pass with the clock within [max_time], with nothing
          scheduled: an engine may count them itself and charge them later *)
  next_event : unit -> float option;             (** when the next timed event is due *)
  advance_to : float -> unit;                    (** the clock moves on; the events due happen *)
  every_task_waits : string list -> unit;
      (** ch. 14: the scheduler says that every running task, these, waits, before the clock
          moves on (a socket wait then holds the clock, doc/rulings.md R-13-sockwait2) *)
  collisions : bool;
      (** the stimulus holds collisions: the motion may report at any time (doc/motion.md) *)

  (* Signals in value context and assigned (§2.16). *)
  read_signal : Value.t -> (Value.t, string) result;
      (** ERR_NO_ALIASIO_DEF when the handle is not connected to a configured signal *)
  write_signal : Value.t -> Value.t -> (unit, string) result;
      (** ERR_NO_ALIASIO_DEF (not connected), ERR_ARGVALERR (a digital signal set to neither 0
          nor 1); [Error ""] for a value that is not a num (excluded by the static semantics) *)

  (* Interrupts (ch. 8, §4.15). *)
  connect : trap:int -> (int, string) result;
      (** CONNECT: a new interrupt number bound to the trap (the engine's identity of the
          routine), or ERR_INOMAX *)
  connected : int -> bool;
  take_interrupt : unit -> (int * int) option;
      (** the first queued interrupt and its trap, when interrupts are enabled *)
  observations : unit -> Rapid_observable.Controller_observation.t list;
      (** what the controller observed since last asked, in order *)

  (* The motion (doc/motion.md). *)
  motion_events : unit -> Rapid_observable.Motion_event.t list;
      (** what the motion did since last asked: moves planned, begun, ended *)
  motion_finish : unit -> Rapid_observable.Motion_event.t list;
      (** at the end of the task: the rest of the motion the robot still does *)
  motion_error : unit -> motion_error option;
      (** an asynchronous error of the motion due now, once (§7.4, §7.6) *)
  set_backward : bool -> unit;
      (** a BACKWARD handler begins (true) or ends (false) its run (ch. 6) *)
  wait_abandoned : Rapid_observable.Wait.t -> unit;
      (** a wait an error or a long jump leaves (§7.2): a move instruction's move is cancelled
          and the rest of the path dropped *)
  prepare : Ir.program -> Ir.program;
      (** the installed data that depend on the robot (vmax's v_tcp), before the run *)
}
