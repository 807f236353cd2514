(* Which forms a parsed module holds. The benchmark refuses a generated module that lacks one
   of them: a generator that drifted to aggregates only would otherwise time a fraction of the
   grammar and still look fast. *)

open Rapid_syntax.Ast

let forms = [
  "assignment (§4.5)"; "procedure call (§4.6)"; "late-bound call (§4.6)"; "goto (§4.7)";
  "break (§4.8)"; "continue (§4.9)"; "return (§4.10)"; "raise (§4.11)"; "exit (§4.12)";
  "retry (§4.13)"; "trynext (§4.14)"; "connect (§4.15)"; "if (§4.16)"; "elseif (§4.16)";
  "else (§4.16)"; "compact if (§4.17)"; "for with step (§4.18)"; "while (§4.19)";
  "test (§4.20)"; "default (§4.20)"; "label (§4.4)"; "comment (§2.10)";
  "backward clause (§5.4)"; "error clause (§5.4)"; "error number list (§7.2)";
  "undo clause (§5.4)"; "function (§5.5)"; "trap (§5.6)"; "record (§2.14)"; "alias (§2.15)";
  "string literal (§2.7)"; "optional argument (§4.6)"; "conditional argument (§4.6)";
  "routine data declaration (§5.4)"; "%%% header (doc/dialect.md)";
]

let count (m : module_declaration) =
  let table = Hashtbl.create 64 in
  let count form = Option.value ~default:0 (Hashtbl.find_opt table form) in
  let see form = Hashtbl.replace table form (1 + count form) in
  let rec expression (e : expression) =
    match e.it with
    | String_literal _ -> see "string literal (§2.7)"
    | Num_literal _ | Bool_literal _ | EXP_placeholder | Data_reference _ -> ()
    | Function_call f -> arguments (call_arguments f)
    | Aggregate (es, rs) -> Array.iter expression (members es rs)
    | Unary (_, e, at) -> expression (operand e at)
    | Binary (_, l, r) -> expression l; expression r
  and arguments args =
    Array.iter (fun (a : argument) ->
        match a.it with
        | Required_argument (_, e, at) -> expression (operand e at)
        | Positional_argument e -> expression (operand e a.at)
        | Optional_argument (_, e) -> see "optional argument (§4.6)"; Option.iter expression e
        | Conditional_argument _ -> see "conditional argument (§4.6)"
        | ARG_placeholder -> ()) args
  in
  let rec statement (s : statement) =
    match s.it with
    | Assignment (_, e) -> see "assignment (§4.5)"; expression e
    | Procedure_call (Procedure_name _, args, rs) ->
        see "procedure call (§4.6)"; arguments (Rapid_syntax.Ast.arguments args rs)
    | Procedure_call (Late_bound e, args, rs) ->
        see "late-bound call (§4.6)"; expression e; arguments (Rapid_syntax.Ast.arguments args rs)
    | Goto _ -> see "goto (§4.7)"
    | Break -> see "break (§4.8)"
    | Continue -> see "continue (§4.9)"
    | Return e -> see "return (§4.10)"; Option.iter expression e
    | Raise e -> see "raise (§4.11)"; Option.iter expression e
    | Exit -> see "exit (§4.12)"
    | Retry -> see "retry (§4.13)"
    | Trynext -> see "trynext (§4.14)"
    | Connect _ -> see "connect (§4.15)"
    | If i ->
        see "if (§4.16)";
        expression i.condition;
        statements i.then_branch;
        List.iter (fun (c : elseif_clause) ->
            match c.it with
            | Elseif (e, l) -> see "elseif (§4.16)"; expression e; statements l
            | EIT_placeholder -> ()) i.elseifs;
        Option.iter (fun l -> see "else (§4.16)"; statements l) i.else_branch
    | Compact_if (e, s) -> see "compact if (§4.17)"; expression e; statement s
    | For f ->
        if f.step <> None then see "for with step (§4.18)";
        statements f.body
    | While (e, l) -> see "while (§4.19)"; expression e; statements l
    | Test t ->
        see "test (§4.20)";
        List.iter (fun (c : case_clause) ->
            match c.it with Case (_, l) -> statements l | CSE_placeholder -> ()) t.cases;
        Option.iter (fun l -> see "default (§4.20)"; statements l) t.default
    | Label _ -> see "label (§4.4)"
    | Statement_comment _ -> see "comment (§2.10)"
    | SMT_placeholder -> ()
  and statements l = List.iter statement l in
  let body (b : routine_body) =
    if b.declarations <> [] then see "routine data declaration (§5.4)";
    statements b.statements;
    Option.iter (fun l -> see "backward clause (§5.4)"; statements l) b.backward;
    Option.iter (fun h ->
        see "error clause (§5.4)";
        if h.error_numbers <> None then see "error number list (§7.2)";
        statements h.handler) b.error;
    Option.iter (fun l -> see "undo clause (§5.4)"; statements l) b.undo
  in
  List.iter (fun (t : type_definition) ->
      match t.it with
      | Record_definition _ -> see "record (§2.14)"
      | Alias_definition _ -> see "alias (§2.15)"
      | Type_comment _ | TDN_placeholder -> ()) m.type_definitions;
  List.iter (fun (r : routine_declaration) ->
      match r.it with
      | Procedure_declaration { body = b; _ } -> body b
      | Function_declaration { body = b; _ } -> see "function (§5.5)"; body b
      | Trap_declaration { body = b; _ } -> see "trap (§5.6)"; body b
      | Routine_comment _ | RDN_placeholder -> ()) m.routine_declarations;
  if m.header <> None then see "%%% header (doc/dialect.md)";
  List.map (fun form -> (form, count form)) forms
