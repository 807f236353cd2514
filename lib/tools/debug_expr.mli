(** The expressions of the debugger's [print] and [set] (doc/debugger.md): RAPID expressions of
    chapter 3, read with the grammar of chapter 10 and evaluated against the data of a stopped
    task, without running the program. Operators take their row of §3.12 from their operands'
    values (a num with a dnum is read as dnum, a record of three nums as a pos, of four as an
    orient); function calls are refused, since they could change what they inspect. *)

open Rapid_syntax

(** A data object as the session sees it. *)
type datum = {
  value : Value.t option;                          (** [None]: an absent optional parameter *)
  typ : Rapid_typing.Types.object_type option;     (** its declared type, when known *)
  write : (Value.t -> bool) option;                (** stores a whole new value; [None]: read-only *)
}

type env = string -> (datum, string) result
(** A name of the current routine's scope (§2.20); [Error] says why there is none. *)

val parse_expression : string -> (Ast.expression, string) result
val parse_assignment : string -> (Ast.data_reference * Ast.expression, string) result
(** [TARGET := EXPR], as the assignment statement of §4.5. *)

val eval : env -> Ast.expression -> (Value.t, string) result
(** The value, or why there is none: an execution error by its name (ERR_DIVZERO,
    ERR_OUTOFBND, ...), a function call, a component of a value whose type is not known. *)

val assign : env -> Ast.data_reference -> Ast.expression -> (Value.t, string) result
(** Evaluates the expression, then stores it at the reference (a whole object, an element, a
    component): the value must have the kind of the value it replaces (a num where a num was, an
    aggregate of as many members as the record or array, ...). The stored value. *)
