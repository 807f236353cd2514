(** A run set up from its options ({!Run_options}): the stimulus and the robot read, the world of
    the controller made (signals, clock, services) with the motion around it, the task buffer or
    the tasks loaded in it, and the engine started; both engines run in the same world. What the
    command line used to assemble itself, here so that each command only says what it prints.

    Nothing is printed here: what a person should be told on the way comes out as a {!notice},
    in the order it happens, and what stops the run as a {!failure}; the command line writes
    them. *)

(** {1 What happens on the way} *)

type notice =
  | Inferred_signal of Rapid_controller.Io_config.signal * Rapid_syntax.Source.region
      (** R-13-aa: under --allow-unknown --stub-unmodelled, an undeclared name the program passes
          as a signal became a virtual signal at 0; the region of its first use *)
  | Warnings of Rapid_typing.Report.t list * string option
      (** the warnings of the static semantics and the summary of the unknown names (one task
          buffer), or the warnings of every task (several) *)
  | Stdin_not_saved
      (** --save with a module read from standard input: it has no file to write back to *)
  | Samples_capped of int
      (** --samples wrote the most samples a run writes ({!Tcp_samples.max_samples}); the rest
          are left out *)
  | Backup_warning of string
      (** what a controller backup holds that the run does not model, FILE:LINE: warning: ...
          (R-bk-7), each once, before anything runs *)

type failure =
  | Usage of string
      (** an option that cannot be used as given, or a file it names that cannot be read: the
          whole message, one line (exit status 2) *)
  | Refused of Rapid_load.Session.failure         (** the task buffer is refused before it runs *)
  | Task_refused of string * Rapid_load.Session.failure   (** this task's buffer is *)
  | Tasks_refused of string
      (** the tasks cannot start: no such entry routine, no such motion task, too many tasks *)
  | Cannot_start of { entry : string; reason : string }
      (** the one task cannot start on this entry routine: it does not exist or takes
          parameters, an initial value fails *)
  | Save_failed of string                         (** --save: what is wrong *)

(** {1 The pieces} *)

val read_io : string option -> (Rapid_controller.Io_config.t, string) result
(** --io: the I/O configuration of the file, or none. *)

val load_robot : string option -> (Rapid_motion_model.Robot.t, string) result
(** --robot: the robot description of the file, or of the library's robot of that name or
    type, or the built-in IRB 120; an error reads FILE:LINE:COL: robot description error:
    MESSAGE for a file, and rapid-sem: MESSAGE for a name the library does not know. *)

val parse_base_frames : string list -> ((string option * Rapid_motion_model.Geom.pose) list, string) result
(** Each --base-frame [TASK=]X,Y,Z,Q1,Q2,Q3,Q4 ({!Rapid_motion_model.Base_frame.of_text}): the task
    it names, [None] for the run's robot; an error is the whole message, one line (R-bk-12). *)

val base_frame_for :
  (string option * Rapid_motion_model.Geom.pose) list -> string option -> Rapid_motion_model.Geom.pose option
(** The last base frame given for this task ([None]: the run's robot), letter case aside. *)

val install_services : Run_options.services -> Rapid_controller.World.t -> (unit, string) result
(** The services of the options given to the world (its file sandbox, its sockets). *)

val machine_gc : unit -> unit
(** A run allocates frames that live as long as their routine: with deep recursion the live heap
    grows with the call depth, and the collector's default pace makes each step cost more the
    deeper it is. A lazier pace keeps the cost of a step nearly independent of depth
    (bench/README.md, "The machine"). Runs of the machine and of several tasks set it. *)

val entry : Run_options.tasks -> (string, failure) result
(** Without --task: the entry routine (the last --entry, default main), once the files are there
    and neither --schedule, --motion-task nor TASK=ROUTINE was given, which go with --task. *)

(** {1 One task buffer} *)

type single = {
  loaded : Rapid_load.Session.loaded;
  world : Run.world;              (** the controller of the options, and the robot *)
}

val single :
  ?history:bool -> ?testing:bool -> ?robot:Rapid_motion_model.Robot.t -> notify:(notice -> unit) ->
  Run_options.t -> string list -> (single, failure) result
(** The task buffer of these files loaded, in the controller of the options (signals, stimulus,
    clock, services, robot), which either engine runs it in. [history]: the motion history is
    kept, within --max-memory (--samples, rapid-sem motion). [testing]: the assertions of
    rapid-sem test are installed (doc/rulings.md R-test-a). [robot]: a backup's robot, unless
    --robot gives one. *)

type one_task_events = {
  task : string;                              (** the backup task's name *)
  before : Task_load.event_routine list;      (** its event routines before its entry routine (R-bk-8) *)
  after : Task_load.event_routine list;       (** after it *)
  debug : Task_load.event_routine list;       (** those debug's commands make happen (R-bk-11) *)
}

val no_events : one_task_events
(** Files: none. *)

val one_task :
  notify:(notice -> unit) -> Run_options.t -> string list -> entry:string ->
  (Run_options.t * string list * string * Rapid_motion_model.Robot.t option * one_task_events, failure) result
(** The one task buffer of these files: as they are, the modules of a .pgf file, or a controller
    backup's first motion task alone (its modules, its entry routine when [entry] is main, its
    robot, its EIO.cfg unless --io, its event routines), the backup's warnings notified: what
    debug, motion and trace of one task run. *)

val fresh_world :
  ?robot:Rapid_motion_model.Robot.t -> notify:(notice -> unit) -> Run_options.t -> string list ->
  (Run.world, failure) result
(** Another world of the same options for the task buffer of these files, as {!single} makes it:
    each start of the program {!single} loaded in one of them begins afresh (module data, clock,
    signals, robot), without loading the files again (rapid-sem test: a world per test). *)

val machine :
  ?observe:bool -> ?events:one_task_events -> ?notify:(notice -> unit) -> Run_options.t -> single -> entry:string ->
  (Rapid_semantics.Machine.config, failure) result
(** The machine started on the entry routine, with the limits of the options; with [events], a
    backup task's event routines before and after it (R-bk-8), those the buffer lacks notified. *)

val start_machine :
  ?observe:bool -> ?history:bool -> ?robot:Rapid_motion_model.Robot.t -> ?events:one_task_events ->
  notify:(notice -> unit) ->
  Run_options.t -> string list -> entry:string ->
  (Rapid_semantics.Machine.config * Run.world, failure) result
(** {!one_task}, {!single}, then {!machine}, the collector paced for the machine first: what trace,
    motion and debug run. *)

(** {1 Several tasks (ch. 14)} *)

type several = {
  specs : Task_load.spec list;    (** the tasks in the order of the --task options *)
  names : string list;
  io : Rapid_controller.Io_config.t;
  controller : Rapid_controller.World.t;
  motion : Rapid_installed.Motion_routines.state;       (** the run's motion task's robot *)
  robots : (string * Rapid_installed.Motion_routines.state) list;   (** the other motion tasks' *)
  connected : (string * string) list;   (** a task without a robot, the motion task it reads *)
  motion_task : string option;          (** --motion-task, else a backup's first motion task *)
  summary : Backup_setup.summary option;   (** a backup's *)
  robotware : Rapid_syntax.Robotware.t option;   (** --robotware, else a backup's (R-2.4-rw6) *)
  events : (string * (Task_load.event_routine list * Task_load.event_routine list)) list;
      (** a backup's event routines by task: before and after the entry routine (R-bk-8) *)
}

val several :
  ?history:bool -> ?cell:Backup_setup.cell -> notify:(notice -> unit) -> Run_options.t -> Run_options.tasks ->
  (several, failure) result
(** The --task and --entry options read (NAME=FILE,...; TASK=ROUTINE), the names checked (unique,
    an entry for a task that exists), and the controller every task shares made: the signals are
    the controller's, inferred from every task's modules. Nothing loaded yet. With [cell], the
    backup's tasks, entry routines, EIO.cfg and robots, which --task NAME=FILE,... (the files of
    a task), --entry, --io, --robot and --motion-task override (R-bk-3). *)

val machine_tasks :
  ?observe:bool -> notify:(notice -> unit) -> Run_options.t -> Run_options.tasks -> several ->
  (Rapid_semantics.Task_set.t * Task_load.loaded, failure) result
(** The tasks loaded and started as machines ({!Run.machine_tasks}); their warnings notified. *)

val closure_tasks :
  notify:(notice -> unit) -> Run_options.t -> Run_options.tasks -> several ->
  (Rapid_closure.Closure_tasks.t * Task_load.loaded, failure) result
(** The same tasks for the closure engine ({!Run.closure_tasks}). *)
