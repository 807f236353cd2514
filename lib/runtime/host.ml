type motion_error = { error : string; move : int option; handled : bool }

type t = {
  routine : string -> Installed_routine.entry option;
  book_error : unit -> int;
  booked : int -> bool;
  now : unit -> float;
  max_time : float;
  reached : float -> bool;
  statement : unit -> unit;
  statement_within : unit -> bool;
  statements : int -> unit;
  statements_left : unit -> int;
  next_event : unit -> float option;
  advance_to : float -> unit;
  every_task_waits : string list -> unit;
  collisions : bool;
  read_signal : Value.t -> (Value.t, string) result;
  write_signal : Value.t -> Value.t -> (unit, string) result;
  connect : trap:int -> (int, string) result;
  connected : int -> bool;
  take_interrupt : unit -> (int * int) option;
  observations : unit -> Rapid_observable.Controller_observation.t list;
  motion_events : unit -> Rapid_observable.Motion_event.t list;
  motion_finish : unit -> Rapid_observable.Motion_event.t list;
  motion_error : unit -> motion_error option;
  set_backward : bool -> unit;
  wait_abandoned : Rapid_observable.Wait.t -> unit;
  prepare : Ir.program -> Ir.program;
}
