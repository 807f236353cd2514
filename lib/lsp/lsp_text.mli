(** The text of a module as the editor and the front end both see it, and the two ways of
    naming a place in it. The front end counts characters (Unicode code points, after
    decoding UTF-8 or Latin-1: {!Rapid_syntax.Decode}), lines and columns from 1; LSP 3.17
    counts lines from 0 and, in the default position encoding, UTF-16 code units within the
    line: a character beyond U+FFFF is two. *)

type t

val of_bytes : string -> t
(** A file's bytes as the front end reads them: UTF-8 (a byte-order mark dropped) or Latin-1. *)

val text : t -> string
(** UTF-8, what the parser reads. *)

type position = { line : int; character : int }
(** LSP's: 0-based line, UTF-16 code units. *)

val position_of_offset : t -> int -> position
(** The position of a character offset (clamped to the text). *)

val offset_of_position : t -> position -> int
(** The character offset of a position; a character beyond the line's end is its end (LSP
    3.17: "defaults back to the line length"), a line beyond the last is the text's end. *)

val byte_of_offset : t -> int -> int

val apply_change : t -> (position * position) option -> string -> t
(** [apply_change t range new_text]: [None] replaces the whole text (full sync), [Some (a, b)]
    the text between [a] and [b] (incremental sync). *)

val slice : t -> int -> int -> string
(** The UTF-8 text between two character offsets. *)

val length : t -> int
(** In characters. *)

val json_position : position -> Yojson.Safe.t
val position_of_json : Yojson.Safe.t -> position option
val json_range : t -> int -> int -> Yojson.Safe.t
(** The LSP range of the characters between two offsets. *)
