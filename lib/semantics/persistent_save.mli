(** [--save] (doc/services.md): a module written back after a run with every PERS
    declaration's initial value replaced by the persistent's current value (§2.23: persistents
    keep their value). Only the initial value's text changes: comments, layout and everything
    else stay byte for byte. *)

val literal : Value.t -> string
(** The value as RAPID text that reads back as exactly this value: numbers with the fewest
    digits that round-trip (single precision for num, double for dnum), strings as
    {!Format.string_literal}, records and arrays as aggregates. *)

val splice :
  original:string -> Rapid_syntax.Ast.module_declaration -> (string -> Value.t option) -> string
(** The module's text (the file's bytes) with each module-level PERS declaration's initial
    value replaced by the value the function gives for its name ([None]: unchanged); a PERS
    declared without an initial value gets [:= value]. *)

val write_atomically : string -> string -> (unit, string) result
(** [write_atomically path text]: the text goes to a temporary file in the same folder, is
    flushed to the disk, and is renamed to [path], so that a run stopped at any moment leaves
    either the old file or the new one. *)

val save_modules :
  dir:string -> files:string list -> (string * string * Value.t) list -> (string list, string) result
(** At the end of a run: each module file, spliced with the current values of its module's
    data (module, name, value), written atomically to [dir] under its own base name. The names
    written, or the first problem. *)
