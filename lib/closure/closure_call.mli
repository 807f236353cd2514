(** Which calls the closure engine makes by its direct path ({!Closure_engine}; doc/semantics.md,
    "The second engine"): calls whose arguments need no binder. *)

(** Where the value of one argument comes from. *)
type source =
  | Value of Ir.expr      (** an expression, evaluated *)
  | Read of Ir.place      (** a data reference given for an in parameter: its value *)

val direct : Ir.routine -> Ir.argument array -> source array option
(** [Some sources], one per parameter, when every parameter of the routine is an in parameter
    that is neither optional nor a switch, each given a value, and the routine has neither an
    error handler nor an UNDO handler: its activation then needs no aliases, no presence and
    no handler state (§5.2, §7.1, §4.13 UNDO). [None] otherwise, and for an installed
    routine. *)
