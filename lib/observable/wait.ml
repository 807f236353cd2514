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

let first_poll wait ~now motion =
  let period = Option.value wait.poll ~default:0. in
  match motion with Some t -> Float.max t (now +. period) | None -> now +. period
