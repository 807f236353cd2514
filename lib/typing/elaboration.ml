open Rapid_syntax

type binding = { callee : Env.routine; bound : (Env.parameter * Ast.argument) list }

type t = {
  names : (Source.region, Env.obj) Hashtbl.t;
  declared : (Source.region, Env.obj) Hashtbl.t;
  components : (Source.region, int) Hashtbl.t;
  binary : (Source.region, Tables.binary_row) Hashtbl.t;
  unary : (Source.region, Tables.unary_row) Hashtbl.t;
  dnum_literals : (Source.region, unit) Hashtbl.t;
  bindings : (Source.region, binding) Hashtbl.t;
  aggregates : (Source.region, [ `Record | `Array ]) Hashtbl.t;
  late_arguments : (Source.region, Types.object_type option) Hashtbl.t;
}

let create () = {
  names = Hashtbl.create 1024; declared = Hashtbl.create 1024; components = Hashtbl.create 256;
  binary = Hashtbl.create 256; unary = Hashtbl.create 64; dnum_literals = Hashtbl.create 64;
  bindings = Hashtbl.create 256; aggregates = Hashtbl.create 256;
  late_arguments = Hashtbl.create 16;
}

let copy e = {
  names = Hashtbl.copy e.names; declared = Hashtbl.copy e.declared; components = Hashtbl.copy e.components;
  binary = Hashtbl.copy e.binary; unary = Hashtbl.copy e.unary; dnum_literals = Hashtbl.copy e.dnum_literals;
  bindings = Hashtbl.copy e.bindings; aggregates = Hashtbl.copy e.aggregates;
  late_arguments = Hashtbl.copy e.late_arguments;
}
