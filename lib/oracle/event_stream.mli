(** The observable events of a run as another implementation writes them: JSON Lines, one
    object per line, the first naming the schema (doc/observable.md, doc/oracle.md). *)

type event = Yojson.Safe.t
(** One event: a JSON object with at least the field ["event"]. *)

type t = { schema : string option; events : event list }
(** [schema] is the ["schema"] field of the first line when that line is a ["start"] event;
    [events] are the lines after it (the ["end"] object included). *)

val max_depth : int
(** 100: a line whose arrays and objects nest deeper is refused before it is parsed. *)

val max_events : int
(** 1,000,000: the objects a stream may hold, the start line included. *)

val max_values : int
(** 8,000,000: the JSON values of a stream (object member names counted too), which bound the
    memory its events take. *)

type reader
(** A stream read line by line, as the implementation writes it. *)

val reader : unit -> reader

val add_line : reader -> int -> string -> (unit, string) result
(** [add_line r n line] reads line [n] (counted from 1). A blank line is passed over; a line
    that is not a JSON object, nests deeper than {!max_depth}, or comes after {!max_events}
    objects or {!max_values} values is an [Error] naming its line number, its text clipped ({!clip}). *)

val read_line : reader -> int -> string -> (event option, string) result
(** [add_line] without keeping the event: [Some] the line's event ({!canonical}), [None] for a
    blank line; the bounds are counted all the same. What the oracle uses to compare an
    implementation's events as they come, holding none of them. *)

val contents : reader -> t
(** What the lines read so far make. *)

val kind : event -> string
(** The ["event"] field, or [""]. *)

val to_string : event -> string
(** One line of JSON, fields in a stable order (sorted by name, recursively). *)

val show : event -> string
(** [to_string], clipped for a report ({!clip}). *)

val clip : string -> string
(** Text of another implementation made fit for a report: on one line (a line break shown as a
    space), each control character (C0, DEL, C1) and each byte of invalid UTF-8 shown as [\XX]
    (hexadecimal), and when longer than 300 bytes its first characters within 300 bytes
    followed by [... (N bytes)]: the result is valid UTF-8 and drives no terminal. *)

val canonical : event -> event
(** Fields sorted by name, recursively: how {!add_line} gives each event. *)
