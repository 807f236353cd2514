(** The events schema rapid-sem/2 adds, as JSON objects (doc/trace-format.md). *)

val event : text:(string -> Yojson.Safe.t) -> Rapid_runtime.Observation.t -> Yojson.Safe.t
(** [text] converts a RAPID string or name to JSON text (UTF-8, Latin-1 bytes read as such). *)
