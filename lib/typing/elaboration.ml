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
let create ?(text = 0) ?installed () =
  let n = match installed with Some _ -> 16 | None -> 1024 in
  let table = Source.Table.create in
  (* A large program's names and calls sized from its text at once (about a name every eight
     characters, a call every forty), not doubled a dozen times on the way. *)
  { names = table (max n (text / 8)); declared = table n; components = table (n / 4);
    binary = table (n / 4); unary = table (n / 16); dnum_literals = table (n / 16);
    bindings = table (max (n / 4) (text / 40)); aggregates = table (n / 4);
    late_arguments = table 16; installed }
