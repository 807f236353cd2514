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
  installed : t option;
}

(* A task's own tables start small when the installed level's are apart: a fuzzing campaign
   makes them for thousands of small programs, and a large first size is memory the major
   collector has to go through. *)
let create ?installed () =
  let n = match installed with Some _ -> 16 | None -> 1024 in
  { names = Hashtbl.create n; declared = Hashtbl.create n; components = Hashtbl.create (n / 4);
    binary = Hashtbl.create (n / 4); unary = Hashtbl.create (n / 16); dnum_literals = Hashtbl.create (n / 16);
    bindings = Hashtbl.create (n / 4); aggregates = Hashtbl.create (n / 4);
    late_arguments = Hashtbl.create 16; installed }
