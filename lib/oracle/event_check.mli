(** An implementation's events compared with rapid-sem's as they come, line by line, holding
    none of them (doc/oracle.md, "Bounds"): what {!Oracle.check} does with one task's stream. *)

type t

val create : ?ignore:string list -> ?context:int -> expected:Event_stream.t -> unit -> t
(** [expected] is rapid-sem's stream, kept as the text of its events; [context] (default 3)
    the agreed events a divergence shows before it. *)

val add_line : t -> int -> string -> (unit, string) result
(** Line [n] of the implementation's standard output, read and bounded as
    {!Event_stream.add_line} reads it, then compared with the event rapid-sem wrote at that
    place (after the kinds in [ignore] are taken out and {!Event_diff.implementation_specific}
    fields removed). Of the implementation's events only the first that differs is kept. *)

type verdict = Agree of int | Diverge of Event_diff.divergence | Broken of string

val finish : t -> verdict
(** The verdict on the lines read so far, as {!Oracle.compare_streams} gives it on the whole
    streams: the schema of the implementation's first line decides how they are compared. *)
