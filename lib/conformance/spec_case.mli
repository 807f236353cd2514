(** A case of the conformance suite (spec/README.md): one RAPID file, or a folder [NAME.task]
    whose files are the modules of one task buffer, and the directives written in its comments. *)

type expectation =
  | Accepted                                       (** [! @expect ok] *)
  | Refused of { error_class : string; file : string option; line : int; col : int }
      (** [! @expect lexical-error 4:10], [! @expect semantic-error b.mod:4:10]: the class as
          spelled in the directive; the file (its base name) in a multi-module case *)

type t = {
  path : string;                  (** the file, or the [.task] folder *)
  files : string list;            (** the modules, in name order *)
  sections : string list;         (** [! @section 2.5], in order *)
  expectation : expectation option;
  strict : bool;                  (** [! @options strict] *)
  robotware : Rapid_syntax.Robotware.t;
      (** [! @options robotware-6]: read as RobotWare 5 and 6 read modules (R-2.4-rw6) *)
  allow_unknown : bool;           (** [! @options allow-unknown]: unknown names are warnings *)
  stub_unmodelled : bool;
      (** [! @options stub-unmodelled] (format 3): installed routines rapid-sem does not model
          run as no-ops (rapid-sem run --stub-unmodelled) *)
  description : string option;
  problems : string list;         (** malformed or conflicting directives *)
  format : string;                (** [! @format N]; "1" when absent *)
  run : run option;               (** format 3: what running the case must do *)
}

(** Format 3: the case is run after the static semantics accepts it. *)
and run = {
  entry : string;                 (** [! @entry NAME]; main by default *)
  outputs : string list;          (** [! @output TEXT], in order: the whole output *)
  exit_status : int;              (** [! @exit N]; 0 by default *)
  error : (string * int * int) option;
      (** [! @error NAME LINE:COL]: with [@exit 1] the error and the statement where it
          occurred; with [@exit 4] the installed routine rapid-sem does not model and its call *)
  error_file : string option;     (** [! @error NAME FILE:LINE:COL] in a [.task] case *)
  max_steps : int option;         (** [! @max-steps N] *)
  retry_limit : int option;       (** [! @retry-limit N] *)
  io : string option;             (** [! @io FILE]: the stimulus file, beside the case *)
  statement_time : float option;  (** [! @statement-time SECONDS] *)
  max_time : float option;        (** [! @max-time SECONDS] *)
  home : string option;           (** [! @home FOLDER]: what HOME: holds at the start *)
  tasks : (string * string list) list;
      (** format 4: [! @task NAME] in each file of a [.task] folder: the tasks, in the order of
          their first file, each with its files; empty: one task of every file *)
  schedule : int option;          (** format 4, [! @schedule SEED]: rapid-sem run --schedule *)
  motion_task : string option;    (** format 4, [! @motion-task NAME] *)
  task_entries : (string * string) list;
      (** format 4, [! @entry TASK=ROUTINE]: that task's entry routine (the others: [entry]) *)
  robot : string option;          (** [! @robot FILE]: the robot description (rapid-sem run --robot), beside the case *)
  egm_devices : string list;      (** [! @egm-device NAME=HOST:PORT]: UdpUc devices of EGM (--egm-device) *)
  base_frames : string list;
      (** each [! @base-frame [TASK=]X,Y,Z,Q1,Q2,Q3,Q4]: where the cell mounts a robot (--base-frame, R-bk-12) *)
  operator : string option;
      (** [! @operator FILE]: the FlexPendant operator's script beside the case (--operator, R-13-ui2) *)
}

val read : string -> t
(** Reads the directives of the case at this path (a file, or a [.task] folder). A case that
    cannot be read has a problem. *)

val readable_file : string -> (unit, string) result
(** [Ok ()] for a regular file; otherwise why it is not read: a FIFO, a device, a folder, a file
    that cannot be looked at. *)

val known_formats : string list
(** The formats this runner reads: ["1"] (the front end), ["2"] (the static semantics too),
    ["3"] (running the program too) and ["4"] (several tasks, [@task]). *)

val checks_semantics : t -> bool
(** Formats 2 and 3: the case is also checked by the static semantics. *)

val error_classes : string list
(** The classes an [@expect] may name. *)

val expectation_to_string : expectation -> string
