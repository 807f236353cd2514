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

let equal a b = module_declaration a = module_declaration b
