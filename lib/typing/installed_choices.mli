(** The choices between required arguments of installed routines.

    ABB's syntax of an installed routine can offer two required parameters in one place
    ("SearchL ... Signal | PersBool ...": a signal or a persistent bool, exactly one of them). A
    RAPID parameter list has alternatives only among optional parameters (§5.2), so the
    installed module (lib/typing/installed/*.sys) declares the alternatives as one optional
    group, and this table says which groups are in fact required: the checker makes such a
    group a {!Env.Required_choice}, which takes the argument in its place (the alternative
    named by the argument, or else the one whose type the argument has) and refuses a call
    that gives none. The engines see an optional group: the alternative not chosen is absent.

    The table is data: a routine joins it with its group's names, nothing else changes. *)

val required : (string * string list) list
(** Each routine (ABB's name) with the names of one group of its alternatives that is
    required. *)

val apply : string -> Env.parameter_slot list -> Env.parameter_slot list
(** [apply routine slots]: the slots of an installed routine, each optional group the table
    names for it made a required choice. *)
