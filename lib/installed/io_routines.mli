(** The behaviour of the installed routines that talk to the controller around the program
    (doc/controller.md): waiting, I/O signals, interrupts, clocks and the date. They act on the
    run's {!Rapid_controller.World}, reached through the primitive context; a wait is returned
    to the engine, which carries it out step by step. *)

val call : Primitive.context -> string -> Primitive.argument array -> Primitive.outcome option
(** [None]: not one of these routines. Arguments are found by the names of the routine's
    parameters ([context.parameters]), so that optional parameters added to a declaration later
    do not move them. *)

val modelled : string -> bool

val date_time : float -> int * int * int * int * int * int * int
(** Seconds since 1970-01-01 00:00:00 to year, month, day, hour, minute, second and the day of
    the week (1 Monday .. 7 Sunday, GetTime \WDay). *)

val signal : Primitive.context -> Primitive.argument array -> string -> (int, string) result
(** The configured signal a signal argument (by parameter name) denotes: its identity, or
    ERR_NO_ALIASIO_DEF for a signal object connected to none (doc/rulings.md R-8-a). *)
