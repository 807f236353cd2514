(* From the checked syntax tree to the program the machine runs. Every name goes where the
   static semantics bound it (Elaboration), every operator to its row of §3.12, every argument to
   its parameter. The program has passed the static semantics, so what is missing here is an
   unknown name allowed by --allow-unknown: it becomes an execution error (ERR_REFUNKDAT,
   ERR_REFUNKPRC, ERR_REFUNKFUN) when it is reached. *)

open Rapid_syntax
open Rapid_typing
module A = Ast
module E = Elaboration

(* Lists as long as a module's statements or declarations (a CAD module holds hundreds of
   thousands): mapped without growing the stack, which List.map of OCaml 4.13 does. *)
let map_long f l = Array.map f (Array.of_list l)
let list_long f l = List.rev (List.rev_map f l)
let concat_long ls = List.rev (List.fold_left (fun acc l -> List.rev_append l acc) [] ls)

type ctx = {
  elab : E.t;
  routine_index : int Source.Table.t;    (* by the region of the routine's name *)
  global_index : int Source.Table.t;     (* by the region of the declared name *)
  mutable locals : int Source.Table.t;   (* of the routine being lowered *)
  mutable local_count : int;
  mutable labels : (int * int) Source.Table.t;
  mutable blocks : int;
  (* For the trace (Ir.names): the routine being lowered (-1: module data), its slots' names,
     the components' names. *)
  mutable routine_now : int;
  mutable slot_names : (int, string) Hashtbl.t;
  component_names : (Ir.name_key, string) Hashtbl.t;
  argument_texts : string Source.Table.t;
  installed_index : (int Source.Table.t * int Source.Table.t) option;
      (* the routine and global numbers of the installed part, when it is shared (below) *)
  argument_types : string option array Ir.Argument_types.t;
}

let index table installed region =
  match Source.Table.find_opt table region, installed with
  | (Some _ as found), _ | (None as found), None -> found
  | None, Some t -> Source.Table.find_opt t region

let routine_number ctx region = index ctx.routine_index (Option.map fst ctx.installed_index) region
let global_number ctx region = index ctx.global_index (Option.map snd ctx.installed_index) region

let rec name_path (p : Ir.place) =
  match p with
  | Whole s -> Some (s, [])
  | Element (q, idx) ->
      Option.map (fun (s, path) -> (s, path @ List.init (Array.length idx) (fun _ -> -1))) (name_path q)
  | Component (q, k) -> Option.map (fun (s, path) -> (s, path @ [ k ])) (name_path q)
  | Unresolved _ -> None

let slot_of ctx (d : Env.data_object) : Ir.slot option =
  match d.d_level with
  | Routine_level -> Option.map (fun i -> Ir.Local i) (Source.Table.find_opt ctx.locals d.d_region)
  | Module_level _ | Installed_level ->
      Option.map (fun i -> Ir.Global i) (global_number ctx d.d_region)

(* The shape only: the value is built when the machine runs, within its memory budget. *)
let shape_default (t : Types.object_type) =
  match Value.shape_of_type t with
  | shape -> shape
  | exception Invalid_argument _ -> Value.S_bool

(* ------------------------------------------------------------------ expressions *)

let recent_parameters : (Env.routine * Env.parameter array) list ref = ref []

(* A literal of at most seven decimal digits (§2.5): its value without the exact arithmetic. *)
let small_integer text =
  let n = String.length text in
  n >= 1 && n <= 7
  && (let rec digits i = i >= n || (match String.unsafe_get text i with '0' .. '9' -> digits (i + 1) | _ -> false) in
      digits 0)

(* The region of the name a reference starts with, under which the checker recorded what the
   name denotes (an entire variable's name has the reference's region, ast.ml). *)
let rec root_at (r : A.data_reference) =
  match r.it with
  | Entire _ -> Some r.at
  | Element (n, _) -> Some n.at
  | Component (r, _) -> root_at r
  | VAR_placeholder -> None


(* §2.5: the value of a numeric literal, rounded to num or dnum: a pure function of its text,
   kept for the texts already met (the same few literals recur in every program of a fuzzing
   campaign, and reading one goes through exact rationals). Values are immutable. The table is
   emptied when it grows large, so that long literals of hostile texts do not pile up. *)
let literal_values : (string * bool, Value.t) Hashtbl.t = Hashtbl.create 256

let literal_value text precision =
  let key = (text, precision = `Dnum) in
  match Hashtbl.find_opt literal_values key with
  | Some v -> Some v
  | None -> (
      match Num_literal.of_text text with
      | Ok t ->
          let v = Value.of_literal t precision in
          if Hashtbl.length literal_values >= 4096 then Hashtbl.reset literal_values;
          Hashtbl.replace literal_values key v;
          Some v
      | Error _ -> None)

let rec place ctx (r : A.data_reference) : Ir.place =
  match r.it with
  | VAR_placeholder -> Unresolved "<VAR>"
  | Entire spelling -> entire ctx { A.it = spelling; at = r.at }
  | Element (name, indexes) ->
      Element (entire ctx name, Array.of_list (List.map (expr ctx ~dnum:false) indexes))
  | Component (inner, comp) -> (
      match Source.Table.find_opt ctx.elab.components comp.at with
      | Some k ->
          let p = Ir.Component (place ctx inner, k) in
          (match name_path p with
           | Some ((Global _ as s), path) -> Hashtbl.replace ctx.component_names (-1, s, path) comp.it
           | Some (s, path) -> Hashtbl.replace ctx.component_names (ctx.routine_now, s, path) comp.it
           | None -> ());
          p
      | None -> Unresolved comp.it)

and entire ctx (name : A.name) : Ir.place =
  match Source.Table.find_opt ctx.elab.names name.at with
  | Some (Data d) -> (match slot_of ctx d with Some s -> Whole s | None -> Unresolved name.it)
  | _ -> Unresolved name.it

and expr ctx ~dnum (e : A.expression) : Ir.expr =
  let dnum = dnum || Source.Table.mem ctx.elab.dnum_literals e.at in
  let make d = { Ir.e = d; at = e.at } in
  match e.it with
  | Num_literal text when small_integer text ->
      (* Below 2^24 an integer is exact in single and double precision alike. *)
      let n = float_of_int (int_of_string text) in
      make (Literal (if dnum then Value.Dnum n else Value.Num n))
  | Num_literal text -> (
      match literal_value text (if dnum then `Dnum else `Num) with
      | Some v -> make (Literal v)
      | None -> make Placeholder)
  | String_literal s -> make (Literal (Value.String s.bytes))
  | Bool_literal b -> make (Literal (Value.Bool b))
  | Data_reference r ->
      let r = A.reference e r in
      let semi_value =
        match r.it, Option.bind (root_at r) (Source.Table.find_opt ctx.elab.names) with
        | (Entire _ | Element _), Some (Data { d_type = { base; _ }; _ }) -> Types.value_class base = Semi_value
        | _ -> false in
      if semi_value then make (Read_signal (place ctx r)) else make (Read (place ctx r))
  | Function_call f -> make (Call (call ~texts:false ctx e.at f.func))
  | Aggregate (es, rs) ->
      let kind = match Source.Table.find_opt ctx.elab.aggregates e.at with
        | Some `Record -> Ir.Record_value | _ -> Ir.Array_value in
      make (Aggregate (Array.map (expr ctx ~dnum) (A.members es rs), kind))
  | Unary (op, a, a_at) -> (
      let a = A.operand a a_at in
      match Source.Table.find_opt ctx.elab.unary e.at with
      | Some row ->
          let operand = if dnum then Tables.O_dnum else row.operand in
          make (Unary (unary_op op operand, expr ctx ~dnum:(operand = O_dnum) a))
      | None -> make (Unary ((if op = Not then Arith.Not else Arith.Num_neg), expr ctx ~dnum a)))
  | Binary (And, a, b) -> make (And (expr ctx ~dnum:false a, expr ctx ~dnum:false b))
  | Binary (Or, a, b) -> make (Or (expr ctx ~dnum:false a, expr ctx ~dnum:false b))
  | Binary ((Equal | Not_equal) as op, a, b) ->
      make (Binary ((if op = Equal then Arith.Equal else Arith.Not_equal),
                    expr ctx ~dnum:false a, expr ctx ~dnum:false b))
  | Binary (op, a, b) -> (
      match Source.Table.find_opt ctx.elab.binary e.at with
      | Some row ->
          let left = if dnum && row.left = O_num then Tables.O_dnum else row.left in
          let right = if dnum && row.right = O_num then Tables.O_dnum else row.right in
          make (Binary (binary_op op left right, expr ctx ~dnum:(left = O_dnum) a,
                        expr ctx ~dnum:(right = O_dnum) b))
      | None -> make (Binary (Arith.Equal, expr ctx ~dnum a, expr ctx ~dnum b)))
  | EXP_placeholder -> make Placeholder

(* §3.12: the row's operation. *)
and binary_op (op : A.binary_operator) (l : Tables.operand) (r : Tables.operand) : Arith.binary =
  match op, l, r with
  | Plus, O_num, _ -> Num_add | Plus, O_dnum, _ -> Dnum_add | Plus, O_pos, _ -> Pos_add
  | Plus, O_string, _ -> String_concat
  | Minus, O_num, _ -> Num_sub | Minus, O_dnum, _ -> Dnum_sub | Minus, O_pos, _ -> Pos_sub
  | Mul, O_num, O_pos -> Num_pos_mul | Mul, O_pos, O_num -> Pos_num_mul
  | Mul, O_pos, O_pos -> Pos_cross | Mul, O_orient, _ -> Orient_mul
  | Mul, O_num, _ -> Num_mul | Mul, O_dnum, _ -> Dnum_mul
  | Div, O_pos, _ -> Pos_num_div | Div, O_dnum, _ -> Dnum_div | Div, _, _ -> Num_div
  | Int_div, O_dnum, _ -> Dnum_intdiv | Int_div, _, _ -> Num_intdiv
  | Modulo, O_dnum, _ -> Dnum_mod | Modulo, _, _ -> Num_mod
  | Less, O_dnum, _ -> Dnum_lt | Less, _, _ -> Num_lt
  | Less_equal, O_dnum, _ -> Dnum_le | Less_equal, _, _ -> Num_le
  | Greater, O_dnum, _ -> Dnum_gt | Greater, _, _ -> Num_gt
  | Greater_equal, O_dnum, _ -> Dnum_ge | Greater_equal, _, _ -> Num_ge
  | Xor, _, _ -> Xor
  | Equal, _, _ -> Equal | Not_equal, _, _ -> Not_equal
  | (Plus | Minus | Mul | And | Or), _, _ -> Equal

and unary_op (op : A.unary_operator) (o : Tables.operand) : Arith.unary =
  match op, o with
  | Not, _ -> Not
  | Unary_minus, O_dnum -> Dnum_neg | Unary_minus, O_pos -> Pos_neg | Unary_minus, _ -> Num_neg
  | Unary_plus, O_dnum -> Dnum_plus | Unary_plus, O_pos -> Pos_plus | Unary_plus, _ -> Num_plus

(* §3.11, §4.6, §5.2: each parameter of the callee gets its argument. *)
(* [texts]: the in arguments' texts are kept (Ir.names) for a procedure call only: what reads
   them (Installed_routine.argument_label: the motion's labels, SyncID) is an installed
   procedure's, and a function's arguments (the -20 of Offs(p, 0, 0, -20)) were a fifth of the
   printing of a module of moves. *)
and call ~texts ctx (at : Source.region) (name : A.identifier) : Ir.call =
  let unknown () =
    { Ir.callee = Unknown_routine (match name.it with Ident s -> s | ID_placeholder -> "<ID>");
      arguments = [||]; call_at = at } in
  match Source.Table.find_opt ctx.elab.names name.at, Source.Table.find_opt ctx.elab.bindings at with
  | Some (Routine r), Some binding -> (
      match routine_number ctx r.r_region with
      | None -> unknown ()
      | Some index ->
          let params = parameter_array r in
          (* The bound arguments are in parameter order (Elaboration): one walk along both lists,
             not a search per parameter, since a call may have thousands of arguments. *)
          let bound = ref binding.bound in
          let types = ref [] in
          let arguments = Array.mapi (fun i (p : Env.parameter) ->
              match !bound with
              | ((q : Env.parameter), a) :: rest when q == p ->
                  bound := rest;
                  (match p.p_type with
                   | Some { base = Anytype; _ } -> (
                       match argument_type ctx a with Some t -> types := (i, t) :: !types | None -> ())
                   | _ -> ());
                  argument ~texts ctx p a
              | _ -> Ir.Absent) params in
          if !types <> [] then begin
            let named = Array.make (Array.length arguments) None in
            List.iter (fun (i, t) -> named.(i) <- Some t) !types;
            Ir.Argument_types.replace ctx.argument_types arguments named
          end;
          { callee = Routine index; arguments; call_at = at })
  | _ -> unknown ()

(* The name of the static type of a data reference given for an anytype parameter (Ir's
   Argument_types): its declared type, an element's or a component's. *)
and argument_type ctx (a : A.argument) =
  let e = match a.it with
    | Required_argument (_, e, at) -> Some (A.operand e at)
    | Positional_argument e -> Some (A.operand e a.at)
    | Optional_argument (_, Some e) -> Some e
    | Optional_argument (_, None) | Conditional_argument _ | ARG_placeholder -> None in
  match e with
  | Some ({ it = Data_reference r; _ } as e) ->
      Option.map (fun (t : Types.object_type) -> Types.name t.base) (reference_type ctx (A.reference e r))
  | _ -> None

and reference_type ctx (r : A.data_reference) : Types.object_type option =
  let declared (n : Source.region) = match Source.Table.find_opt ctx.elab.names n with
    | Some (Data d) -> Some d.d_type
    | _ -> None in
  match r.it with
  | VAR_placeholder -> None
  | Entire _ -> declared r.at
  | Element (n, _) -> Option.map (fun (t : Types.object_type) -> Types.scalar t.base) (declared n.at)
  | Component (inner, comp) -> (
      match reference_type ctx inner, Source.Table.find_opt ctx.elab.components comp.at with
      | Some { base = Record rt; _ }, Some k ->
          Option.map (fun (_, t) -> Types.scalar t) (List.nth_opt rt.components k)
      | _ -> None)

and parameters_of (r : Env.routine) =
  List.concat_map (function Env.Required_slot p -> [ p ] | Optional_slot ps | Required_choice ps -> ps) r.r_slots

(* A call's callee's parameters, kept for the last routines called (a module of moves calls
   MoveL and Offs ten thousand times each): the routine records are never changed. *)
and parameter_array (r : Env.routine) =
  match List.find_opt (fun (r', _) -> r' == r) !recent_parameters with
  | Some (_, a) -> a
  | None ->
      let a = Array.of_list (parameters_of r) in
      recent_parameters := (r, a) :: List.filteri (fun i _ -> i < 7) !recent_parameters;
      a

(* A loop variable, ERRNO or INTNO: a read-only variable of the access-mode table (§5.2). *)
and read_only ctx (e : A.expression) =
  match e.it with
  | Data_reference r -> (
      match Option.bind (root_at (A.reference e r)) (Source.Table.find_opt ctx.elab.names) with
      | Some (Data { d_kind = Loop_variable | Read_only_variable; _ }) -> true
      | _ -> false)
  | _ -> false

and reference_kind ctx (e : A.expression) : Ir.reference_kind =
  match e.it with
  | Data_reference r ->
      (match Option.bind (root_at (A.reference e r)) (Source.Table.find_opt ctx.elab.names) with
       | Some (Data { d_kind = Variable | Parameter _ | Loop_variable | Read_only_variable; _ }) -> Ref_variable
       | Some (Data { d_kind = Persistent; _ }) -> Ref_persistent
       | Some (Data { d_kind = Constant; _ }) -> Ref_constant
       | _ -> Ref_other)
  | _ -> Ref_other

and optional_parameter_slot ctx (e : A.expression) =
  match e.it with
  | Data_reference (Entire _) -> (
      match Source.Table.find_opt ctx.elab.names e.at with
      | Some (Data ({ d_optional = true; _ } as d)) -> slot_of ctx d
      | _ -> None)
  | _ -> None

(* The text of an in argument as the programmer wrote it, kept for the motion's output (Ir.names). *)
and written ctx (source : A.expression) (e : Ir.expr) =
  (match e.e with
   | Literal _ | Aggregate _ | Read (Whole (Global _)) | Placeholder -> ()  (* a named global, or "line N" *)
   | _ ->
       let text = Printer.expression source in
       let text = if String.length text > 48 then String.sub text 0 45 ^ "..." else text in
       Source.Table.replace ctx.argument_texts e.at text);
  e

and argument ~texts ctx (p : Env.parameter) (a : A.argument) : Ir.argument =
  let dnum = match p.p_type with Some { base = Dnum; dims = Scalar } -> true | _ -> false in
  let value (e : A.expression) : Ir.argument =
    match p.p_mode with
    | Mode_in when (match p.p_type with Some { base = Anytype; _ } -> true | _ -> false) -> (
        (* An anytype parameter is no value context (§2.16): a semi-value object passed to
           one (AliasIO's FromSignal) is the object, not its value (doc/rulings.md R-8-m). *)
        match expr ctx ~dnum e with
        | { e = Read_signal place; at } -> By_value { e = Read place; at }
        | other -> By_value other)
    | Mode_in -> let v = expr ctx ~dnum e in By_value (if texts then written ctx e v else v)
    | Mode_ref when optional_parameter_slot ctx e <> None ->
        (* Present and the other REF parameters see an absent optional parameter as absent
           instead of using its value (§5.2, ch. 11). *)
        Pass_on (Option.get (optional_parameter_slot ctx e))
    | _ -> (
        match e.it with
        | Data_reference r -> By_reference (place ctx (A.reference e r), reference_kind ctx e)
        | _ -> By_value (expr ctx ~dnum e))
  in
  match a.it with
  | Optional_argument (_, None) -> Present_switch
  | Conditional_argument (_, r) -> (
      match place ctx r with Whole s -> Pass_on s | _ -> Absent)
  | ARG_placeholder -> By_value { e = Placeholder; at = a.at }
  | Required_argument (_, e, at) -> value (A.operand e at)
  | Positional_argument e -> value (A.operand e a.at)
  | Optional_argument (_, Some e) -> value e

(* ------------------------------------------------------------------ statements *)

let new_block ctx = ctx.blocks <- ctx.blocks + 1; ctx.blocks

let rec block ctx (l : A.statement list) : Ir.block =
  let id = new_block ctx in
  let l = List.filter (fun (s : A.statement) -> match s.it with Statement_comment _ -> false | _ -> true) l in
  List.iteri (fun i (s : A.statement) ->
      match s.it with
      | Label name -> Source.Table.replace ctx.labels name.at (id, i)
      | _ -> ()) l;
  { id; body = map_long (statement ctx) l }

and statement ctx (s : A.statement) : Ir.stmt =
  let make d = { Ir.s = d; sat = s.at } in
  match s.it with
  | Assignment (target, e) ->
      (* A literal value takes dnum from a dnum target through the elaboration (dnum_literals). *)
      make (Assign (place ctx target, expr ctx ~dnum:false e))
  | Procedure_call (_, args, _) when Array.exists (fun (a : A.argument_desc) -> a = ARG_placeholder) args ->
      (* §2.9: executing a placeholder is ERR_EXECPHR. *)
      make Placeholder_statement
  | Procedure_call (Procedure_name id, _, _) -> make (Call_procedure (call ~texts:true ctx s.at id))
  | Procedure_call (Late_bound e, args, regions) ->
      let args = A.arguments args regions in
      let late (a : A.argument) : Ir.late_argument =
        let name (i : A.identifier) = match i.it with Ident n -> Some n | ID_placeholder -> None in
        (* §4.6, §5.2: the type the checker found, compared with the parameter's when the call
           runs; a numeric literal expression is lowered both ways (R-2.5-b). *)
        let typed (e : A.expression) : Ir.late_type =
          match Source.Table.find_opt ctx.elab.late_arguments a.at with
          | Some (Some t) -> Late_typed t
          | Some None -> Late_numeric (expr ctx ~dnum:true e)
          | None -> Late_untyped in
        let value n (e : A.expression) : Ir.late_argument =
          { late_name = n; late_value = Late_expr (expr ctx ~dnum:false e); late_kind = reference_kind ctx e;
            late_type = typed e; late_read_only = read_only ctx e; late_optional = false } in
        match a.it with
        | Required_argument (n, e, at) -> value (Option.bind n name) (A.operand e at)
        | Positional_argument e -> value None (A.operand e a.at)
        | Optional_argument (n, None) ->
            { late_name = name n; late_value = Late_switch; late_kind = Ref_other; late_type = Late_untyped;
              late_read_only = false; late_optional = true }
        | Optional_argument (n, Some e) -> { (value (name n) e) with late_optional = true }
        | Conditional_argument (n, r) ->
            let slot = match place ctx r with Whole s -> Some s | _ -> None in
            let late_type = match Source.Table.find_opt ctx.elab.late_arguments a.at with
              | Some (Some t) -> Ir.Late_typed t | _ -> Late_untyped in
            { late_name = name n; late_value = Late_conditional slot; late_kind = Ref_variable; late_type;
              late_read_only = false; late_optional = true }
        | ARG_placeholder ->
            { late_name = None; late_value = Late_expr { e = Placeholder; at = a.at }; late_kind = Ref_other;
              late_type = Late_untyped; late_read_only = false; late_optional = false }
      in
      make (Call_late (expr ctx ~dnum:false e, Array.map late args))
  | Goto id -> (
      match Source.Table.find_opt ctx.elab.names id.at with
      | Some (Label at) -> (
          match Source.Table.find_opt ctx.labels at with
          | Some (b, i) -> make (Goto (b, i))
          | None -> make Placeholder_statement)
      | _ -> make Placeholder_statement)
  | Break -> make Break
  | Continue -> make Continue
  | Return e -> make (Return (Option.map (expr ctx ~dnum:false) e))
  | Raise e -> make (Raise (Option.map (expr ctx ~dnum:false) e))
  | Exit -> make Exit
  | Retry -> make Retry
  | Trynext -> make Trynext
  | Connect (target, trap) -> (
      match Source.Table.find_opt ctx.elab.names trap.at with
      | Some (Routine r) -> (
          match routine_number ctx r.r_region with
          | Some i -> make (Connect (place ctx target, i))
          | None -> make Placeholder_statement)
      | _ -> make Placeholder_statement)
  | If i ->
      (* ELSEIF is an IF in the ELSE list: the chain is built from its end, in a loop, since a
         generated program may hold hundreds of thousands of ELSEIF clauses. Nothing after an
         <EIT> placeholder is reached. *)
      let rec upto_placeholder acc = function
        | [] -> (acc, None)
        | ({ it = A.EIT_placeholder; at } : A.elseif_clause) :: _ -> (acc, Some at)
        | ({ it = A.Elseif (c, l); at } : A.elseif_clause) :: rest -> upto_placeholder ((c, l, at) :: acc) rest
      in
      let reversed, placeholder = upto_placeholder [] i.elseifs in
      let then_ = block ctx i.then_branch in
      let condition = expr ctx ~dnum:false i.condition in
      let last = match placeholder with
        | Some at -> { Ir.id = new_block ctx; body = [| { Ir.s = Placeholder_statement; sat = at } |] }
        | None -> (match i.else_branch with Some l -> block ctx l | None -> block ctx []) in
      let chain = List.fold_left (fun else_ (c, l, at) ->
          (* Elseif: RETRY and TRYNEXT after an error in its condition go to the whole IF (R-4.16). *)
          let inner = { Ir.s = Ir.Elseif (expr ctx ~dnum:false c, block ctx l, else_); sat = at } in
          { Ir.id = new_block ctx; body = [| inner |] }) last reversed in
      make (If (condition, then_, chain))
  | Compact_if (c, body) -> make (Compact_if (expr ctx ~dnum:false c, statement ctx body))
  | For f ->
      let variable = ctx.local_count in
      ctx.local_count <- ctx.local_count + 1;
      Source.Table.replace ctx.locals f.loop_variable.at variable;
      Hashtbl.replace ctx.slot_names variable (match f.loop_variable.it with Ident s -> s | ID_placeholder -> "<ID>");
      make (For { variable; from_ = expr ctx ~dnum:false f.from_; to_ = expr ctx ~dnum:false f.to_;
                  step = Option.map (expr ctx ~dnum:false) f.step; loop_body = block ctx f.body })
  | While (c, body) -> make (While (expr ctx ~dnum:false c, block ctx body))
  | Test t ->
      let cases = list_long (fun (c : A.case_clause) ->
          match c.it with
          | Case (values, l) -> (map_long (expr ctx ~dnum:false) values, block ctx l)
          | CSE_placeholder -> ([| { Ir.e = Placeholder; at = c.at } |], block ctx [])) t.cases in
      make (Test (expr ctx ~dnum:false t.test_expression, Array.of_list cases,
                  (match t.default with Some l -> block ctx l | None -> block ctx [])))
  | Label _ -> make Label
  | Statement_comment _ -> make Label
  | SMT_placeholder -> make Placeholder_statement

(* ------------------------------------------------------------------ routines and the program *)

let initial ctx (d : Env.data_object) : Ir.init =
  match d.d_initial with
  | Some e ->
      let dnum = d.d_type.base = Dnum && d.d_type.dims = Scalar in
      Init_expr (expr ctx ~dnum e)
  | None -> Init_default (shape_default d.d_type)

let routine ctx ~module_name ~installed (decl : A.routine_declaration) : Ir.routine option =
  let lower (name : A.identifier) (kind : Ir.routine_kind) (body : A.routine_body) =
    match Source.Table.find_opt ctx.elab.declared name.at with
    | Some (Routine r) ->
        ctx.locals <- Source.Table.create 16;
        ctx.labels <- Source.Table.create 8;
        let params = parameters_of r in
        List.iteri (fun i (p : Env.parameter) -> Source.Table.replace ctx.locals p.p_region i) params;
        ctx.slot_names <- Hashtbl.create 16;
        List.iteri (fun i (p : Env.parameter) -> Hashtbl.replace ctx.slot_names i p.p_name) params;
        ctx.local_count <- List.length params;
        let optionals = List.concat_map (function
            | Env.Optional_slot ps | Env.Required_choice ps -> ps | Env.Required_slot _ -> []) r.r_slots in
        let optional p = optionals <> [] && List.memq p optionals in
        (* §5.2: the alternatives of one optional slot are mutually exclusive. *)
        let group p =
          let rec find k = function
            | [] -> -1
            | (Env.Optional_slot ps | Env.Required_choice ps) :: _ when List.memq p ps -> k
            | _ :: rest -> find (k + 1) rest in
          find 0 r.r_slots in
        let parameters = Array.of_list (List.map (fun (p : Env.parameter) ->
            { Ir.p_name = p.p_name; p_mode = p.p_mode; p_optional = optional p;
              p_switch = p.p_type = None;
              p_default = (match p.p_type with Some t -> shape_default t | None -> Value.S_bool);
              p_type = p.p_type; p_group = group p })
            params) in
        let inits = List.filter_map (fun (d : A.data_declaration) ->
            match d.it with
            | Data_declaration { name; _ } -> (
                match Source.Table.find_opt ctx.elab.declared name.at with
                | Some (Data obj) ->
                    let slot = ctx.local_count in
                    ctx.local_count <- slot + 1;
                    Source.Table.replace ctx.locals obj.d_region slot;
                    Hashtbl.replace ctx.slot_names slot obj.d_name;
                    Some (slot, initial ctx obj)
                | _ -> None)
            | Declaration_comment _ | DDN_placeholder -> None) body.declarations in
        let main = block ctx body.statements in
        let backward = Option.map (block ctx) body.backward in
        let error = Option.map (fun (h : A.error_handler) ->
            let all_errors = ref false in
            let recovery = Option.map (List.filter_map (fun (n : A.recovery_error_number) ->
                match n.it with
                | Error_number_literal t -> (
                    match Num_literal.of_text t with
                    | Ok v -> Some (Ir.Number (Z.to_int (Q.num (Num_literal.to_q v))))
                    | Error _ -> None)
                | Error_number_name nm ->
                    if String.uppercase_ascii nm.it = "LONG_JMP_ALL_ERR" then (all_errors := true; None)
                    else (
                      match Source.Table.find_opt ctx.elab.names nm.at with
                      | Some (Data d) -> Option.map (fun s -> Ir.Object s) (slot_of ctx d)
                      | _ -> None))) h.error_numbers in
            { Ir.recovery; all_errors = !all_errors; handler = block ctx h.handler }) body.error in
        let undo = Option.map (block ctx) body.undo in
        let is_empty = body.statements = [] && body.declarations = [] in
        Some { Ir.name = r.r_name; module_name; kind; parameters; locals = ctx.local_count;
               local_inits = inits; body = main; backward; error; undo;
               primitive = (if installed && is_empty then Some r.r_name else None); at = name.at;
               stub_result = (match r.r_kind with Function t -> Some (shape_default t) | _ -> None);
               local = r.r_local; nostepin = false }
    | _ -> None
  in
  match decl.it with
  | Procedure_declaration { name; body; _ } -> lower name Procedure body
  | Function_declaration { name; body; _ } -> lower name Function body
  | Trap_declaration { name; body; _ } -> lower name Trap body
  | Routine_comment _ | RDN_placeholder -> None

let module_name (m : A.module_declaration) =
  match m.module_name.it with Ident s -> s | ID_placeholder -> "<ID>"

(* The routines and module data of some modules, numbered from [routine_base] and
   [global_base]: the installed modules first, then the task's, as the program lists them. *)
type part = {
  part_routines : Ir.routine array;
  part_globals : Ir.global array;
  part_local_names : string array array;
  part_error_numbers : (string * int) list;   (* the ERR_ constants the part declares *)
  part_system : (string * int) list;          (* ERRNO and INTNO, if the part declares them *)
  part_entry_points : (string * int) list;
}

let lower_part ctx ~routine_base ~global_base (all : (A.module_declaration * bool) list) =
  let elab = ctx.elab in
  (* Routine and global numbering first: bodies and initial values refer to any of them. *)
  let routine_decls = concat_long (list_long (fun ((m : A.module_declaration), inst) ->
      List.filter_map (fun (r : A.routine_declaration) ->
          match r.it with
          | Procedure_declaration { name; _ } | Function_declaration { name; _ }
          | Trap_declaration { name; _ } -> Some (m, inst, r, name)
          | Routine_comment _ | RDN_placeholder -> None) m.routine_declarations) all) in
  let routine_decls = List.filter (fun (_, _, _, (name : A.identifier)) ->
      match Source.Table.find_opt elab.declared name.at with Some (Routine _) -> true | _ -> false) routine_decls in
  List.iteri (fun i (_, _, _, (name : A.identifier)) ->
      match Source.Table.find_opt elab.declared name.at with
      | Some (Routine r) -> Source.Table.replace ctx.routine_index r.r_region (routine_base + i)
      | _ -> ()) routine_decls;
  let global_decls = concat_long (list_long (fun ((m : A.module_declaration), _) ->
      List.filter_map (fun (d : A.data_declaration) ->
          match d.it with
          | Data_declaration { name; _ } -> (
              match Source.Table.find_opt elab.declared name.at with
              | Some (Data obj) -> Some (m, obj)
              | _ -> None)
          | Declaration_comment _ | DDN_placeholder -> None) m.data_declarations) all) in
  List.iteri (fun i (_, (obj : Env.data_object)) ->
      Source.Table.replace ctx.global_index obj.d_region (global_base + i))
    global_decls;
  ctx.routine_now <- -1;
  let globals = map_long (fun (m, (obj : Env.data_object)) ->
      { Ir.g_name = obj.d_name; g_module = module_name m; g_init = initial ctx obj;
        g_read_only = obj.d_kind = Read_only_variable; g_at = obj.d_region }) global_decls in
  let local_names = ref [] in
  let routines = Array.mapi (fun i (m, inst, r, _) ->
      ctx.routine_now <- routine_base + i;
      match routine ctx ~module_name:(module_name m) ~installed:inst r with
      | Some r ->
          (* §9.4: the routines of a NOSTEPIN module (and of a NOVIEW one, R-9.4-a) are below the
             user level (§7.3). *)
          let r = { r with nostepin =
                             (not inst)
                             && List.exists (fun (a : A.module_attribute) -> a.it = A.NOSTEPIN || a.it = A.NOVIEW)
                                  m.A.attributes } in
          local_names := Array.init r.locals (fun s ->
              Option.value (Hashtbl.find_opt ctx.slot_names s) ~default:"?") :: !local_names;
          r
      | None -> assert false) (Array.of_list routine_decls) in
  let error_numbers = List.filter_map (fun (_, (obj : Env.data_object)) ->
      let n = String.uppercase_ascii obj.d_name in
      if obj.d_kind = Constant && (String.length n > 4 && String.sub n 0 4 = "ERR_" || n = "LONG_JMP_ALL_ERR") then
        match obj.d_initial with
        | Some { it = Num_literal t; _ } -> (
            match Num_literal.of_text t with
            | Ok v -> Some (obj.d_name, Z.to_int (Q.num (Num_literal.to_q v)))
            | Error _ -> None)
        | _ -> None
      else None) global_decls in
  let system = List.filter_map (fun name ->
      let rec go i = if i >= Array.length globals then None
        else if String.uppercase_ascii globals.(i).Ir.g_name = name then Some (name, global_base + i) else go (i + 1) in
      go 0) [ "ERRNO"; "INTNO" ] in
  let entry_points = List.filter_map (fun x -> x)
      (Array.to_list (Array.mapi (fun i (r : Ir.routine) ->
           if r.kind = Procedure && Array.length r.parameters = 0 && r.primitive = None then
             Some (r.name, routine_base + i)
           else None) routines)) in
  { part_routines = routines; part_globals = globals; part_local_names = Array.of_list (List.rev !local_names);
    part_error_numbers = error_numbers; part_system = system; part_entry_points = entry_points }

let new_ctx elab =
  { elab; routine_index = Source.Table.create 256; global_index = Source.Table.create 256;
    locals = Source.Table.create 16; local_count = 0; labels = Source.Table.create 8; blocks = 0;
    routine_now = -1; slot_names = Hashtbl.create 16; component_names = Hashtbl.create 64;
    argument_texts = Source.Table.create 64; installed_index = None; argument_types = Ir.Argument_types.create 4 }

(* The installed modules' part is the same for every task (its names are bound by the installed
   level alone, and it comes first), so it is lowered once and shared when the checker shares
   the installed level's elaboration (Elaboration.installed): the last one lowered is kept, with
   the tables its lowering filled, keyed by the installed modules and that elaboration, both
   compared physically. The Ir is immutable, so tasks may share it. *)
let installed_cache : (A.module_declaration list * E.t * part * ctx) option ref = ref None

let installed_part ~installed (elab : E.t) =
  let base = Option.value elab.installed ~default:elab in
  match !installed_cache with
  | Some (l, e, part, c) when Rapid_typing.Installed_env.same l installed && e == base -> (part, c)
  | _ ->
      let ctx = new_ctx base in
      (* a level the image's part is not for: its declarations read (Installed_env.full) *)
      let declarations = Rapid_typing.Installed_env.full installed in
      let part = lower_part ctx ~routine_base:0 ~global_base:0 (List.map (fun m -> (m, true)) declarations) in
      if Option.is_some elab.installed then installed_cache := Some (installed, base, part, ctx);
      (part, ctx)

type installed_lowering = A.module_declaration list * E.t * part * ctx

let installed_lowering ~installed (elab : E.t) : installed_lowering =
  let base = Option.value elab.installed ~default:elab in
  let ctx = new_ctx base in
  (installed, base, lower_part ctx ~routine_base:0 ~global_base:0 (List.map (fun m -> (m, true)) installed), ctx)

let installed_lowering_of (_, base, part, ctx) level : installed_lowering = (level, base, part, ctx)

let use_installed_lowering l = installed_cache := Some l

let program ~installed ~modules (elab : E.t) : Ir.program =
  let inst, c = installed_part ~installed elab in
  let ctx = { c with elab; routine_index = Source.Table.create 16; global_index = Source.Table.create 16;
                     component_names = Hashtbl.copy c.component_names;
                     argument_texts = Source.Table.copy c.argument_texts;
                     installed_index = Some (c.routine_index, c.global_index);
                     argument_types = Ir.Argument_types.create 16 } in
  let user = lower_part ctx ~routine_base:(Array.length inst.part_routines)
      ~global_base:(Array.length inst.part_globals) (List.map (fun m -> (m, false)) modules) in
  let routines = Array.append inst.part_routines user.part_routines in
  let globals = Array.append inst.part_globals user.part_globals in
  let local_names = Array.append inst.part_local_names user.part_local_names in
  let find_global name =
    let rec go i = if i >= Array.length globals then 0
      else if String.uppercase_ascii globals.(i).g_name = name then i else go (i + 1) in
    (* ERRNO and INTNO are installed: found among the installed globals, once *)
    match List.assoc_opt name inst.part_system with Some i -> i | None -> go 0 in
  let entry_points = inst.part_entry_points @ user.part_entry_points in
  { routines; globals; errno = find_global "ERRNO"; intno = find_global "INTNO";
    error_numbers = inst.part_error_numbers; entry_points;
    names = { local_names; component_names = ctx.component_names; argument_texts = ctx.argument_texts };
    argument_types = ctx.argument_types }
