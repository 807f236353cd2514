open Rapid_syntax
module T = Rapid_typing.Types

type datum = {
  value : Value.t option;
  typ : T.object_type option;
  write : (Value.t -> bool) option;
}

type env = string -> (datum, string) result

let ( let* ) = Result.bind

(* The text becomes a statement of a routine of a module of its own, so that chapter 10's
   grammar reads it exactly as in a program. *)
let statement_of text =
  let source = Printf.sprintf "MODULE debugger\nPROC debugger()\n%s;\nENDPROC\nENDMODULE\n" text in
  match Parse.parse_string ~name:"<debugger>" source with
  | Error d -> Error (Printf.sprintf "%s: %s" (Diagnostic.class_name d.error_class) d.message)
  | Ok m -> (
      match m.routine_declarations with
      | [ { it = Procedure_declaration { body; _ }; _ } ] -> (
          match body.statements with
          | [ { it = Assignment (target, e); _ } ] -> Ok (target, e)
          | _ -> Error "not a RAPID expression")
      | _ -> Error "not a RAPID expression")

let has_newline text = String.contains text '\n' || String.contains text '\r' || String.contains text ';'

let parse_expression text =
  if has_newline text then Error "an expression stands on one line, without ';'"
  else Result.map snd (statement_of ("debugger := " ^ text))

(* A target that is no data reference would be reported as a statement of the wrapping
   routine (a call, a declaration): the command's form says more. *)
let parse_assignment text =
  if has_newline text then Error "an assignment stands on one line, without ';'"
  else
    match statement_of text with
    | Ok a -> Ok a
    | Error m ->
        let target = match String.index_opt text ':' with Some i -> String.trim (String.sub text 0 i) | None -> "" in
        if target <> "" && Result.is_error (statement_of (target ^ " := 0")) then
          Error (Printf.sprintf "set REF := EXPR: %s is not a data object, an element or a component (§4.5)" target)
        else Error m

(* A value with the type it is known to have, for its components. *)
type typed = { v : Value.t; t : T.object_type option }

let element_type (t : T.object_type option) = Option.map (fun (t : T.object_type) -> T.scalar t.base) t

let to_index v =
  match v with
  (* Beyond any array's bounds before int_of_float could wrap it round into one. *)
  | Value.Num f | Value.Dnum f when Float.is_integer f && Float.abs f > 1e15 ->
      Error (Printf.sprintf "ERR_OUTOFBND: index %.9g is outside the array (§3.6)" f)
  | Value.Num f | Value.Dnum f when Float.is_integer f -> Ok (int_of_float f)
  | Value.Num _ | Value.Dnum _ -> Error "ERR_NOTINTVAL: an index is an integer (§3.6)"
  | _ -> Error "an index is a num (§3.6)"

let index_into (x : typed) i =
  match x.v with
  | Value.Array es when i >= 1 && i <= Array.length es -> Ok { v = es.(i - 1); t = x.t }
  | Value.Array _ -> Error (Printf.sprintf "ERR_OUTOFBND: index %d is outside the array (§3.6)" i)
  | _ -> Error "only an array has elements (§3.6)"

let component (x : typed) name =
  match x.v, x.t with
  | Value.Record cs, Some { base = T.Record rt; dims = T.Scalar } -> (
      let rec find k = function
        | [] -> Error (Printf.sprintf "the record type %s has no component %s (§3.6)" rt.record_name name)
        | (n, ty) :: rest ->
            if String.lowercase_ascii n = String.lowercase_ascii name && k < Array.length cs then
              Ok (k, { v = cs.(k); t = Some (T.scalar ty) })
            else find (k + 1) rest in
      find 0 rt.components)
  | Value.Record _, _ -> Error (Printf.sprintf "the type of this record is not known: no component %s" name)
  | _ -> Error (Printf.sprintf "only a record has components (%s, §3.6)" name)

(* §3.12 by the operands' values. *)
let binary_row (op : Ast.binary_operator) a b : (Arith.binary * Value.t * Value.t, string) result =
  let dnum = function Value.Num f -> Value.Dnum f | v -> v in
  let a, b = match a, b with
    | Value.Num _, Value.Dnum _ -> (dnum a, b) | Value.Dnum _, Value.Num _ -> (a, dnum b) | _ -> (a, b) in
  let pos = function Value.Record cs -> Array.length cs = 3 | _ -> false in
  let orient = function Value.Record cs -> Array.length cs = 4 | _ -> false in
  let row (r : Arith.binary) = Ok (r, a, b) in
  let none () = Error "no operator of §3.12 takes operands of these types" in
  match op, a, b with
  | Plus, Value.Num _, Num _ -> row Num_add | Plus, Dnum _, Dnum _ -> row Dnum_add
  | Plus, String _, String _ -> row String_concat | Plus, _, _ when pos a && pos b -> row Pos_add
  | Minus, Num _, Num _ -> row Num_sub | Minus, Dnum _, Dnum _ -> row Dnum_sub
  | Minus, _, _ when pos a && pos b -> row Pos_sub
  | Mul, Num _, Num _ -> row Num_mul | Mul, Dnum _, Dnum _ -> row Dnum_mul
  | Mul, Num _, _ when pos b -> row Num_pos_mul | Mul, _, Num _ when pos a -> row Pos_num_mul
  | Mul, _, _ when pos a && pos b -> row Pos_cross | Mul, _, _ when orient a && orient b -> row Orient_mul
  | Div, Num _, Num _ -> row Num_div | Div, Dnum _, Dnum _ -> row Dnum_div
  | Div, _, Num _ when pos a -> row Pos_num_div
  | Int_div, Num _, Num _ -> row Num_intdiv | Int_div, Dnum _, Dnum _ -> row Dnum_intdiv
  | Modulo, Num _, Num _ -> row Num_mod | Modulo, Dnum _, Dnum _ -> row Dnum_mod
  | Less, Num _, Num _ -> row Num_lt | Less_equal, Num _, Num _ -> row Num_le
  | Greater, Num _, Num _ -> row Num_gt | Greater_equal, Num _, Num _ -> row Num_ge
  | Less, Dnum _, Dnum _ -> row Dnum_lt | Less_equal, Dnum _, Dnum _ -> row Dnum_le
  | Greater, Dnum _, Dnum _ -> row Dnum_gt | Greater_equal, Dnum _, Dnum _ -> row Dnum_ge
  | Equal, _, _ -> row Equal | Not_equal, _, _ -> row Not_equal
  | Xor, Bool _, Bool _ -> row Xor
  | _ -> none ()

let arith r = Result.map_error (fun name -> name ^ " (§3.12)") r

let rec eval_typed (env : env) (e : Ast.expression) : (typed, string) result =
  match e.it with
  | Num_literal text -> (
      match Num_literal.of_text text with
      | Ok l ->
          (* Beyond num's range a literal can still be a dnum (§2.5, R-2.5-c). *)
          let v = Value.of_literal l `Num in
          if Float.is_finite (Value.num_value v) then Ok { v; t = None }
          else
            let d = Value.of_literal l `Dnum in
            if Float.is_finite (Value.num_value d) then Ok { v = d; t = None }
            else Error "the number is beyond the range of num and dnum (§2.13)"
      | Error _ -> Error "a numeric literal out of range (§2.5)")
  | String_literal s -> Ok { v = Value.String s.bytes; t = None }
  | Bool_literal b -> Ok { v = Value.Bool b; t = None }
  | Data_reference d -> reference env { Ast.it = d; at = e.at }
  | Function_call _ -> Error "function calls are not evaluated by the debugger: they could change the task's data"
  | Aggregate (descs, regions) ->
      let members = Ast.members descs regions in
      let* vs = all env (Array.to_list members) in
      Ok { v = Value.Array (Array.of_list vs); t = None }
  | Unary (op, d, at) -> (
      let* x = eval_typed env (Ast.operand d at) in
      let pos = match x.v with Value.Record cs -> Array.length cs = 3 | _ -> false in
      let row : (Arith.unary, string) result = match op, x.v with
        | Unary_minus, Num _ -> Ok Num_neg | Unary_minus, Dnum _ -> Ok Dnum_neg
        | Unary_minus, _ when pos -> Ok Pos_neg
        | Unary_plus, Num _ -> Ok Num_plus | Unary_plus, Dnum _ -> Ok Dnum_plus
        | Unary_plus, _ when pos -> Ok Pos_plus
        | Not, Bool _ -> Ok Not
        | _ -> Error "no operator of §3.12 takes an operand of this type" in
      let* r = row in
      (* A record of three members is read as a pos: tooldata (robhold, tframe, tload) too. *)
      let* v = (try arith (Arith.unary r x.v) with Value.Type_mismatch _ ->
          Error "no operator of §3.12 takes an operand of this type") in
      Ok { v; t = None })
  | Binary ((And | Or) as op, l, r) -> (
      (* §3.1: the right operand only when the left one does not decide. *)
      let* a = eval_typed env l in
      match op, a.v with
      | And, Bool false -> Ok { v = Bool false; t = None }
      | Or, Bool true -> Ok { v = Bool true; t = None }
      | _, Bool _ -> (
          let* b = eval_typed env r in
          match b.v with Bool _ -> Ok { v = b.v; t = None } | _ -> Error "AND and OR take bool operands (§3.12)")
      | _ -> Error "AND and OR take bool operands (§3.12)")
  | Binary (op, l, r) ->
      let* a = eval_typed env l in
      let* b = eval_typed env r in
      let* row, a, b = binary_row op a.v b.v in
      let* v = (try arith (Arith.binary row a b) with Value.Type_mismatch _ ->
          Error "no operator of §3.12 takes operands of these types") in
      Ok { v; t = None }
  | EXP_placeholder -> Error "ERR_EXECPHR: a placeholder has no value (§2.9)"

and all env = function
  | [] -> Ok []
  | e :: rest -> let* x = eval_typed env e in let* xs = all env rest in Ok (x.v :: xs)

and reference env (d : Ast.data_reference) : (typed, string) result =
  match d.it with
  | Entire name -> (
      let* datum = env name in
      match datum.value with
      | None -> Error (Printf.sprintf "%s is an absent optional parameter (ERR_NOTPRES, §5.2)" name)
      | Some v -> Ok { v; t = datum.typ })
  | Element (name, indexes) ->
      let* x = reference env { Ast.it = Entire name.it; at = name.at } in
      let x = { x with t = element_type x.t } in
      List.fold_left (fun acc ix ->
          let* x = acc in
          let* i = eval_typed env ix in
          let* i = to_index i.v in
          index_into x i) (Ok x) indexes
  | Component (base, name) ->
      let* x = reference env base in
      let* _, c = component x name.it in
      Ok c
  | VAR_placeholder -> Error "ERR_EXECPHR: a placeholder has no value (§2.9)"

(* The operators' rows are taken from the values (doc/debugger.md), not from checked types: a
   value that is not of its row's type is the user's expression, refused, never a crash. *)
let mismatch f = try f () with Value.Type_mismatch _ -> Error "no operator of §3.12 takes operands of these types"

let eval env e = mismatch (fun () -> Result.map (fun x -> x.v) (eval_typed env e))

(* The new value in the form of the one it replaces: an aggregate becomes a record where a record
   was (§3.10), a num becomes a dnum where a dnum was (§2.5, R-2.5-b). *)
let rec fit (old : Value.t) (v : Value.t) : (Value.t, string) result =
  match old, v with
  | Num _, Num _ | Dnum _, Dnum _ | Bool _, Bool _ | String _, String _ -> Ok v
  | Dnum _, Num f -> Ok (Value.Dnum f)
  | Num _, Dnum _ -> Error "the value is a dnum, or beyond the range of num (§2.13)"
  | (Record os | Array os), (Array vs | Record vs) when Array.length os = Array.length vs ->
      let out = Array.make (Array.length vs) v in
      let rec go i =
        if i >= Array.length vs then Ok (match old with Record _ -> Value.Record out | _ -> Value.Array out)
        else match fit os.(i) vs.(i) with Ok x -> out.(i) <- x; go (i + 1) | Error m -> Error m in
      go 0
  | (Record _ | Array _), (Array _ | Record _) -> Error "the aggregate has another number of members (§3.10)"
  | _ -> Error "the value is not of the type of the data it would replace (§4.5)"

let rec assign env target e = mismatch (fun () -> assign_checked env target e)

and assign_checked env (target : Ast.data_reference) (e : Ast.expression) =
  let* v = eval env e in
  (* The reference as its root name and the steps down to the place. *)
  let rec path (d : Ast.data_reference) =
    match d.it with
    | Entire name -> Ok (name, [])
    | Element (name, ixs) -> Ok (name.it, [ `Index ixs ])
    | Component (base, c) -> let* root, steps = path base in Ok (root, steps @ [ `Component c.it ])
    | VAR_placeholder -> Error "ERR_EXECPHR: a placeholder is no place (§2.9)" in
  let* root, steps = path target in
  let* datum = env root in
  let* write = match datum.write with
    | Some w -> Ok w
    | None -> Error (root ^ " is read-only: a constant, a loop variable or a system variable (§4.5)") in
  let* whole = match datum.value with
    | Some w -> Ok w
    | None -> Error (root ^ " is an absent optional parameter (ERR_NOTPRES, §5.2)") in
  match steps with
  | [] -> let* v = fit whole v in if write v then Ok v else Error (root ^ " cannot be written")
  | _ ->
      (* Down to the container of the last step, then the value is put in it in place. *)
      let step (x : typed) s : (typed * (Value.t array * int), string) result =
        match s with
        | `Component c -> (
            let* k, y = component x c in
            match x.v with Value.Record cs -> Ok (y, (cs, k)) | _ -> Error "only a record has components (§3.6)")
        | `Index ixs ->
            let x = { x with t = element_type x.t } in
            let rec go (x : typed) slot = function
              | [] -> (match slot with Some s -> Ok (x, s) | None -> Error "an index list is empty")
              | ix :: rest ->
                  let* i = eval env ix in
                  let* i = to_index i in
                  let* y = index_into x i in
                  (match x.v with
                   | Value.Array es -> go y (Some (es, i - 1)) rest | _ -> Error "only an array has elements (§3.6)") in
            go x None ixs in
      let rec walk (x : typed) slot = function
        | [] -> Ok slot
        | s :: rest -> let* y, sl = step x s in walk y (Some sl) rest in
      let* slot = walk { v = whole; t = datum.typ } None steps in
      match slot with
      | None -> Error "no place"
      | Some (container, k) ->
          let* v = fit container.(k) v in
          container.(k) <- v; Ok v
