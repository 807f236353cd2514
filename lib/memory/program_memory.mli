(** Program memory (chapter 16): how many bytes of the controller's program memory (internal
    format) a module, its data and its routines take.

    Chapter 16 lists 22 constructs with their figures. rapid-sem's model (doc/memory.md) is
    additive, with coefficients fitted so that every construct the chapter lists gets the
    chapter's figure, except the call [proc1;] alone, which the chapter's own figures for the
    compact IF and the IF statement contradict (doc/rulings.md R-16). *)

open Rapid_syntax

type item = {
  label : string;              (** "VAR num reg1", "PROC main", "module" *)
  bytes : int;
  parts : item list;           (** a routine's data and statements, one item each *)
}

val module_memory : records:Ast.module_declaration list -> Ast.module_declaration -> item
(** The module's bytes: the empty module's 1732, then each declaration and routine. [records]
    are other modules (the installed environment, the task's other modules) whose RECORD and
    ALIAS definitions give the sizes of values. *)

val value_bytes : records:Ast.module_declaration list -> string -> int
(** The bytes of one value of the named type (num 4, dnum 8, bool 4, string 84, a record the
    sum of its components, other installed types 4). *)

val statement_bytes : Ast.statement -> int
val expression_bytes : Ast.expression_desc -> int
