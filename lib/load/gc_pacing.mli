(** The major collector's first cycle, begun at initialisation (Installed_image), once the
    installed image is known to be usable. Its minor collection then promotes only the few words
    the modules initialised so far allocated, and its roots are darkened before the image's
    roots hook is installed (installed_image_stubs.c), so that this cycle does not scan the
    image's fields: an empty main 4.69 M instructions instead of 6.69 M without it
    (bench/README.md, "Start-up: the image in the executable's data").

    Only the collector's pacing is touched (the counters of the work it owes); colours and
    phases are the runtime's own doing. Nothing a program observes depends on it. *)

val begin_cycle : unit -> unit
(** When no cycle is under way, begins one (after a minor collection, as the runtime requires),
    with what the collector counted before forgotten. *)
