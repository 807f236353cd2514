(* The syntax tree as an S-expression without locations.

   The form is chosen so that it can be read back unambiguously, which is what makes "equal
   dumps" the same as "equal trees, locations aside":
   - a constructor without arguments is an atom, one with arguments is a list headed by its
     name; record fields are lists headed by the field name;
   - identifiers, names and numeric literals are atoms when they consist of letters, digits,
     '_', '.', '+', '-' and non-ASCII bytes only, and quoted otherwise; the placeholder <ID>
     (§2.9) is the atom <ID>, which no identifier spelling can give;
   - string literals (by their raw text, §2.7), comments (§2.10) and header lines are quoted,
     with '"', '\' and control bytes escaped, so that every text has exactly one quoted form;
   - an absent optional part is left out where the arity of the node tells it apart, and an
     absent optional list (ELSE, DEFAULT, BACKWARD, UNDO, ...) is told from an empty one by
     the presence of its field.

   Layout: declarations, statements and record components each start a line, indented two
   spaces per level; expressions are written on the line of the node that holds them.

   Recursion follows the nesting of the tree only (bounded by [Parse.max_nesting]); lists,
   which may hold millions of elements in generated modules, are walked with List.iter. *)

open Ast

let is_atom_char c =
  match c with
  | 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_' | '.' | '+' | '-' -> true
  | c -> Char.code c >= 0x80

let add_quoted b s =
  Buffer.add_char b '"';
  String.iter (fun c ->
      match c with
      | '"' -> Buffer.add_string b "\\\""
      | '\\' -> Buffer.add_string b "\\\\"
      | c when Char.code c < 0x20 || Char.code c = 0x7F ->
          Buffer.add_string b (Printf.sprintf "\\x%02X" (Char.code c))
      | c -> Buffer.add_char b c) s;
  Buffer.add_char b '"'

(* An atom argument: a space, then the text bare or quoted. *)
let atom b s =
  Buffer.add_char b ' ';
  if s <> "" && String.for_all is_atom_char s then Buffer.add_string b s else add_quoted b s

let quoted b s = Buffer.add_char b ' '; add_quoted b s

let word b w = Buffer.add_char b ' '; Buffer.add_string b w

(* A node on the current line: " (Name". *)
let node b name = Buffer.add_string b " ("; Buffer.add_string b name
let close b = Buffer.add_char b ')'

(* A node that starts a new line at indentation [ind]. *)
let line b ind = Buffer.add_char b '\n'; Buffer.add_string b (String.make ind ' ')
let line_node b ind name = line b ind; Buffer.add_char b '('; Buffer.add_string b name
let line_word b ind w = line b ind; Buffer.add_string b w

let bool_word v = if v then "true" else "false"

let identifier b (i : identifier) =
  match i.it with
  | Ident s -> atom b s
  | ID_placeholder -> word b "<ID>"

let name b (n : name) = atom b n.it

(* ------------------------------------------------------------------ expressions *)

let unary_operator = function
  | Unary_plus -> "Unary_plus" | Unary_minus -> "Unary_minus" | Not -> "Not"

let binary_operator = function
  | Mul -> "Mul" | Div -> "Div" | Int_div -> "Int_div" | Modulo -> "Modulo"
  | Plus -> "Plus" | Minus -> "Minus"
  | Less -> "Less" | Less_equal -> "Less_equal" | Equal -> "Equal" | Greater -> "Greater"
  | Greater_equal -> "Greater_equal" | Not_equal -> "Not_equal"
  | And -> "And" | Or -> "Or" | Xor -> "Xor"

let rec expression b (e : expression) =
  match e.it with
  (* The tree has no [Literal] node any more (ast.ml); the dump still writes one, so that its
     format, which the golden tests pin, does not depend on the tree's representation. *)
  | Num_literal s -> node b "Literal"; node b "Num_literal"; atom b s; close b; close b
  | String_literal s -> node b "Literal"; node b "String_literal"; quoted b s.raw; close b; close b
  | Bool_literal v -> node b "Literal"; node b "Bool_literal"; word b (bool_word v); close b; close b
  | Data_reference r -> node b "Data_reference"; reference b r; close b
  | Function_call f ->
      node b "Function_call"; identifier b f.func;
      node b "arguments"; Array.iter (argument b) (call_arguments f); close b;
      close b
  | Aggregate (es, rs) -> node b "Aggregate"; Array.iter (expression b) (members es rs); close b
  | Unary (op, e, at) -> node b "Unary"; word b (unary_operator op); expression b (operand e at); close b
  | Binary (op, l, r) ->
      node b "Binary"; word b (binary_operator op); expression b l; expression b r; close b
  | EXP_placeholder -> word b "EXP_placeholder"

and data_reference b (r : data_reference) = reference b r.it

and reference b (r : data_reference_desc) =
  match r with
  | Entire n -> node b "Entire"; atom b n; close b
  | Element (n, es) ->
      node b "Element"; name b n; List.iter (expression b) es; close b
  | Component (r, n) -> node b "Component"; data_reference b r; name b n; close b
  | VAR_placeholder -> word b "VAR_placeholder"

and argument b (a : argument) =
  match a.it with
  | Positional_argument e -> node b "Required_argument"; expression b (operand e a.at); close b
  | Required_argument (n, e, at) ->
      node b "Required_argument";
      Option.iter (fun n -> node b "name"; identifier b n; close b) n;
      expression b (operand e at); close b
  | Optional_argument (n, e) ->
      node b "Optional_argument"; identifier b n; Option.iter (expression b) e; close b
  | Conditional_argument (n, r) ->
      node b "Conditional_argument"; identifier b n; data_reference b r; close b
  | ARG_placeholder -> word b "ARG_placeholder"

(* ------------------------------------------------------------------ statements *)

let rec statement b ind (s : statement) =
  match s.it with
  | Assignment (r, e) ->
      line_node b ind "Assignment"; data_reference b r; expression b e; close b
  | Procedure_call (p, args, regions) ->
      line_node b ind "Procedure_call";
      (match p with
       | Procedure_name i -> node b "Procedure_name"; identifier b i; close b
       | Late_bound e -> node b "Late_bound"; expression b e; close b);
      Array.iter (argument b) (Ast.arguments args regions);
      close b
  | Goto i -> line_node b ind "Goto"; identifier b i; close b
  | Break -> line_word b ind "Break"
  | Continue -> line_word b ind "Continue"
  | Return e -> line_node b ind "Return"; Option.iter (expression b) e; close b
  | Raise e -> line_node b ind "Raise"; Option.iter (expression b) e; close b
  | Exit -> line_word b ind "Exit"
  | Retry -> line_word b ind "Retry"
  | Trynext -> line_word b ind "Trynext"
  | Connect (r, i) -> line_node b ind "Connect"; data_reference b r; identifier b i; close b
  | If i ->
      line_node b ind "If"; expression b i.condition;
      statement_list b (ind + 2) "then_branch" i.then_branch;
      line_node b (ind + 2) "elseifs";
      List.iter (fun (c : elseif_clause) ->
          match c.it with
          | Elseif (e, l) ->
              line_node b (ind + 4) "Elseif"; expression b e;
              List.iter (statement b (ind + 6)) l;
              close b
          | EIT_placeholder -> line_word b (ind + 4) "EIT_placeholder") i.elseifs;
      close b;
      Option.iter (statement_list b (ind + 2) "else_branch") i.else_branch;
      close b
  | Compact_if (e, s) ->
      line_node b ind "Compact_if"; expression b e; statement b (ind + 2) s; close b
  | For f ->
      line_node b ind "For";
      node b "loop_variable"; identifier b f.loop_variable; close b;
      node b "from_"; expression b f.from_; close b;
      node b "to_"; expression b f.to_; close b;
      Option.iter (fun e -> node b "step"; expression b e; close b) f.step;
      statement_list b (ind + 2) "body" f.body;
      close b
  | While (e, l) ->
      line_node b ind "While"; expression b e; statement_list b (ind + 2) "body" l; close b
  | Test t ->
      line_node b ind "Test"; expression b t.test_expression;
      line_node b (ind + 2) "cases";
      List.iter (fun (c : case_clause) ->
          match c.it with
          | Case (values, l) ->
              line_node b (ind + 4) "Case";
              node b "values"; List.iter (expression b) values; close b;
              List.iter (statement b (ind + 6)) l;
              close b
          | CSE_placeholder -> line_word b (ind + 4) "CSE_placeholder") t.cases;
      close b;
      Option.iter (statement_list b (ind + 2) "default") t.default;
      close b
  | Label i -> line_node b ind "Label"; identifier b i; close b
  | Statement_comment c -> line_node b ind "Statement_comment"; quoted b c; close b
  | SMT_placeholder -> line_word b ind "SMT_placeholder"

(* A statement list under a field name, one statement per line. *)
and statement_list b ind field l =
  line_node b ind field; List.iter (statement b (ind + 2)) l; close b

(* ------------------------------------------------------------------ declarations *)

let storage = function Var -> "Var" | Pers -> "Pers" | Const -> "Const"
let scope = function Global -> "Global" | Local -> "Local" | Task -> "Task"

let data_declaration b ind (d : data_declaration) =
  match d.it with
  | Data_declaration d ->
      line_node b ind "Data_declaration";
      node b "scope"; word b (scope d.scope); close b;
      node b "storage"; word b (storage d.storage); close b;
      node b "data_type"; identifier b d.data_type; close b;
      node b "name"; identifier b d.name; close b;
      node b "dims"; List.iter (expression b) d.dims; close b;
      Option.iter (fun e -> node b "initial_value"; expression b e; close b) d.initial_value;
      close b
  | Declaration_comment c -> line_node b ind "Declaration_comment"; quoted b c; close b
  | DDN_placeholder -> line_word b ind "DDN_placeholder"

let record_component b ind (c : record_component) =
  match c.it with
  | Record_component (t, n) -> line_node b ind "Record_component"; identifier b t; identifier b n; close b
  | Component_comment c -> line_node b ind "Component_comment"; quoted b c; close b

let type_definition b ind (t : type_definition) =
  match t.it with
  | Record_definition r ->
      line_node b ind "Record_definition";
      node b "local"; word b (bool_word r.local); close b;
      node b "name"; identifier b r.name; close b;
      List.iter (record_component b (ind + 2)) r.components;
      close b
  | Alias_definition a ->
      line_node b ind "Alias_definition";
      node b "local"; word b (bool_word a.local); close b;
      node b "base"; identifier b a.base; close b;
      node b "name"; identifier b a.name; close b;
      close b
  | Type_comment c -> line_node b ind "Type_comment"; quoted b c; close b
  | TDN_placeholder -> line_word b ind "TDN_placeholder"

(* ------------------------------------------------------------------ routines *)

let access_mode = function
  | In -> "In" | Var_mode -> "Var_mode" | Pers_mode -> "Pers_mode" | Inout -> "Inout"
  | Ref_mode -> "Ref_mode"

let parameter_declaration b (p : parameter_declaration) =
  match p.it with
  | Parameter p ->
      node b "Parameter";
      node b "mode"; word b (access_mode p.mode); close b;
      node b "data_type"; identifier b p.data_type; close b;
      node b "name"; identifier b p.name; close b;
      node b "array";
      (match p.array with
       | Not_array -> word b "Not_array"
       | Conformant n -> node b "Conformant"; word b (string_of_int n); close b
       | DIM_placeholder -> word b "DIM_placeholder");
      close b;
      close b
  | Switch n -> node b "Switch"; identifier b n; close b

let parameter b ind (p : parameter) =
  match p.it with
  | Required_parameter d -> line_node b ind "Required_parameter"; parameter_declaration b d; close b
  | Optional_parameter alts ->
      line_node b ind "Optional_parameter";
      List.iter (fun (a : alternative) ->
          match a.it with
          | Alternative d -> node b "Alternative"; parameter_declaration b d; close b
          | ALT_placeholder -> word b "ALT_placeholder") alts;
      close b
  | PAR_placeholder -> line_word b ind "PAR_placeholder"

let routine_body b ind (body : routine_body) =
  line_node b ind "declarations"; List.iter (data_declaration b (ind + 2)) body.declarations; close b;
  statement_list b ind "statements" body.statements;
  Option.iter (statement_list b ind "backward") body.backward;
  Option.iter (fun (h : error_handler) ->
      line_node b ind "error";
      Option.iter (fun ns ->
          node b "error_numbers";
          List.iter (fun (n : recovery_error_number) ->
              match n.it with
              | Error_number_literal s -> node b "Error_number_literal"; atom b s; close b
              | Error_number_name n -> node b "Error_number_name"; name b n; close b) ns;
          close b) h.error_numbers;
      statement_list b (ind + 2) "handler" h.handler;
      close b) body.error;
  Option.iter (statement_list b ind "undo") body.undo

let parameters b ind ps =
  line_node b ind "parameters"; List.iter (parameter b (ind + 2)) ps; close b

let routine_declaration b ind (r : routine_declaration) =
  match r.it with
  | Procedure_declaration p ->
      line_node b ind "Procedure_declaration";
      node b "local"; word b (bool_word p.local); close b;
      node b "name"; identifier b p.name; close b;
      parameters b (ind + 2) p.parameters;
      routine_body b (ind + 2) p.body;
      close b
  | Function_declaration f ->
      line_node b ind "Function_declaration";
      node b "local"; word b (bool_word f.local); close b;
      node b "return_type"; identifier b f.return_type; close b;
      node b "name"; identifier b f.name; close b;
      parameters b (ind + 2) f.parameters;
      routine_body b (ind + 2) f.body;
      close b
  | Trap_declaration t ->
      line_node b ind "Trap_declaration";
      node b "local"; word b (bool_word t.local); close b;
      node b "name"; identifier b t.name; close b;
      routine_body b (ind + 2) t.body;
      close b
  | Routine_comment c -> line_node b ind "Routine_comment"; quoted b c; close b
  | RDN_placeholder -> line_word b ind "RDN_placeholder"

(* ------------------------------------------------------------------ modules *)

let module_attribute (a : module_attribute) =
  match a.it with
  | SYSMODULE -> "SYSMODULE" | NOVIEW -> "NOVIEW" | NOSTEPIN -> "NOSTEPIN"
  | VIEWONLY -> "VIEWONLY" | READONLY -> "READONLY"

let module_declaration (m : module_declaration) =
  let b = Buffer.create 4096 in
  Buffer.add_string b "(Module_declaration";
  Option.iter (fun lines ->
      line_node b 2 "header"; List.iter (quoted b) lines; close b) m.header;
  if m.prologue_comments <> [] then begin
    line_node b 2 "prologue_comments"; List.iter (quoted b) m.prologue_comments; close b
  end;
  line_node b 2 "module_name"; identifier b m.module_name; close b;
  line_node b 2 "attributes"; List.iter (fun a -> word b (module_attribute a)) m.attributes; close b;
  line_node b 2 "type_definitions"; List.iter (type_definition b 4) m.type_definitions; close b;
  line_node b 2 "data_declarations"; List.iter (data_declaration b 4) m.data_declarations; close b;
  line_node b 2 "routine_declarations";
  List.iter (routine_declaration b 4) m.routine_declarations;
  close b;
  Buffer.add_string b ")\n";
  Buffer.contents b

let expression e =
  let b = Buffer.create 256 in
  expression b e;
  (* [expression] writes each argument after a separating space. *)
  Buffer.sub b 1 (Buffer.length b - 1)
