(* R-13-aa: virtual signals for the undeclared names a program passes as signals. The kind
   comes from the called routine's own declaration (installed or the program's), so no routine
   list is kept here. *)

open Rapid_syntax
module Io = Rapid_controller.Io_config

let lower = String.lowercase_ascii

let kind_of_type t =
  match lower t with
  | "signaldi" -> Some Io.DI | "signaldo" -> Some Io.DO | "signalai" -> Some Io.AI
  | "signalao" -> Some Io.AO | "signalgi" -> Some Io.GI | "signalgo" -> Some Io.GO
  | _ -> None

let ident_name (i : Ast.identifier) = match i.it with Ast.Ident s -> Some s | Ast.ID_placeholder -> None

(* A routine's signal parameters: the kinds of its required parameters in order (None for a
   parameter of another type), and its optional parameters' kinds by name. *)
type signature = { required : Io.signal_type option list; optional : (string * Io.signal_type) list }

let param_kind (p : Ast.parameter_declaration) =
  match p.it with
  | Ast.Parameter { data_type; name; _ } -> (ident_name name, Option.bind (ident_name data_type) kind_of_type)
  | Ast.Switch name -> (ident_name name, None)

let signature_of (params : Ast.parameter list) =
  let required, optional =
    List.fold_left (fun (req, opt) (p : Ast.parameter) ->
        match p.it with
        | Ast.Required_parameter d -> (snd (param_kind d) :: req, opt)
        | Ast.Optional_parameter alts ->
            let opt = List.fold_left (fun opt (a : Ast.alternative) ->
                match a.it with
                | Ast.Alternative d -> (
                    match param_kind d with Some n, Some k -> (lower n, k) :: opt | _ -> opt)
                | Ast.ALT_placeholder -> opt) opt alts in
            (req, opt)
        | Ast.PAR_placeholder -> (None :: req, opt)) ([], []) params in
  { required = List.rev required; optional }

let has_signal s = List.exists Option.is_some s.required || s.optional <> []

let signatures (installed : Ast.module_declaration list) =
  let table = Hashtbl.create 64 in
  List.iter (fun (m : Ast.module_declaration) ->
      List.iter (fun (r : Ast.routine_declaration) ->
          match r.it with
          | Ast.Procedure_declaration { name; parameters; _ } | Ast.Function_declaration { name; parameters; _ } -> (
              match ident_name name with
              | Some n ->
                  let s = signature_of parameters in
                  if has_signal s then Hashtbl.replace table (lower n) s
              | None -> ())
          | _ -> ()) m.routine_declarations) installed;
  table

(* Every name a module declares: data objects (module and routine level), parameters, routines,
   types; such a name is never inferred, whatever it is. *)
let declared (modules : Ast.module_declaration list) =
  let names = Hashtbl.create 64 in
  let add i = Option.iter (fun n -> Hashtbl.replace names (lower n) ()) (ident_name i) in
  let data (d : Ast.data_declaration) = match d.it with
    | Ast.Data_declaration { name; _ } -> add name | _ -> () in
  let param (p : Ast.parameter) = match p.it with
    | Ast.Required_parameter { it = Ast.Parameter { name; _ } | Ast.Switch name; _ } -> add name
    | Ast.Optional_parameter alts ->
        List.iter (fun (a : Ast.alternative) -> match a.it with
            | Ast.Alternative { it = Ast.Parameter { name; _ } | Ast.Switch name; _ } -> add name
            | Ast.ALT_placeholder -> ()) alts
    | _ -> () in
  List.iter (fun (m : Ast.module_declaration) ->
      add m.module_name;
      List.iter data m.data_declarations;
      List.iter (fun (t : Ast.type_definition) -> match t.it with
          | Ast.Record_definition { name; _ } | Ast.Alias_definition { name; _ } -> add name
          | _ -> ()) m.type_definitions;
      List.iter (fun (r : Ast.routine_declaration) -> match r.it with
          | Ast.Procedure_declaration { name; parameters; body; _ }
          | Ast.Function_declaration { name; parameters; body; _ } ->
              add name; List.iter param parameters; List.iter data body.declarations
          | Ast.Trap_declaration { name; body; _ } -> add name; List.iter data body.declarations
          | _ -> ()) m.routine_declarations) modules;
  names

let infer ~installed modules =
  (* The program's own routines count as well: a signal handed to a parameter of type
     signaldo is a signal whoever declares the parameter. *)
  let table = signatures (installed @ modules) in
  let known = declared (installed @ modules) in
  let found = ref [] in
  let note at name kind =
    if not (Hashtbl.mem known (lower name))
    && not (List.exists (fun (n, _, _) -> lower n = lower name) !found) then
      found := (name, kind, at) :: !found in
  let entire = function Ast.Data_reference (Ast.Entire n) -> Some n | _ -> None in
  let rec expr (e : Ast.expression_desc) = match e with
    | Ast.Function_call { func; arguments; argument_regions; _ } -> call func arguments argument_regions
    | Ast.Aggregate (es, _) -> Array.iter expr es
    | Ast.Unary (_, e, _) -> expr e
    | Ast.Binary (_, a, b) -> expr a.it; expr b.it
    | Ast.Data_reference r -> reference r
    | _ -> ()
  and reference = function
    | Ast.Element (_, es) -> List.iter (fun (e : Ast.expression) -> expr e.it) es
    | Ast.Component (r, _) -> reference r.it
    | _ -> ()
  and call func (args : Ast.argument_desc array) (regions : Source.region array) =
    let sg = Option.bind (ident_name func) (fun n -> Hashtbl.find_opt table (lower n)) in
    let required = ref (match sg with Some s -> s.required | None -> []) in
    Array.iteri (fun i (a : Ast.argument_desc) ->
        let at = if i < Array.length regions then regions.(i) else Source.no_region in
        match a with
        | Ast.Required_argument (_, e, _) | Ast.Positional_argument e ->
            (match !required with
             | k :: rest -> required := rest; (match k, entire e with Some k, Some n -> note at n k | _ -> ())
             | [] -> ());
            expr e
        | Ast.Optional_argument (name, Some e) ->
            (match sg, ident_name name, entire e.it with
             | Some s, Some p, Some n -> Option.iter (note e.at n) (List.assoc_opt (lower p) s.optional)
             | _ -> ());
            expr e.it
        | _ -> ()) args
  in
  let rec stmt (s : Ast.statement) = match s.it with
    | Ast.Assignment (r, e) -> reference r.it; expr e.it
    | Ast.Procedure_call (Ast.Procedure_name p, args, regions) -> call p args regions
    | Ast.Procedure_call (Ast.Late_bound e, args, regions) ->
        expr e.it; call { it = Ast.ID_placeholder; at = e.at } args regions
    | Ast.Return (Some e) | Ast.Raise (Some e) -> expr e.it
    | Ast.If { condition; then_branch; elseifs; else_branch } ->
        expr condition.it; stmts then_branch;
        List.iter (fun (c : Ast.elseif_clause) -> match c.it with
            | Ast.Elseif (e, b) -> expr e.it; stmts b | Ast.EIT_placeholder -> ()) elseifs;
        Option.iter stmts else_branch
    | Ast.Compact_if (e, s) -> expr e.it; stmt s
    | Ast.For { from_; to_; step; body; _ } ->
        expr from_.it; expr to_.it; Option.iter (fun (e : Ast.expression) -> expr e.it) step; stmts body
    | Ast.While (e, b) -> expr e.it; stmts b
    | Ast.Test { test_expression; cases; default } ->
        expr test_expression.it;
        List.iter (fun (c : Ast.case_clause) -> match c.it with
            | Ast.Case (es, b) -> List.iter (fun (e : Ast.expression) -> expr e.it) es; stmts b
            | Ast.CSE_placeholder -> ()) cases;
        Option.iter stmts default
    | _ -> ()
  and stmts l = List.iter stmt l in
  let body (b : Ast.routine_body) =
    stmts b.statements; Option.iter stmts b.backward;
    Option.iter (fun (h : Ast.error_handler) -> stmts h.handler) b.error; Option.iter stmts b.undo in
  List.iter (fun (m : Ast.module_declaration) ->
      List.iter (fun (r : Ast.routine_declaration) -> match r.it with
          | Ast.Procedure_declaration { body = b; _ } | Ast.Function_declaration { body = b; _ }
          | Ast.Trap_declaration { body = b; _ } -> body b
          | _ -> ()) m.routine_declarations) modules;
  List.rev !found

let extend (io : Io.t) inferred =
  let have n = List.exists (fun (s : Io.signal) -> lower s.name = lower n) io.signals in
  let extra = List.filter_map (fun (name, kind, _) ->
      if have name then None else Some { Io.name; kind; initial = 0.; line = 0; col = 0 }) inferred in
  { io with signals = io.signals @ extra }

let for_run ~allow_unknown ~stub_unmodelled modules io =
  if not (allow_unknown && stub_unmodelled) then (io, [])
  else
    match Rapid_typing.Installed_env.modules () with
    | Error _ -> (io, [])
    | Ok installed ->
        let inferred = infer ~installed modules in
        let io' = extend io inferred in
        let first_use (s : Io.signal) =
          match List.find_opt (fun (n, _, _) -> lower n = lower s.name) inferred with
          | Some (_, _, at) -> at
          | None -> Source.no_region in
        (io', List.filter_map (fun s -> if List.memq s io.signals then None else Some (s, first_use s)) io'.signals)
