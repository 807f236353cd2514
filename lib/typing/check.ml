(* The typing judgement. Each rule of doc/typing.md is one function or one match clause below,
   and names itself in the reports it makes ([~rule]); the rule's section is cited with it. *)

open Rapid_syntax
open Ast
module T = Types

type options = { allow_unknown : bool }

let default_options = { allow_unknown = false }

type unknown_name = { what : string; name : string; first : Source.region; uses : int }

type result = { reports : Report.t list; elaboration : Elaboration.t; unknown : unknown_name list }

let errors r = List.filter (fun (d : Report.t) -> d.severity = Error) r.reports

(* The type of an expression as the judgement infers it. A numeric expression built from
   literals only has no type of its own: it is num, or dnum where the context wants dnum
   (§2.5, §2.13). [Unknown] follows an error already reported (or an unknown name allowed by
   --allow-unknown, or a placeholder): nothing more is said about it. *)
type ty = Known of T.object_type | Numeric_literal | Unknown

type ctx = {
  report : Report.collector;
  options : options;
  installed : Env.table;
  globals : Env.table;
  pos_type : T.data_type;
  orient_type : T.data_type;
  switch_type : T.data_type;     (* the empty domain of a switch parameter (§5.2) *)
  module_names : Env.table;
  elab : Elaboration.t;
  early_constants : (string, string * bool * expression) Hashtbl.t;
      (* name -> (module, local, initial value), for every module constant *)
      (* module constants' initial values, known before their declarations are registered, so
         that an array dimension may name a constant declared later or in another module *)
  installed_constants : (string, string * bool * expression) Hashtbl.t;
      (* for a task's half: the installed half's [early_constants], shared and only read, whose
         bindings come after the task's own (Hashtbl.find_all on one table holding both, the
         task's added last, gave them in that order) *)
  unknown_uses : (string * string, unknown_name * string * string option) Hashtbl.t;
      (* --allow-unknown: (kind, name in lower case) -> the name, its first use, the number of
         uses, the sections; reported once per name when the task is checked *)
  unknown_reported : (string, unit) Hashtbl.t;
      (* routine, kind and name of each unknown name reported in a routine: once is enough *)
  const_cache : Const_eval.cache;   (* each constant's value computed once (R-3.2-b) *)
  mutable signal_argument : string option;
      (* the signal type of the parameter whose argument is being checked: an unknown name there
         is a signal of the controller's I/O configuration, and the hint says where to give it *)
}

(* Where in a routine the judgement is. *)
type place = {
  scope : Env.scope;
  module_name : string;
  routine : Env.routine option;          (* None: module-level declarations *)
  in_error_handler : bool;
  in_nostepin : bool;                    (* a routine of a NOSTEPIN or NOVIEW module (§7.3, §9.4) *)
  in_loop : bool;
  labels : (string, unit) Hashtbl.t option list;
      (* labels of the enclosing statement lists (by key), innermost first; None: a list without
         labels. Tables, since a routine may hold thousands of labels and GOTOs. *)
}

let error ctx ~rule ~section region fmt =
  Printf.ksprintf (Report.error ctx.report ~rule ~section region) fmt

let key = String.lowercase_ascii

(* The type of an object whose declared type could not be resolved (an error or, with
   --allow-unknown, a warning was reported): every use of the object is then left unjudged. *)
let unknown_type = T.Installed_atomic { atomic_name = "?"; atomic_class = Value; associated = None }
let unknown_object_type = { T.base = unknown_type; dims = Scalar }
(* By its name, which no RAPID type can have: the installed environment's image (built at build
   time, lib/load/installed_image.ml) holds copies of this value, not this value itself. *)
let is_unknown_base = function T.Installed_atomic { atomic_name = "?"; _ } -> true | _ -> false
let is_unknown (t : T.object_type) = is_unknown_base t.base

let name_of_identifier (i : identifier) = match i.it with Ident s -> Some s | ID_placeholder -> None

let type_string = function
  | Known t -> T.to_string t
  | Numeric_literal -> "num"
  | Unknown -> "?"

(* ------------------------------------------------------------------ names *)

(* The sections an unknown name's report cites, by what the name was to be. *)
let unknown_name_section = function
  | "data type" -> "2.11,2.12,13"
  | "function" -> "3.11,5.3,13"
  | "procedure" -> "4.6,5.3,13"
  | "trap" -> "4.15,5.3,13"
  | _ -> "2.20,13"

(* --allow-unknown: every use of an unknown name counted, one warning per name (its first use)
   when the task is checked. The hint ("did you mean") is computed only for a use that becomes
   the first one: it searches every name in scope. *)
let unknown_use ctx ~hint region what name =
  let k = (what, key name) in
  let earlier a b =
    let file r = match Source.file_of r with Some f -> Source.name f | None -> "" in
    compare (file a, Source.start_offset a) (file b, Source.start_offset b) < 0 in
  let section = unknown_name_section what in
  match Hashtbl.find_opt ctx.unknown_uses k with
  | Some (u, _, first_hint) ->
      let u, hint = if earlier region u.first then ({ u with first = region; name }, hint ()) else (u, first_hint) in
      Hashtbl.replace ctx.unknown_uses k ({ u with uses = u.uses + 1 }, section, hint)
  | None -> Hashtbl.replace ctx.unknown_uses k ({ what; name; first = region; uses = 1 }, section, hint ())

(* The names in scope at [place] of the kind [what] names, innermost first, spelt as declared:
   the candidates of "did you mean" (Suggest). *)
let names_in_scope (place : place) what =
  let fits (o : Env.obj) = match what, o with
    | "data type", Type _ -> true
    | "function", Routine { r_kind = Function _; _ } -> true
    | "procedure", Routine { r_kind = Procedure; _ } -> true
    | "trap", Routine { r_kind = Trap; _ } -> true
    | "data object", Data _ -> true
    | _ -> false
  in
  let spelling (o : Env.obj) = match o with
    | Data d -> Some d.d_name | Routine r -> Some r.r_name | Type t -> Some t.t_name
    | Label _ | Module _ -> None
  in
  let from table =
    let acc = ref [] in
    Env.iter (fun _ o -> if fits o then Option.iter (fun n -> acc := n :: !acc) (spelling o)) table;
    List.sort String.compare !acc
  in
  let sc = place.scope in
  List.concat_map from sc.routine @ from sc.module_objects
  @ (if sc.in_installed_module then [] else from sc.globals) @ from sc.installed

(* The names rapid-sem test installs beside the others (doc/rulings.md R-test-a): unknown to any
   other command, where their hint says so. *)
let test_names =
  lazy (match Installed_env.test_modules () with
      | Error _ -> []
      | Ok ms ->
          List.concat_map (fun (m : Ast.module_declaration) ->
              List.filter_map (fun (r : Ast.routine_declaration) -> match r.it with
                  | Procedure_declaration { name = { it = Ident n; _ }; _ } -> Some n
                  | _ -> None) m.routine_declarations
              @ List.filter_map (fun (d : Ast.data_declaration) -> match d.it with
                  | Data_declaration { name = { it = Ident n; _ }; _ } -> Some n
                  | _ -> None) m.data_declarations) ms)

let test_hint name =
  match List.find_opt (fun n -> String.lowercase_ascii n = String.lowercase_ascii name) (Lazy.force test_names) with
  | Some n -> Some (Printf.sprintf "%s belongs to the assertions of rapid-sem test, installed only in the modules \
                                    that command runs (doc/testing.md)" n)
  | None -> None

(* §2.20, ch. 13: a name that is neither declared nor installed. In a routine it is reported
   at its first use only, not at every use; each module-level declaration is judged on its own.
   The hint names the names in scope closest to it. *)
(* The kind a stimulus file gives a signal of this type (doc/controller.md): signaldi -> di. *)
let io_kind kind =
  let k = String.lowercase_ascii kind in
  if String.length k > 6 && String.sub k 0 6 = "signal" then String.sub k 6 (String.length k - 6) else k

let unknown_name ctx place region what name =
  let k = match place.routine with
    | Some r ->
        Some (String.concat "\000" [ key place.module_name;
                                      string_of_int (Source.start_offset r.r_region); what; key name ])
    | None -> None in
  (* An unknown name passed for a signal parameter: the signals of a controller's EIO
     configuration are not part of the program (§2.16, R-13-aa); a name of another kind is no
     help. *)
  let suggest () = match what, ctx.signal_argument with
    | "data object", Some kind ->
        Some (Printf.sprintf "%s is passed as a %s: give the controller's I/O signals in a stimulus file (--io FILE \
                              with a line \"signal %s %s\", doc/controller.md), or run with --allow-unknown \
                              --stub-unmodelled to make it a virtual %s at 0" name kind name
                (io_kind kind) kind)
    | _ -> Suggest.hint name (names_in_scope place what) in
  if ctx.options.allow_unknown then
    unknown_use ctx ~hint:suggest region what name
  else if not (match k with Some k -> Hashtbl.mem ctx.unknown_reported k | None -> false) then begin
    Option.iter (fun k -> Hashtbl.add ctx.unknown_reported k ()) k;
    let section = unknown_name_section what in
    let hint = match test_hint name with Some h -> Some h | None -> suggest () in
    Report.error ctx.report ?hint ~rule:"unknown-name" ~section region
      (Printf.sprintf "unknown %s %s: it is neither declared nor installed" what name)
  end

(* §2.11: <data type> ::= <identifier>, bound to a type definition. *)
let resolve_type ctx place (id : identifier) : T.data_type option =
  match id.it with
  | ID_placeholder -> None
  | Ident name -> (
      match Env.lookup_type place.scope name with
      | Some (Type t) ->
          if t.t_type = T.Anytype && not place.scope.in_installed_module then begin
            error ctx ~rule:"anytype-installed-only" ~section:"11" id.at
              "anytype marks parameters of installed routines only: RAPID routines cannot use it";
            None
          end
          else Some t.t_type
      | Some o ->
          error ctx ~rule:"data-type-name" ~section:"2.11,13" id.at "%s is a %s, not a data type" name
            (Env.obj_kind_name o);
          None
      | None -> unknown_name ctx place id.at "data type" name; None)

(* ------------------------------------------------------------------ constants *)

let constant_lookup ctx place name =
  match Env.lookup place.scope name with
  | Some (Data { d_kind = Constant; d_initial; _ }) -> d_initial
  | Some _ -> None
  | None ->
      (* Only constants in scope: the module's own, or global ones of other modules (§2.20). *)
      let k = key name in
      let candidates = Hashtbl.find_all ctx.early_constants k @ Hashtbl.find_all ctx.installed_constants k in
      (match List.find_opt (fun (m, _, _) -> T.same_name m place.module_name) candidates with
       | Some (_, _, e) -> Some e
       | None ->
           List.find_map (fun (m, local, e) ->
               if local || T.same_name m place.module_name then None else Some e) candidates)

let const_value ctx place e = Const_eval.eval ~cache:ctx.const_cache ~lookup:(constant_lookup ctx place) e

(* ------------------------------------------------------------------ types of operands *)

let is_scalar (t : T.object_type) = t.dims = T.Scalar

let operand_of ctx : ty -> Tables.operand option = function
  | Numeric_literal -> Some O_num
  | Unknown -> None
  | Known t when not (is_scalar t) -> None
  | Known t -> (
      match t.base with
      | Num -> Some O_num
      | Dnum -> Some O_dnum
      | Bool -> Some O_bool
      | String -> Some O_string
      | b when T.same_data_type b ctx.pos_type -> Some O_pos
      | b when T.same_data_type b ctx.orient_type -> Some O_orient
      | _ -> None)

let type_of_operand ctx : Tables.operand -> ty = function
  | O_num -> Known (T.scalar Num)
  | O_dnum -> Known (T.scalar Dnum)
  | O_bool -> Known (T.scalar Bool)
  | O_string -> Known (T.scalar String)
  | O_pos -> Known (T.scalar ctx.pos_type)
  | O_orient -> Known (T.scalar ctx.orient_type)
  | O_any_value -> Unknown

(* §2.16: a semi-value object in value context behaves as its associated value type. *)
let in_value_context (t : T.object_type) =
  match T.associated_value_type t.base with
  | Some v -> { t with T.base = v }
  | None -> t

(* §2.17 for the judgement's types: a numeric literal matches num and dnum. *)
let compatible ~expected (actual : ty) =
  match actual with
  | Unknown -> true
  | Numeric_literal -> expected.T.base = T.Anytype
                       || is_scalar expected && (expected.base = Num || expected.base = Dnum
                                              || T.associated_value_type expected.base = Some Num
                                              || T.associated_value_type expected.base = Some Dnum)
  | Known t -> expected.base = T.Anytype || T.equal_types ~value_context:true expected t

(* ------------------------------------------------------------------ data references *)

(* What a reference denotes: its object (for the access-mode table) and its type. *)
type reference = { object_ : Env.data_object option; rtype : ty }

let rec reference ctx place (r : data_reference) : reference =
  match r.it with
  | VAR_placeholder -> { object_ = None; rtype = Unknown }
  | Entire spelling -> (
      let name = { it = spelling; at = r.at } in
      match Env.lookup place.scope name.it with
      | Some (Data d as o) ->
          Source.Table.replace ctx.elab.names name.at o;
          { object_ = Some d; rtype = (if is_unknown d.d_type then Unknown else Known d.d_type) }
      | Some o ->
          error ctx ~rule:"data-object-name"
            ~section:(match o with Label _ -> "4.4,3.6" | _ -> "3.6,2.20,13") name.at "%s is a %s, not a data object"
            name.it (Env.obj_kind_name o);
          { object_ = None; rtype = Unknown }
      | None -> unknown_name ctx place name.at "data object" name.it; { object_ = None; rtype = Unknown })
  | Element (name, indexes) -> (
      let whole = reference ctx place { it = Entire name.it; at = name.at } in
      List.iter (fun i -> check_expression ~sections:"3.6,2.17" ctx place i (T.scalar Num)) indexes;
      match whole.rtype with
      | Known { base; dims = Sized sizes } when List.length sizes <> List.length indexes ->
          index_count ctx name indexes (List.length sizes);
          { whole with rtype = Known (T.scalar base) }
      | Known { base; dims = Conformant rank } when rank <> List.length indexes ->
          index_count ctx name indexes rank;
          { whole with rtype = Known (T.scalar base) }
      | Known { base; dims = Sized sizes } ->
          List.iter2 (fun (i : expression) size ->
              match Option.bind (const_value ctx place i) Const_eval.integer_of with
              | Some n when Z.lt n Z.one || Z.gt n (Z.of_int size) ->
                  error ctx ~rule:"index-range" ~section:"3.6" i.at
                    "index %s is outside the dimension 1..%d of %s" (Z.to_string n) size name.it
              | _ -> ()) indexes sizes;
          { whole with rtype = Known (T.scalar base) }
      | Known { base; dims = Conformant _ } -> { whole with rtype = Known (T.scalar base) }
      | Known { dims = Scalar; _ } ->
          error ctx ~rule:"index-not-array" ~section:"3.6" r.at "%s is not an array" name.it;
          { whole with rtype = Unknown }
      | Numeric_literal | Unknown -> { whole with rtype = Unknown })
  | Component (inner, comp) -> (
      let whole = reference ctx place inner in
      match whole.rtype with
      | Known { base = Record rt; dims = Scalar } -> (
          match T.component rt comp.it with
          | Some t when is_unknown_base t ->
              (* R-2.14-unknown1: not judged; left unresolved, reaching it is ERR_REFUNKDAT. *)
              { whole with rtype = Unknown }
          | Some t ->
              let rec index i = function
                | [] -> i | (n, _) :: rest -> if T.same_name n comp.it then i else index (i + 1) rest in
              Source.Table.replace ctx.elab.components comp.at (index 0 rt.components);
              { whole with rtype = Known (T.scalar t) }
          | None ->
              error ctx ~rule:"component-name" ~section:"3.6,2.14" comp.at
                "the record type %s has no component %s" rt.record_name comp.it;
              { whole with rtype = Unknown })
      | Known t ->
          error ctx ~rule:"component-not-record" ~section:"3.6,2.14" comp.at
            "a value of type %s has no components" (T.to_string t);
          { whole with rtype = Unknown }
      | Numeric_literal | Unknown -> { whole with rtype = Unknown })

(* §3.6: "the number of elements in the index list must fit the declared rank (1, 2 or 3)";
   reported at the first index too many, or at the array's name when there are too few. *)
and index_count ctx (name : name) indexes rank =
  let at = match List.nth_opt indexes rank with Some (i : expression) -> i.at | None -> name.at in
  error ctx ~rule:"index-count" ~section:"3.6" at "%s has %d dimension(s), but %d index(es) are given"
    name.it rank (List.length indexes)

(* ------------------------------------------------------------------ expressions *)

and infer ctx place (e : expression) : ty =
  match e.it with
  | EXP_placeholder -> Unknown
  | Num_literal _ -> Numeric_literal
  | String_literal _ -> Known (T.scalar String)
  | Bool_literal _ -> Known (T.scalar Bool)
  | Data_reference r -> value_of_reference ctx place (Ast.reference e r)
  | Function_call call -> function_call ctx place e.at call
  | Aggregate _ ->
      error ctx ~rule:"aggregate-context" ~section:"3.10" e.at
        "the data type of this aggregate cannot be determined by its context";
      Unknown
  | Unary (op, a, at) -> unary ctx place e op (operand a at)
  | Binary (op, a, b) -> binary ctx place e op a b

(* §2.16: an object used in an expression is of a value type, or of a semi-value type used as
   its associated value type. *)
and value_of_reference ctx place r =
  let { object_; rtype } = reference ctx place r in
  match rtype with
  | Known t -> (
      if t.base = ctx.switch_type then begin
        error ctx ~rule:"switch-no-value" ~section:"5.2" r.at
          "a switch parameter has no value: it can only be tested with Present or passed on";
        Unknown
      end
      else
        match T.value_class t.base with
        | Value -> Known t
        | Semi_value -> Known (in_value_context t)
        | Non_value ->
            error ctx ~rule:"value-class-reference" ~section:"2.16" r.at
              "%s is of the non-value type %s and cannot be used in an expression"
              (match object_ with Some d -> d.d_name | None -> "this object") (T.to_string t);
            Unknown)
  | Numeric_literal | Unknown -> rtype

and unary ctx place e op a =
  let ta = infer ctx place a in
  match ta, operand_of ctx ta with
  | Unknown, _ -> Unknown
  | _, Some operand -> (
      match List.find_opt (fun (row : Tables.unary_row) -> row.unary = op && row.operand = operand)
              Tables.unary_operators with
      | Some row ->
          Source.Table.replace ctx.elab.unary e.at row;
          if ta = Numeric_literal then Numeric_literal else type_of_operand ctx row.unary_result
      | None -> unary_error ctx e op ta)
  | _, None -> unary_error ctx e op ta

and unary_error ctx e op ta =
  error ctx ~rule:"operator-types" ~section:"3.12" e.at "the operator %s cannot be applied to %s"
    (Tables.unary_symbol op) (type_string ta);
  Unknown

(* §3.12: the operator table, row by row. A numeric literal operand takes the type of the other
   operand where that is num or dnum. *)
and binary ctx place e op a b =
  let is_aggregate (x : expression) = match x.it with Aggregate _ -> true | _ -> false in
  match op with
  | Equal | Not_equal -> equality ctx place e op a b
  | _ when is_aggregate a <> is_aggregate b -> aggregate_operand ctx place e op a b
  | _ ->
      let ta = infer ctx place a and tb = infer ctx place b in
      if ta = Unknown || tb = Unknown then Unknown
      else begin
        let operand t other =
          match t, operand_of ctx other with
          | Numeric_literal, Some O_dnum -> Some Tables.O_dnum
          | _ -> operand_of ctx t
        in
        match operand ta tb, operand tb ta with
        | Some la, Some lb -> (
            match List.find_opt (fun (row : Tables.binary_row) -> row.op = op && row.left = la && row.right = lb)
                    Tables.binary_operators with
            | Some row ->
                Source.Table.replace ctx.elab.binary e.at row;
                integer_operands ctx place e row a b;
                if ta = Numeric_literal && tb = Numeric_literal && row.result = O_num then Numeric_literal
                else type_of_operand ctx row.result
            | None -> binary_error ctx e op ta tb)
        | _ -> binary_error ctx e op ta tb
      end

(* §3.10, R-3.10-operand1: an aggregate operand of an operator other than = and <> has the type
   the operator table leaves it, given the other operand's type: the one row whose other operand
   is that type and whose operand in the aggregate's place is a record (pos or orient; an
   aggregate is no scalar, and arrays are operands of = and <> only). p.rot * [0,0,0,1] is an
   orient, pos + [1,2,3] a pos, 2 * [1,2,3] a pos. No such row: no context gives the type. *)
and aggregate_operand ctx place e op a b =
  let aggregate_left = match a.it with Aggregate _ -> true | _ -> false in
  let agg, other = if aggregate_left then (a, b) else (b, a) in
  match infer ctx place other with
  | Unknown -> loosely_expression ctx place agg; Unknown
  | t_other ->
      let other_operands = match t_other with
        | Numeric_literal -> [ Tables.O_num; Tables.O_dnum ]
        | t -> Option.to_list (operand_of ctx t) in
      let record_operand (o : Tables.operand) = o = O_pos || o = O_orient in
      let rows = List.filter (fun (row : Tables.binary_row) ->
          let mine, theirs = if aggregate_left then (row.left, row.right) else (row.right, row.left) in
          row.op = op && record_operand mine && List.mem theirs other_operands) Tables.binary_operators in
      match rows with
      | [ row ] -> (
          let mine = if aggregate_left then row.left else row.right in
          match type_of_operand ctx mine with
          | Known t ->
              check_expression ~sections:"3.12" ctx place agg t;
              Source.Table.replace ctx.elab.binary e.at row;
              type_of_operand ctx row.result
          | Numeric_literal | Unknown -> Unknown)
      | _ ->
          error ctx ~rule:"aggregate-context" ~section:"3.10" agg.at
            "the data type of this aggregate cannot be determined by its context: no row of the \
             operator %s takes an aggregate (a pos or orient) with %s" (Tables.operator_symbol op)
            (type_string t_other);
          Unknown

and binary_error ctx e op ta tb =
  error ctx ~rule:"operator-types" ~section:"3.12" e.at "the operator %s cannot be applied to %s and %s"
    (Tables.operator_symbol op) (type_string ta) (type_string tb);
  Unknown

(* §3.12 notes (b), (c): operands of DIV and MOD must represent integers (positive ones for
   dnum); where an operand is constant, that is known before execution. *)
and integer_operands ctx place (e : expression) (row : Tables.binary_row) a b =
  let natural = List.mem Tables.Natural_operands row.notes in
  if natural || List.mem Tables.Integer_operands row.notes then
    List.iter (fun (x : expression) ->
        match const_value ctx place x with
        | Some (Number q as v) -> (
            match Const_eval.integer_of v with
            | None ->
                error ctx ~rule:"integer-operand" ~section:"3.12" e.at
                  "an operand of %s must represent an integer value, and %s does not"
                  (Tables.operator_symbol row.op) (Q.to_string q)
            | Some n when natural && Z.lt n Z.zero ->
                error ctx ~rule:"integer-operand" ~section:"3.12" e.at
                  "an operand of dnum %s must represent a positive integer value (>= 0)"
                  (Tables.operator_symbol row.op)
            | Some _ -> ())
        | _ -> ()) [ a; b ]

(* §3.12: = and <> take operands of any value type, of equal types (arrays included). An
   aggregate operand takes its type from the other operand (doc/rulings.md R-3.10). *)
and equality ctx place e op a b =
  let is_aggregate (x : expression) = match x.it with Aggregate _ -> true | _ -> false in
  (match is_aggregate a, is_aggregate b with
   | true, true ->
       error ctx ~rule:"aggregate-context" ~section:"3.10" e.at
         "the data types of these aggregates cannot be determined by their context"
   | true, false -> (
       match infer ctx place b with
       | Known t -> check_expression ctx place a t
       | Numeric_literal -> check_expression ctx place a (T.scalar Num)
       | Unknown -> ())
   | false, true -> (
       match infer ctx place a with
       | Known t -> check_expression ctx place b t
       | Numeric_literal -> check_expression ctx place b (T.scalar Num)
       | Unknown -> ())
   | false, false -> (
       let ta = infer ctx place a and tb = infer ctx place b in
       match ta, tb with
       | Unknown, _ | _, Unknown -> ()
       | Numeric_literal, Numeric_literal -> ()
       | Numeric_literal, Known t | Known t, Numeric_literal ->
           if is_scalar t && t.base = Dnum then
             Source.Table.replace ctx.elab.dnum_literals (if ta = Numeric_literal then a.at else b.at) ();
           if not (compatible ~expected:t Numeric_literal) then
             error ctx ~rule:"equality-types" ~section:"3.12" e.at
               "the operator %s needs operands of equal types, not %s and %s"
               (Tables.operator_symbol op) (type_string ta) (type_string tb)
       | Known x, Known y ->
           if T.value_class x.base <> Value then
             error ctx ~rule:"equality-types" ~section:"3.12" e.at
               "the operator %s needs operands of a value type, not %s" (Tables.operator_symbol op)
               (T.to_string x)
           else if not (T.equal_types ~value_context:true x y) then
             error ctx ~rule:"equality-types" ~section:"3.12" e.at
               "the operator %s needs operands of equal types, not %s and %s"
               (Tables.operator_symbol op) (T.to_string x) (T.to_string y)));
  Known (T.scalar Bool)

(* An expression where the context determines the type it must have (§2.17): assignment,
   initial values, arguments, RETURN, test values, aggregate members. *)
and check_expression ?(sections = "2.17") ctx place (e : expression) (expected : T.object_type) =
  match e.it with
  | _ when is_unknown expected -> loosely_expression ctx place e
  | Aggregate (es, rs) -> aggregate ~sections ctx place e (members es rs) expected
  | Binary ((Plus | Minus | Mul | Div | Int_div | Modulo) as op, a, b)
    when is_scalar expected && expected.base = Dnum -> (
      (* A literal operand takes dnum from the context: 2 * d, d + 1. *)
      match infer ctx place e with
      | Numeric_literal -> ignore op; ignore a; ignore b; Source.Table.replace ctx.elab.dnum_literals e.at ()
      | t -> mismatch ~sections ctx e expected t)
  | _ -> mismatch ~sections ctx e expected (infer ctx place e)

and mismatch ~sections ctx (e : expression) expected actual =
  if actual = Numeric_literal && is_scalar expected
     && (expected.base = Dnum || T.associated_value_type expected.base = Some Dnum) then
    Source.Table.replace ctx.elab.dnum_literals e.at ();
  if not (compatible ~expected actual) then
    error ctx ~rule:"equal-types" ~section:sections e.at "expected a value of type %s, found %s"
      (T.to_string expected) (type_string actual)

(* §3.10, §2.17 rule 2: an aggregate is an array or record value whose members have the types of
   the corresponding elements or components. *)
and aggregate ~sections ctx place e members expected =
  let count = Array.length members in
  let element_type (dims : T.dims) : T.dims =
    match dims with
    | Sized [ _ ] | Conformant 1 -> Scalar
    | Sized (_ :: rest) -> Sized rest
    | Conformant n -> Conformant (n - 1)
    | Sized [] | Scalar -> Scalar
  in
  (match expected.dims, expected.base with
   | (Sized (_ :: _) | Conformant _), _ -> Source.Table.replace ctx.elab.aggregates e.at `Array
   | Scalar, Record _ -> Source.Table.replace ctx.elab.aggregates e.at `Record
   | _ -> ());
  match expected.dims, expected.base with
  | (Sized (n :: _)), base ->
      if n <> count then
        error ctx ~rule:"aggregate-size" ~section:("3.10," ^ sections) e.at
          "this aggregate has %d members, but the array dimension is %d" count n;
      Array.iter (fun m -> check_expression ~sections ctx place m { base; dims = element_type expected.dims }) members
  | Conformant _, base ->
      Array.iter (fun m -> check_expression ~sections ctx place m { base; dims = element_type expected.dims }) members
  | Scalar, Record rt ->
      let components = rt.components in
      if List.length components <> count then
        error ctx ~rule:"aggregate-size" ~section:("3.10," ^ sections) e.at
          "this aggregate has %d members, but the record type %s has %d components" count
          rt.record_name (List.length components)
      else List.iteri (fun i (_, t) -> check_expression ~sections ctx place members.(i) (T.scalar t)) components
  | Scalar, T.Anytype -> Array.iter (fun m -> ignore (infer ctx place m)) members
  | Scalar, _ | Sized [], _ ->
      error ctx ~rule:"equal-types" ~section:("3.10," ^ sections) e.at "expected a value of type %s, found an aggregate"
        (T.to_string expected)

(* ------------------------------------------------------------------ calls *)

(* The access-mode table of §5.2: which kind of argument a reference is. *)
and argument_kind (e : expression) (r : reference option) : Tables.argument_kind =
  match e.it, r with
  | Data_reference _, Some { object_ = Some d; _ } -> (
      match d.d_kind with
      | Constant -> Arg_constant
      | Loop_variable | Read_only_variable -> Arg_readonly_variable
      | Variable -> Arg_variable
      | Persistent -> Arg_persistent
      | Parameter Mode_in -> Arg_parameter_in
      | Parameter Mode_var -> Arg_parameter_var
      | Parameter Mode_pers -> Arg_parameter_pers
      | Parameter (Mode_inout | Mode_ref) -> Arg_parameter_inout)
  | _ -> Arg_other_expression

and mode_name : Tables.access_mode -> string = function
  | Mode_in -> "in" | Mode_var -> "VAR" | Mode_pers -> "PERS" | Mode_inout -> "INOUT" | Mode_ref -> "REF"

(* One argument against one parameter: its type (§2.17), its value class (§2.16) and its
   access mode (§5.2). *)
and argument ~call ctx place (arg : argument) (e : expression) (p : Env.parameter) =
  let outer = ctx.signal_argument in
  ctx.signal_argument <- (match p.p_type with
      | Some { base; dims = Scalar } when T.value_class base = T.Semi_value -> Some (T.name base)
      | _ -> None);
  (* Fun.protect's closures at every argument are not needed: nothing here raises but to leave. *)
  match argument_checked ~call ctx place arg e p with
  | () -> ctx.signal_argument <- outer
  | exception x -> ctx.signal_argument <- outer; raise x

and argument_checked ~call ctx place (arg : argument) (e : expression) (p : Env.parameter) =
  (* the sections an error cites, only when it is reported *)
  let sections () = call ^ ",5.2,2.17" in
  match p.p_type with
  | None -> ()
  | Some ptype when is_unknown ptype -> loosely_expression ctx place e
  | Some ptype -> (
      match p.p_mode with
      | Mode_in -> (
          match e.it with
          | Aggregate _ -> check_expression ~sections:(sections ()) ctx place e ptype
          | _ ->
              let actual = infer ctx place e in
              if actual = Numeric_literal && is_scalar ptype && ptype.base = Dnum then
                Source.Table.replace ctx.elab.dnum_literals e.at ();
              if not (compatible ~expected:ptype actual) then
                error ctx ~rule:"equal-types" ~section:(sections ()) arg.at
                  "expected a value of type %s for the parameter %s, found %s" (T.to_string ptype)
                  p.p_name (type_string actual))
      | mode -> (
          let r = match e.it with Data_reference r -> Some (reference ctx place (Ast.reference e r)) | _ -> None in
          let kind = argument_kind e r in
          let unresolved = match r with Some { object_ = None; rtype = Unknown } -> true | _ -> false in
          (match Tables.access_cell kind mode with
           | _ when unresolved -> ()
           | Illegal ->
               error ctx ~rule:"access-mode" ~section:("5.2," ^ call) arg.at
                 "this argument cannot be passed to the %s parameter %s: %s" (mode_name mode) p.p_name
                 (match kind with
                  | Arg_constant -> "it is a constant"
                  | Arg_readonly_variable -> "it is a read-only variable"
                  | Arg_variable -> "it is a variable"
                  | Arg_persistent -> "it is a persistent"
                  | Arg_parameter_in -> "it is an in parameter"
                  | Arg_parameter_var -> "it is a VAR parameter"
                  | Arg_parameter_pers -> "it is a PERS parameter"
                  | Arg_parameter_inout -> "it is an INOUT parameter"
                  | Arg_other_expression -> "it is not a data object reference")
           | Legal | Execution_error | Not_applicable -> ());
          match r with
          | Some { rtype = Known t; _ } ->
              (* §2.16, object references, footnote iii: a non-value or semi-value object is an
                 argument only to a var or ref parameter. *)
              (match T.value_class t.base, mode with
               | (Non_value | Semi_value), (Mode_pers | Mode_inout) when t.base <> ctx.switch_type ->
                   error ctx ~rule:"argument-value-class" ~section:("2.16,5.2," ^ call) arg.at
                     "%s is of the %s type %s: it can be passed only to a VAR or REF parameter, and %s is %s"
                     (match r with Some { object_ = Some d; _ } -> d.d_name | _ -> "this object")
                     (if T.value_class t.base = Non_value then "non-value" else "semi-value")
                     (T.to_string t) p.p_name (mode_name mode)
               | _ -> ());
              if ptype.base <> T.Anytype && not (T.equal_types ~value_context:false ptype t) then
                error ctx ~rule:"equal-types" ~section:(sections ()) arg.at
                  "expected a value of type %s for the parameter %s, found %s"
                  (T.to_string ptype) p.p_name (T.to_string t)
          | Some _ -> ()
          | None -> if kind = Arg_other_expression && mode = Mode_ref then ignore (infer ctx place e)))

(* §3.11, §4.6: the arguments of a call against the routine's parameter list, in order. *)
and arguments ctx place (call_region : Source.region) (routine : Env.routine) (args : argument array) =
  if routine.r_open then loose_arguments ctx place args else
  (* The matching against the parameter slots consumes the arguments from the front. *)
  let args = Array.to_list args in
  let call = match routine.r_kind with Procedure -> "4.6" | Function _ | Trap -> "3.11" in
  let bound = ref [] in
  let bind p a = bound := (p, a) :: !bound in
  let has_placeholder = List.exists (fun (a : argument) -> match a.it with ARG_placeholder -> true | _ -> false) args in
  let arg_name (a : argument) =
    match a.it with
    | Optional_argument (n, _) | Conditional_argument (n, _) -> name_of_identifier n
    | Required_argument (Some n, _, _) -> name_of_identifier n
    | Required_argument (None, _, _) | Positional_argument _ | ARG_placeholder -> None
  in
  (* only for an optional or conditional argument *)
  let optional_names = lazy (List.concat_map (function
      | Env.Optional_slot ps -> List.map (fun (p : Env.parameter) -> p.p_name) ps
      | Env.Required_slot _ | Env.Required_choice _ -> []) routine.r_slots) in
  (* An optional or conditional argument that names no optional parameter of the routine. *)
  let unknown_optional (a : argument) =
    match a.it, arg_name a with
    | (Optional_argument _ | Conditional_argument _), Some n ->
        not (List.exists (fun p -> T.same_name p n) (Lazy.force optional_names))
    | _ -> false in
  let rec go slots (args : argument list) =
    match slots, args with
    | _, ({ it = ARG_placeholder; _ } :: rest) -> go (match slots with _ :: s -> s | [] -> []) rest
    | [], [] -> ()
    | [], a :: _ when unknown_optional a -> ()  (* reported below, once, with the names it may mean *)
    | [], a :: _ ->
        Report.error ctx.report ?hint:(backslash_hint ctx place routine a) ~rule:"argument-count"
          ~section:call a.at (Printf.sprintf "%s takes no more arguments" routine.r_name)
    | Env.Required_slot p :: slots, ({ it = Required_argument (name, e, e_at); _ } as a) :: rest ->
        let e = operand e e_at in
        (match Option.bind name name_of_identifier with
         | Some n when not (T.same_name n p.p_name) ->
             Report.error ctx.report ?hint:(backslash_hint ctx place routine a) ~rule:"argument-name"
               ~section:call a.at
               (Printf.sprintf "the argument is named %s, but the parameter in this place is %s" n p.p_name)
         | _ -> ());
        argument ~call ctx place a e p;
        bind p a;
        go slots rest
    | Env.Required_slot p :: slots, ({ it = Positional_argument e; at } as a) :: rest ->
        argument ~call ctx place a (operand e at) p;
        bind p a;
        go slots rest
    | Env.Required_choice ps :: slots, ({ it = Required_argument (name, e, e_at); _ } as a) :: rest ->
        required_choice slots rest a ps (Option.bind name name_of_identifier) (operand e e_at)
    | Env.Required_choice ps :: slots, ({ it = Positional_argument e; at } as a) :: rest ->
        required_choice slots rest a ps None (operand e at)
    | Env.Required_choice ps :: _, (a :: _) ->
        error ctx ~rule:"argument-required" ~section:call a.at
          "the required argument %s must come here" (choice_names ps)
    | Env.Required_choice ps :: _, [] ->
        if not has_placeholder then
          error ctx ~rule:"argument-required" ~section:call call_region
            "the required argument %s of %s is missing" (choice_names ps) routine.r_name
    | Env.Required_slot p :: _, (a :: _) ->
        error ctx ~rule:"argument-required" ~section:call a.at
          "the required argument %s must come here" p.p_name
    | Env.Required_slot p :: _, [] ->
        if not has_placeholder then
          error ctx ~rule:"argument-required" ~section:call call_region
            "the required argument %s of %s is missing" p.p_name routine.r_name
    | Env.Optional_slot alternatives :: slots, args -> (
        let matches (a : argument) =
          match a.it, arg_name a with
          | (Optional_argument _ | Conditional_argument _), Some n ->
              List.find_opt (fun (p : Env.parameter) -> T.same_name p.p_name n) alternatives
          | _ -> None
        in
        match args with
        | a :: rest -> (
            match matches a with
            | Some p ->
                optional_argument ~call ctx place a p;
                bind p a;
                (* §5.2: at most one of mutually exclusive parameters. *)
                let rec exclusive = function
                  | b :: more -> (
                      match matches b with
                      | Some q when b.it <> ARG_placeholder ->
                          (match b.it with
                           | Conditional_argument _
                             when (match a.it with Conditional_argument _ -> true | _ -> false) ->
                               (* §3.11: several conditional arguments may serve mutually
                                  exclusive parameters; at most one is present when it runs. *)
                               optional_argument ~call ctx place b q;
                               bind q b
                           | _ ->
                               error ctx ~rule:"argument-exclusive" ~section:("5.2," ^ call) b.at
                                 "%s and %s are mutually exclusive: at most one may be given" p.p_name q.p_name);
                          exclusive more
                      | _ -> b :: more)
                  | [] -> []
                in
                go slots (exclusive rest)
            | None -> go slots args)
        | [] -> go slots [])
  (* ABB's "Signal | PersBool" (Installed_choices): the alternative the argument names, or else
     the one whose type it has; an argument of neither type is judged against the first. *)
  and required_choice slots rest (a : argument) (ps : Env.parameter list) named e =
    let chosen = match named with
      | Some n -> (
          match List.find_opt (fun (p : Env.parameter) -> T.same_name p.p_name n) ps with
          | Some p -> Some p
          | None ->
              Report.error ctx.report ~rule:"argument-name" ~section:call a.at
                (Printf.sprintf "the argument is named %s, but the parameter in this place is %s" n
                   (choice_names ps));
              None)
      | None ->
          let quiet = { ctx with report = Report.create (); unknown_reported = Hashtbl.copy ctx.unknown_reported } in
          let ty = infer quiet place e in
          let fits (p : Env.parameter) = match ty, p.p_type with
            | Known t, Some pt -> T.equal_types ~value_context:false t pt
            | Numeric_literal, Some pt -> pt.base = T.Num && pt.dims = T.Scalar
            | _ -> false in
          Some (match List.find_opt fits ps with Some p -> p | None -> List.hd ps) in
    (match chosen with
     | Some p -> argument ~call ctx place a e p; bind p a
     | None -> ());
    go slots rest
  and choice_names ps = String.concat " or " (List.map (fun (p : Env.parameter) -> p.p_name) ps) in
  go routine.r_slots args;
  Source.Table.replace ctx.elab.bindings call_region { Elaboration.callee = routine; bound = List.rev !bound };
  (* Optional or conditional arguments that match no parameter. *)
  List.iter (fun (a : argument) ->
      match a.it, arg_name a with
      | (Optional_argument _ | Conditional_argument _), Some _ when unknown_optional a ->
          let n = Option.get (arg_name a) in
          (* "did you mean \\DecelMax?": the names as an optional argument is written *)
          (* Among names as close, the ones that begin as the name written does (DecMax: DecelMax,
             not AccMax). *)
          let prefix a b =
            let a = String.lowercase_ascii a and b = String.lowercase_ascii b in
            let rec go i = if i < String.length a && i < String.length b && a.[i] = b.[i] then go (i + 1) else i in
            go 0 in
          let close = Suggest.closest n (Lazy.force optional_names) in
          let best = List.fold_left (fun m c -> max m (prefix n c)) 0 close in
          let close = List.filter (fun c -> prefix n c = best) close in
          let hint = match List.map (fun p -> "\\" ^ p) close with
            | [ c ] -> Some (Printf.sprintf "did you mean %s?" c)
            | c :: more -> Some (Printf.sprintf "did you mean %s or %s?" (String.concat ", " more) c)
            | [] when Lazy.force optional_names = [] ->
                Some (Printf.sprintf "%s has no optional parameters" routine.r_name)
            | [] ->
                Some (Printf.sprintf "its optional parameters: %s"
                        (String.concat ", " (List.map (fun p -> "\\" ^ p) (Lazy.force optional_names)))) in
          Report.error ctx.report ?hint ~rule:"argument-name" ~section:call a.at
            (Printf.sprintf "%s has no optional parameter %s" routine.r_name n)
      | _ -> ()) args

(* §4.6, §3.11: an optional argument is written with a backslash and its parameter's name. A
   required argument that names an optional parameter ("WObj:=wobj0"), or one more argument
   than the required parameters take whose type is that of exactly one optional parameter
   ("TPWrite "a = ", a;"), most likely lacks the backslash: the hint writes it out. *)
and backslash_hint ctx place (routine : Env.routine) (a : argument) =
  let optionals = List.concat_map (function
      | Env.Optional_slot ps -> ps | Env.Required_slot _ | Env.Required_choice _ -> []) routine.r_slots in
  let written e = Rapid_syntax.Printer.expression e in
  match a.it with
  | Required_argument (Some { it = Ident n; _ }, e, e_at) -> (
      match List.find_opt (fun (p : Env.parameter) -> T.same_name p.p_name n) optionals with
      | Some p ->
          Some (Printf.sprintf "%s is an optional parameter of %s: write \\%s:=%s (§4.6)"
                  p.p_name routine.r_name p.p_name (written (operand e e_at)))
      | None -> None)
  | Positional_argument _ | Required_argument (None, _, _) -> (
      let e = match Ast.argument_value a with Some e -> e | None -> operand EXP_placeholder a.at in
      (* The argument's type, judged apart: its errors are not this call's to report. *)
      let quiet = { ctx with report = Report.create (); unknown_reported = Hashtbl.copy ctx.unknown_reported } in
      let ty = infer quiet place e in
      let fits (p : Env.parameter) =
        match ty, p.p_type with
        | Known t, Some pt -> T.equal_types ~value_context:true t pt
        | Numeric_literal, Some pt -> pt.base = T.Num && pt.dims = T.Scalar
        | _ -> false
      in
      match List.filter fits optionals with
      | [ p ] ->
          Some (Printf.sprintf "an optional argument is written with a backslash and its \
                                parameter's name: \\%s:=%s (§4.6)" p.p_name (written e))
      | _ -> None)
  | _ -> None

(* §3.11: an optional argument gives the parameter's value (a switch has none); a conditional
   argument passes on an optional parameter of the calling routine. *)
and optional_argument ~call ctx place (a : argument) (p : Env.parameter) =
  match a.it with
  | Optional_argument (_, None) ->
      if p.p_type <> None then
        error ctx ~rule:"optional-argument-value" ~section:call a.at
          "the optional parameter %s is not a switch: give it a value with :=" p.p_name
  | Optional_argument (_, Some e) ->
      if p.p_type = None then
        error ctx ~rule:"switch-argument-value" ~section:call a.at
          "%s is a switch: it takes no value" p.p_name
      else argument ~call ctx place a e p
  | Conditional_argument (_, r) -> (
      let { object_; rtype } = reference ctx place r in
      (match object_ with
       | Some { d_optional = true; _ } | None -> ()
       | Some d ->
           error ctx ~rule:"conditional-argument" ~section:call r.at
             "a conditional argument passes on an optional parameter, and %s is not one" d.d_name);
      match rtype, p.p_type with
      | Known t, Some pt when t.base <> ctx.switch_type && pt.base <> T.Anytype ->
          if not (T.equal_types ~value_context:false pt t) then
            error ctx ~rule:"equal-types" ~section:(call ^ ",2.17") a.at "expected a value of type %s, found %s"
              (T.to_string pt) (T.to_string t)
      | _ -> ())
  | Required_argument _ | Positional_argument _ | ARG_placeholder -> ()

(* An expression whose expected type is not known (an argument of an unknown routine or of a
   parameter whose type is unknown): a data reference may be of any value class there. *)
and loosely_expression ctx place (e : expression) =
  match e.it with
  | Aggregate (es, rs) -> Array.iter (loosely_expression ctx place) (members es rs)
  | Data_reference r -> ignore (reference ctx place (Ast.reference e r))
  | _ -> ignore (infer ctx place e)

and function_call ctx place region (call : function_call) : ty =
  match call.func.it with
  | ID_placeholder -> loose_arguments ctx place (call_arguments call); Unknown
  | Ident name -> (
      match Env.lookup place.scope name with
      | Some (Routine ({ r_kind = Function result; _ } as r) as o) ->
          Source.Table.replace ctx.elab.names call.func.at o;
          arguments ctx place region r (call_arguments call);
          if is_unknown result then Unknown else Known result
      | Some (Routine _) ->
          error ctx ~rule:"function-call" ~section:"3.11" call.func.at "%s is not a function" name;
          Unknown
      | Some o ->
          error ctx ~rule:"function-call" ~section:"3.11" call.func.at "%s is a %s, not a function" name
            (Env.obj_kind_name o);
          Unknown
      | None ->
          unknown_name ctx place call.func.at "function" name; loose_arguments ctx place (call_arguments call); Unknown)

and loose_arguments ctx place (args : argument array) =
  Array.iter (fun (a : argument) ->
      match a.it with
      | Required_argument _ | Positional_argument _ | Optional_argument _ | ARG_placeholder ->
          Option.iter (loosely_expression ctx place) (argument_value a)
      | Conditional_argument (_, r) -> ignore (reference ctx place r)) args

(* §4.6: the arguments of a late-bound call, whose types the binding compares with the
   parameters' when the call runs (ERR_CALLPROC); recorded by the argument's region. *)
and late_arguments ctx place (args : argument array) =
  let record (a : argument) = function
    | Known t -> Source.Table.replace ctx.elab.late_arguments a.at (Some t)
    | Numeric_literal -> Source.Table.replace ctx.elab.late_arguments a.at None
    | Unknown -> () in
  Array.iter (fun (a : argument) ->
      match a.it, argument_value a with
      | Conditional_argument (_, r), _ -> record a (reference ctx place r).rtype
      | _, Some ({ it = Data_reference r; _ } as e) -> record a (reference ctx place (Ast.reference e r)).rtype
      | _, Some ({ it = Aggregate _; _ } as e) -> loosely_expression ctx place e
      | _, Some e -> record a (infer ctx place e)
      | _, None -> ()) args

(* ------------------------------------------------------------------ assignment targets *)

(* §4.5: the target is a variable, persistent or parameter of a value or semi-value type; not a
   constant, a loop variable (§4.18) or a read-only system variable (ch. 12). Also the CONNECT
   target of §4.15 goes through here for its type. *)
let assignment_target ctx place (r : data_reference) : ty =
  let { object_; rtype } = reference ctx place r in
  (match object_ with
   | Some { d_kind = Constant; d_name; _ } ->
       error ctx ~rule:"assign-constant" ~section:"4.5" r.at "%s is a constant: it cannot be assigned" d_name
   | Some { d_kind = Loop_variable; d_name; _ } ->
       error ctx ~rule:"assign-loop-variable" ~section:"4.18" r.at
         "%s is a FOR loop variable: it is read-only" d_name
   | Some { d_kind = Read_only_variable; d_name; _ } ->
       error ctx ~rule:"assign-read-only" ~section:"12" r.at
         "%s is read-only: only the system updates it" d_name
   | Some { d_kind = Parameter Mode_ref; d_name; _ } ->
       ignore d_name
   | _ -> ());
  match rtype with
  | Known t when t.base = ctx.switch_type ->
      error ctx ~rule:"switch-no-value" ~section:"5.2" r.at "a switch parameter has no value to assign";
      Unknown
  | Known t -> (
      match T.value_class t.base with
      | Value -> rtype
      | Semi_value when List.exists (T.same_name (T.name t.base)) Installed_atomic.refuses_update ->
          error ctx ~rule:"assign-refused-by-type" ~section:"2.16" r.at
            "the target is of the semi-value type %s, which refuses an update by value (an input)"
            (T.to_string t);
          Unknown
      | Semi_value -> Known (in_value_context t)
      | Non_value ->
          error ctx ~rule:"assign-value-class" ~section:"4.5" r.at
            "the target is of the non-value type %s: only installed routines change it" (T.to_string t);
          Unknown)
  | _ -> rtype

(* ------------------------------------------------------------------ constant expressions *)

(* §3.2: a constant expression contains no variable, persistent or function call, at any
   level. The first one found is reported. *)
let constant_expression ctx place ~what (e : expression) =
  let offending = ref None in
  let rec walk (e : expression) =
    if !offending = None then
      match e.it with
      | Num_literal _ | String_literal _ | Bool_literal _ | EXP_placeholder -> ()
      | Function_call _ -> offending := Some (e.at, "a function call")
      | Aggregate (es, rs) -> Array.iter walk (members es rs)
      | Unary (_, a, at) -> walk (operand a at)
      | Binary (_, a, b) -> walk a; walk b
      | Data_reference r -> reference_walk (Ast.reference e r)
  and reference_walk (r : data_reference) =
    match r.it with
    | VAR_placeholder -> ()
    | Component (inner, _) -> reference_walk inner
    | Element (name, indexes) -> entire name; List.iter walk indexes
    | Entire spelling -> entire { it = spelling; at = r.at }
  and entire (name : name) =
    if !offending = None then
      match Env.lookup place.scope name.it with
      | Some (Data { d_kind = Constant; _ }) | None -> ()
      | Some (Data { d_kind = Persistent; _ }) -> offending := Some (name.at, "a persistent")
      | Some (Data { d_kind = Parameter _; _ }) -> offending := Some (name.at, "a parameter")
      | Some (Data _) -> offending := Some (name.at, "a variable")
      | Some _ -> ()
  in
  walk e;
  match !offending with
  | Some (at, thing) ->
      error ctx ~rule:"constant-expression" ~section:"3.2" at
        "%s must be a constant expression, which contains no variable, persistent or function \
         call, but this is %s" what thing;
      false
  | None -> true

(* §3.3: a literal expression is a literal (a numeric one possibly signed) or an aggregate whose
   members are literal expressions. *)
let literal_expression ctx (e : expression) =
  let rec ok (e : expression) =
    match e.it with
    | Num_literal _ | String_literal _ | Bool_literal _ | EXP_placeholder -> true
    | Unary ((Unary_plus | Unary_minus), Num_literal _, _) -> true
    | Aggregate (es, rs) -> Array.for_all ok (members es rs)
    | _ -> false
  in
  let rec first_bad (e : expression) =
    match e.it with
    | Aggregate (es, rs) ->
        Array.find_map (fun m -> if ok m then None else Some (first_bad m)) (members es rs)
        |> Option.value ~default:e.at
    | _ -> e.at
  in
  if not (ok e) then
    error ctx ~rule:"literal-expression" ~section:"3.3" (first_bad e)
      "the initial value of a persistent must be a literal expression: a literal, a signed \
       numeric literal, or an aggregate of literal expressions"

(* ------------------------------------------------------------------ statements *)

let labels_of (l : statement list) =
  match List.filter_map (fun (s : statement) ->
      match s.it with Label i -> name_of_identifier i | _ -> None) l with
  | [] -> None
  | names ->
      let t = Hashtbl.create 8 in
      List.iter (fun n -> Hashtbl.replace t (key n) ()) names;
      Some t

let check_condition ~section ctx place (e : expression) =
  check_expression ~sections:(section ^ ",3.4,2.17") ctx place e (T.scalar Bool)

let rec statements ctx place (l : statement list) =
  let place = { place with labels = labels_of l :: place.labels } in
  List.iter (statement ctx place) l

and statement ctx place (s : statement) =
  match s.it with
  | Assignment (target, e) -> (
      match assignment_target ctx place target with
      | Known t -> check_expression ~sections:"4.5,2.17" ctx place e t
      | Numeric_literal | Unknown -> loosely_expression ctx place e)
  | Procedure_call (Procedure_name id, args, regions) ->
      procedure_call ctx place s id (Ast.arguments args regions)
  | Procedure_call (Late_bound e, args, regions) ->
      let args = Ast.arguments args regions in
      (* §4.6: the name is a string evaluated at run time; the arguments are checked against the
         routine then (ERR_REFUNKPRC, ERR_CALLPROC). *)
      check_expression ~sections:"4.6,2.17" ctx place e (T.scalar String);
      late_arguments ctx place args
  | Goto id -> goto ctx place id
  | Break ->
      if not place.in_loop then
        error ctx ~rule:"break-in-loop" ~section:"4.8" s.at "BREAK may be used only in a WHILE or FOR loop"
  | Continue ->
      if not place.in_loop then
        error ctx ~rule:"continue-in-loop" ~section:"4.9" s.at "CONTINUE may be used only in a WHILE or FOR loop"
  | Return e -> return ctx place s e
  | Raise e -> raise_ ctx place s e
  | Exit -> ()
  | Retry ->
      if not place.in_error_handler then
        error ctx ~rule:"retry-in-handler" ~section:"4.13" s.at "RETRY may be used only in an error handler"
  | Trynext ->
      if not place.in_error_handler then
        error ctx ~rule:"trynext-in-handler" ~section:"4.14" s.at "TRYNEXT may be used only in an error handler"
  | Connect (target, trap) -> connect ctx place target trap
  | If i ->
      check_condition ~section:"4.16" ctx place i.condition;
      statements ctx place i.then_branch;
      List.iter (fun (c : elseif_clause) ->
          match c.it with
          | Elseif (cond, l) -> check_condition ~section:"4.16" ctx place cond; statements ctx place l
          | EIT_placeholder -> ()) i.elseifs;
      Option.iter (statements ctx place) i.else_branch
  | Compact_if (cond, s) -> check_condition ~section:"4.17" ctx place cond; statement ctx place s
  | For f -> for_ ctx place f
  | While (cond, body) ->
      check_condition ~section:"4.19" ctx place cond;
      statements ctx { place with in_loop = true } body
  | Test t -> test ctx place t
  | Label _ | Statement_comment _ | SMT_placeholder -> ()

and procedure_call ctx place (s : statement) (id : identifier) args =
  let loose () = loose_arguments ctx place args in
  match id.it with
  | ID_placeholder -> loose ()
  | Ident name -> (
      match Env.lookup place.scope name with
      | Some (Routine ({ r_kind = Procedure; _ } as r) as o) ->
          Source.Table.replace ctx.elab.names id.at o;
          User_level_check.raise_to_user ~report:ctx.report ~in_error_handler:place.in_error_handler
            ~in_nostepin:place.in_nostepin ~installed:(r.r_level = Env.Installed_level) ~at:s.at name args;
          arguments ctx place s.at r args
      | Some (Routine { r_kind = Function _; _ }) ->
          error ctx ~rule:"procedure-call" ~section:"4.6" id.at
            "%s is a function: it is called in an expression, not as a statement" name;
          loose ()
      | Some (Routine { r_kind = Trap; _ }) ->
          error ctx ~rule:"procedure-call" ~section:"5.1" id.at
            "%s is a trap: a trap is never called from RAPID code, only by the system (CONNECT)" name;
          loose ()
      | Some o ->
          error ctx ~rule:"procedure-call" ~section:(match o with Module _ -> "4.6,9.2" | _ -> "4.6") id.at
            "%s is a %s, not a procedure" name
            (Env.obj_kind_name o);
          loose ()
      | None -> unknown_name ctx place id.at "procedure" name; loose ())

(* §4.7: GOTO continues at a label of the same routine, and may not transfer control into a
   statement list: the label stands in the GOTO's own statement list or an enclosing one. *)
and goto ctx place (id : identifier) =
  match name_of_identifier id with
  | None -> ()
  | Some name ->
      let visible = List.exists (function Some t -> Hashtbl.mem t (key name) | None -> false) place.labels in
      (match Env.lookup place.scope name with
       | Some (Label _ as o) -> Source.Table.replace ctx.elab.names id.at o
       | _ -> ());
      if not visible then
        match Env.lookup place.scope name with
        | Some (Label _) ->
            error ctx ~rule:"goto-into-list" ~section:"4.7" id.at
              "GOTO %s would transfer control into a statement list: the label must stand in the \
               GOTO's statement list or one that encloses it" name
        | _ ->
            error ctx ~rule:"goto-label" ~section:"4.7" id.at "there is no label %s in this routine" name

(* §4.10: RETURN with an expression of the function's type in a function, without one in a
   procedure or trap. *)
and return ctx place (s : statement) e =
  match place.routine, e with
  | Some { r_kind = Function t; _ }, Some e -> check_expression ~sections:"4.10,2.17" ctx place e t
  | Some { r_kind = Function _; r_name; _ }, None ->
      error ctx ~rule:"return-function" ~section:"4.10" s.at
        "RETURN in the function %s must give the return value" r_name
  | Some { r_kind = Procedure | Trap; _ }, Some e ->
      error ctx ~rule:"return-procedure" ~section:"4.10" s.at
        "RETURN in a procedure or trap has no return expression";
      loosely_expression ctx place e
  | _, _ -> ()

(* §4.11: RAISE without an error number only in an error handler. RAISE with one "may not stand
   in an error handler": a dialect extension accepts it there (doc/dialect.md, R-4.11-handler1),
   and --strict refuses it when the module is read (Parse, rule raise-number-in-handler). *)
and raise_ ctx place (s : statement) e =
  match e with
  | Some e -> check_expression ~sections:"4.11,2.17" ctx place e (T.scalar Num)
  | None ->
      if not place.in_error_handler then
        error ctx ~rule:"raise-without-number" ~section:"4.11" s.at
          "RAISE without an error number may stand only in an error handler"

(* §4.15: the target is of type num (or an alias of num), a module variable or a VAR or INOUT
   parameter; the trap is a trap routine. *)
and connect ctx place (target : data_reference) (trap : identifier) =
  let { object_; rtype } = reference ctx place target in
  (match rtype with
   | Known { base = Num; dims = Scalar } | Unknown -> ()
   | t ->
       error ctx ~rule:"connect-target-type" ~section:"4.15" target.at
         "the CONNECT target must be of type num or intnum, not %s" (type_string t));
  (match object_ with
   | None -> ()
   | Some d -> (
       match d.d_kind, d.d_level with
       | Variable, (Env.Module_level _ | Env.Installed_level) -> ()
       | Parameter (Mode_var | Mode_inout), _ -> ()
       | Variable, Env.Routine_level ->
           error ctx ~rule:"connect-target-module-variable" ~section:"4.15" target.at
             "the CONNECT target must be a module variable, and %s is a routine variable" d.d_name
       | _ ->
           error ctx ~rule:"connect-target-variable" ~section:"4.15" target.at
             "the CONNECT target must be a module variable or a VAR or INOUT parameter"));
  match trap.it with
  | ID_placeholder -> ()
  | Ident name -> (
      match Env.lookup place.scope name with
      | Some (Routine { r_kind = Trap; _ } as o) -> Source.Table.replace ctx.elab.names trap.at o
      | Some o ->
          error ctx ~rule:"connect-trap" ~section:"4.15" trap.at "%s is a %s, not a trap" name
            (Env.obj_kind_name o)
      | None -> unknown_name ctx place trap.at "trap" name)

(* §4.18: the loop variable is declared by its appearance, of type num, read-only, scoped to the
   loop's statement list, hiding other objects of the same name; FROM, TO and STEP are num. *)
and for_ ctx place (f : for_statement) =
  check_expression ~sections:"4.18,2.17" ctx place f.from_ (T.scalar Num);
  check_expression ~sections:"4.18,2.17" ctx place f.to_ (T.scalar Num);
  Option.iter (fun e -> check_expression ~sections:"4.18,2.17" ctx place e (T.scalar Num)) f.step;
  let loop_scope = Env.create_table () in
  (match f.loop_variable.it with
   | Ident name ->
       let o = Env.Data { d_name = name; d_type = T.scalar Num; d_kind = Loop_variable; d_region = f.loop_variable.at;
                          d_level = Routine_level; d_scope = Global; d_optional = false; d_initial = None } in
       Source.Table.replace ctx.elab.declared f.loop_variable.at o;
       Env.add loop_scope name o
   | ID_placeholder -> ());
  let scope = { place.scope with routine = loop_scope :: place.scope.routine } in
  statements ctx { place with scope; in_loop = true } f.body

(* §4.20: the test expression is of a value or semi-value type; test values are constant
   expressions of an equal type. *)
and test ctx place (t : test_statement) =
  let tt = infer ctx place t.test_expression in
  List.iter (fun (c : case_clause) ->
      match c.it with
      | Case (values, l) ->
          (* §4.20 prints <test value> ::= <constant expression>, but ch. 8's own example tests
             INTNO against variables (TEST INTNO CASE empty:): test values may be any
             expression of the test expression's type (doc/rulings.md R-4.20). *)
          List.iter (fun (v : expression) ->
              match tt with
              | Known ty -> check_expression ~sections:"4.20,2.17" ctx place v ty
              | Numeric_literal -> check_expression ~sections:"4.20,2.17" ctx place v (T.scalar Num)
              | Unknown -> loosely_expression ctx place v) values;
          statements ctx place l
      | CSE_placeholder -> ()) t.cases;
  Option.iter (statements ctx place) t.default

(* ------------------------------------------------------------------ data declarations *)

(* §2.22: array dimensions are 1, 2 or 3 constant expressions of positive integer value. *)
let dimensions ctx place (dims : expression list) : T.dims option =
  if dims = [] then Some Scalar
  else begin
    (match List.nth_opt dims 3 with
     | Some (d : expression) ->
         error ctx ~rule:"array-rank" ~section:"2.22" d.at "an array has 1, 2 or 3 dimensions"
     | None -> ());
    let sizes = List.map (fun (d : expression) ->
        let constant = constant_expression ctx place ~what:"an array dimension" d in
        match d.it with
        | EXP_placeholder -> None
        | _ when not constant -> None
        | _ -> (
            match Option.bind (const_value ctx place d) Const_eval.integer_of with
            | Some n when Z.gt n Z.zero && Z.fits_int n -> Some (Z.to_int n)
            | None when infer ctx place d = Unknown -> None
            | _ ->
                error ctx ~rule:"array-dimension" ~section:"2.22" d.at
                  "an array dimension must be a constant expression of positive integer value";
                None)) dims in
    if List.for_all Option.is_some sizes && List.length dims <= 3 then
      Some (Sized (List.map Option.get sizes))
    else None
  end

(* R-1.4-c: a type whose values have more components than any memory could hold (records of
   records grow exponentially with their depth) is a program too complex for the system's
   resources (§1.4). Values that some memory could hold are the run's memory budget's (R-1.4-b:
   exit status 3 at the declaration). *)
let max_value_components = 1 lsl 40

let value_size_allowed ctx (at : Source.region) what (t : T.object_type) =
  let n = T.value_size t in
  if n > max_value_components then begin
    error ctx ~rule:"value-too-large" ~section:"1.4,2.14" at
      "program too complex: a value of %s has %s atomic components, more than the %d a value \
       may hold in any memory (a system resource, §1.4)" what
      (if n = max_int then "too many" else string_of_int n) max_value_components;
    false
  end
  else true

(* §2.16, first table: which declarations each value class allows. *)
let value_class_allows ctx ~rule ~section (at : Source.region) kind (t : T.data_type) what =
  let cls = T.value_class t in
  match Tables.declaration_cell kind cls with
  | Legal -> ()
  | Illegal | Not_applicable | Execution_error ->
      error ctx ~rule ~section at "%s cannot be of the %s type %s" what
        (match cls with Value -> "value" | Non_value -> "non-value" | Semi_value -> "semi-value")
        (T.name t)

(* §2.18-§2.24: a data declaration, at module level ([routine = false]) or in a routine. *)
let data_declaration ?(later = fun f -> f ()) ctx place ~in_routine ~(level : Env.level)
    (decl : data_declaration) : (string * Env.obj) option =
  match decl.it with
  | Declaration_comment _ | DDN_placeholder -> None
  | Data_declaration { scope; storage; data_type; name; dims; initial_value } -> (
      if in_routine then begin
        (match scope with
         | Local ->
             error ctx ~rule:"local-in-routine" ~section:"2.18" decl.at
               "LOCAL may be used only at module level, not inside a routine"
         | Task ->
             error ctx ~rule:"task-in-routine" ~section:"2.18" decl.at
               "TASK may be used only at module level, not inside a routine"
         | Global -> ());
        if storage = Pers then
          error ctx ~rule:"pers-in-routine" ~section:"2.23" decl.at
            "a persistent may be declared only at module level, not inside a routine"
      end;
      let base = resolve_type ctx place data_type in
      let shape = dimensions ctx place dims in
      let what = match storage with Var -> "a variable" | Pers -> "a persistent" | Const -> "a constant" in
      (match base with
       | Some t ->
           let kind : Tables.declaration_kind =
             match storage, initial_value with
             | Const, _ -> Constant
             | Pers, _ -> Persistent
             | Var, Some _ -> Variable_initialised
             | Var, None -> Variable_uninitialised
           in
           value_class_allows ctx ~rule:"declaration-value-class" ~section:"2.16" data_type.at kind t
             (match kind with Variable_initialised -> "an initialised variable" | _ -> what)
       | None -> ());
      (match storage, initial_value with
       | (Var | Const), Some init ->
           later (fun () -> ignore (constant_expression ctx place ~what:"an initial value" init))
       | Pers, Some init -> literal_expression ctx init
       | Pers, None when scope <> Global && not in_routine ->
           error ctx ~rule:"pers-initial-value" ~section:"2.23" decl.at
             "a LOCAL or TASK persistent must have an initial value: only system-global \
              persistents may omit it"
       | _, None -> ());
      let object_type = match base, shape with Some b, Some d -> Some { T.base = b; dims = d } | _ -> None in
      let object_type = match object_type with
        | Some t when not (value_size_allowed ctx data_type.at ("the type " ^ T.to_string t) t) -> None
        | t -> t in
      let sections = match storage with Var -> "2.22,2.17" | Pers -> "2.23,2.17" | Const -> "2.24,2.17" in
      (* Module data is in scope in its whole module (§2.20): initial values are judged once every
         module's data is registered ([later]). *)
      (match object_type, initial_value with
       | Some t, Some init when T.value_class t.base = Value ->
           later (fun () -> check_expression ~sections ctx place init t)
       | _, Some init -> ignore init
       | _, None -> ());
      match name_of_identifier name with
      | None -> None
      | Some n ->
          let d_type = Option.value object_type ~default:unknown_object_type in
          (* R-2.22-w: a placeholder for a dimension is executed when the data object is made
             (ERR_EXECPHR, as a placeholder for its initial value is): the data has no shape. *)
          let d_initial = match List.find_opt (fun (d : expression) -> d.it = EXP_placeholder) dims with
            | Some d -> Some d
            | None -> initial_value in
          let o = Env.Data { d_name = n; d_type; d_region = name.at; d_level = level; d_scope = scope;
                             d_optional = false; d_initial;
                             d_kind = (match storage with Var -> Variable | Pers -> Persistent | Const -> Constant) } in
          Source.Table.replace ctx.elab.declared name.at o;
          Some (n, o))

(* ------------------------------------------------------------------ parameters and routines *)

let access_mode : Ast.access_mode -> Tables.access_mode = function
  | In -> Mode_in | Var_mode -> Mode_var | Pers_mode -> Mode_pers | Inout -> Mode_inout
  | Ref_mode -> Mode_ref

(* §5.2: one parameter declaration; [optional] when it stands after '\'. *)
let parameter_declaration ctx place ~optional (p : parameter_declaration) : Env.parameter option =
  match p.it with
  | Switch name -> (
      if not optional then
        error ctx ~rule:"switch-optional" ~section:"5.2" name.at
          "a switch parameter must be optional: write \\switch %s"
          (Option.value (name_of_identifier name) ~default:"");
      match name_of_identifier name with
      | Some n -> Some { p_name = n; p_mode = Mode_in; p_type = None; p_region = name.at }
      | None -> None)
  | Parameter { mode; data_type; name; array } -> (
      let mode = access_mode mode in
      let base = resolve_type ctx place data_type in
      let dims : T.dims option =
        match array with
        | Not_array -> Some Scalar
        | Conformant rank ->
            if rank > 3 then begin
              error ctx ~rule:"array-rank" ~section:"5.2" p.at "an array parameter has 1, 2 or 3 dimensions";
              None
            end
            else Some (Conformant rank)
        | DIM_placeholder -> None
      in
      (match base with
       | Some t when t <> T.Anytype ->
           let kind : Tables.declaration_kind =
             match mode with
             | Mode_in -> Parameter_in
             | Mode_var -> Parameter_var
             | Mode_pers -> Parameter_pers
             | Mode_ref -> Parameter_ref
             | Mode_inout -> Parameter_inout_var
           in
           value_class_allows ctx ~rule:"parameter-value-class" ~section:"2.16" data_type.at kind t
             (match mode with
              | Mode_in -> "an in parameter" | Mode_var -> "a VAR parameter"
              | Mode_pers -> "a PERS parameter" | Mode_inout -> "an INOUT parameter"
              | Mode_ref -> "a REF parameter")
       | _ -> ());
      match name_of_identifier name with
      | None -> None
      | Some n ->
          let p_type = match base, dims with
            | Some b, Some d
              when value_size_allowed ctx data_type.at ("the type " ^ T.name b) { T.base = b; dims = Scalar } ->
                Some { T.base = b; dims = d }
            | _ -> Some unknown_object_type in
          Some { p_name = n; p_mode = mode; p_type; p_region = name.at })

let parameter_slots ctx place (params : Ast.parameter list) : Env.parameter_slot list =
  List.filter_map (fun (p : Ast.parameter) ->
      match p.it with
      | PAR_placeholder -> None
      | Required_parameter d ->
          Option.map (fun p -> Env.Required_slot p) (parameter_declaration ctx place ~optional:false d)
      | Optional_parameter alternatives ->
          let ps = List.filter_map (fun (a : alternative) ->
              match a.it with
              | ALT_placeholder -> None
              | Alternative d -> parameter_declaration ctx place ~optional:true d) alternatives in
          if ps = [] then None else Some (Env.Optional_slot ps)) params

let switch_object ctx (p : Env.parameter) ~optional : Env.data_object =
  let d_type, d_kind =
    match p.p_type with
    | None -> (T.scalar ctx.switch_type, Env.Parameter Mode_in)
    | Some t -> (t, Env.Parameter p.p_mode)
  in
  { d_name = p.p_name; d_type; d_kind; d_region = p.p_region; d_level = Routine_level; d_scope = Global;
    d_optional = optional; d_initial = None }

(* ------------------------------------------------------------------ routine bodies *)

(* Every label of a routine, in all its statement lists (§4.4: their scope is the routine). *)
let rec all_labels acc (l : statement list) =
  List.fold_left (fun acc (s : statement) ->
      match s.it with
      | Label i -> (match name_of_identifier i with Some n -> (n, i.at) :: acc | None -> acc)
      | If i ->
          let acc = all_labels acc i.then_branch in
          let acc = List.fold_left (fun acc (c : elseif_clause) ->
              match c.it with Elseif (_, l) -> all_labels acc l | EIT_placeholder -> acc) acc i.elseifs in
          Option.fold ~none:acc ~some:(all_labels acc) i.else_branch
      | Compact_if (_, s) -> all_labels acc [ s ]
      | For f -> all_labels acc f.body
      | While (_, l) -> all_labels acc l
      | Test t ->
          let acc = List.fold_left (fun acc (c : case_clause) ->
              match c.it with Case (_, l) -> all_labels acc l | CSE_placeholder -> acc) acc t.cases in
          Option.fold ~none:acc ~some:(all_labels acc) t.default
      | _ -> acc) acc l

(* §2.20, §4.4: names declared in a routine — parameters, data, labels — are distinct. *)
let add_routine_name ctx table name (obj : Env.obj) =
  match Env.find table name with
  | Some previous ->
      let rule, section, message =
        match previous, obj with
        | Label _, Label _ -> ("label-clash", "4.4", "two labels of one routine may not share a name")
        | Label _, _ | _, Label _ ->
            ("label-data-clash", "4.4", "a routine data object and a label of the same routine may not share a name")
        | _ -> ("routine-data-clash", "2.20", "two data objects of one routine may not share a name")
      in
      error ctx ~rule ~section (Env.obj_region obj) "%s: %s is declared twice" message name
  | None -> Env.add table name obj

(* §7.2 <error number> of an ERROR list: a num literal, or an entire constant, variable or
   persistent of type errnum (an alias of num). *)
let recovery_error_number ctx place (n : recovery_error_number) =
  match n.it with
  | Error_number_literal t -> (
      (* An error number is a whole number a num holds exactly (§7.2, §2.4: ERRNO is a num);
         any other literal names no error. *)
      match Rapid_syntax.Num_literal.of_text t with
      | Ok v ->
          let q = Rapid_syntax.Num_literal.to_q v in
          if not (Z.equal (Q.den q) Z.one && Z.leq (Z.abs (Q.num q)) (Z.of_int 8388608)) then
            error ctx ~rule:"error-number-list" ~section:"7.2" n.at
              "an error number of an ERROR list is a whole number from -8388608 to 8388608, not %s" t
      | Error m -> error ctx ~rule:"error-number-list" ~section:"7.2" n.at "%s" m)
  | Error_number_name name -> (
      match Env.lookup place.scope name.it with
      | Some (Data { d_type = { base = Num; dims = Scalar }; d_kind = Constant | Variable | Persistent; _ } as o) ->
          Source.Table.replace ctx.elab.names name.at o
      | Some (Data _) ->
          error ctx ~rule:"error-number-list" ~section:"7.2" n.at
            "an error number of an ERROR list is a num literal or an entire constant, variable or \
             persistent of type errnum"
      | Some o ->
          error ctx ~rule:"error-number-list" ~section:"7.2" n.at "%s is a %s, not an error number" name.it
            (Env.obj_kind_name o)
      | None -> unknown_name ctx place name.at "data object" name.it)

let routine_body ctx (module_place : place) (routine : Env.routine) (body : routine_body) =
  let table = Env.create_table () in
  let parameter (p : Env.parameter) ~optional =
    let o = Env.Data (switch_object ctx p ~optional) in
    Source.Table.replace ctx.elab.declared p.p_region o;
    add_routine_name ctx table p.p_name o
  in
  List.iter (function
      | Env.Required_slot p -> parameter p ~optional:false
      | Env.Optional_slot ps | Env.Required_choice ps -> List.iter (parameter ~optional:true) ps)
    routine.r_slots;
  let place = { module_place with scope = { module_place.scope with routine = [ table ] };
                                  routine = Some routine } in
  List.iter (fun decl ->
      match data_declaration ctx place ~in_routine:true ~level:Routine_level decl with
      | Some (n, o) -> add_routine_name ctx table n o
      | None -> ()) body.declarations;
  let lists = body.statements :: List.filter_map Fun.id
                [ body.backward; Option.map (fun h -> h.handler) body.error; body.undo ] in
  List.iter (fun (n, at) ->
      Source.Table.replace ctx.elab.declared at (Label at); add_routine_name ctx table n (Label at))
    (List.rev (List.fold_left all_labels [] lists));
  statements ctx place body.statements;
  Option.iter (statements ctx place) body.backward;
  Option.iter (fun (h : error_handler) ->
      Option.iter (List.iter (recovery_error_number ctx place)) h.error_numbers;
      statements ctx { place with in_error_handler = true } h.handler) body.error;
  Option.iter (statements ctx place) body.undo

(* ------------------------------------------------------------------ modules and the task *)

type module_info = {
  m : module_declaration;
  m_name : string;
  objects : Env.table;
  is_installed : bool;
}

(* §9.2: each attribute at most once, in the order of the table, and NOVIEW excludes NOSTEPIN,
   VIEWONLY and READONLY, VIEWONLY and READONLY exclude each other. *)
let module_attributes ctx (attributes : module_attribute list) =
  let rank a = let rec find i = function
      | [] -> 0 | x :: rest -> if x = a then i else find (i + 1) rest in find 0 Tables.attribute_order in
  ignore (List.fold_left (fun seen (a : module_attribute) ->
      let name = Tables.attribute_name a.it in
      if List.mem a.it seen then
        error ctx ~rule:"attribute-once" ~section:"9.2" a.at "the attribute %s is given twice" name
      else if List.exists (fun s -> rank s > rank a.it) seen then
        error ctx ~rule:"attribute-order" ~section:"9.2" a.at
          "the attribute %s must come before %s: attributes follow the order SYSMODULE, NOVIEW, \
           NOSTEPIN, VIEWONLY, READONLY" name
          (Tables.attribute_name (List.find (fun s -> rank s > rank a.it) seen));
      (match List.find_opt (fun s -> List.mem (s, a.it) Tables.attribute_exclusions
                                     || List.mem (a.it, s) Tables.attribute_exclusions) seen with
       | Some other ->
           error ctx ~rule:"attribute-exclusion" ~section:"9.2" a.at "the attributes %s and %s exclude each other"
             (Tables.attribute_name other) name
       | None -> ());
      a.it :: seen) [] attributes)

(* §2.12, §2.20, §5.3, §9.2: registering a module-level object, with the name-clash rules. *)
let register ctx info ~local name (obj : Env.obj) =
  match Env.find info.objects name with
  | Some _ ->
      error ctx ~rule:"module-object-clash" ~section:"2.20,2.12,5.3" (Env.obj_region obj)
        "two objects declared in the module %s may not share the name %s" info.m_name name
  | None ->
      Env.add info.objects name obj;
      if not local then begin
        let table = if info.is_installed then ctx.installed else ctx.globals in
        match Env.find table name with
        | Some _ when not info.is_installed ->
            error ctx ~rule:"global-object-clash" ~section:"2.20,2.12,5.3" (Env.obj_region obj)
              "two global objects of the task buffer may not share the name %s" name
        | Some _ ->
            error ctx ~rule:"global-object-clash" ~section:"13" (Env.obj_region obj)
              "the installed object %s is declared twice" name
        | None -> Env.add table name obj
      end

let scope_of ctx info : Env.scope =
  { installed = ctx.installed; globals = ctx.globals; module_objects = info.objects;
    module_names = ctx.module_names; routine = [];
    in_installed_module = info.is_installed }

let module_place ctx info =
  { scope = scope_of ctx info; module_name = info.m_name; routine = None; in_error_handler = false;
    in_nostepin = List.exists (fun (a : module_attribute) -> a.it = NOSTEPIN || a.it = NOVIEW) info.m.attributes;
    in_loop = false; labels = [] }

(* §2.14, §2.15: type definitions. Records are created first, so that components may name
   records defined later; an alias may not be defined on an alias; a record may not contain
   itself. *)
let type_definitions ctx infos =
  let pending = ref [] in
  List.iter (fun info ->
      List.iter (fun (td : type_definition) ->
          match td.it with
          | Record_definition { local; name; components } -> (
              match name_of_identifier name with
              | Some n ->
                  let rt = { T.record_id = T.new_record_id (); record_name = n; components = [] } in
                  register ctx info ~local n
                    (Type { t_name = n; t_type = Record rt; t_alias = false; t_region = name.at;
                            t_level = (if info.is_installed then Installed_level else Module_level info.m_name);
                            t_local = local });
                  pending := `Record (info, rt, components) :: !pending
              | None -> ())
          | Alias_definition { local; base; name } -> (
              match name_of_identifier name with
              | Some n -> pending := `Alias (info, local, n, name.at, base) :: !pending
              | None -> ())
          | Type_comment _ | TDN_placeholder -> ()) info.m.type_definitions) infos;
  let pending = List.rev !pending in
  (* Aliases next: their base may be a record of any module, or a built-in type. *)
  List.iter (function
      | `Alias (info, local, n, at, (base : identifier)) -> (
          let place = module_place ctx info in
          let target =
            match base.it with
            | ID_placeholder -> None
            | Ident b -> (
                match Env.lookup place.scope b with
                | Some (Type { t_alias = true; _ }) ->
                    error ctx ~rule:"alias-of-alias" ~section:"2.15" base.at
                      "an alias type may not be defined on another alias type (%s is one)" b;
                    None
                | _ -> resolve_type ctx place base)
          in
          match target with
          | Some t ->
              register ctx info ~local n
                (Type { t_name = n; t_type = t; t_alias = true; t_region = at;
                        t_level = (if info.is_installed then Installed_level else Module_level info.m_name);
                        t_local = local })
          | None -> ())
      | `Record _ -> ()) pending;
  List.iter (function
      | `Record (info, (rt : T.record_type), (components : record_component list)) ->
          let place = module_place ctx info in
          let seen = Hashtbl.create 8 in
          rt.components <- List.filter_map (fun (c : record_component) ->
              match c.it with
              | Component_comment _ -> None
              | Record_component (t, n) -> (
                  match name_of_identifier n with
                  | None -> None
                  | Some cn ->
                      if Hashtbl.mem seen (key cn) then begin
                        error ctx ~rule:"component-clash" ~section:"2.14" n.at
                          "two components of the record %s may not share the name %s" rt.record_name cn;
                        None
                      end
                      else begin
                        Hashtbl.add seen (key cn) ();
                        match resolve_type ctx place t with
                        | Some T.Anytype -> None
                        | Some ty -> Some (cn, ty)
                        | None ->
                            (* R-2.14-unknown1: a component whose type is unknown (reported: an
                               error, or a warning under --allow-unknown) stays a component, of
                               unknown type: its uses are not judged, as an object's would not be. *)
                            Some (cn, unknown_type)
                      end)) components
      | `Alias _ -> ()) pending;
  (* A record that contains itself, directly or through other records, has no finite value
     (§2.14): exactly the records on a cycle of the "has a component of type" graph. One pass
     over the graph (Tarjan's strongly connected components), so that long chains of records
     each using the previous one cost time linear in their number. *)
  let records = List.filter_map (function
      | `Record (info, (rt : T.record_type), _) -> Some (info, rt)
      | `Alias _ -> None) pending in
  let on_cycle = Record_cycles.on_cycle
      ~id:(fun (_, (rt : T.record_type)) -> rt.record_id)
      ~successors:(fun (_, (rt : T.record_type)) ->
          List.filter_map (fun (_, (c : T.data_type)) ->
              match c with Record r -> Some r.record_id | _ -> None) rt.components)
      records in
  List.iter (fun (info, (rt : T.record_type)) ->
      if on_cycle rt.record_id then begin
        (match Env.find info.objects rt.record_name with
         | Some o ->
             error ctx ~rule:"record-recursive" ~section:"2.14" (Env.obj_region o)
               "the record %s contains itself" rt.record_name
         | None -> ())
      end) records;
  List.iter (fun (_, (rt : T.record_type)) -> if on_cycle rt.record_id then rt.components <- []) records

(* §5.1-§5.6: a routine's signature, registered before any body is checked so that calls may
   name routines declared later or in other modules. *)
let routine_signature ctx info (r : routine_declaration) =
  let place = module_place ctx info in
  let level = if info.is_installed then Env.Installed_level else Env.Module_level info.m_name in
  let make local (name : identifier) kind params =
    match name_of_identifier name with
    | None -> None
    | Some n ->
        let slots = parameter_slots ctx place params in
        let slots = if info.is_installed then Installed_choices.apply n slots else slots in
        (* A parameter list with placeholders (§2.9) is not known enough to check calls. *)
        let r_open = List.exists (fun (p : Ast.parameter) ->
            match p.it with
            | PAR_placeholder -> true
            | Optional_parameter alts ->
                List.exists (fun (a : alternative) -> match a.it with
                    | ALT_placeholder -> true
                    | Alternative { it = Parameter { array = DIM_placeholder; _ }; _ } -> true
                    | Alternative _ -> false) alts
            | Required_parameter { it = Parameter { array = DIM_placeholder; _ }; _ } -> true
            | Required_parameter _ -> false) params in
        let routine = { Env.r_name = n; r_kind = kind; r_slots = slots; r_region = name.at;
                        r_level = level; r_local = local; r_open } in
        Source.Table.replace ctx.elab.declared name.at (Routine routine);
        register ctx info ~local n (Routine routine);
        Some routine
  in
  match r.it with
  | Procedure_declaration { local; name; parameters; body } ->
      Option.map (fun x -> (x, body)) (make local name Procedure parameters)
  | Function_declaration { local; return_type; name; parameters; body } -> (
      match resolve_type ctx place return_type with
      | Some t when not (value_size_allowed ctx return_type.at ("the type " ^ T.name t) (T.scalar t)) ->
          Option.map (fun x -> (x, body)) (make local name (Function unknown_object_type) parameters)
      | Some t ->
          value_class_allows ctx ~rule:"function-value-class" ~section:"2.16" return_type.at
            Function_return t "the return value of a function";
          Option.map (fun x -> (x, body)) (make local name (Function (T.scalar t)) parameters)
      | None ->
          Option.map (fun x -> (x, body)) (make local name (Function unknown_object_type) parameters))
  | Trap_declaration { local; name; body } -> Option.map (fun x -> (x, body)) (make local name Trap [])
  | Routine_comment _ | RDN_placeholder -> None

(* §9.1: the entry routine of a task takes no parameters. *)
let entry_routine ctx (routine : Env.routine) =
  if T.same_name routine.r_name "main" && routine.r_kind = Procedure && routine.r_slots <> [] then
    error ctx ~rule:"entry-routine-parameters" ~section:"9.1" routine.r_region
      "the entry routine main cannot have parameters"


(* The installed constants of the installed half itself: none (never added to; [copy_ctx] tells
   the installed half by it). *)
let no_constants : (string, string * bool * expression) Hashtbl.t = Hashtbl.create 1

let builtin_environment report options =
  let installed = Env.create_table () in
  let add_type ?(alias = false) name t =
    Env.add installed name (Type { t_name = name; t_type = t; t_alias = alias; t_region = Source.no_region;
                                   t_level = Installed_level; t_local = false })
  in
  (* §2.13 *)
  List.iter (fun (row : Tables.atomic_row) -> add_type (T.name row.atomic) row.atomic) Tables.atomic_types;
  add_type "anytype" T.Anytype;
  (* The installed atomic types, which RAPID source cannot declare. *)
  List.iter (fun (name, cls, associated) ->
      add_type name (T.Installed_atomic { atomic_name = name; atomic_class = cls; associated }))
    Installed_atomic.atomic_types;
  (* §2.14: built-in records, components in order. *)
  let records = List.map (fun (name, _) ->
      let rt = { T.record_id = T.new_record_id (); record_name = name; components = [] } in
      add_type name (Record rt); (name, rt)) Tables.builtin_records in
  let resolve tn = match Env.find installed tn with Some (Type t) -> t.t_type | _ -> T.Anytype in
  List.iter (fun (name, components) ->
      let rt = List.assoc name records in
      rt.components <- List.map (fun (c, tn) -> (c, resolve tn)) components) Tables.builtin_records;
  (* §2.15: built-in aliases. *)
  List.iter (fun (name, base) -> add_type ~alias:true name (resolve base)) Tables.builtin_aliases;
  {
    report; options; installed; globals = Env.create_table ();
    pos_type = resolve "pos"; orient_type = resolve "orient";
    switch_type = T.Installed_atomic { atomic_name = "switch"; atomic_class = Non_value; associated = None };
    module_names = Env.create_table ();
    elab = Elaboration.create ();
    early_constants = Hashtbl.create 64; installed_constants = no_constants;
    unknown_uses = Hashtbl.create 16;
    unknown_reported = Hashtbl.create 16;
    const_cache = Const_eval.create_cache (); signal_argument = None;
  }

(* ch. 12: ERRNO and INTNO are variables that only the system updates; C_MOTSET likewise (ABB's
   motsetdata: only the motion settings instructions change it; R-13-motset1). *)
let read_only_system_variables = [ "ERRNO"; "INTNO"; "C_MOTSET" ]

(* The installed level is checked once and shared (fuzzing checks thousands of small tasks
   over the same installed environment): nothing of it depends on the user modules, since an
   installed module sees only itself and the installed level (ch. 13, Env.lookup). So the task
   is checked in two halves, the installed modules and then the user modules, each going through
   the phases of the task in order (module data, initial values, signatures, bodies); the second
   half starts from a copy of the tables the first one filled. *)

let module_info is_installed (m : module_declaration) =
  let m_name = Option.value (name_of_identifier m.module_name) ~default:"" in
  { m; m_name; objects = Env.create_table (); is_installed }

let early_constants ctx infos =
  List.iter (fun i ->
      List.iter (fun (d : data_declaration) ->
          match d.it with
          | Data_declaration { storage = Const; scope; name = { it = Ident n; _ }; initial_value = Some e; _ } ->
              Hashtbl.add ctx.early_constants (key n) (i.m_name, scope = Local, e)
          | _ -> ()) i.m.data_declarations) infos

(* Module data, in declaration order; initial values once all is registered. *)
let module_data ctx infos =
  let deferred = ref [] in
  let later f = deferred := f :: !deferred in
  List.iter (fun i ->
      let place = module_place ctx i in
      let level = if i.is_installed then Env.Installed_level else Env.Module_level i.m_name in
      List.iter (fun (d : data_declaration) ->
          match data_declaration ~later ctx place ~in_routine:false ~level d with
          | Some (n, Data obj) ->
              let obj =
                if i.is_installed && List.exists (T.same_name n) read_only_system_variables
                then Env.Data { obj with d_kind = Read_only_variable } else Env.Data obj in
              let local = match d.it with Data_declaration { scope = Local; _ } -> true | _ -> false in
              register ctx i ~local n obj
          | Some (n, o) -> register ctx i ~local:false n o
          | None -> ()) i.m.data_declarations) infos;
  List.iter (fun f -> f ()) (List.rev !deferred)

let signatures ctx infos =
  List.concat_map (fun i ->
      List.filter_map (fun r -> Option.map (fun x -> (i, x)) (routine_signature ctx i r))
        i.m.routine_declarations) infos

let bodies ctx l =
  List.iter (fun (i, (routine, body)) ->
      if not i.is_installed then entry_routine ctx routine;
      routine_body ctx (module_place ctx i) routine body) l

(* The first half: the installed modules, in a fresh environment. *)
let check_installed options installed =
  let ctx = builtin_environment (Report.create ()) options in
  let infos = List.map (module_info true) installed in
  early_constants ctx infos;
  type_definitions ctx infos;
  module_data ctx infos;
  bodies ctx (signatures ctx infos);
  (ctx, infos)

(* The environment after the first half, for a task's second half. The second half adds
   nothing to the installed level's table, nor to the installed modules' own tables (it registers
   user objects in the globals), so those are shared; the tables it adds to are copied, and the
   task's elaboration keeps its own nodes apart from the installed modules' ones
   (Elaboration.installed). *)
let copy_ctx ?text report ctx =
  (* the installed half's constants shared rather than copied for every task: 1 % of a fuzzing
     campaign *)
  let early_constants, installed_constants =
    if ctx.installed_constants == no_constants then (Hashtbl.create 64, ctx.early_constants)
    else (Hashtbl.copy ctx.early_constants, ctx.installed_constants) in
  { ctx with report; globals = Env.copy_table ctx.globals; module_names = Env.copy_table ctx.module_names;
             elab = Elaboration.create ?text ~installed:ctx.elab ();
             early_constants; installed_constants; unknown_uses = Hashtbl.copy ctx.unknown_uses;
             unknown_reported = Hashtbl.copy ctx.unknown_reported; const_cache = Const_eval.copy_cache ctx.const_cache }

(* The last installed environment checked, when its check reported nothing: [installed] is
   compared physically, so that a new list (another I/O configuration's signals) is checked
   afresh. *)
let installed_cache : (module_declaration list * options * ctx * module_info list) option ref = ref None

(* A check without reports under [allow_unknown = false] met no unknown name, so it is also the
   check under [allow_unknown = true] (which differs only in what it does with unknown names). *)
let installed_half ?text options installed =
  match !installed_cache with
  | Some (l, o, ctx, infos) when Installed_env.same l installed && (o = options || not o.allow_unknown) ->
      ({ (copy_ctx ?text (Report.create ()) ctx) with options }, infos)
  | _ ->
      (* a level the image's state is not for: its declarations read (Installed_env.full) *)
      let ctx, infos = check_installed options (Installed_env.full installed) in
      if Report.all ctx.report = [] then begin
        installed_cache := Some (installed, options, ctx, infos);
        (copy_ctx ?text (Report.create ()) ctx, infos)
      end
      else (ctx, infos)

(* The characters the modules' text spans (of their own files): how large the tables grow. *)
let text_of modules =
  List.fold_left (fun acc (m : module_declaration) ->
      acc + max 0 (Source.stop_offset m.module_region - Source.start_offset m.module_region)) 0 modules

let check_task ?(options = default_options) ~installed modules =
  let ctx, installed_infos = installed_half ~text:(text_of modules) options installed in
  let report = ctx.report in
  let user = List.map (module_info false) modules in
  let infos = installed_infos @ user in
  (* §9.2: two modules may not share a name. *)
  ignore (List.fold_left (fun seen i ->
      if i.m_name <> "" && List.mem (key i.m_name) seen then begin
        error ctx ~rule:"module-name-clash" ~section:"9.2" i.m.module_name.at
          "two modules may not share the name %s" i.m_name;
        seen
      end
      else key i.m_name :: seen) [] infos);
  List.iter (fun i -> module_attributes ctx i.m.attributes;
                      if i.m_name <> "" then Env.add ctx.module_names i.m_name (Module i.m.module_name.at)) user;
  (* Constants' initial values, for array dimensions that name them. *)
  early_constants ctx user;
  type_definitions ctx user;
  module_data ctx user;
  let user_bodies = signatures ctx user in
  (* §2.20, §5.3, §9.2: a global object and a module may not share a name. *)
  let index_of_module name =
    let rec go k = function [] -> -1 | i :: rest -> if T.same_name i.m_name name then k else go (k + 1) rest in
    go 0 infos in
  List.iteri (fun k i ->
      match Env.find ctx.globals i.m_name with
      | Some o ->
          (* Reported at whichever of the two comes later in the task buffer. *)
          let object_module = match o with
            | Data { d_level = Module_level m; _ } | Routine { r_level = Module_level m; _ }
            | Type { t_level = Module_level m; _ } -> index_of_module m
            | _ -> -1 in
          let at = if object_module >= k + List.length installed then Env.obj_region o else i.m.module_name.at in
          error ctx ~rule:"global-module-clash" ~section:"9.2" at
            "a global object and a module may not share the name %s" i.m_name
      | None -> ()) user;
  bodies ctx user_bodies;
  (* §5.5: a function whose statements can complete ends without RETURN (ERR_FNCNORET). *)
  List.iter (fun i ->
      List.iter (fun (name, at, last) ->
          let hint = Printf.sprintf "end every path of %s with RETURN and its value (an ELSE or DEFAULT with its \
                                     RETURN, or a RETURN before ENDFUNC)" name in
          match last with
          | Some at ->
              Report.warning report ~hint ~rule:"function-no-return" ~section:"5.5" at
                (Printf.sprintf "the function %s can end without RETURN: after this statement its ENDFUNC is \
                                 reached, and the call raises ERR_FNCNORET (a function's evaluation must end with a \
                                 RETURN statement)" name)
          | None ->
              Report.warning report ~hint ~rule:"function-no-return" ~section:"5.5" at
                (Printf.sprintf "the function %s has no statement: it ends without RETURN, and every call raises \
                                 ERR_FNCNORET" name))
        (Fall_off.functions i.m)) user;
  (* --allow-unknown: one warning per unknown name, at its first use, with the number of uses. *)
  let unknown = Hashtbl.fold (fun _ u acc -> u :: acc) ctx.unknown_uses [] in
  List.iter (fun ((u : unknown_name), section, hint) ->
      Report.warning report ?hint ~rule:"unknown-name" ~section u.first
        (Printf.sprintf "unknown %s %s (neither declared nor installed; allowed by --allow-unknown): %s"
           u.what u.name (if u.uses = 1 then "1 use" else Printf.sprintf "%d uses, the first here" u.uses)))
    unknown;
  let unknown = List.sort (fun (a : unknown_name) b ->
      compare (String.lowercase_ascii a.name, a.what) (String.lowercase_ascii b.name, b.what))
      (List.map (fun (u, _, _) -> u) unknown) in
  { reports = Report.all report; elaboration = ctx.elab; unknown }

let unknown_summary r =
  match r.unknown with
  | [] -> None
  | names ->
      let uses = List.fold_left (fun n u -> n + u.uses) 0 names in
      Some (Printf.sprintf "%d name%s unknown (%d use%s); they are warnings under --allow-unknown"
              (List.length names) (if List.length names = 1 then "" else "s")
              uses (if uses = 1 then "" else "s"))

type installed_state = module_declaration list * options * ctx * module_info list

let installed_state installed =
  let ctx, infos = check_installed default_options installed in
  if Report.all ctx.report = [] then Ok (installed, default_options, ctx, infos) else Error (Report.all ctx.report)

let installed_state_of (_, options, ctx, infos) level =
  (* the second half reads of an installed module its name, attributes and region only *)
  (level, options, ctx, List.map2 (fun i m -> { i with m }) infos level)

let use_installed_state state = installed_cache := Some state
