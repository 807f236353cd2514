(* The tree with what Ast_dump leaves out taken out, so that OCaml's structural equality on the
   results is the dump's equality without writing two dumps (the fuzzer's round trip compares a
   tree with its printed and parsed again copy for every program).

   What the dump leaves out: every region (set to [no_region] here), a string literal's bytes
   (derived from its raw text, which stays), and the difference between a positional argument
   and a required one without a name (both are dumped as [Required_argument]; both become the
   latter here). Anything this function forgot to erase would make equal trees differ, never
   different trees equal: a mistake here shows as a round-trip failure, not as a missed one.

   Lists are rebuilt with tail-recursive maps: a generated module may hold millions of
   elements. The recursion otherwise follows the nesting of the tree, as Ast_dump's does. *)

open Ast

let no_region = Source.no_region

let map f l = List.rev (List.rev_map f l)

let identifier (i : identifier) : identifier = { it = i.it; at = no_region }
let name (n : name) : name = { it = n.it; at = no_region }

let rec expression (e : expression) : expression = { it = expression_desc e.it; at = no_region }

and expression_desc (d : expression_desc) : expression_desc =
  match d with
  | Num_literal _ | Bool_literal _ | EXP_placeholder -> d
  | String_literal s -> String_literal { raw = s.raw; bytes = "" }
  | Data_reference r -> Data_reference (reference r)
  | Function_call f ->
      Function_call { func = identifier f.func; arguments = Array.map argument_desc f.arguments;
                      argument_regions = Array.map (fun _ -> no_region) f.argument_regions }
  | Aggregate (es, rs) -> Aggregate (Array.map expression_desc es, Array.map (fun _ -> no_region) rs)
  | Unary (op, e, _) -> Unary (op, expression_desc e, no_region)
  | Binary (op, l, r) -> Binary (op, expression l, expression r)

and data_reference (r : data_reference) : data_reference = { it = reference r.it; at = no_region }

and reference (r : data_reference_desc) : data_reference_desc =
  match r with
  | Entire _ | VAR_placeholder -> r
  | Element (n, es) -> Element (name n, map expression es)
  | Component (r, n) -> Component (data_reference r, name n)

and argument_desc (a : argument_desc) : argument_desc =
  match a with
  | Positional_argument e -> Required_argument (None, expression_desc e, no_region)
  | Required_argument (n, e, _) -> Required_argument (Option.map identifier n, expression_desc e, no_region)
  | Optional_argument (n, e) -> Optional_argument (identifier n, Option.map expression e)
  | Conditional_argument (n, r) -> Conditional_argument (identifier n, data_reference r)
  | ARG_placeholder -> ARG_placeholder

let regions rs = Array.map (fun _ -> no_region) rs

let rec statement (s : statement) : statement = { it = statement_desc s.it; at = no_region }

and statements l = map statement l

and statement_desc (s : statement_desc) : statement_desc =
  match s with
  | Assignment (r, e) -> Assignment (data_reference r, expression e)
  | Procedure_call (p, args, rs) ->
      let p = match p with
        | Procedure_name i -> Procedure_name (identifier i)
        | Late_bound e -> Late_bound (expression e) in
      Procedure_call (p, Array.map argument_desc args, regions rs)
  | Goto i -> Goto (identifier i)
  | Break | Continue | Exit | Retry | Trynext | Statement_comment _ | SMT_placeholder -> s
  | Return e -> Return (Option.map expression e)
  | Raise e -> Raise (Option.map expression e)
  | Connect (r, i) -> Connect (data_reference r, identifier i)
  | If i ->
      If { condition = expression i.condition; then_branch = statements i.then_branch;
           elseifs = map (fun (c : elseif_clause) ->
               { it = (match c.it with
                     | Elseif (e, l) -> Elseif (expression e, statements l)
                     | EIT_placeholder -> EIT_placeholder); at = no_region }) i.elseifs;
           else_branch = Option.map statements i.else_branch }
  | Compact_if (e, s) -> Compact_if (expression e, statement s)
  | For f ->
      For { loop_variable = identifier f.loop_variable; from_ = expression f.from_; to_ = expression f.to_;
            step = Option.map expression f.step; body = statements f.body }
  | While (e, l) -> While (expression e, statements l)
  | Test t ->
      Test { test_expression = expression t.test_expression;
             cases = map (fun (c : case_clause) ->
                 { it = (match c.it with
                       | Case (values, l) -> Case (map expression values, statements l)
                       | CSE_placeholder -> CSE_placeholder); at = no_region }) t.cases;
             default = Option.map statements t.default }
  | Label i -> Label (identifier i)

let data_declaration (d : data_declaration) : data_declaration =
  { it = (match d.it with
        | Data_declaration d ->
            Data_declaration { d with data_type = identifier d.data_type; name = identifier d.name;
                                      dims = map expression d.dims;
                                      initial_value = Option.map expression d.initial_value }
        | (Declaration_comment _ | DDN_placeholder) as d -> d);
    at = no_region }

let record_component (c : record_component) : record_component =
  { it = (match c.it with
        | Record_component (t, n) -> Record_component (identifier t, identifier n)
        | Component_comment _ as c -> c);
    at = no_region }

let type_definition (t : type_definition) : type_definition =
  { it = (match t.it with
        | Record_definition r ->
            Record_definition { r with name = identifier r.name; components = map record_component r.components }
        | Alias_definition a -> Alias_definition { a with base = identifier a.base; name = identifier a.name }
        | (Type_comment _ | TDN_placeholder) as t -> t);
    at = no_region }

let parameter_declaration (p : parameter_declaration) : parameter_declaration =
  { it = (match p.it with
        | Parameter p -> Parameter { p with data_type = identifier p.data_type; name = identifier p.name }
        | Switch n -> Switch (identifier n));
    at = no_region }

let parameter (p : parameter) : parameter =
  { it = (match p.it with
        | Required_parameter d -> Required_parameter (parameter_declaration d)
        | Optional_parameter alts ->
            Optional_parameter (map (fun (a : alternative) ->
                { it = (match a.it with
                      | Alternative d -> Alternative (parameter_declaration d)
                      | ALT_placeholder -> ALT_placeholder); at = no_region }) alts)
        | PAR_placeholder -> PAR_placeholder);
    at = no_region }

let routine_body (b : routine_body) : routine_body =
  { declarations = map data_declaration b.declarations;
    statements = statements b.statements;
    backward = Option.map statements b.backward;
    error = Option.map (fun (h : error_handler) ->
        { error_numbers = Option.map (map (fun (n : recovery_error_number) ->
              { it = (match n.it with
                    | Error_number_literal _ as l -> l
                    | Error_number_name n -> Error_number_name (name n)); at = no_region })) h.error_numbers;
          handler = statements h.handler }) b.error;
    undo = Option.map statements b.undo }

let routine_declaration (r : routine_declaration) : routine_declaration =
  { it = (match r.it with
        | Procedure_declaration p ->
            Procedure_declaration { p with name = identifier p.name; parameters = map parameter p.parameters;
                                           body = routine_body p.body }
        | Function_declaration f ->
            Function_declaration { f with return_type = identifier f.return_type; name = identifier f.name;
                                          parameters = map parameter f.parameters; body = routine_body f.body }
        | Trap_declaration t -> Trap_declaration { t with name = identifier t.name; body = routine_body t.body }
        | (Routine_comment _ | RDN_placeholder) as r -> r);
    at = no_region }

let module_declaration (m : module_declaration) : module_declaration =
  { header = m.header;
    prologue_comments = m.prologue_comments;
    module_name = identifier m.module_name;
    attributes = map (fun (a : module_attribute) -> { it = a.it; at = no_region }) m.attributes;
    type_definitions = map type_definition m.type_definitions;
    data_declarations = map data_declaration m.data_declarations;
    routine_declarations = map routine_declaration m.routine_declarations;
    module_region = no_region }

(* [equal] below is [module_declaration a = module_declaration b] without building the two
   erased copies (their allocation and the runtime's generic comparison were 3 % of a fuzzing
   campaign): each function compares what the function of the same name above keeps, and
   compares with [=] exactly what it keeps as it is. Each outer match names every constructor,
   so that a constructor added to the tree is a compilation error here, not a silent [false].
   test/test_ast_erase.ml checks the two agree. *)
module Eq = struct
  let list f a b = List.length a = List.length b && List.for_all2 f a b
  let array f a b =
    Array.length a = Array.length b
    && (let rec go i = i >= Array.length a || (f a.(i) b.(i) && go (i + 1)) in go 0)
  let option f a b = match a, b with None, None -> true | Some x, Some y -> f x y | _ -> false
  let same_length a b = Array.length a = Array.length b

  let identifier (a : identifier) (b : identifier) = a.it = b.it
  let name (a : name) (b : name) = String.equal a.it b.it

  let rec expression (a : expression) (b : expression) = expression_desc a.it b.it

  and expression_desc (a : expression_desc) (b : expression_desc) =
    match a with
    | Num_literal _ | Bool_literal _ | EXP_placeholder -> a = b
    | String_literal s -> (match b with String_literal t -> String.equal s.raw t.raw | _ -> false)
    | Data_reference r -> (match b with Data_reference r' -> reference r r' | _ -> false)
    | Function_call f -> (
        match b with
        | Function_call g ->
            identifier f.func g.func && array argument_desc f.arguments g.arguments
            && same_length f.argument_regions g.argument_regions
        | _ -> false)
    | Aggregate (es, rs) -> (
        match b with Aggregate (es', rs') -> array expression_desc es es' && same_length rs rs' | _ -> false)
    | Unary (op, e, _) -> (match b with Unary (op', e', _) -> op = op' && expression_desc e e' | _ -> false)
    | Binary (op, l, r) -> (
        match b with Binary (op', l', r') -> op = op' && expression l l' && expression r r' | _ -> false)

  and data_reference (a : data_reference) (b : data_reference) = reference a.it b.it

  and reference (a : data_reference_desc) (b : data_reference_desc) =
    match a with
    | Entire _ | VAR_placeholder -> a = b
    | Element (n, es) -> (match b with Element (n', es') -> name n n' && list expression es es' | _ -> false)
    | Component (r, n) -> (match b with Component (r', n') -> data_reference r r' && name n n' | _ -> false)

  (* a positional argument is a required one without a name *)
  and argument_desc (a : argument_desc) (b : argument_desc) =
    let required = function
      | Positional_argument e -> Some (None, e)
      | Required_argument (n, e, _) -> Some (n, e)
      | Optional_argument _ | Conditional_argument _ | ARG_placeholder -> None in
    match a with
    | Positional_argument _ | Required_argument _ -> (
        match required a, required b with
        | Some (n, e), Some (n', e') -> option identifier n n' && expression_desc e e'
        | _ -> false)
    | Optional_argument (n, e) -> (
        match b with Optional_argument (n', e') -> identifier n n' && option expression e e' | _ -> false)
    | Conditional_argument (n, r) -> (
        match b with Conditional_argument (n', r') -> identifier n n' && data_reference r r' | _ -> false)
    | ARG_placeholder -> b = ARG_placeholder

  let rec statement (a : statement) (b : statement) = statement_desc a.it b.it

  and statements a b = list statement a b

  and statement_desc (a : statement_desc) (b : statement_desc) =
    match a with
    | Assignment (r, e) -> (match b with Assignment (r', e') -> data_reference r r' && expression e e' | _ -> false)
    | Procedure_call (p, args, rs) -> (
        match b with
        | Procedure_call (p', args', rs') ->
            (match p, p' with
             | Procedure_name i, Procedure_name i' -> identifier i i'
             | Late_bound e, Late_bound e' -> expression e e'
             | (Procedure_name _ | Late_bound _), _ -> false)
            && array argument_desc args args' && same_length rs rs'
        | _ -> false)
    | Goto i -> (match b with Goto i' -> identifier i i' | _ -> false)
    | Break | Continue | Exit | Retry | Trynext | Statement_comment _ | SMT_placeholder -> a = b
    | Return e -> (match b with Return e' -> option expression e e' | _ -> false)
    | Raise e -> (match b with Raise e' -> option expression e e' | _ -> false)
    | Connect (r, i) -> (match b with Connect (r', i') -> data_reference r r' && identifier i i' | _ -> false)
    | If i -> (
        match b with
        | If j ->
            expression i.condition j.condition && statements i.then_branch j.then_branch
            && list (fun (c : elseif_clause) (d : elseif_clause) ->
                match c.it with
                | Elseif (e, l) -> (match d.it with Elseif (e', l') -> expression e e' && statements l l' | _ -> false)
                | EIT_placeholder -> d.it = EIT_placeholder) i.elseifs j.elseifs
            && option statements i.else_branch j.else_branch
        | _ -> false)
    | Compact_if (e, s) -> (match b with Compact_if (e', s') -> expression e e' && statement s s' | _ -> false)
    | For f -> (
        match b with
        | For g ->
            identifier f.loop_variable g.loop_variable && expression f.from_ g.from_ && expression f.to_ g.to_
            && option expression f.step g.step && statements f.body g.body
        | _ -> false)
    | While (e, l) -> (match b with While (e', l') -> expression e e' && statements l l' | _ -> false)
    | Test t -> (
        match b with
        | Test u ->
            expression t.test_expression u.test_expression
            && list (fun (c : case_clause) (d : case_clause) ->
                match c.it with
                | Case (vs, l) -> (
                    match d.it with Case (vs', l') -> list expression vs vs' && statements l l' | _ -> false)
                | CSE_placeholder -> d.it = CSE_placeholder) t.cases u.cases
            && option statements t.default u.default
        | _ -> false)
    | Label i -> (match b with Label i' -> identifier i i' | _ -> false)

  let data_declaration (a : data_declaration) (b : data_declaration) =
    match a.it with
    | Data_declaration d -> (
        match b.it with
        | Data_declaration e ->
            d.scope = e.scope && d.storage = e.storage && identifier d.data_type e.data_type
            && identifier d.name e.name && list expression d.dims e.dims
            && option expression d.initial_value e.initial_value
        | _ -> false)
    | Declaration_comment _ | DDN_placeholder -> a.it = b.it

  let record_component (a : record_component) (b : record_component) =
    match a.it with
    | Record_component (t, n) -> (
        match b.it with Record_component (t', n') -> identifier t t' && identifier n n' | _ -> false)
    | Component_comment _ -> a.it = b.it

  let type_definition (a : type_definition) (b : type_definition) =
    match a.it with
    | Record_definition r -> (
        match b.it with
        | Record_definition r' ->
            r.local = r'.local && identifier r.name r'.name && list record_component r.components r'.components
        | _ -> false)
    | Alias_definition x -> (
        match b.it with
        | Alias_definition y -> x.local = y.local && identifier x.base y.base && identifier x.name y.name
        | _ -> false)
    | Type_comment _ | TDN_placeholder -> a.it = b.it

  let parameter_declaration (a : parameter_declaration) (b : parameter_declaration) =
    match a.it with
    | Parameter p -> (
        match b.it with
        | Parameter q ->
            p.mode = q.mode && identifier p.data_type q.data_type && identifier p.name q.name && p.array = q.array
        | _ -> false)
    | Switch n -> (match b.it with Switch n' -> identifier n n' | _ -> false)

  let parameter (a : parameter) (b : parameter) =
    match a.it with
    | Required_parameter d -> (match b.it with Required_parameter d' -> parameter_declaration d d' | _ -> false)
    | Optional_parameter alts -> (
        match b.it with
        | Optional_parameter alts' ->
            list (fun (x : alternative) (y : alternative) ->
                match x.it with
                | Alternative d -> (match y.it with Alternative d' -> parameter_declaration d d' | _ -> false)
                | ALT_placeholder -> y.it = ALT_placeholder) alts alts'
        | _ -> false)
    | PAR_placeholder -> b.it = PAR_placeholder

  let routine_body (a : routine_body) (b : routine_body) =
    list data_declaration a.declarations b.declarations && statements a.statements b.statements
    && option statements a.backward b.backward
    && option (fun (h : error_handler) (k : error_handler) ->
        option (list (fun (n : recovery_error_number) (m : recovery_error_number) ->
            match n.it with
            | Error_number_literal _ -> n.it = m.it
            | Error_number_name x -> (match m.it with Error_number_name y -> name x y | _ -> false)))
          h.error_numbers k.error_numbers
        && statements h.handler k.handler) a.error b.error
    && option statements a.undo b.undo

  let routine_declaration (a : routine_declaration) (b : routine_declaration) =
    match a.it with
    | Procedure_declaration p -> (
        match b.it with
        | Procedure_declaration q ->
            p.local = q.local && identifier p.name q.name && list parameter p.parameters q.parameters
            && routine_body p.body q.body
        | _ -> false)
    | Function_declaration f -> (
        match b.it with
        | Function_declaration g ->
            f.local = g.local && identifier f.return_type g.return_type && identifier f.name g.name
            && list parameter f.parameters g.parameters && routine_body f.body g.body
        | _ -> false)
    | Trap_declaration t -> (
        match b.it with
        | Trap_declaration u -> t.local = u.local && identifier t.name u.name && routine_body t.body u.body
        | _ -> false)
    | Routine_comment _ | RDN_placeholder -> a.it = b.it

  let module_declaration (a : module_declaration) (b : module_declaration) =
    a.header = b.header && a.prologue_comments = b.prologue_comments && identifier a.module_name b.module_name
    && list (fun (x : module_attribute) (y : module_attribute) -> x.it = y.it) a.attributes b.attributes
    && list type_definition a.type_definitions b.type_definitions
    && list data_declaration a.data_declarations b.data_declarations
    && list routine_declaration a.routine_declarations b.routine_declarations
end

let equal = Eq.module_declaration
