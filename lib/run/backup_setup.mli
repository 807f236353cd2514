(** A controller backup or a program file given where a run takes its files
    ([rapid-sem run|check|trace|debug|motion BACKUP_DIR] or [PROGRAM.pgf]; doc/user-guide.md,
    "Controller backups"): the backup read ({!Rapid_load.Backup}), each motion task's robot made
    from MOC.cfg's robot type and joint bounds, and what the user reads first about the cell. *)

module Backup = Rapid_load.Backup

type cell = {
  backup : Backup.t;
  robots : (string * Rapid_motion_model.Robot.t) list;   (** each motion task's robot *)
  stand_in : (string * string) list;
      (** the motion tasks whose robot is not their MOC.cfg type's, and why: "--robot", "not in the
          robot library", "no robot in MOC.cfg" *)
  warnings : string list;     (** the backup's, then the robots' (R-bk-5), FILE:LINE: warning: ... *)
}

type input =
  | Files of string list      (** module files: as given, or the modules a .pgf lists *)
  | Cell of cell              (** a backup *)

val input : robot:string option -> string list -> (input, string) result
(** The files of a run: one folder that is a backup is that backup; one [.pgf] file is its
    modules; anything else the files as they are. [robot] (--robot) is every motion task's
    arm instead of MOC.cfg's type (options override the backup), at MOC.cfg's base frame (the
    cell's, R-bk-12). *)

val narrow : Rapid_motion_model.Robot.t -> Backup.bound list -> Rapid_motion_model.Robot.t * string list
(** The description's axis ranges narrowed to the arms' joint bounds (radians), never widened; a
    bound that leaves nothing of a range keeps the range, with a warning (R-bk-5). *)

val base_frame : Backup.robot -> Rapid_motion_model.Geom.pose * string list
(** The robot's base frame in the world (mm, a unit quaternion: R-bk-12), with a warning at its
    FILE:LINE for an orientation that is not a unit quaternion (the world's orientation taken)
    or an origin beyond {!Rapid_motion_model.Base_frame.max_offset} (the world's origin taken). *)

val robot_of_type :
  Backup.robot -> ((Rapid_motion_model.Robot.t * string list) * bool, string) result
(** The robot of a MOC.cfg ROBOT: its type's description from the robot library, its axis ranges
    narrowed to the arms' joint bounds (radians), standing at its base frame ({!base_frame}); an
    unknown type is the default IRB 120 (at the base frame too), with a warning naming the type and
    its FILE:LINE (R-bk-5); [false] then. *)

type task_summary = {
  task : string;
  kind : string;              (** NORMAL, STATIC, SEMISTATIC *)
  entry : string;
  motion : bool;
  robot : string option;      (** a motion task's robot: its description's name *)
  robot_type : string option; (** MOC.cfg's -use_robot_type *)
  stand_in : string option;   (** why the robot is not that type's (then --robot's, or the default IRB 120) *)
  reads : string option;      (** a task without a robot: the motion task whose robot it reads *)
  modules : int;
  event_routines : (string * string) list;
      (** its event routines, in the order it runs them, each with its event (R-bk-8): the
          backup's; those the task runs once loaded ({!Run_drive}) *)
}

type summary = { dir : string; tasks : task_summary list; io : string option; signals : int; warned : int }
(** What the run of a backup was: its tasks, their entry routines, the robots, the I/O
    configuration used (its file and how many signals), how many warnings were given. *)

val summary : cell -> run:Task_load.spec list -> io:Rapid_controller.Io_config.t -> summary
(** The summary of the tasks that run (the backup's, as options changed them). *)
