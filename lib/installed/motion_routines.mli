(** The installed routines of motion (lib/typing/installed/motion.sys; ABB's RAPID Instructions,
    Functions and Data types) as primitives of both engines: the moves hand their segments to the
    run's planner ({!Rapid_motion_model.Planner}) and the program pointer waits, on the virtual
    clock and open to interrupts, until the planner's ready time; the position functions read the
    robot where it is at the current virtual time (doc/motion.md, "Moves in the machine"). *)

type state
(** The motion of one run: the robot, its planner, the active tool and work object. *)

val create : ?robot:Rapid_motion_model.Robot.t -> ?history:int -> unit -> state
(** The robot (default the IRB 120) standing at axis angles 0 from time 0. Without [history] the
    planner forgets what the run no longer needs (doc/motion.md, "Memory"): its memory does not
    grow with the moves made, and the planner answers for the present and the future only. With
    [history] (a budget in bytes, --max-memory's) the whole path is kept, for samples and
    drawings, each move counting {!history_bytes}; the move beyond the budget raises
    {!History_exhausted}. *)

exception History_exhausted of string
(** The motion history goes beyond its budget: the message says so; the engine ends the run as a
    resource exhausted (§1.4). *)

val history_bytes : int

val robot_data : state -> Ir.program -> Ir.program
(** The installed data that depend on the robot: vmax's v_tcp is its maximum TCP speed. *)

val planner : state -> Rapid_motion_model.Planner.t
val robot : state -> Rapid_motion_model.Robot.t

type effects = {
  at_move : bool;
      (** the failure is a \SyncLastMoveInst error (§7.4): its handler's TRYNEXT executes as
          RETRY *)
  new_move : int option;
      (** the move the call planned: the engine records which routine activation executed it,
          to raise its asynchronous errors there (§7.4, §7.6) *)
  first_poll : float option;
      (** WaitUntil \InPos: the time of the first evaluation of the condition, when the robot
          moves *)
}

val call :
  Primitive.context -> state -> string -> Primitive.argument array -> (Primitive.outcome * effects) option
(** [None]: not a routine of motion (WaitTime and WaitUntil without \InPos included). The
    effects are those of this call. TriggL, TriggJ and TriggC are answered as the moves MoveL,
    MoveJ and MoveC with their arguments (ABB: the same moves, with events), for
    {!Trigg_routines}, which claims them and adds their triggers. *)

val modelled : string -> bool

val drain : state -> Rapid_controller.World.t -> Rapid_observable.Motion_event.t list
(** What happened since the last call: moves planned, moves the clock has seen begin and end;
    outputs of MoveLDO/MoveJDO are scheduled in the world once their point's time is known. *)

val finish : state -> Rapid_observable.Motion_event.t list
(** At the end of the task: the rest of the motion the robot still does, with its times. *)

val connect_robots : state -> (string * state) list -> unit
(** The motion tasks of the run by name, with their states, for the position functions of this
    task's state (CJointT, CRobT and CPos, \TaskName and \TaskRef, and a task without a robot:
    doc/rulings.md R-14-pos1). Without it (one task), a task reads its own robot. *)

val set_backward : state -> bool -> unit
(** A BACKWARD handler begins (true) or ends (false) its run (ch. 6): its move instructions
    retrace the forward moves, the newest first (§6.3). *)

val retracing : state -> bool
(** A BACKWARD handler runs: a Trigg move retraces a forward path, and sets no trigger. *)

(** {1 For the modules of bodies built on the motion (lib/installed/trigg_routines.ml)} *)

type extension = ..
(** What such a module keeps for the run beside the motion (the trigger data TriggIO defines). *)

val extensions : state -> extension list
val add_extension : state -> extension -> unit

val on_drain : state -> (Rapid_controller.World.t -> unit) -> unit
(** [f] runs at each {!drain}, first: a trigger held up by StopMove is set again when the path
    goes on. *)

val take_org_error : state -> (string * int option * bool) option
(** An asynchronous error to raise now in the routine of a move (ProcerrRecovery
    \SyncOrgMoveInst, a collision): its ERR_ name, the move the robot executed, and whether an
    error handler may take it (false: a collision while the program has switched Collision Error
    Handling off, §7.6), once. Errors of \SyncLastMoveInst are raised by the move instructions
    themselves. *)

val wait_abandoned : state -> Rapid_controller.World.wait -> now:float -> unit
(** A wait an error or a long jump leaves (§7.2): if it is a move instruction's, the move is
    cancelled and the rest of the path dropped (ClearPath); any other wait is no concern. *)

val move_waits_in_progress : state -> int
(** How many move instructions the program pointer waits in (a trap's move above the main one's
    makes two); 0 when the task has ended. *)

(** {1 For Externally Guided Motion (lib/installed/egm_routines.ml)} *)

val axes_now : state -> now:float -> float array
(** The arm's six axis angles (degrees) at this time, as CJointT reads them. *)

val servo : Primitive.context -> state -> float array -> duration:float -> (unit, string) result
(** The arm goes from where it is now to these axis angles in [duration] seconds and stops
    there (one EGM cycle); [Error] with the ERR_ name a move would raise (ERR_ROBLIMIT beyond an
    axis's range), its reason in the event log. *)
