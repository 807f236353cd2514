(** Random states made from a seed array, as the campaign makes three for every program. *)

val make : int array -> Random.State.t
(** [make seed] is equal to [Random.State.make seed] (the same state, so the same draws),
    made with fewer instructions. *)
