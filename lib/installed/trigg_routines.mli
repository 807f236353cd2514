(** The moves with triggers and the triggers they take (ABB's RAPID Instructions: TriggL,
    TriggJ, TriggC, TriggIO, TriggEquip, TriggInt, TriggSpeed; motion.sys, cell.sys).

    ABB defines a trigger once, in a triggdata variable (TriggIO stores its condition there),
    and lets every later TriggL, TriggJ or TriggC that names it act on it where the robot's TCP
    is on that move's path: so a trigger here is data kept with its variable, and becomes a
    timed event only when a Trigg move is planned, at the moment
    {!Rapid_motion_model.Planner.mark} gives for its position (doc/motion.md, law T-distance,
    rule M-trigg). The event is the world's ({!Rapid_controller.World.at}): its output changes,
    or its interrupt occurs through the task's interrupt queue, at that exact time, whatever the
    program pointer is doing, as MoveLDO's output does (ABB: such events do not depend on the
    program pointer). A StopMove holds it back with the robot, a ClearPath drops it with the
    path (doc/rulings.md R-4.1-trigg1 to R-4.1-trigg6).

    The Trigg moves are Motion_routines' MoveL, MoveJ and MoveC (ABB describes TriggL as a
    linear move with events): same planning, zones, speeds, \T, \Conc, tool and work object,
    errors. *)

val modelled : string -> bool

val claims : Rapid_controller.World.t -> string -> bool
(** The names this module answers, for the registry (in every task: a Trigg move in a task
    without the robot is ERR_NOT_MOVETASK, R-14-e). *)

val reach : string -> Installed_routine.reach
(** The moves reach the motion; the definitions the world (their signals and interrupts). *)

val call :
  standstill:(unit -> float) -> Primitive.context -> Motion_routines.state -> string -> Primitive.argument array ->
  (Primitive.outcome * Motion_routines.effects) option
(** The body of one of {!modelled}'s routines. Before a Trigg move is planned its TriggSpeed
    triggers are checked (ABB, TriggL: ERR_AO_LIM, ERR_DIPLAG_LIM); a definition's bad
    argument is its error (ERR_ARGVALERR, ERR_GO_LIM, ERR_AO_LIM, ERR_NO_ALIASIO_DEF,
    ERR_UNKINO), and \ProcID, which ABB keeps for its own process options, is not modelled. *)
