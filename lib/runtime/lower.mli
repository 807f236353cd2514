(** From the checked syntax tree to the program the machine runs (lib/semantics/ir.ml): names
    resolved to slots and routines, operators to their rows of §3.12, arguments to parameters,
    as the static semantics elaborated them. *)

val program :
  installed:Rapid_syntax.Ast.module_declaration list ->
  modules:Rapid_syntax.Ast.module_declaration list ->
  Rapid_typing.Elaboration.t ->
  Ir.program
(** The task buffer [modules] over the installed environment [installed]; the elaboration is
    that of a check without errors. *)
