(** Data read once and kept for the whole process, the installed image (200,000 words), read
    so that the major collector's first cycle need not mark it (bench/README.md, "Fourth
    round"). OCaml 4.13 marks every live word once per cycle, and a program that allocates past
    its first minor collection (fib(25) does) would have its first cycle mark the image with
    the rest: about 10 million instructions, as many as the program's own work. What the
    collector allocates while its cycle is marking it allocates marked, so the image is read
    inside a cycle begun for it, which then owes its marking of everything else to the next
    slice, as the cycle would have done.

    Only the collector's pacing is touched (the counters of the work it owes); colours and
    phases are the runtime's own doing. Nothing a program observes depends on it. *)

val begin_cycle : unit -> unit
(** When no cycle is under way, begins one (after a minor collection, as the runtime requires),
    with what the collector counted before forgotten. Called as early as the image is known to be
    usable: the minor collection then promotes the few words the modules initialised so far
    allocated, not the 35,000 more that start-up allocates before the image is read (1.2 million
    instructions and 200 page faults of an empty main's start-up, bench/README.md "Sixth round"). *)

val read_marked : (unit -> 'a) -> 'a
(** [read_marked f] is [f ()]. When no cycle is under way, one is begun first ([begin_cycle]).
    When its marking is under way, what the collector counted since is forgotten (the standard
    channels' buffers, the words allocated while building) so that it does not hurry the cycle's
    end, and after [f], one cycle's marking owed to the next slice. *)
