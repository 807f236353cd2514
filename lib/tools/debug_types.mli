(** The declared types of a task's data by name, for the debugger's print and set
    (doc/debugger.md): the lowered program the machine runs keeps no types, so the task is checked
    again and each data object of the elaboration is found by its name in its routine's scope or
    among the module and installed data. *)

val type_of :
  Rapid_syntax.Ast.module_declaration list -> Ir.routine -> string -> (Rapid_typing.Types.object_type * bool) option
(** [type_of modules] checks [modules] (over the installed environment) once; the function then
    gives a name's declared type in a routine's scope (its parameters, routine data and loop
    variables first, then module data of the task and installed data, letters compared without
    case, §2.3), and whether it may be written: a variable, a persistent or a parameter, not a
    constant, a loop variable or a system variable (ERRNO, INTNO). [None]: not known (an
    unknown name, or a task the checker refuses there). *)
