(** The observable events schema [rapid-sem/2] adds to [rapid-sem/1] (doc/observable.md), and
    the canonical text of values and places both engines write them with.

    The texts are computed where the event happens, only when the run observes them
    ([Machine.start ~observe], [Closure_engine.run ~observe]): a plain run never builds them. *)

type t =
  | Stored of { place : string; value : string }
      (** a data object, or a part of it, written: the place as RAPID writes it ([a{2}.x]) and
          the value written: an assignment (§4.5), FOR's variable (§4.18), routine data's initial
          value (§2.21), CONNECT (§4.15), an installed routine's write through a reference
          parameter that changes the value (§5.2) *)
  | Called of { routine : string; arguments : (string * string option) list }
      (** after [Routine_entered]: each present argument by its parameter's name, with the
          value the parameter has on entry ([None] for a switch, §5.2; R-4.6-m) *)
  | Returned of { routine : string; value : string }
      (** before [Routine_left]: the value a function returns (§4.10) *)
  | Propagated of { name : string; number : int; routine : string; caller : string }
      (** the error left [routine] without being handled and is raised again at the call point
          in [caller] (§7.1) *)
  | Retried of string                     (** RETRY in this routine's error handler (§4.13) *)
  | Tried_next of string                  (** TRYNEXT in this routine's error handler (§4.14) *)

val value : Value.t -> string
(** A value in RAPID's literal syntax, one text per value: a num with the fewest significant
    digits that read back to the same single-precision number (an integer in plain decimal
    notation, padded with zeros: [9000000000] for 9E+09, never the 8999999488 it is stored as),
    a dnum with the fewest that read back to the same double, minus zero as [0]; strings as §2.7
    writes them; [TRUE], [FALSE]; records and arrays as [[a,b,c]]; an installed object as
    [<kind #n>] (doc/rulings.md R-4.5-m). *)

type step = Index of int | Component_of of int
(** [Index] from 1, [Component_of] from 0. *)

val path_within : Value.t array * int -> Value.t -> step list option
(** The path from a record or array value down to a location inside it (the container and the
    index there), or [None] when the value does not hold it. *)

val routine_index : Ir.program -> Ir.routine -> int
(** The routine's index in the program's table, [-1] when it is not there. *)

val slot_name : Ir.program -> int -> Ir.slot -> string
(** The name of a slot of the routine of that index (module data by its own name). *)

val component_name : Ir.program -> int -> Ir.slot -> int list -> int -> string
(** The name of component [k] at a path of components within a slot's record value. *)

type roots = {
  n_locals : int;
  local : int -> Value.t array * int;       (** the location of local slot [i] *)
  n_globals : int;
  global_box : int -> Value.t array;        (** the location of module data [g]: its container *)
  global_idx : int -> int;                  (** and its index there *)
}
(** The data objects a place can be named by: the routine's local slots (a reference parameter's
    being the location it denotes) and the module data, as an engine stores them. *)

val find : Value.t array * int -> roots -> (Ir.slot * step list) option
(** Where a location is: first a data object that is the location itself, local slots before
    module data (a reference parameter before the data it denotes: the routine that writes it
    names it so); else one that holds it in a record or an array, local slots first. Both
    engines give their roots alike, so they name a place the same way. *)

val place : Ir.program -> Ir.routine -> Ir.slot * step list -> string
(** The place as RAPID writes it, in [routine]: [total], [a{2}], [m{2,3}], [path{1}.x]; a place a
    reference parameter denotes by the parameter's name. *)

val place_of : Ir.program -> Ir.routine -> Value.t array * int -> roots -> string
(** [find], then [place]; a location no root holds is written [<a value no data object holds>]. *)

val to_string : t -> string
(** One line, for the engines' comparisons and the fuzzer's reports. *)

val references : Argument.t array -> (Value.t array * int * Value.t) list
(** The locations an installed routine's reference arguments denote, with a copy of their values
    before the call (Incr, Add, Clear and the like write through them, §5.2). *)

val changed : (Value.t array * int * Value.t) list -> (Value.t array * int) list
(** Those whose value the call changed, in argument order: the store writes it made. *)
