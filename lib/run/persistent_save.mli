(** [--save] (doc/services.md): a module written back after a run with every PERS
    declaration's initial value replaced by the persistent's current value (§2.23: persistents
    keep their value). Only the initial value's text changes: comments, layout and everything
    else stay byte for byte. *)

val literal : Value.t -> string
(** The value as RAPID text that reads back as exactly this value in a UTF-8 module: numbers
    with the fewest digits that round-trip (single precision for num, double for dnum), strings
    as {!string_literal}, records and arrays as aggregates. Raises [Value.Type_mismatch] for a
    value that has no literal (a handle, a number that is not finite). *)

val string_literal : latin1:bool -> string -> string
(** §2.7: a string literal whose value, read from a module of that encoding (Latin-1 or
    UTF-8), is exactly these bytes: characters the file can hold as themselves, every other byte
    as a character code [\HH], a quote and a backslash written twice. *)

val splice :
  original:string -> Rapid_syntax.Ast.module_declaration -> (string -> Value.t option) -> string
(** The module's text (the file's bytes) with each module-level PERS declaration's initial
    value replaced by the value the function gives for its name ([None]: unchanged); a PERS
    declared without an initial value gets [:= value]. The regions are measured in characters
    and replaced in the file's bytes, in its encoding (a character beyond U+00FF in a Latin-1
    file's value as [\HH] codes, the file staying Latin-1, R-2.23-save2n); only a Latin-1 file
    that would then read as UTF-8 with other characters is written as UTF-8 instead
    (doc/rulings.md R-2.23-save1). *)

val write_atomically : string -> string -> (unit, string) result
(** [write_atomically path text]: the text goes to the temporary file [path.PID.rapid-sem.part]
    in the same folder (locked by this process until its rename, R-2.23-save3), is flushed to
    the disk, and is renamed to [path], so that a run stopped at any moment leaves either the
    old file or the new one. The temporary files of [path] that an earlier save left (its
    process is gone) are removed first. A [path] that is a folder is refused before anything is
    written. *)

val check : dir:string -> files:string list -> (unit, string) result
(** What [save_modules] refuses before it reads anything, to be asked before the run: an empty
    [dir] (it would be the current folder unasked), a [dir] that is not a folder, two files of one
    base name (one would replace the other). *)

val save_modules :
  dir:string -> files:string list -> (string * string * Value.t) list -> (string list, string) result
(** At the end of a run: each module file, spliced with the current values of its module's
    data (module, name, value), written to [dir] (made if missing) under its own base name, in
    two phases. First every text and every temporary file (as {!write_atomically}), with a check
    that each destination can be replaced; a problem there (one of {!check}'s, a module that
    cannot be read or whose saved text would not read back, a destination that is a folder, a
    write that fails) removes them all, and a [dir] this call made, and changes no module. Then
    the renames, each atomic; one that fails stops the rest (their temporary files removed), and
    the message names the modules saved and those not. The names written, or the problem. *)
