(** The installed routines of several tasks (ch. 14; doc/semantics.md, "Several tasks"):
    GetTaskName, WaitSyncTask, SyncMoveOn, SyncMoveOff, SyncMoveUndo, IsSyncMoveOn, and
    ERR_NOT_MOVETASK for a motion instruction in a task that is not the motion task
    (doc/rulings.md R-14-d to R-14-f, R-14-m). *)

val call :
  ?standstill:(unit -> float) -> Primitive.context -> string -> Primitive.argument array ->
  Primitive.outcome option
(** [None]: not one of these routines (and not refused here). [standstill]: when the task's
    robot stands still (WaitSyncTask \InPos). *)

val modelled : string -> bool

val motion_instructions : string list
