(** The I/O configuration of a run and what the outside world does to its inputs: the file of
    [rapid-sem run --io FILE] (doc/controller.md, "The stimulus file"), or the [EIO_SIGNAL]
    entries of a RobotWare EIO.cfg file, told apart by their content. *)

type signal_type = DI | DO | AI | AO | GI | GO

type signal = {
  name : string;
  kind : signal_type;
  initial : float;                  (** the value at time 0 *)
  line : int;                       (** where the file names it, so that the checker's errors about
                                        the name point there; 0 for a signal no file declares *)
  col : int;
}

(** At [time] seconds of virtual time, the input [signal] takes [value]. *)
type stimulus = { time : float; signal : string; value : float }

(** A system input (EIO.cfg's SYSSIG_IN, a stimulus file's [system-input] line): the digital input
    [input] starts the system action [action] (ABB's names: [LimitSpeed], [MotorOn], ...) while it
    is 1; [arg6] is the mechanical unit it acts on where the action takes one (LimitSpeed's
    -Arg6), [""] otherwise. *)
type system_input = { action : string; input : string; arg6 : string; si_line : int; si_col : int }

type t = {
  file : string;                    (** the file read; [""] for none *)
  signals : signal list;            (** in the order of the file *)
  stimuli : stimulus list;          (** in the order of the file *)
  collisions : float list;          (** [at TIME collision]: the robot collides (doc/motion.md) *)
  system_inputs : system_input list; (** in the order of the file; each names a configured DI *)
  mechanical_units : string list;
      (** the mechanical units a backup's MOC.cfg configures (R-bk-13): installed data objects of
          type mecunit, beside ROB_1 .. ROB_4; never read from an I/O file *)
  task_ids : string list;
      (** the program tasks of a run of several tasks, in order (R-14-taskid): each has its
          predefined taskid variable NAMEId in every task; never read from an I/O file *)
}

val empty : t

val parse : file:string -> string -> (t, string) result
(** The text of a stimulus file or of an EIO.cfg file. An error is one line,
    [FILE:LINE:COL: io error: MESSAGE]. Every number is decimal and within num's range (§2.13),
    and fits what it feeds: a digital value 0 or 1, a group value the group's bits (32, or an
    EIO.cfg's -DeviceMap), an analog value an EIO.cfg's -MinLog .. -MaxLog, a time not negative
    and in order (doc/controller.md; R-8-numbers1). A UTF-8 byte order mark first is skipped. *)

val read_file : string -> (t, string) result

val type_name : signal_type -> string
(** The installed type of a signal of this kind: [signaldi] ... [signalgo] (§2.16). *)

val is_input : signal_type -> bool

val is_digital : signal_type -> bool
