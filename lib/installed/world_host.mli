(** The host of one task (lib/runtime's {!Rapid_runtime.Host}), made of the run's controller
    ({!Rapid_controller.World}: the virtual clock, signals, interrupts, services) and motion
    ({!Motion_routines}: the robot and its planner), with the task's {!Registry}. *)

val make : Rapid_controller.World.t -> Motion_routines.state -> Host.t

val read_signal : Rapid_controller.World.t -> Value.t -> (Value.t, string) result
(** §2.16: a signal in value context is its value; ERR_NO_ALIASIO_DEF when it is not connected
    to a configured signal. *)

val write_signal : Rapid_controller.World.t -> Value.t -> Value.t -> (unit, string) result
(** §2.16: an assignment to an output signal sets it: ERR_NO_ALIASIO_DEF (not connected),
    ERR_ARGVALERR (a digital signal set to neither 0 nor 1). [Error ""] for a value that is not a
    num (excluded by the static semantics). *)
