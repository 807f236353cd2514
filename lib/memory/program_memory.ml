(* The coefficients of doc/memory.md. Each figure of chapter 16 that fixes one is named. *)

open Rapid_syntax
open Ast

type item = { label : string; bytes : int; parts : item list }

(* A string of 0-80 characters takes the same space: the figures hold for every length. *)
let string_value = 84                   (* VAR string string1; 236 = 152 + 84 *)
let empty_module = 1732                 (* MODULE module1 ENDMODULE *)
let empty_routine = 224                 (* PROC proc1() ENDPROC *)
let declaration = 152                   (* VAR num reg1; 156 = 152 + a num's 4 *)
let leaf = 8                            (* a literal or a data reference *)
let string_leaf = 16                    (* string1:= "..."; 52 = 28 + 8 + 16 *)
let assignment = 28                     (* reg1:=1; 44 = 28 + 8 + 8 *)
let call = 36                           (* WaitTime 1; 88 = 36 + 44 + 8 *)
let argument = 44                       (* SetDO do1,1; 140 = 36 + 2 * (44 + 8) *)
let operator = 36                       (* WaitUntil di1=1 AND di2=1; 220 = 36 + 44 + 3 * 36 + 4 * 8 *)
let compact_if = 36                     (* IF reg1=1 proc1; 124 = 36 + (36 + 8 + 8) + 36 *)
let if_ = 60                            (* IF reg1=1 THEN proc1; ELSE proc2; ENDIF 184 = 60 + 52 + 2 * 36 *)
let tpwrite_extra = 80                  (* TPWrite "..."; 176 = 36 + 44 + 16 + 80 *)
let comment = 36                        (* !0-7 characters: 36, and 4 for every 4 more *)


(* An initial value is kept besides the current value: VAR string string1 := "..."; 344 =
   236 + 84 + 24, CONST string 332 = 236 + 84 + 12, CONST robtarget 292 = 152 + 68 + 68 + 4. *)
let initial_overhead ~storage ~type_name =
  match String.lowercase_ascii type_name, storage with
  | "string", Const -> 12
  | "string", (Var | Pers) -> 24
  | _ -> 4

let comment_bytes text =
  let n = String.length text in
  if n <= 7 then comment else comment + 4 * ((n - 7 + 3) / 4)

let rec expression_bytes (e : expression_desc) =
  match e with
  | Num_literal _ | Bool_literal _ | Data_reference _ -> leaf
  | String_literal _ -> string_leaf
  | EXP_placeholder -> leaf
  | Unary (_, operand, _) -> operator + expression_bytes operand
  | Binary (_, a, b) -> operator + expression_bytes a.it + expression_bytes b.it
  | Aggregate _ -> leaf + aggregate_value e
  | Function_call f -> call + arguments_bytes f.arguments

(* An aggregate is a value written in place: it takes the value's bytes (4 a num or bool, 84 a
   string), plus what its members that are not literals compute. MoveL with a robtarget
   aggregate (the FlexPendant's "*"), 312 = 244 - 8 + 8 + 17 * 4. *)
and aggregate_value (e : expression_desc) =
  match e with
  | Num_literal _ | Bool_literal _ -> 4
  | String_literal _ -> string_value
  | Aggregate (members, _) -> Array.fold_left (fun n m -> n + aggregate_value m) 0 members
  | other -> expression_bytes other

and argument_bytes (a : argument_desc) =
  match a with
  | Required_argument (_, e, _) | Positional_argument e -> argument + expression_bytes e
  | Optional_argument (_, Some e) -> argument + expression_bytes e.it
  | Optional_argument (_, None) | Conditional_argument _ -> argument
  | ARG_placeholder -> argument + leaf

and arguments_bytes args = Array.fold_left (fun n a -> n + argument_bytes a) 0 args

let is_tpwrite = function
  | Procedure_name { it = Ident name; _ } -> String.lowercase_ascii name = "tpwrite"
  | _ -> false

let rec statement_bytes (s : statement) =
  match s.it with
  | Assignment (_, e) -> assignment + leaf + expression_bytes e.it
  | Procedure_call (p, args, _) ->
      let callee = match p with Late_bound e -> expression_bytes e.it | Procedure_name _ -> 0 in
      call + callee + arguments_bytes args + if is_tpwrite p then tpwrite_extra else 0
  | Compact_if (c, inner) -> compact_if + expression_bytes c.it + statement_bytes inner
  | If i ->
      if_ + expression_bytes i.condition.it + list_bytes i.then_branch
      + List.fold_left (fun n (c : elseif_clause) -> n + match c.it with
          | Elseif (e, body) -> if_ + expression_bytes e.it + list_bytes body
          | EIT_placeholder -> if_) 0 i.elseifs
      + (match i.else_branch with Some b -> list_bytes b | None -> 0)
  | For f ->
      if_ + leaf + expression_bytes f.from_.it + expression_bytes f.to_.it
      + (match f.step with Some e -> expression_bytes e.it | None -> 0) + list_bytes f.body
  | While (c, body) -> if_ + expression_bytes c.it + list_bytes body
  | Test t ->
      if_ + expression_bytes t.test_expression.it
      + List.fold_left (fun n (c : case_clause) -> n + match c.it with
          | Case (values, body) ->
              if_ + List.fold_left (fun n (v : expression) -> n + expression_bytes v.it) 0 values + list_bytes body
          | CSE_placeholder -> if_) 0 t.cases
      + (match t.default with Some b -> list_bytes b | None -> 0)
  | Return (Some e) | Raise (Some e) -> call + expression_bytes e.it
  | Connect _ -> call + 2 * leaf
  | Statement_comment text -> comment_bytes text
  | Return None | Raise None | Goto _ | Break | Continue | Exit | Retry | Trynext | Label _
  | SMT_placeholder -> call

and list_bytes l = List.fold_left (fun n s -> n + statement_bytes s) 0 l

(* ------------------------------------------------------------------ values *)

let same a b = String.lowercase_ascii a = String.lowercase_ascii b

let ident_name (i : identifier) = match i.it with Ident n -> n | ID_placeholder -> ""

let find_type ~records name =
  List.find_map (fun (m : module_declaration) ->
      List.find_map (fun (t : type_definition) ->
          match t.it with
          | Record_definition { name = n; components; _ } when same (ident_name n) name -> Some (`Record components)
          | Alias_definition { base; name = n; _ } when same (ident_name n) name -> Some (`Alias (ident_name base))
          | _ -> None) m.type_definitions) records

let rec value_bytes_in ~records ~seen name =
  match String.lowercase_ascii name with
  | "num" | "bool" -> 4
  | "dnum" -> 8
  | "string" -> string_value
  (* The built-in records of §2.14. *)
  | "pos" -> 12
  | "orient" -> 16
  | "pose" -> 28
  | lower when List.mem lower seen -> 4
  | lower -> (
      match find_type ~records name with
      | Some (`Record components) ->
          List.fold_left (fun n (c : record_component) -> n + match c.it with
              | Record_component (t, _) -> value_bytes_in ~records ~seen:(lower :: seen) (ident_name t)
              | Component_comment _ -> 0) 0 components
      | Some (`Alias base) -> value_bytes_in ~records ~seen:(lower :: seen) base
      | None -> 4)

let value_bytes ~records name = value_bytes_in ~records ~seen:[] name

let storage_word = function Var -> "VAR" | Pers -> "PERS" | Const -> "CONST"

let elements (dims : expression list) =
  List.fold_left (fun n (d : expression) ->
      match d.it with
      | Num_literal s -> (match int_of_string_opt s with Some k when k > 0 -> n * k | _ -> n)
      | _ -> n) 1 dims

let data_item ~records (d : data_declaration) =
  match d.it with
  | Data_declaration { storage; data_type; name; dims; initial_value; _ } ->
      let type_name = ident_name data_type in
      let value = value_bytes ~records type_name * elements dims in
      let init = match initial_value with
        | Some _ -> value + initial_overhead ~storage ~type_name
        | None -> 0 in
      Some { label = Printf.sprintf "%s %s %s" (storage_word storage) type_name (ident_name name);
             bytes = declaration + value + init; parts = [] }
  | Declaration_comment text -> Some { label = "comment"; bytes = comment_bytes text; parts = [] }
  | DDN_placeholder -> None

let statement_label (s : statement) =
  let p = Source.start s.at in
  Printf.sprintf "line %d" p.line

let routine_item ~records (r : routine_declaration) =
  let item kind name parameters (body : routine_body) =
    let data = List.filter_map (data_item ~records) body.declarations in
    let statements l = List.map (fun s -> { label = statement_label s; bytes = statement_bytes s; parts = [] }) l in
    let section name = function
      | Some l -> [ { label = name; bytes = list_bytes l; parts = statements l } ]
      | None -> [] in
    let parts =
      data @ statements body.statements @ section "BACKWARD" body.backward
      @ (match body.error with Some h -> section "ERROR" (Some h.handler) | None -> [])
      @ section "UNDO" body.undo in
    let params = List.length parameters * argument in
    { label = kind ^ " " ^ ident_name name;
      bytes = empty_routine + params + List.fold_left (fun n p -> n + p.bytes) 0 parts; parts }
  in
  match r.it with
  | Procedure_declaration { name; parameters; body; _ } -> Some (item "PROC" name parameters body)
  | Function_declaration { name; parameters; body; _ } -> Some (item "FUNC" name parameters body)
  | Trap_declaration { name; body; _ } -> Some (item "TRAP" name [] body)
  | Routine_comment text -> Some { label = "comment"; bytes = comment_bytes text; parts = [] }
  | RDN_placeholder -> None

(* Chapter 16 gives no figure for a type definition: the model counts it as a declaration
   without a value (doc/memory.md). *)
let type_item (t : type_definition) =
  match t.it with
  | Record_definition { name; _ } -> Some { label = "RECORD " ^ ident_name name; bytes = declaration; parts = [] }
  | Alias_definition { name; _ } -> Some { label = "ALIAS " ^ ident_name name; bytes = declaration; parts = [] }
  | Type_comment text -> Some { label = "comment"; bytes = comment_bytes text; parts = [] }
  | TDN_placeholder -> None

let module_memory ~records (m : module_declaration) =
  let records = m :: records in
  let parts =
    List.filter_map type_item m.type_definitions
    @ List.filter_map (data_item ~records) m.data_declarations
    @ List.filter_map (routine_item ~records) m.routine_declarations in
  { label = "MODULE " ^ ident_name m.module_name;
    bytes = empty_module + List.fold_left (fun n p -> n + p.bytes) 0 parts; parts }
