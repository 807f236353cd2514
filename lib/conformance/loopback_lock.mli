(** Cases that bind sockets on the loopback pick "the first free port from N" (spec/13-services):
    two processes running such cases at once (dune runs the suite and the engines' comparison in
    parallel; several checkouts may test on one machine) would see different ports free, and two
    runs of one case would then differ for a reason outside the program. Runs of such cases take
    one lock, shared by every process of the machine, so that they run one at a time. *)

val uses_loopback : Spec_case.t -> bool
(** The case's modules name a socket routine (SocketCreate, SocketBind, ...). *)

val exclusive : Spec_case.t -> (unit -> 'a) -> 'a
(** [exclusive case f] runs [f] holding the lock when the case uses the loopback, and [f]
    alone otherwise. If the lock file cannot be opened, [f] runs without it. *)
