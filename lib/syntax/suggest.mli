(** "Did you mean ...": the names closest to a misspelt one, for the hint of an unknown name
    (§2.20, ch. 13). Names are compared without regard to letter case, as §2.3 compares them. *)

val distance : string -> string -> int
(** The edit distance between the two names in lower case: insertions, deletions,
    substitutions and transpositions of neighbouring characters each count one. *)

val closest : string -> string list -> string list
(** [closest name candidates]: the candidates nearest to [name], at most three, in the order
    given; none when even the nearest differs by more than a third of the name's length (at
    least one edit, at most three), and none for a name shorter than three characters. *)

val hint : string -> string list -> string option
(** ["did you mean tool0?"], ["did you mean a, b or c?"], or [None]. *)
