open Rapid_syntax

type routine_kind = Proc | Func of string | Trap_routine

type param = { p_name : string; p_mode : string; p_type : string option; p_dims : int }

type slot = Required of param | Optional of param list

type kind =
  | Module
  | Record of (string * string) list
  | Alias of string
  | Atomic
  | Data of { storage : string; type_name : string; dims : int; parameter : bool }
  | Routine of { routine : routine_kind; slots : slot list }
  | Component of { record : string; type_name : string }
  | Label

type decl = {
  name : string;
  kind : kind;
  uri : string option;
  name_start : int;
  name_stop : int;
  decl_start : int;
  decl_stop : int;
  module_name : string;
  routine : string option;
  local : bool;
  installed_file : string option;
}

type occurrence = { o_start : int; o_stop : int; decl : decl }

type source = { uri : string; text : Lsp_text.t; ast : Ast.module_declaration; fresh : bool }

let key s = String.lowercase_ascii s

let same_decl (a : decl) (b : decl) =
  a.uri = b.uri && a.installed_file = b.installed_file && a.name_start = b.name_start && key a.name = key b.name

(* A level of names: every declaration of a name (a type and a parameter may share one). *)
type level = (string, decl) Hashtbl.t

let find_in (l : level) name pred = List.find_opt pred (List.rev (Hashtbl.find_all l (key name)))
let add (l : level) d = Hashtbl.add l (key d.name) d

(* The declarations that belong to another: a routine's parameters, a record's components. *)
type members = (string, decl list) Hashtbl.t

let member_key (d : decl) =
  Printf.sprintf "%s|%s|%d|%s" (Option.value d.uri ~default:"") (Option.value d.installed_file ~default:"")
    d.name_start (key d.name)

let ident_name (i : Ast.identifier) = match i.it with Ast.Ident s -> Some s | ID_placeholder -> None

let offsets (r : Source.region) =
  if r = Source.no_region then None else Some (Source.start_offset r, Source.stop_offset r)

(* {1 Declarations} *)

let mode_name : Ast.access_mode -> string = function
  | In -> "" | Var_mode -> "VAR" | Pers_mode -> "PERS" | Inout -> "INOUT" | Ref_mode -> "REF"

let storage_name : Ast.storage -> string = function Var -> "VAR" | Pers -> "PERS" | Const -> "CONST"

type ctx = {
  uri : string option;
  file : string option;
  module_name : string;
  members : members;
}

let make ctx ?routine ?(local = false) ~at ~whole name kind =
  let ns, ne = Option.value (offsets at) ~default:(0, 0) in
  let ds, de = Option.value (offsets whole) ~default:(ns, ne) in
  { name; kind; uri = ctx.uri; name_start = ns; name_stop = ne; decl_start = ds; decl_stop = de;
    module_name = ctx.module_name; routine; local; installed_file = ctx.file }

let param_of (p : Ast.parameter_declaration) =
  match p.it with
  | Parameter { mode; data_type; name; array } ->
      Option.map (fun n ->
          ({ p_name = n; p_mode = mode_name mode; p_type = ident_name data_type;
             p_dims = (match array with Conformant k -> k | Not_array | DIM_placeholder -> 0) }, name.at))
        (ident_name name)
  | Switch name -> Option.map (fun n -> ({ p_name = n; p_mode = ""; p_type = None; p_dims = 0 }, name.at))
                     (ident_name name)

let slots_of (ps : Ast.parameter list) =
  List.filter_map (fun (p : Ast.parameter) ->
      match p.it with
      | Required_parameter d -> Option.map (fun (q, at) -> (Required q, [ (q, at) ])) (param_of d)
      | Optional_parameter alts ->
          let qs = List.filter_map (fun (a : Ast.alternative) ->
              match a.it with Alternative d -> param_of d | ALT_placeholder -> None) alts in
          if qs = [] then None else Some (Optional (List.map fst qs), qs)
      | PAR_placeholder -> None) ps

let param_decl ctx routine (q, at) =
  make ctx ~routine ~local:true ~at ~whole:at q.p_name
    (Data { storage = (if q.p_mode = "" then "IN" else q.p_mode);
            type_name = Option.value q.p_type ~default:"switch"; dims = q.p_dims;
            parameter = true })

let data_decl ctx ?routine (d : Ast.data_declaration) =
  match d.it with
  | Data_declaration { scope; storage; data_type; name; dims; _ } -> (
      match ident_name name, ident_name data_type with
      | Some n, Some t ->
          Some (make ctx ?routine ~local:(routine <> None || scope = Local) ~at:name.at ~whole:d.at n
                  (Data { storage = storage_name storage; type_name = t; dims = List.length dims;
                          parameter = false }))
      | _ -> None)
  | Declaration_comment _ | DDN_placeholder -> None

let type_decl ctx (t : Ast.type_definition) =
  match t.it with
  | Record_definition { local; name; components } -> (
      match ident_name name with
      | None -> None
      | Some n ->
          let comps = List.filter_map (fun (c : Ast.record_component) ->
              match c.it with
              | Record_component (ty, cn) -> (
                  match ident_name ty, ident_name cn with
                  | Some ty, Some cn -> Some (ty, cn, cn, c.at)
                  | _ -> None)
              | Component_comment _ -> None) components in
          let d = make ctx ~local ~at:name.at ~whole:t.at n
              (Record (List.map (fun (ty, cn, _, _) -> (ty, cn)) comps)) in
          let comp_decls = List.filter_map (fun (c : Ast.record_component) ->
              match c.it with
              | Record_component (ty, cn) -> (
                  match ident_name ty, ident_name cn with
                  | Some ty, Some cs ->
                      Some (make ctx ~at:cn.at ~whole:c.at cs (Component { record = n; type_name = ty }))
                  | _ -> None)
              | Component_comment _ -> None) components in
          Hashtbl.replace ctx.members (member_key d) comp_decls;
          Some d)
  | Alias_definition { local; base; name } -> (
      match ident_name name, ident_name base with
      | Some n, Some b -> Some (make ctx ~local ~at:name.at ~whole:t.at n (Alias b))
      | _ -> None)
  | Type_comment _ | TDN_placeholder -> None

let routine_decl ctx (r : Ast.routine_declaration) =
  let mk local name params routine =
    match ident_name name with
    | None -> None
    | Some n ->
        let slots = slots_of params in
        let d = make ctx ~local ~at:name.at ~whole:r.at n (Routine { routine; slots = List.map fst slots }) in
        Hashtbl.replace ctx.members (member_key d)
          (List.concat_map (fun (_, qs) -> List.map (param_decl ctx n) qs) slots);
        Some d in
  match r.it with
  | Procedure_declaration { local; name; parameters; _ } -> mk local name parameters Proc
  | Function_declaration { local; return_type; name; parameters; _ } ->
      mk local name parameters (Func (Option.value (ident_name return_type) ~default:"?"))
  | Trap_declaration { local; name; _ } -> mk local name [] Trap_routine
  | Routine_comment _ | RDN_placeholder -> None

(* The module-level declarations of a module, in source order (types, data, routines: §9.2). *)
let module_decls ctx (m : Ast.module_declaration) =
  let name = Option.value (ident_name m.module_name) ~default:"" in
  let md = make ctx ~at:m.module_name.at ~whole:m.module_region name Module in
  (md, List.filter_map (type_decl ctx) m.type_definitions
       @ List.filter_map (data_decl ctx) m.data_declarations
       @ List.filter_map (routine_decl ctx) m.routine_declarations)

(* {1 The installed environment} *)

let atomic = [ "num"; "dnum"; "bool"; "string" ]

type installed = { i_decls : decl list; i_level : level; i_members : members }

let index_installed modules =
  lazy
    (let members = Hashtbl.create 512 in
     let level = Hashtbl.create 1024 in
     let decls =
       match modules with
       | Error _ -> []
       | Ok modules ->
           List.concat_map (fun (m : Ast.module_declaration) ->
               let file = match Source.file_of m.module_region with Some f -> Source.name f | None -> "installed" in
               let ctx = { uri = None; file = Some file; members;
                           module_name = Option.value (ident_name m.module_name) ~default:"" } in
               (* Only what a program sees: LOCAL declarations of an installed module stay inside it. *)
               List.filter (fun d -> not d.local) (snd (module_decls ctx m))) modules in
     let ctx = { uri = None; file = Some "built-in"; members; module_name = "" } in
     let none = Source.no_region in
     let atomics = List.map (fun n -> make ctx ~at:none ~whole:none n Atomic)
         (atomic @ List.map (fun (n, _, _) -> n) Rapid_typing.Installed_atomic.atomic_types) in
     (* §2.14, §2.15: the kernel's records and aliases, which no installed module declares *)
     let records = List.map (fun (n, cs) ->
         let d = make ctx ~at:none ~whole:none n (Record (List.map (fun (c, t) -> (t, c)) cs)) in
         Hashtbl.replace members (member_key d)
           (List.map (fun (c, t) -> make ctx ~at:none ~whole:none c (Component { record = n; type_name = t })) cs);
         d) Rapid_typing.Tables.builtin_records in
     let aliases =
       List.map (fun (n, b) -> make ctx ~at:none ~whole:none n (Alias b)) Rapid_typing.Tables.builtin_aliases in
     let decls = atomics @ records @ aliases @ decls in
     List.iter (add level) decls;
     { i_decls = decls; i_level = level; i_members = members })

(* The installed modules taken at the first use, not at initialisation: a command that needs no
   installed environment (a usage error, --version) does not read the image. *)
let current = ref (lazy (Lazy.force (index_installed (Rapid_typing.Installed_env.modules ()))))

let use_installed modules = current := index_installed (Ok modules)

let installed_decls () = (Lazy.force !current).i_decls

(* {1 The index of a task} *)

type module_info = {
  source : source;
  module_decl : decl;
  top : decl list;              (* module level *)
  inner : decl list;            (* routine level: parameters, data, labels, loop variables *)
  module_level : level;
  mutable occurrences : occurrence list;
}

type t = {
  modules : module_info list;
  globals : level;
  members : members;
}

let sources t = List.map (fun m -> m.source) t.modules
let find_module t uri = List.find_opt (fun m -> m.source.uri = uri) t.modules
let source t uri = Option.map (fun m -> m.source) (find_module t uri)

let decls t uri =
  match find_module t uri with
  | None -> []
  | Some m ->
      List.sort (fun a b -> compare a.decl_start b.decl_start) ((m.module_decl :: m.top) @ m.inner)

let all_decls t = List.concat_map (fun m -> m.module_decl :: m.top @ m.inner) t.modules

let is_type d = match d.kind with Record _ | Alias _ | Atomic -> true | _ -> false
let is_data d = match d.kind with Data _ -> true | _ -> false
let is_routine d = match d.kind with Routine _ -> true | _ -> false
let is_label d = match d.kind with Label -> true | _ -> false
let is_object d = not (is_type d) && not (is_label d) && d.kind <> Module

let members_of t d =
  match Hashtbl.find_opt t.members (member_key d) with
  | Some l -> l
  | None -> Option.value (Hashtbl.find_opt (Lazy.force !current).i_members (member_key d)) ~default:[]

(* The levels of ch. 13 from a routine outwards. A name hidden by a module's own declaration is
   found there first; the installed level comes last. *)
let levels t (m : module_info) routine_levels =
  routine_levels @ [ m.module_level; t.globals; (Lazy.force !current).i_level ]

let lookup_levels levels name pred = List.find_map (fun l -> find_in l name pred) levels

let type_of_decl d =
  match d.kind with
  | Data { type_name; _ } | Component { type_name; _ } -> Some type_name
  | Routine { routine = Func r; _ } -> Some r
  | _ -> None

(* A record type's components, aliases followed (at most a few steps: §2.15 forbids cycles, and
   the checker reports them; the bound keeps a broken program from looping here). *)
let rec components t levels type_name steps =
  if steps = 0 then [] else
    match lookup_levels levels type_name is_type with
    | Some ({ kind = Record _; _ } as d) -> members_of t d
    | Some { kind = Alias b; _ } -> components t levels b (steps - 1)
    | _ -> []

(* {2 Walking a module} *)

type walk = {
  index : t;
  info : module_info;
  text : Lsp_text.t;
  mutable routine_levels : level list;
  mutable found : occurrence list;
}

(* A use is recorded only where the text holds the name as written (case aside): a rename then
   edits exactly the name, whatever region the tree gives a node. *)
let emit w (at : Source.region) name decl =
  match offsets at with
  | Some (s, e) when key (Lsp_text.slice w.text s e) = key name ->
      w.found <- { o_start = s; o_stop = e; decl } :: w.found
  | _ -> ()

let resolve w (at : Source.region) name pred =
  match lookup_levels (levels w.index w.info w.routine_levels) name pred with
  | Some d -> emit w at name d; Some d
  | None -> None

let resolve_id w (i : Ast.identifier) pred =
  match ident_name i with Some n -> resolve w i.at n pred | None -> None

let rec expression w (e : Ast.expression) = expression_desc w e.it e.at

and expression_desc w (d : Ast.expression_desc) at =
  match d with
  | Num_literal _ | String_literal _ | Bool_literal _ | EXP_placeholder -> ()
  | Data_reference r -> ignore (reference w { Ast.it = r; at })
  | Function_call f ->
      let callee = resolve_id w f.func (fun d -> match d.kind with Routine { routine = Func _; _ } -> true
                                                                 | _ -> false) in
      arguments w callee (Ast.call_arguments f)
  | Aggregate (ds, rs) -> Array.iteri (fun i d -> expression_desc w d rs.(i)) ds
  | Unary (_, d, r) -> expression_desc w d r
  | Binary (_, a, b) -> expression w a; expression w b

(* The type of the reference, when known, for the component after it. *)
and reference w (r : Ast.data_reference) : string option =
  let data name at = Option.bind (resolve w at name is_object) type_of_decl in
  match r.it with
  | Entire s -> data s r.at
  | Element (n, idx) -> let t = data n.it n.at in List.iter (expression w) idx; t
  | Component (inner, n) -> (
      match reference w inner with
      | None -> None
      | Some ty ->
          let comps = components w.index (levels w.index w.info w.routine_levels) ty 8 in
          match List.find_opt (fun c -> key c.name = key n.it) comps with
          | Some c -> emit w n.at n.it c; type_of_decl c
          | None -> None)
  | VAR_placeholder -> None

and arguments w callee (args : Ast.argument array) =
  let params = match callee with Some c -> members_of w.index c | None -> [] in
  let param (i : Ast.identifier) =
    match ident_name i with
    | Some n -> (match List.find_opt (fun p -> key p.name = key n) params with
        | Some p -> emit w i.at n p | None -> ())
    | None -> () in
  Array.iter (fun (a : Ast.argument) ->
      match a.it with
      | Required_argument (name, d, r) -> Option.iter param name; expression_desc w d r
      | Positional_argument d -> expression_desc w d a.at
      | Optional_argument (i, e) -> param i; Option.iter (expression w) e
      | Conditional_argument (i, r) -> param i; ignore (reference w r)
      | ARG_placeholder -> ()) args

let rec statement w (s : Ast.statement) =
  match s.it with
  | Assignment (r, e) -> ignore (reference w r); expression w e
  | Procedure_call (Procedure_name id, descs, regions) ->
      let callee = resolve_id w id is_routine in
      arguments w callee (Ast.arguments descs regions)
  | Procedure_call (Late_bound e, descs, regions) ->
      expression w e; arguments w None (Ast.arguments descs regions)
  | Goto id -> ignore (resolve_id w id is_label)
  | Return e | Raise e -> Option.iter (expression w) e
  | Connect (r, id) ->
      ignore (reference w r);
      ignore (resolve_id w id (fun d -> match d.kind with Routine { routine = Trap_routine; _ } -> true | _ -> false))
  | If i ->
      expression w i.condition; statements w i.then_branch;
      List.iter (fun (c : Ast.elseif_clause) -> match c.it with
          | Elseif (e, b) -> expression w e; statements w b | EIT_placeholder -> ()) i.elseifs;
      Option.iter (statements w) i.else_branch
  | Compact_if (e, s) -> expression w e; statement w s
  | For f ->
      expression w f.from_; expression w f.to_; Option.iter (expression w) f.step;
      (* §4.18: the loop variable is declared by the loop, over its body only. *)
      let level = Hashtbl.create 1 in
      (match List.find_opt (fun d -> d.name_start = Source.start_offset f.loop_variable.at
                                     && (match d.kind with Data { storage = "FOR"; _ } -> true | _ -> false))
               w.info.inner with
       | Some d -> add level d; emit w f.loop_variable.at d.name d
       | None -> ());
      let saved = w.routine_levels in
      w.routine_levels <- level :: saved;
      statements w f.body;
      w.routine_levels <- saved
  | While (e, b) -> expression w e; statements w b
  | Test t ->
      expression w t.test_expression;
      List.iter (fun (c : Ast.case_clause) -> match c.it with
          | Case (es, b) -> List.iter (expression w) es; statements w b | CSE_placeholder -> ()) t.cases;
      Option.iter (statements w) t.default
  | Label id -> ignore (resolve_id w id is_label)
  | Break | Continue | Exit | Retry | Trynext | Statement_comment _ | SMT_placeholder -> ()

and statements w l = List.iter (statement w) l

(* The labels (§4.4) and loop variables (§4.18) of a routine body, at any depth. *)
let rec inner_names ctx routine acc (s : Ast.statement) =
  let more l = List.fold_left (inner_names ctx routine) acc l in
  let more_acc acc l = List.fold_left (inner_names ctx routine) acc l in
  match s.it with
  | Label id -> (match ident_name id with
      | Some n -> make ctx ~routine ~local:true ~at:id.at ~whole:s.at n Label :: acc | None -> acc)
  | If i ->
      let acc = more i.then_branch in
      let acc = List.fold_left (fun acc (c : Ast.elseif_clause) ->
          match c.it with Elseif (_, b) -> more_acc acc b | EIT_placeholder -> acc) acc i.elseifs in
      (match i.else_branch with Some b -> more_acc acc b | None -> acc)
  | Compact_if (_, s) -> inner_names ctx routine acc s
  | For f ->
      let acc = match ident_name f.loop_variable with
        | Some n -> make ctx ~routine ~local:true ~at:f.loop_variable.at ~whole:s.at n
                      (Data { storage = "FOR"; type_name = "num"; dims = 0; parameter = false }) :: acc
        | None -> acc in
      more_acc acc f.body
  | While (_, b) -> more b
  | Test t ->
      let acc = List.fold_left (fun acc (c : Ast.case_clause) ->
          match c.it with Case (_, b) -> more_acc acc b | CSE_placeholder -> acc) acc t.cases in
      (match t.default with Some b -> more_acc acc b | None -> acc)
  | _ -> acc

let body_statements (b : Ast.routine_body) =
  b.statements @ Option.value b.backward ~default:[]
  @ (match b.error with Some e -> e.handler | None -> []) @ Option.value b.undo ~default:[]

let routine_parts (r : Ast.routine_declaration) =
  match r.it with
  | Procedure_declaration { name; parameters; body; _ } -> Some (name, parameters, None, body)
  | Function_declaration { name; parameters; body; return_type; _ } -> Some (name, parameters, Some return_type, body)
  | Trap_declaration { name; body; _ } -> Some (name, [], None, body)
  | Routine_comment _ | RDN_placeholder -> None

let data_declaration w decl (d : Ast.data_declaration) =
  match d.it with
  | Data_declaration { data_type; name; dims; initial_value; _ } ->
      ignore (resolve_id w data_type is_type);
      List.iter (expression w) dims;
      Option.iter (expression w) initial_value;
      Option.iter (fun dd -> emit w name.at dd.name dd) decl
  | Declaration_comment _ | DDN_placeholder -> ()

let find_decl l (at : Source.region) =
  match offsets at with
  | Some (s, _) -> List.find_opt (fun d -> d.name_start = s) l
  | None -> None

let walk_module w =
  let m = w.info.source.ast in
  let top = w.info.top in
  emit w m.module_name.at w.info.module_decl.name w.info.module_decl;
  List.iter (fun (t : Ast.type_definition) ->
      match t.it with
      | Record_definition { name; components; _ } ->
          let d = find_decl top name.at in
          Option.iter (fun d -> emit w name.at d.name d) d;
          let comps = match d with Some d -> members_of w.index d | None -> [] in
          List.iter (fun (c : Ast.record_component) -> match c.it with
              | Record_component (ty, cn) ->
                  ignore (resolve_id w ty is_type);
                  Option.iter (fun d -> emit w cn.at d.name d) (find_decl comps cn.at)
              | Component_comment _ -> ()) components
      | Alias_definition { base; name; _ } ->
          ignore (resolve_id w base is_type);
          Option.iter (fun d -> emit w name.at d.name d) (find_decl top name.at)
      | Type_comment _ | TDN_placeholder -> ()) m.type_definitions;
  List.iter (fun (d : Ast.data_declaration) ->
      match d.it with
      | Data_declaration { name; _ } -> data_declaration w (find_decl top name.at) d
      | _ -> ()) m.data_declarations;
  List.iter (fun (r : Ast.routine_declaration) ->
      match routine_parts r with
      | None -> ()
      | Some (name, parameters, return_type, body) ->
          let rd = find_decl top name.at in
          Option.iter (fun d -> emit w name.at d.name d) rd;
          Option.iter (fun t -> ignore (resolve_id w t is_type)) return_type;
          let rname = Option.value (ident_name name) ~default:"" in
          let level = Hashtbl.create 16 in
          let params = match rd with Some d -> members_of w.index d | None -> [] in
          List.iter (add level) params;
          let mine = List.filter (fun d -> d.routine = Some rname && d.decl_start >= Source.start_offset r.at
                                           && d.decl_stop <= Source.stop_offset r.at) w.info.inner in
          List.iter (fun d -> match d.kind with
              | Data { storage = "FOR"; _ } -> () | _ -> add level d) mine;
          w.routine_levels <- [ level ];
          (* The parameters' types and names. *)
          List.iter (fun (p : Ast.parameter) ->
              let decl (pd : Ast.parameter_declaration) = match pd.it with
                | Parameter { data_type; name; _ } ->
                    ignore (resolve_id w data_type is_type);
                    Option.iter (fun d -> emit w name.at d.name d) (find_decl params name.at)
                | Switch name -> Option.iter (fun d -> emit w name.at d.name d) (find_decl params name.at) in
              match p.it with
              | Required_parameter pd -> decl pd
              | Optional_parameter alts ->
                  List.iter (fun (a : Ast.alternative) -> match a.it with
                      | Alternative pd -> decl pd | ALT_placeholder -> ()) alts
              | PAR_placeholder -> ()) parameters;
          List.iter (fun (d : Ast.data_declaration) ->
              match d.it with
              | Data_declaration { name; _ } -> data_declaration w (find_decl mine name.at) d
              | _ -> ()) body.declarations;
          statements w body.statements;
          Option.iter (statements w) body.backward;
          Option.iter (fun (e : Ast.error_handler) ->
              Option.iter (List.iter (fun (n : Ast.recovery_error_number) -> match n.it with
                  | Error_number_name nm -> ignore (resolve w nm.at nm.it is_data)
                  | Error_number_literal _ -> ())) e.error_numbers;
              statements w e.handler) body.error;
          Option.iter (statements w) body.undo;
          w.routine_levels <- []) m.routine_declarations

let build sources =
  let members = Hashtbl.create 256 in
  let globals = Hashtbl.create 256 in
  let modules = List.map (fun (s : source) ->
      let ctx = { uri = Some s.uri; file = None; members;
                  module_name = Option.value (ident_name s.ast.module_name) ~default:"" } in
      let module_decl, top = module_decls ctx s.ast in
      let inner = List.concat_map (fun (r : Ast.routine_declaration) ->
          match routine_parts r with
          | None -> []
          | Some (name, _, _, body) ->
              let rname = Option.value (ident_name name) ~default:"" in
              List.filter_map (data_decl ctx ~routine:rname) body.declarations
              @ List.rev (List.fold_left (inner_names ctx rname) [] (body_statements body)))
          s.ast.routine_declarations in
      let module_level = Hashtbl.create 64 in
      List.iter (add module_level) top;
      { source = s; module_decl; top; inner; module_level; occurrences = [] }) sources in
  (* The global level: every module's non-LOCAL objects (§2.20: TASK data is global in its task). *)
  List.iter (fun m -> List.iter (fun d -> if not d.local then add globals d) m.top) modules;
  let t = { modules; globals; members } in
  List.iter (fun info ->
      let w = { index = t; info; text = info.source.text; routine_levels = []; found = [] } in
      (try walk_module w with Not_found | Invalid_argument _ -> ());
      info.occurrences <- List.rev w.found) modules;
  t

let occurrence_at t uri offset =
  match find_module t uri with
  | Some m when m.source.fresh ->
      List.find_opt (fun o -> o.o_start <= offset && offset <= o.o_stop) m.occurrences
  | _ -> None

let occurrences_of t decl =
  List.concat_map (fun m ->
      List.filter_map (fun o -> if same_decl o.decl decl then Some (m.source.uri, o) else None) m.occurrences)
    t.modules

let routine_at (m : module_info) offset =
  List.find_opt (fun d -> is_routine d && d.decl_start <= offset && offset <= d.decl_stop) m.top

let routine_levels_at t (m : module_info) offset =
  match routine_at m offset with
  | None -> []
  | Some r ->
      let level = Hashtbl.create 16 in
      List.iter (add level) (members_of t r);
      List.iter (fun d ->
          if d.routine = Some r.name && d.decl_start >= r.decl_start && d.decl_stop <= r.decl_stop then
            match d.kind with
            (* a loop variable over its loop only *)
            | Data { storage = "FOR"; _ } when not (d.decl_start <= offset && offset <= d.decl_stop) -> ()
            | _ -> add level d) m.inner;
      [ level ]

let levels_at t uri offset =
  match find_module t uri with
  | None -> [ t.globals; (Lazy.force !current).i_level ]
  | Some m -> levels t m (routine_levels_at t m offset)

let visible_at t uri offset =
  let seen = Hashtbl.create 512 in
  List.concat_map (fun (l : level) ->
      Hashtbl.fold (fun k d acc -> if Hashtbl.mem seen k then acc else (Hashtbl.replace seen k (); d :: acc)) l []
      |> List.sort (fun a b -> compare (key a.name) (key b.name)))
    (levels_at t uri offset)
  |> List.filter (fun d -> d.kind <> Module)

let lookup_at t uri offset name = lookup_levels (levels_at t uri offset) name is_object
let lookup_any t uri offset name = lookup_levels (levels_at t uri offset) name (fun d -> d.kind <> Module)
let members = members_of
let lookup_type t uri offset name = lookup_levels (levels_at t uri offset) name is_type
let components_of_type t uri offset name = components t (levels_at t uri offset) name 8

(* {1 Text} *)

let param_text q =
  match q.p_type with
  | None -> "switch " ^ q.p_name
  | Some ty ->
      (if q.p_mode = "" then "" else q.p_mode ^ " ") ^ ty ^ " " ^ q.p_name
      ^ (if q.p_dims = 0 then "" else "{" ^ String.concat "," (List.init q.p_dims (fun _ -> "*")) ^ "}")

let slot_text = function
  | Required q -> param_text q
  | Optional qs -> "\\" ^ String.concat " | " (List.map param_text qs)

let slots_text slots = String.concat ", " (List.map slot_text slots)

let signature d =
  let local = if d.local && d.routine = None then "LOCAL " else "" in
  match d.kind with
  | Module -> "MODULE " ^ d.name
  | Record cs -> Printf.sprintf "%sRECORD %s (%s)" local d.name
                   (String.concat "; " (List.map (fun (t, c) -> t ^ " " ^ c) cs))
  | Alias b -> Printf.sprintf "%sALIAS %s %s" local b d.name
  | Atomic -> "atomic type " ^ d.name
  | Data { storage = "FOR"; _ } -> "FOR " ^ d.name ^ " (num, §4.18)"
  | Data { storage; type_name; dims; _ } ->
      let dims = if dims = 0 then "" else "{" ^ String.concat "," (List.init dims (fun _ -> "*")) ^ "}" in
      let storage = match storage with "IN" -> "" | s -> s ^ " " in
      if type_name = "switch" then "switch " ^ d.name
      else Printf.sprintf "%s%s%s %s%s" local storage type_name d.name dims
  | Routine { routine = Proc; slots } -> Printf.sprintf "%sPROC %s (%s)" local d.name (slots_text slots)
  | Routine { routine = Func r; slots } -> Printf.sprintf "%sFUNC %s %s (%s)" local r d.name (slots_text slots)
  | Routine { routine = Trap_routine; _ } -> Printf.sprintf "%sTRAP %s" local d.name
  | Component { record; type_name } -> Printf.sprintf "%s %s (component of %s)" type_name d.name record
  | Label -> d.name ^ ":"

let kind_name d =
  match d.kind with
  | Module -> "module"
  | Record _ -> "record type"
  | Alias _ -> "alias type"
  | Atomic -> "atomic type"
  | Data { parameter = true; _ } -> "parameter"
  | Data { storage = "VAR"; _ } -> "variable"
  | Data { storage = "PERS"; _ } -> "persistent"
  | Data { storage = "CONST"; _ } -> "constant"
  | Data { storage = "FOR"; _ } -> "loop variable"
  | Data _ -> "parameter"
  | Routine { routine = Proc; _ } -> "procedure"
  | Routine { routine = Func _; _ } -> "function"
  | Routine { routine = Trap_routine; _ } -> "trap"
  | Component _ -> "record component"
  | Label -> "label"
