(** Comparing an implementation that writes schema [rapid-sem/1] with rapid-sem, which writes
    [rapid-sem/2] (doc/oracle.md, "Implementations of schema rapid-sem/1"). *)

val current : string
(** ["rapid-sem/2"], the schema rapid-sem writes. *)

val accepted : string list
(** The schemas an implementation may write: [rapid-sem/2] and [rapid-sem/1]. *)

val to_v1 : Event_stream.event list -> Event_stream.event list
(** A /2 stream as /1 says the same run: the events /2 added left out ([store], [arguments],
    [returned], [retry], [trynext]), each [error-propagated] written as the [error-raised] again
    that /1 wrote at the call point (with the place the error was first raised), the entry
    routine's [routine-entered] (the first event) left out, [task-ended] left out (/1 left it
    out after Stop), [error-handled] without [number], and the end object without [at]. *)

val v1_actual : Event_stream.event list -> Event_stream.event list
(** A /1 implementation's stream prepared for the comparison: [task-ended] left out. *)
