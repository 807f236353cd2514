type log_entry =
  | Err_log of { id : int; kind : string; arguments : string list }
  | Skip_warning

type t =
  | Output of string
  | Erase
  | Event_log of log_entry
  | Log of string
  | Routine_entered of string
  | Routine_left of string
  | Error_raised of { name : string; number : int; at : Rapid_syntax.Source.region }
  | Error_handled of { name : string; routine : string }
  | Undo_run of string
  | Task_ended
  | Controller of Rapid_observable.Controller_observation.t
  | Trap_entered of { number : int; trap : string; time : float }
  | Trap_left of { trap : string; time : float }
  | Stubbed of { routine : string; at : Rapid_syntax.Source.region }
  | Motion of Rapid_observable.Motion_event.t
  | Observed of Observation.t

let world_event = function Controller _ | Motion _ -> true | _ -> false
