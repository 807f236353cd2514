(** The static rules of RaiseToUser (§7.3; ABB's RaiseToUser): where it may stand and the switch
    it needs. *)

val raise_to_user :
  report:Report.collector -> in_error_handler:bool -> in_nostepin:bool -> installed:bool ->
  at:Rapid_syntax.Source.region -> string -> Rapid_syntax.Ast.argument array -> unit
(** [raise_to_user ~report ... name args] checks a procedure call of [name] (the installed
    routine when [~installed]) with [args]: RaiseToUser stands only in the error handler of a
    routine of a NOSTEPIN module, and has one of \Continue, \Resume, \BreakOff. Any other call
    is left alone. *)
