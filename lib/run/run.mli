(** A run assembled (doc/architecture.md, "The life of a run"): the world around the program
    (the controller and the motion, made one {!Rapid_runtime.Host}), and the engine that runs
    it, behind one signature, for the command line, the conformance suite, the fuzzer and the
    tests alike. *)

(** The world of one task. *)
type world = {
  controller : Rapid_controller.World.t;
  motion : Rapid_installed.Motion_routines.state;
  host : Host.t;                  (** both, as an engine sees them *)
}

val setup :
  ?controller:Rapid_controller.World.t -> ?motion:Rapid_installed.Motion_routines.state -> unit -> world
(** The world of a run: by default a controller with no signal, the default timing and sandbox,
    and the default robot (the IRB 120) standing at axis angles 0. *)

(** How an engine's run ended. *)
type result = {
  outcome : Outcome.t;            (** [Running] when the work ran out (--max-steps) *)
  work : int;                     (** the machine's steps, the closure engine's units of fuel *)
}

(** An engine: the small-step machine (the definition) or the closure engine (the fast one). *)
module type ENGINE = sig
  val name : string               (** as [--engine] names it *)

  val run :
    ?limits:Limits.t -> ?fuel:int -> ?stub_unmodelled:bool -> ?all_events:bool -> ?observe:bool ->
    ?on_event:(Event.t -> unit) -> ?module_data:((string * string * Value.t) list -> unit) ->
    host:Host.t -> Ir.program -> entry:string -> (result, string) Stdlib.result
  (** Runs the entry routine to its end, or until [fuel] (default 100,000,000) runs out, calling
      [on_event] on each observable event in order; with [all_events:false] only on [Output],
      [Erase] and [Log] are wanted. [module_data]: the module data at the end (--save).
      [Error]: the run cannot start (no such entry routine, an initial value that fails). *)
end

module Machine : ENGINE
module Closure : ENGINE

val engine : [ `Machine | `Closure ] -> (module ENGINE)

(** {1 Several tasks (ch. 14)} *)

val machine_tasks :
  ?limits:Limits.t -> ?stub_unmodelled:bool -> ?allow_unknown:bool -> ?robotware:Rapid_syntax.Robotware.t ->
  ?observe:bool -> ?io:Rapid_controller.Io_config.t -> ?seed:int -> ?motion_task:string ->
  ?robots:(string * Rapid_installed.Motion_routines.state) list -> ?connected:(string * string) list ->
  ?events:(string * (Task_load.event_routine list * Task_load.event_routine list)) list ->
  controller:Rapid_controller.World.t -> motion:Rapid_installed.Motion_routines.state -> Task_load.spec list ->
  (Rapid_semantics.Task_set.t * Task_load.loaded, Task_load.failure) Stdlib.result
(** The tasks loaded ({!Task_load.load}) and started as machines ({!Rapid_semantics.Task_set});
    a task that cannot start is [Refused]. [events]: a backup's event routines by task
    ({!Task_load.load}). *)

val closure_tasks :
  ?limits:Limits.t -> ?stub_unmodelled:bool -> ?allow_unknown:bool -> ?robotware:Rapid_syntax.Robotware.t ->
  ?io:Rapid_controller.Io_config.t -> ?seed:int -> ?motion_task:string ->
  ?robots:(string * Rapid_installed.Motion_routines.state) list -> ?connected:(string * string) list ->
  ?events:(string * (Task_load.event_routine list * Task_load.event_routine list)) list ->
  controller:Rapid_controller.World.t -> motion:Rapid_installed.Motion_routines.state -> Task_load.spec list ->
  (Rapid_closure.Closure_tasks.t * Task_load.loaded, Task_load.failure) Stdlib.result
(** The same tasks for the closure engine ({!Rapid_closure.Closure_tasks}). *)

val motion_task : Task_load.loaded -> Task_load.task option
(** The task that has the robot. *)

val task_world : Task_load.task -> world
(** A task's world. *)
