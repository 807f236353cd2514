(** A controller backup read as the controller reads it at start (doc/user-guide.md, "Controller
    backups"; doc/rulings.md R-bk-1 to R-bk-10): the folder a controller or RobotStudio writes,
    [BACKINFO/backinfo.txt] (which task folder is which task, and its modules in load order),
    [SYSPAR/SYS.cfg] (the tasks: [CAB_TASKS], [MECHANICAL_UNIT_GROUP]), [SYSPAR/MOC.cfg] (the
    robots: [ROBOT -use_robot_type], their base frames, the arms' joint bounds), [SYSPAR/EIO.cfg] (the signals),
    [RAPID/TASKn/PROGMOD] and [SYSMOD] (the modules, [.mod], [.modx], [.sys], [.sysx]), [HOME/].
    Also a program file [.pgf] (an XML list of modules). Only what the backup says is gathered
    here; the robots themselves are made in lib/run, which knows the motion model. *)

type kind = Normal | Static | Semistatic

type event_routine = {
  routine : string;            (** CAB_EXEC_HOOKS' -Routine *)
  event : string;              (** its -Shelf: POWER_ON, START, RESTART, STOP, QSTOP, RESET, STEP *)
  hook_at : string;            (** FILE:LINE of its instance *)
}
(** An event routine (SYS.cfg, CAB_EXEC_HOOKS; doc/rulings.md R-bk-8). *)

type task = {
  name : string;               (** the task's name (SYS.cfg, backinfo.txt) *)
  folder : string;             (** its folder, RAPID/TASKn *)
  kind : kind;                 (** -Type *)
  motion : bool;               (** -MotionTask *)
  group : string option;       (** -UseMechanicalUnitGroup *)
  entry : string;              (** -Entry, else main *)
  files : string list;         (** its modules, in the order backinfo.txt gives (R-bk-2) *)
  at : string;                 (** FILE:LINE of its CAB_TASKS instance *)
  before : event_routine list;
      (** the event routines a run makes the task run before its entry routine, in order:
          POWER_ON's, then in a NORMAL task RESET's and START's (R-bk-8) *)
  after : event_routine list;  (** those it runs once the entry routine returned: a NORMAL task's STOP *)
  debug_events : event_routine list;
      (** a NORMAL task's START, RESTART, STEP and STOP routines, which rapid-sem debug's
          commands make happen (R-bk-11) *)
}

type bound = { axis : int; lower : float; upper : float; bound_at : string }
(** An arm's -lower_joint_bound and -upper_joint_bound, radians (or metres for a linear axis). *)

type base_frame = {
  pos : float * float * float;                 (** -base_frame_pos_x, _y, _z: metres, 0 when not given *)
  orient : float * float * float * float;
      (** -base_frame_orient_u0 .. _u3: the quaternion q1 .. q4 as written (not yet normalised), 1, 0, 0, 0
          when not given *)
  coordinated : string option;                 (** -base_frame_coordinated: the unit that moves it *)
  base_at : string;                            (** FILE:LINE of its first attribute, else of the ROBOT *)
}
(** A robot's base frame in the world frame (doc/rulings.md R-bk-12): where the cell mounts the
    arm. A value that is not a number was a warning, and the world frame's value is taken. *)

type track = {
  track_unit : string;         (** the MECHANICAL_UNIT that moves the robot's base frame *)
  travel : float * float;      (** its arm's -lower_joint_bound, -upper_joint_bound: metres *)
  track_orient : float * float * float * float;
      (** its SINGLE's base frame orientation, u0 .. u3 as written: the track moves along its x axis *)
  track_at : string;           (** FILE:LINE of the SINGLE *)
}
(** A track carrying a robot (doc/rulings.md R-bk-15). *)

type robot = {
  robot_name : string;         (** MOC.cfg's ROBOT -name, ROB_1 *)
  robot_type : string;         (** -use_robot_type, ROB1_2400_1.5_10; [""] when not given *)
  bounds : bound list;         (** the arms of its joints, axis 1 first *)
  robot_at : string;           (** FILE:LINE of its ROBOT instance *)
  base_frame : base_frame;
  track : track option;        (** the track its -base_frame_coordinated names, when it is one *)
}

type t = {
  dir : string;
  tasks : task list;                     (** the tasks to run, in the order of their folders *)
  robots : (string * robot) list;        (** each motion task's robot, by the task's name *)
  connected : (string * string) list;    (** a task without a robot and the motion task of its group *)
  eio : string option;                   (** SYSPAR/EIO.cfg when there is one *)
  retry_limit : int option;              (** SYS.cfg SYS_MISC NoOfRetry *)
  robotware : Rapid_syntax.Robotware.t option;
      (** backinfo.txt's "RobotWare Version:" (R-2.4-rw6) *)
  units : string list;
      (** MOC.cfg's MECHANICAL_UNIT names, in its order: mecunit data of every task (R-bk-13) *)
  warnings : string list;                (** what is not modelled: FILE:LINE: warning: ... (R-bk-7) *)
}

val is_backup : string -> bool
(** A folder that holds RAPID/, SYSPAR/ or BACKINFO/backinfo.txt. *)

val read : string -> (t, string) result
(** The backup in this folder. An error is one line with FILE:LINE:COL: a malformed cfg file
    ({!Cfg_file}), a task SYS.cfg names twice, a backup with no task to run. *)

val robotware_of_backinfo : string -> Rapid_syntax.Robotware.t option
(** The release of this backinfo.txt's "RobotWare Version:" line (R-2.4-rw6); [None] when the
    file cannot be read or names none. *)

val read_pgf : string -> (string list, string) result
(** The module files a program file lists, as paths beside it, in its order. *)

val kind_name : kind -> string
(** NORMAL, STATIC, SEMISTATIC. *)
