(** Several tasks loaded for one run (ch. 14; doc/semantics.md, "Several tasks"), for either
    engine's task set: each task buffer read, checked and lowered; the worlds of the tasks made
    to share the clock, the signals and the services ({!Rapid_controller.World.add_task}); the
    data objects they share found (system-global persistents, PERS declared neither TASK nor
    LOCAL, with the same name are one data object for every task that declares them; installed
    data, but ERRNO and INTNO), with the initial values those take (R-14-b). *)

type spec = { name : string; files : string list; entry : string }

type failure =
  | Load of string * Rapid_load.Session.failure
      (** the task's name and why its buffer was refused; a system-global persistent declared
          with another type than in an earlier task is a semantic error at its declaration *)
  | Refused of string   (** no such entry routine, no such motion task, too many tasks *)

type task = {
  rules : Task_rules.task;                             (** what an engine runs *)
  world : Rapid_controller.World.t;                    (** the task's controller *)
  motion : Rapid_installed.Motion_routines.state;      (** the task's robot (the motion task's is the run's) *)
}

type loaded = {
  tasks : task list;
  links : Task_rules.link list;
  warnings : Rapid_typing.Report.t list;
  notes : string list;
      (** a controller backup's event routines that are not run, the task having no procedure
          without parameters of that name: FILE:LINE: warning: ... (R-bk-8) *)
}

type event_routine = Rapid_load.Backup.event_routine

val runnable : note:(string -> unit) -> task:string -> Ir.program -> event_routine list -> string list
(** The names of those event routines the program has as procedures without parameters, in
    order; each other one is noted (FILE:LINE: warning: ..., R-bk-8) and left out. *)

val load :
  ?allow_unknown:bool -> ?robotware:Rapid_syntax.Robotware.t -> ?io:Rapid_controller.Io_config.t ->
  ?motion_task:string -> ?robots:(string * Rapid_installed.Motion_routines.state) list ->
  ?connected:(string * string) list -> ?events:(string * (event_routine list * event_routine list)) list ->
  world:Rapid_controller.World.t -> motion:Rapid_installed.Motion_routines.state -> spec list ->
  (loaded, failure) result
(** The tasks in order, and the warnings of their checks. [robotware]: the release whose reserved
    words the modules are read with (R-2.4-rw6). [world] becomes the first task's
    world; [motion] the motion task's robot ([motion_task], default the first task). More than
    {!Task_rules.max_tasks} tasks are [Refused]. [robots]: the other motion tasks (MultiMove,
    R-bk-4), each with its robot; [connected]: a task without a robot and the motion task whose
    robot it reads by default (its mechanical unit group's), else the first motion task's.
    [events]: a task's event routines, those run before its entry routine and those after
    (R-bk-8); the ones its buffer does not have as procedures without parameters are [notes]. *)
