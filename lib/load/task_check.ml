(* ch. 14 across task buffers: what `run --task` refuses before the run (Task_set, R-14-c),
   judged statically, so that `check --task` reports it with the other static errors. *)

open Rapid_syntax
module R = Rapid_typing.Report
module Env = Rapid_typing.Env
module Types = Rapid_typing.Types

type task = {
  name : string;
  modules : Ast.module_declaration list;
  elaboration : Rapid_typing.Elaboration.t;
}

(* The type as R-14-c compares it: the name written, and the evaluated sizes of an array (the
   judgement evaluated the dimensions, so a constant and a literal of one value agree). *)
let type_text (t : task) (decl_name : Ast.identifier) type_name =
  match Source.Table.find_opt t.elaboration.declared decl_name.at with
  | Some (Env.Data { d_type = { dims = Types.Sized sizes; _ }; _ }) ->
      type_name ^ "{" ^ String.concat ", " (List.map string_of_int sizes) ^ "}"
  | _ -> type_name

let shared_persistents tasks =
  let report = R.create () in
  let first = Hashtbl.create 16 in
  List.iter (fun (t : task) ->
      List.iter (fun (m : Ast.module_declaration) ->
          List.iter (fun (d : Ast.data_declaration) ->
              match d.it with
              | Data_declaration
                  { scope = Global; storage = Pers; data_type; name = { it = Ident name; _ } as id; _ } -> (
                  let written = match data_type.it with Ident s -> s | ID_placeholder -> "" in
                  let text = type_text t id written in
                  let key = String.lowercase_ascii name in
                  match Hashtbl.find_opt first key with
                  | None -> Hashtbl.replace first key (text, t.name)
                  | Some (text0, task0) when String.lowercase_ascii text0 <> String.lowercase_ascii text ->
                      (* ch. 14: persistents "以同样的名称和类型进行声明" (declared with the same name and type) share one value. *)
                      R.error report ~rule:"pers-one-type" ~section:"14" d.at
                        (Printf.sprintf "the persistent %s is %s in task %s but %s here: \
                                         a system-global persistent has one type in every task"
                           name text0 task0 text)
                  | Some _ -> ())
              | _ -> ()) m.data_declarations) t.modules) tasks;
  R.all report
