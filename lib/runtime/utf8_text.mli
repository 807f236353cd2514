(** Text for JSON, which must be valid UTF-8 (doc/trace-format.md, "Text"): RAPID strings are
    bytes (§2.7), and a source file may be Latin-1 (doc/rulings.md R-2.1-b). *)

val is_utf8 : string -> bool

val sequence : string -> int -> int
(** The length of the valid UTF-8 sequence at an index, or 0 (overlong forms, surrogates and code
    points beyond U+10FFFF are not valid). *)

val of_bytes : string -> string
(** The string with its valid UTF-8 sequences kept and every other byte read as the Latin-1
    character of that code (so that 0xE9 becomes "é"). The result is valid UTF-8. *)

val characters : latin1:bool -> string -> string array
(** The characters of a line, each as its UTF-8 bytes: the line's bytes read as UTF-8 (any
    invalid byte as Latin-1), or, with [latin1], each byte one character. *)
