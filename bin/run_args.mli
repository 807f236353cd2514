(** The options of the commands that run a task ([run], [trace], [motion], [debug]) and of those
    that read the same files ([check], [verdict]), as cmdliner terms, and the
    {!Rapid_run.Run_options} they make. Each command composes the terms in its own order (which
    is the order a command line with several bad options is refused in). *)

open Cmdliner

val count : what:string -> int Arg.conv
(** A count: a whole number from 0 to the largest integer; a negative one is refused as a usage
    error (exit status 2) that says so, [what] naming the option. *)

val io_arg : string option Term.t
(** --io FILE *)

val robotware_arg : Rapid_syntax.Robotware.t option Term.t
(** --robotware 5|6|7 (doc/dialect.md, R-2.4-rw6). *)

val controller_args : Rapid_run.Run_options.controller Term.t
(** --io, --statement-time, --max-time, --epoch and the services' options (doc/controller.md,
    doc/services.md). *)

val robot_arg : string option Term.t
(** --robot FILE (doc/motion.md) *)

val base_frame_arg : string list Term.t
(** each --base-frame [TASK=]X,Y,Z,Q1,Q2,Q3,Q4 (doc/rulings.md R-bk-12) *)

val robot_and_base_frames : (string option * string list) Term.t
(** --robot and --base-frame, as the commands that run a task take them *)

val samples_arg : float option Term.t
(** --samples HZ *)

val common_run_args :
  string list Term.t * string Term.t * int Term.t * (bool * bool) Term.t * int Term.t * (int * int) Term.t
(** The files of one task buffer, --entry, --max-steps, (--allow-unknown, --stub-unmodelled),
    --max-call-depth, (--retry-limit, --max-memory). *)

val tasks_args : Rapid_run.Run_options.tasks Term.t
(** FILE, --entry [TASK=]ROUTINE, --task, --schedule and --motion-task, as run and trace take
    them. *)

val options :
  ?base_frames:string list -> max_steps:int -> allow_unknown:bool * bool -> max_depth:int -> retry_limit:int * int ->
  controller:Rapid_run.Run_options.controller -> robot:string option -> unit -> Rapid_run.Run_options.t
(** The options of a run, from the values of the terms above. *)
