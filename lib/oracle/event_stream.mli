(** The observable events of a run as another implementation writes them: JSON Lines, one
    object per line, the first naming the schema (doc/observable.md, doc/oracle.md). *)

type event = Yojson.Safe.t
(** One event: a JSON object with at least the field ["event"]. *)

type t = { schema : string option; events : event list }
(** [schema] is the ["schema"] field of the first line when that line is a ["start"] event;
    [events] are the lines after it (the ["end"] object included). *)

val parse : string -> (t, string) result
(** The text an implementation wrote on standard output. Blank lines are passed over; a line
    that is not a JSON object is an [Error] naming its line number. *)

val kind : event -> string
(** The ["event"] field, or [""]. *)

val to_string : event -> string
(** One line of JSON, fields in a stable order (sorted by name, recursively). *)

val canonical : event -> event
(** Fields sorted by name, recursively: how [parse] gives each event. *)
