(** The numbers RAISE raises (§4.11, doc/rulings.md R-4.11-b), for both engines, and what a run
    stopped by one it cannot raise says to do. *)

val legal : booked:(int -> bool) -> float -> bool
(** An integer of 1..90, or one BookErrNo booked. *)

val refusal : Ir.program -> in_handler:bool -> float -> string
(** The [about] of the ERR_ILLRAISE of [RAISE x] (R-4.11-raise1): the number and its ERR_ name
    when it has one, what RAISE raises and what the program should write instead. *)
