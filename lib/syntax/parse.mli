(** Reading a module: decoding, lexing, parsing and the checks that close the front end. *)

type options = {
  strict : bool;
      (** refuse the extensions of doc/dialect.md (%%% header, byte-order mark, missing final
          newline) *)
  installed : bool;
      (** reading the installed environment (lib/typing/installed): REF is an access mode
          (ch. 11) *)
  robotware : Robotware.t;
      (** the RobotWare release whose reserved words apply (R-2.4-rw6): RobotWare 5 and 6
          reserve neither BREAK nor CONTINUE *)
}

val default_options : options

val max_nesting : int
(** The deepest nesting of statements and expressions accepted; deeper is the fatal static
    error "program too complex" of §1.4. *)

val parse_string :
  ?options:options -> name:string -> string -> (Ast.module_declaration, Diagnostic.t) result
(** [parse_string ~name contents] reads [contents] as the file [name]. Never raises. *)

val parse_file : ?options:options -> string -> (Ast.module_declaration, Diagnostic.t) result
(** Like {!parse_string}, reading the file; a file that cannot be read is reported as a
    diagnostic at line 1, column 1. The path ["-"] reads standard input, named {!stdin_name}
    in diagnostics. *)

val stdin_name : string
(** ["<stdin>"]: the file name of standard input in diagnostics, JSON and SARIF. *)

val source_text : string -> string
(** The bytes of the file at this path (["-"]: standard input, read once and kept). Raises
    [Sys_error]. *)
