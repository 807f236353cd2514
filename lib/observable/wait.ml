type raised = { error : string; at_move : bool }

let error name = Some { error = name; at_move = false }

type t = {
  what : string;
  satisfied : unit -> bool;
  deadline : float option;
  finish : timed_out:bool -> raised option;
  poll : float option;
}

let default_poll_rate = 0.1
