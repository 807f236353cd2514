(** What a run is asked for, as [rapid-sem run], [trace], [motion] and [debug] take it from the
    command line (doc/user-guide.md). The command line builds these records from its options and
    hands them over: how the world, the host and the engine are then put together is lib/run's
    ({!Run_setup}, {!Run_drive}), so that the command line knows options and output only, and
    the conformance suite, the fuzzer and the tests can assemble the same runs. *)

type services = {
  fs : string option;             (** --fs: the folder of the controller's mass memory *)
  fs_quota : int option;          (** --fs-quota: the bytes a run may write there *)
  net : string list;              (** --net: the addresses beyond the loopback sockets may reach *)
  map_address : string list;      (** --map-address: FROM=TO, read before the --net check *)
  egm_device : string list;       (** --egm-device: NAME=HOST:PORT, the UdpUc devices of EGM *)
  operator : string option;       (** --operator: the FlexPendant operator's script (R-13-ui2) *)
}
(** The services of the controller (doc/services.md). *)

type controller = {
  io : string option;             (** --io: a stimulus file or an EIO.cfg (doc/controller.md) *)
  statement_time : float;         (** --statement-time: the virtual time of a statement *)
  max_time : float;               (** --max-time: the virtual time a run may take *)
  epoch : float;                  (** --epoch: the wall-clock time at virtual time 0, in seconds *)
  services : services;
  robotware : Rapid_syntax.Robotware.t option;
      (** --robotware: the controller's RobotWare release, whose reserved words apply (R-2.4-rw6);
          [None]: a backup's backinfo.txt, else the manual's (7) *)
  units : string list;
      (** a backup's mechanical units (MOC.cfg), installed as mecunit data (R-bk-13); no option *)
}
(** The controller around the run. *)

type t = {
  max_steps : int;                (** --max-steps: the machine's steps, the closure engine's fuel *)
  allow_unknown : bool;           (** --allow-unknown *)
  stub_unmodelled : bool;         (** --stub-unmodelled *)
  limits : Limits.t;              (** --max-call-depth, --retry-limit, --max-memory *)
  controller : controller;
  robot : string option;          (** --robot: the robot description, default the IRB 120 *)
  base_frames : string list;
      (** each --base-frame [TASK=]X,Y,Z,Q1,Q2,Q3,Q4: where the cell mounts a robot (R-bk-12) *)
}
(** The options every run shares. *)

type tasks = {
  files : string list;            (** the module files of one task buffer (without --task) *)
  entries : string list;          (** each --entry: ROUTINE, or with --task TASK=ROUTINE *)
  tasks : string list;            (** each --task NAME=FILE[,FILE...] (ch. 14) *)
  schedule : int option;          (** --schedule SEED: turns in the order of SEED *)
  motion_task : string option;    (** --motion-task: the task that has the robot *)
}
(** What runs: one task buffer, or several tasks, as the command line names them. *)
