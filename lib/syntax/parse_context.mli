(** What the grammar's actions need from the parse in progress. Menhir's generated interface
    exports only tokens and entry points, so the file being parsed and the exception by which an
    action refuses its input live here. *)

val file : Source.file ref
(** The file being parsed: the grammar's actions build their regions in it. *)

val strict : bool ref
(** The parse refuses the dialect extensions (doc/dialect.md); set by Parse before a parse. *)

exception Refused of Source.region * string
(** Raised by a grammar action for a syntax error that one token of look-ahead cannot see
    (comments in records, TASK). *)

val start : Source.file -> unit
(** Before a parse of [file]: sets [file] and fresh tables of shared nodes. *)

val num_literal : string -> Ast.expression_desc
(** [Num_literal text], the same node for every occurrence of a short [text] in one parse. *)

val ident : string -> Ast.identifier_desc
(** [Ident spelling], the same node for every occurrence of [spelling] in one parse. *)

val entire_reference : string -> Ast.expression_desc
(** [Data_reference (Entire spelling)], the same node for every occurrence of [spelling] as an
    expression in one parse. *)
