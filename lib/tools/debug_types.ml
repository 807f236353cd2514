open Rapid_syntax
module E = Rapid_typing.Env

let key = String.lowercase_ascii

let ident (i : Ast.identifier) = match i.it with Ident n -> key n | ID_placeholder -> ""

let inside (outer : Source.region) (r : Source.region) =
  (match Source.file_of outer, Source.file_of r with
   | Some a, Some b -> Source.name a = Source.name b
   | _ -> false)
  && Source.start_offset outer <= Source.start_offset r && Source.stop_offset r <= Source.stop_offset outer

let writable (d : E.data_object) =
  match d.d_kind with
  | Variable | Persistent | Parameter _ -> true | Constant | Loop_variable | Read_only_variable -> false

let type_of modules =
  let objects =
    match Session.installed () with
    | Error _ -> []
    | Ok installed ->
        let result = Rapid_typing.Check.check_task ~installed modules in
        Rapid_syntax.Source.Table.fold (fun _ o acc -> match o with E.Data d -> d :: acc | _ -> acc)
          result.elaboration.declared [] in
  (* Routine data, parameters and loop variables by the routine whose text holds them. *)
  let routines = List.concat_map (fun (m : Ast.module_declaration) ->
      List.filter_map (fun (r : Ast.routine_declaration) ->
          match r.it with
          | Procedure_declaration { name; _ } | Function_declaration { name; _ } | Trap_declaration { name; _ } ->
              Some ((ident m.module_name, ident name), r.at)
          | Routine_comment _ | RDN_placeholder -> None) m.routine_declarations) modules in
  let in_routine = Hashtbl.create 64 and global = Hashtbl.create 256 in
  List.iter (fun (d : E.data_object) ->
      match d.d_level with
      | Routine_level -> (
          match List.find_opt (fun (_, at) -> inside at d.d_region) routines with
          | Some (k, _) -> Hashtbl.add in_routine (k, key d.d_name) d
          | None -> ())
      | Module_level _ -> Hashtbl.replace global (key d.d_name) d
      | Installed_level -> if not (Hashtbl.mem global (key d.d_name)) then Hashtbl.replace global (key d.d_name) d)
    objects;
  fun (r : Ir.routine) name ->
    let found = match Hashtbl.find_opt in_routine ((key r.module_name, key r.name), key name) with
      | Some d -> Some d
      | None -> Hashtbl.find_opt global (key name) in
    Option.map (fun (d : E.data_object) -> (d.d_type, writable d)) found
