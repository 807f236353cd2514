(** The arguments of a late-bound procedure call (§4.6, §5.4 "后期绑定") bound to the parameters of
    the procedure its name denotes when the call runs. "The general rules for the argument list
    of a procedure call are exactly those of a function call" (§4.6): what a direct call checks
    statically (§3.11, §5.2), the binding checks here. *)

val bind :
  Ir.routine ->
  kind:(Ir.place -> Ir.reference_kind -> Ir.reference_kind) ->
  Ir.late_argument array ->
  (Ir.argument array, string) result
(** Required arguments in order (a named one must name the parameter in its place), optional,
    switch and conditional arguments by name. [kind] tells what a data reference denotes at
    run time (a parameter passes on what it is bound to, §5.2).

    [Error "ERR_CALLPROC"] when the arguments do not fit the procedure: too many or too few, a
    name that is not the parameter's, an optional argument given twice or two alternatives of
    one optional parameter both given (§5.2), a switch for a parameter that is not one or the
    reverse, a conditional argument for a required parameter, a type that is not the
    parameter's (§3.11: equal types; a numeric literal is num or dnum as its parameter is,
    R-2.5-b; an aggregate must fit the parameter's type, checked when its value is known), an
    object of a non-value type for an in, PERS or INOUT parameter or of a semi-value type for a
    PERS or INOUT one (§2.16).
    [Error "ERR_ARGNOTVAR"] when a VAR or INOUT parameter gets something other than a variable
    (a constant, a read-only variable, a persistent for VAR, any other expression), and
    [Error "ERR_ARGNOTPER"] when a PERS parameter gets a known object that is not a persistent: the
    "-" cells of the access-mode table of §5.2, with the errors chapter 12 names for them
    (doc/rulings.md R-4.6-b). *)

val is_procedure_name : string -> bool
(** §4.6: the string is "name2" or "name1:name2", each an identifier of §2.3 (a letter, then
    letters, digits and '_', at most 32 characters, no reserved word). *)

val unknown_procedure_error : string -> string
(** The error of a late-bound name (or CallByVar's) that denotes no routine (doc/rulings.md
    R-4.6-name1): ["ERR_REFUNKPRC"] for a procedure name that is unknown (ch. 12: "在链接时或运行
    时(后期绑定),未知的无返回值程序的引用"), ["ERR_CALLPROC"] for a string that is no procedure
    name at all, the "syntax" of ch. 12's "运行时(后期绑定)的无返回值程序调用错误 (语法,非无返回值
    程序)". *)

val unresolved : Ir.place -> bool
(** A place whose name is neither declared nor installed (--allow-unknown): binding it raises
    ERR_REFUNKDAT, whatever the parameter's mode (doc/rulings.md R-5.2-unknown1). *)
