open Rapid_syntax

type binding = { callee : Env.routine; bound : (Env.parameter * Ast.argument) list }

type t = {
  names : Env.obj Source.Table.t;
  declared : Env.obj Source.Table.t;
  components : int Source.Table.t;
  binary : Tables.binary_row Source.Table.t;
  unary : Tables.unary_row Source.Table.t;
  dnum_literals : unit Source.Table.t;
  bindings : binding Source.Table.t;
  aggregates : [ `Record | `Array ] Source.Table.t;
  late_arguments : Types.object_type option Source.Table.t;
  installed : t option;
}

(* A task's own tables start small when the installed level's are apart: a fuzzing campaign
   makes them for thousands of small programs, and a large first size is memory the major
   collector has to go through. *)
let create ?installed () =
  let n = match installed with Some _ -> 16 | None -> 1024 in
  let table = Source.Table.create in
  { names = table n; declared = table n; components = table (n / 4);
    binary = table (n / 4); unary = table (n / 16); dnum_literals = table (n / 16);
    bindings = table (n / 4); aggregates = table (n / 4);
    late_arguments = table 16; installed }
