(** The arguments of a late-bound procedure call (§4.6, §5.4 "后期绑定") bound to the parameters of
    the procedure its name denotes when the call runs. *)

val bind : Ir.routine -> Ir.late_argument array -> Ir.argument array option
(** Required arguments in order (a named one must name the parameter in its place), optional
    and switch arguments by name; [None] when they do not fit the procedure (ERR_CALLPROC). *)
