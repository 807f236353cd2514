(** The pace of the major collector while long-lived data is built: loading a program (its
    trees, the elaboration's tables, the lowered program, Session.load). Nearly all of it lives
    on, so the collector would mark it again and again as it grows, for little to free: while it
    is built the collector runs at a tenth of its pace or less, then at the pace it had
    (bench/README.md, "Motion": 16 % fewer instructions for a module of 10,000 moves, the same
    peak resident set). Nothing observable depends on it. The closure engine compiles each
    routine at this pace too (a module of 10,000 moves: 11 % fewer instructions, 9 % more peak
    resident set). *)

val space_overhead : int
(** [Gc.space_overhead] while building: 1000. *)

val building : (unit -> 'a) -> 'a
(** [building f] is [f ()] with the collector slowed down, its pace given back after (also when
    [f] raises). Nested calls keep the outer pace until the outermost ends. *)
