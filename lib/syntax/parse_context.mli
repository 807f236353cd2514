(** What the grammar's actions need from the parse in progress. Menhir's generated interface
    exports only tokens and entry points, so the file being parsed and the exception by which an
    action refuses its input live here. *)

val file : Source.file ref
(** The file being parsed: the grammar's actions build their regions in it. *)

exception Refused of Source.region * string
(** Raised by a grammar action for a syntax error that one token of look-ahead cannot see
    (comments in records, TASK). *)
