(** The bodies of installed routines (ch. 11, 13): the routines declared in
    lib/typing/installed are bound by name to the OCaml functions here when a program runs. The
    pure functions come from {!Library}; this module adds the routines that need more than values:
    output (TPWrite), the locations of their arguments (Incr, Dim, IsVar), the machine (BookErrNo,
    CallByVar, Stop). *)

(** An argument, one per parameter of the routine's declaration in order (alternatives each in
    their own place). *)
open Primitive

val call : context -> string -> argument array -> outcome
(** [Not_modelled]: not one of these routines. *)

val modelled : string -> bool
(** Whether this module gives the installed routine a body. *)

val pure : string -> (argument array -> outcome) option
(** The body of a function of {!Library} by name, when no special case of {!call} takes it: what
    {!call} does for it, without the look-up by name at each call. *)

val pure_values : string -> (Value.t option array -> Library.result) option
(** The same function on the arguments' values (None for an absent one): {!pure} is
    [Array.map value_of] and then this. *)

val pure_fixed : string -> Installed_routine.fixed option
(** The same by its number of parameters ({!Library.find_fixed}), when {!pure_values} gives it. *)
