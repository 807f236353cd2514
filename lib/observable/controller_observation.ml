type t =
  | Signal_changed of { time : float; signal : string; value : float }
  | Interrupt_occurred of { time : float; number : int }
  | Interrupt_discarded of { time : float; number : int; reason : string }
