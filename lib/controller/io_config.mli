(** The I/O configuration of a run and what the outside world does to its inputs: the file of
    [rapid-sem run --io FILE] (doc/controller.md, "The stimulus file"), or the [EIO_SIGNAL]
    entries of a RobotWare EIO.cfg file, told apart by their content. *)

type signal_type = DI | DO | AI | AO | GI | GO

type signal = {
  name : string;
  kind : signal_type;
  initial : float;                  (** the value at time 0 *)
}

(** At [time] seconds of virtual time, the input [signal] takes [value]. *)
type stimulus = { time : float; signal : string; value : float }

type t = {
  signals : signal list;            (** in the order of the file *)
  stimuli : stimulus list;          (** in the order of the file *)
  collisions : float list;          (** [at TIME collision]: the robot collides (doc/motion.md) *)
}

val empty : t

val parse : file:string -> string -> (t, string) result
(** The text of a stimulus file or of an EIO.cfg file. An error is one line,
    [FILE:LINE:COL: io error: MESSAGE]. *)

val read_file : string -> (t, string) result

val type_name : signal_type -> string
(** The installed type of a signal of this kind: [signaldi] ... [signalgo] (§2.16). *)

val is_input : signal_type -> bool

val is_digital : signal_type -> bool
