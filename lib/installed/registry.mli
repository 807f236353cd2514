(** Every installed routine rapid-sem models, by name, behind one look-up (ch. 11, 13): the
    bodies of {!Basic_routines}, {!Io_routines}, {!Service_routines}, {!Task_routines} and
    {!Motion_routines}, as entries of {!Rapid_runtime.Installed_routine} that an engine calls
    without knowing which module holds them. One registry per task: its entries act on the
    task's world and motion. *)

type t

val create : Rapid_controller.World.t -> Motion_routines.state -> t

val find : t -> string -> Installed_routine.entry option
(** The entry of the routine of this name (letter case aside, §2.3), made once; [None] when
    rapid-sem does not model it yet. *)
