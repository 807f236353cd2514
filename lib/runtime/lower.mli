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

type installed_lowering
(** The installed modules' part of every program, lowered once (the first routines and globals
    of every {!program} over the same installed modules and installed elaboration, both compared
    physically). It holds no functional value: lib/load/installed_image.ml marshals it at build
    time. *)

val installed_lowering :
  installed:Rapid_syntax.Ast.module_declaration list -> Rapid_typing.Elaboration.t -> installed_lowering
(** From the elaboration of a task checked over [installed] (or of the installed level itself). *)

val installed_lowering_of : installed_lowering -> Rapid_syntax.Ast.module_declaration list -> installed_lowering
(** The same part keyed by the same modules given by their headers alone (Installed_env.level). *)

val use_installed_lowering : installed_lowering -> unit
(** The next programs over its installed modules and elaboration start from it. *)
