(** What the typing judgement learns about a program and the dynamic semantics needs: what each
    name denotes, which row of the operator table each operation uses, which numeric literals are
    dnum, and how the arguments of each call bind to parameters. Keys are the regions of the syntax
    tree's nodes: the region of a name's occurrence, of an operation, of a call's routine name. *)

open Rapid_syntax

type binding = {
  callee : Env.routine;
  bound : (Env.parameter * Ast.argument) list;   (** in parameter order; absent ones left out *)
}

type t = {
  names : Env.obj Source.Table.t;
      (** an occurrence of a name (data object, routine, label) → what it denotes *)
  declared : Env.obj Source.Table.t;
      (** the name of a declaration (data, parameter, loop variable, routine) → its object *)
  components : int Source.Table.t;
      (** a component name in a reference → its index in the record type *)
  binary : Tables.binary_row Source.Table.t;
  unary : Tables.unary_row Source.Table.t;
  dnum_literals : unit Source.Table.t;
      (** a numeric-literal expression (literals and operators on them only) the context takes
          as dnum (§2.5, doc/rulings.md R-2.5-b) *)
  bindings : binding Source.Table.t;
      (** a call, by the region of the call (the function call expression, or the procedure
          call statement) → its arguments' binding (§3.11, §4.6) *)
  aggregates : [ `Record | `Array ] Source.Table.t;
      (** an aggregate → the kind of value its context gives it (§3.10) *)
  late_arguments : Types.object_type option Source.Table.t;
      (** an argument of a late-bound procedure call (§4.6), by the argument's region → its
          type ([None]: a numeric literal expression, num or dnum as its parameter wants); not
          there: no type (an aggregate, an unknown name). The binding checks it when the call
          runs. *)
  installed : t option;
      (** The elaboration of the installed level, when it is shared by every task (the checker
          checks the installed modules once, lib/typing/check.ml): the entries of the installed
          modules' nodes are there, not in the tables above, which hold the task's own nodes. [None]:
          the tables hold both. *)
}

val create : ?text:int -> ?installed:t -> unit -> t
