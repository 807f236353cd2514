(* The canonical printer. Its one obligation is that the text it writes parses back to the tree
   it was given (locations aside); the layout choices below are made for that first, for
   readability second.

   Recursion follows the nesting of the tree only (bounded by [Parse.max_nesting]); lists are
   walked with List.iter / List.iteri. *)

open Ast

let indent_step = 2

let newline b = Buffer.add_char b '\n'
let indent b ind = Buffer.add_string b (String.make ind ' ')
let str b s = Buffer.add_string b s

(* §2.10: a comment is '!' and the rest of its line. *)
let comment b text = str b "!"; str b text

let identifier b (i : identifier) =
  match i.it with
  | Ident s -> str b s
  | ID_placeholder -> str b "<ID>"          (* §2.9 *)

let name b (n : name) = str b n.it

(* ------------------------------------------------------------------ expressions *)

(* §3.1 is stratified: the levels below are its nonterminals, loosest first. A node is written
   bare where the context asks for its own level or a looser one, and in parentheses
   ('(' <expr> ')' is a <primary>) where the context asks for a tighter one. This places the
   sign and NOT correctly too: NOT makes an <expr> of a <logical term>, a sign makes a <simple
   expr> of a <term>, so `-a * b` is the sign applied to `a * b`, and the sign applied to a
   product's left operand is written `(-a) * b`. *)
let level_expr = 0            (* [NOT] <logical term> { (OR | XOR) <logical term> } *)
let level_logical_term = 1    (* <relation> { AND <relation> } *)
let level_relation = 2        (* <simple expr> [ <relop> <simple expr> ] *)
let level_simple_expr = 3     (* [ <addop> ] <term> { <addop> <term> } *)
let level_term = 4            (* <primary> { <mulop> <primary> } *)
let level_primary = 5

let binary_level = function
  | Or | Xor -> level_expr
  | And -> level_logical_term
  | Less | Less_equal | Equal | Greater | Greater_equal | Not_equal -> level_relation
  | Plus | Minus -> level_simple_expr
  | Mul | Div | Int_div | Modulo -> level_term

let binary_operator = function
  | Mul -> "*" | Div -> "/" | Int_div -> "DIV" | Modulo -> "MOD"
  | Plus -> "+" | Minus -> "-"
  | Less -> "<" | Less_equal -> "<=" | Equal -> "=" | Greater -> ">" | Greater_equal -> ">="
  | Not_equal -> "<>"
  | And -> "AND" | Or -> "OR" | Xor -> "XOR"

let level_of (e : expression) =
  match e.it with
  | Binary (op, _, _) -> binary_level op
  | Unary (Not, _, _) -> level_expr
  | Unary ((Unary_plus | Unary_minus), _, _) -> level_simple_expr
  | Num_literal _ | String_literal _ | Bool_literal _ | Data_reference _ | Function_call _ | Aggregate _
  | EXP_placeholder -> level_primary

(* [expression b level e] writes [e] where the grammar asks for the nonterminal [level]. *)
let rec expression b level (e : expression) =
  if level_of e < level then begin
    str b "("; expression_bare b e; str b ")"
  end else expression_bare b e

and expression_bare b (e : expression) =
  match e.it with
  | Num_literal s -> str b s                              (* §2.5, as written *)
  | String_literal s -> str b "\""; str b s.raw; str b "\""   (* §2.7, as written *)
  | Bool_literal v -> str b (if v then "TRUE" else "FALSE")
  | Data_reference r -> reference b r
  | Function_call f ->
      (* §3.11 *)
      identifier b f.func; str b "("; arguments b ~first_separator:"" (call_arguments f); str b ")"
  | Aggregate (es, rs) ->                                           (* §3.10 *)
      str b "[";
      Array.iteri (fun i e -> if i > 0 then str b ", "; expression b level_expr e) (members es rs);
      str b "]"
  | Unary (Not, e, at) -> str b "NOT "; expression b level_logical_term (operand e at)
  | Unary (Unary_plus, e, at) -> str b "+"; expression b level_term (operand e at)
  | Unary (Unary_minus, e, at) -> str b "-"; expression b level_term (operand e at)
  | Binary (op, l, r) ->
      let level = binary_level op in
      (* Left-associative levels take their own level on the left; relations do not chain,
         so both of their operands are <simple expr>s. *)
      let left = if level = level_relation then level_simple_expr else level in
      expression b left l;
      str b " "; str b (binary_operator op); str b " ";
      expression b (level + 1) r
  | EXP_placeholder -> str b "<EXP>"

(* <expr> { ',' <expr> }: index lists, aggregates. *)
and expression_list b es =
  List.iteri (fun i e -> if i > 0 then str b ", "; expression b level_expr e) es

(* §3.6 *)
and data_reference b (r : data_reference) = reference b r.it

and reference b (r : data_reference_desc) =
  match r with
  | Entire n -> str b n
  | Element (n, es) -> name b n; str b "{"; expression_list b es; str b "}"
  | Component (r, n) -> data_reference b r; str b "."; name b n
  | VAR_placeholder -> str b "<VAR>"

(* §3.11, §4.6: a comma before each required argument and <ARG> but the first; optional and
   conditional arguments are written without one. Argument expressions are written at the
   loosest level: where the grammar asks for <expr> (functions) rather than <expression>
   (procedures), the two differ only by <EXP>, which a derivable tree does not put there. *)
and arguments b ~first_separator args =
  Array.iteri (fun i (a : argument) ->
      (match a.it with
       | Required_argument _ | Positional_argument _ | ARG_placeholder ->
           str b (if i = 0 then first_separator else ", ")
       | Optional_argument _ | Conditional_argument _ ->
           str b (if i = 0 then first_separator else " "));
      match a.it with
      | Required_argument (None, e, at) -> expression b level_expr (operand e at)
      | Positional_argument e -> expression b level_expr (operand e a.at)
      | Required_argument (Some n, e, at) ->
          identifier b n; str b ":="; expression b level_expr (operand e at)
      | Optional_argument (n, None) -> str b "\\"; identifier b n
      | Optional_argument (n, Some e) ->
          str b "\\"; identifier b n; str b ":="; expression b level_expr e
      | Conditional_argument (n, r) -> str b "\\"; identifier b n; str b "?"; data_reference b r
      | ARG_placeholder -> str b "<ARG>") args

let expression_text b e = expression b level_expr e

(* ------------------------------------------------------------------ statements *)

(* [statement b ind s] writes [s] at indentation [ind], with its trailing line break;
   [statement_rest] writes it from the current column (after a compact IF's condition). *)
let rec statement b ind (s : statement) = indent b ind; statement_rest b ind s

and statement_rest b ind (s : statement) =
  match s.it with
  | Assignment (r, e) -> data_reference b r; str b " := "; expression_text b e; str b ";"; newline b
  | Procedure_call (p, args, regions) ->
      (match p with
       | Procedure_name i -> identifier b i
       | Late_bound e -> str b "%"; expression_text b e; str b "%");
      arguments b ~first_separator:" " (Ast.arguments args regions);
      str b ";"; newline b
  | Goto i -> str b "GOTO "; identifier b i; str b ";"; newline b
  | Break -> str b "BREAK;"; newline b
  | Continue -> str b "CONTINUE;"; newline b
  | Return None -> str b "RETURN;"; newline b
  | Return (Some e) -> str b "RETURN "; expression_text b e; str b ";"; newline b
  | Raise None -> str b "RAISE;"; newline b
  | Raise (Some e) -> str b "RAISE "; expression_text b e; str b ";"; newline b
  | Exit -> str b "EXIT;"; newline b
  | Retry -> str b "RETRY;"; newline b
  | Trynext -> str b "TRYNEXT;"; newline b
  | Connect (r, i) ->
      str b "CONNECT "; data_reference b r; str b " WITH "; identifier b i; str b ";"; newline b
  | Label i -> identifier b i; str b ":"; newline b
  | Statement_comment c -> comment b c; newline b
  | SMT_placeholder -> str b "<SMT>"; newline b
  | Compact_if (e, s) ->
      (* §4.17: the statement on the line of its condition. *)
      str b "IF "; expression_text b e; str b " "; statement_rest b ind s
  | If i ->
      (* §4.16 *)
      str b "IF "; expression_text b i.condition; str b " THEN"; newline b;
      statements b (ind + indent_step) i.then_branch;
      List.iter (fun (c : elseif_clause) ->
          match c.it with
          | Elseif (e, l) ->
              indent b ind; str b "ELSEIF "; expression_text b e; str b " THEN"; newline b;
              statements b (ind + indent_step) l
          | EIT_placeholder -> indent b ind; str b "<EIT>"; newline b) i.elseifs;
      Option.iter (fun l ->
          indent b ind; str b "ELSE"; newline b; statements b (ind + indent_step) l) i.else_branch;
      indent b ind; str b "ENDIF"; newline b
  | For f ->
      (* §4.18 *)
      str b "FOR "; identifier b f.loop_variable;
      str b " FROM "; expression_text b f.from_; str b " TO "; expression_text b f.to_;
      Option.iter (fun e -> str b " STEP "; expression_text b e) f.step;
      str b " DO"; newline b;
      statements b (ind + indent_step) f.body;
      indent b ind; str b "ENDFOR"; newline b
  | While (e, l) ->
      (* §4.19 *)
      str b "WHILE "; expression_text b e; str b " DO"; newline b;
      statements b (ind + indent_step) l;
      indent b ind; str b "ENDWHILE"; newline b
  | Test t ->
      (* §4.20 *)
      str b "TEST "; expression_text b t.test_expression; newline b;
      List.iter (fun (c : case_clause) ->
          match c.it with
          | Case (values, l) ->
              indent b ind; str b "CASE ";
              List.iteri (fun i v -> if i > 0 then str b ", "; expression_text b v) values;
              str b ":"; newline b;
              statements b (ind + indent_step) l
          | CSE_placeholder -> indent b ind; str b "<CSE>"; newline b) t.cases;
      Option.iter (fun l ->
          indent b ind; str b "DEFAULT:"; newline b; statements b (ind + indent_step) l) t.default;
      indent b ind; str b "ENDTEST"; newline b

and statements b ind l = List.iter (statement b ind) l

(* ------------------------------------------------------------------ declarations *)

let dims b = function
  | [] -> ()
  | ds ->
      str b "{";
      List.iteri (fun i d -> if i > 0 then str b ", "; expression_text b d) ds;
      str b "}"

(* §2.18 - §2.24 *)
let data_declaration b ind (d : data_declaration) =
  indent b ind;
  (match d.it with
   | Data_declaration d ->
       (match d.scope with
        | Global -> ()
        | Local -> str b "LOCAL "
        | Task -> str b "TASK ");
       str b (match d.storage with Var -> "VAR " | Pers -> "PERS " | Const -> "CONST ");
       identifier b d.data_type; str b " "; identifier b d.name;
       dims b d.dims;
       Option.iter (fun e -> str b " := "; expression_text b e) d.initial_value;
       str b ";"
   | Declaration_comment c -> comment b c
   | DDN_placeholder -> str b "<DDN>");
  newline b

(* §2.14 with §2.10: inside RECORD..ENDRECORD a comment may stand on a line of its own only on
   the last line. Each component starts a line; a comment goes on the line of the item before
   it (the record's name or a component), unless it followed a comment, or stood on a line of
   its own where it was read (the dialect's comment lines, doc/dialect.md: its region starts
   on a later line than the previous item's ends; trees built without regions have none). *)
let record_components b ind (name : identifier) components =
  (* [open_line]: the current line ends with the record's name or a component and may still
     take a comment. [previous]: that item's region. *)
  let open_line = ref true and previous = ref name.at in
  let own_line at =
    Source.file_of at <> None && Source.file_of !previous <> None
    && (Source.start at).line > (Source.stop !previous).line
  in
  List.iter (fun (c : record_component) ->
      match c.it with
      | Record_component (t, n) ->
          newline b; indent b ind; identifier b t; str b " "; identifier b n; str b ";";
          open_line := true; previous := c.at
      | Component_comment text ->
          if !open_line && not (own_line c.at) then str b " "
          else begin newline b; indent b ind end;
          comment b text;
          open_line := false) components;
  newline b

(* §2.11 *)
let type_definition b ind (t : type_definition) =
  match t.it with
  | Record_definition r ->
      indent b ind;
      if r.local then str b "LOCAL ";
      str b "RECORD "; identifier b r.name;
      record_components b (ind + indent_step) r.name r.components;
      indent b ind; str b "ENDRECORD"; newline b
  | Alias_definition a ->
      indent b ind;
      if a.local then str b "LOCAL ";
      str b "ALIAS "; identifier b a.base; str b " "; identifier b a.name; str b ";"; newline b
  | Type_comment c -> indent b ind; comment b c; newline b
  | TDN_placeholder -> indent b ind; str b "<TDN>"; newline b

(* ------------------------------------------------------------------ routines *)

(* §5.2 *)
let parameter_declaration b (p : parameter_declaration) =
  match p.it with
  | Parameter p ->
      str b (match p.mode with
         | In -> "" | Var_mode -> "VAR " | Pers_mode -> "PERS " | Inout -> "INOUT " | Ref_mode -> "REF ");
      identifier b p.data_type; str b " "; identifier b p.name;
      (match p.array with
       | Not_array -> ()
       | Conformant n ->
           str b "{"; for i = 1 to n do if i > 1 then str b ", "; str b "*" done; str b "}"
       | DIM_placeholder -> str b "{<DIM>}")
  | Switch n -> str b "switch "; identifier b n

(* Like arguments: a comma before each required parameter and <PAR> but the first, none before
   an optional one. *)
let parameters b ps =
  str b "(";
  List.iteri (fun i (p : parameter) ->
      match p.it with
      | Required_parameter d -> if i > 0 then str b ", "; parameter_declaration b d
      | PAR_placeholder -> if i > 0 then str b ", "; str b "<PAR>"
      | Optional_parameter alts ->
          if i > 0 then str b " ";
          str b "\\";
          List.iteri (fun j (a : alternative) ->
              if j > 0 then str b " | ";
              match a.it with
              | Alternative d -> parameter_declaration b d
              | ALT_placeholder -> str b "<ALT>") alts) ps;
  str b ")"

(* §5.4 - §5.6, §7.2 *)
let routine_body b ind (body : routine_body) =
  let inner = ind + indent_step in
  List.iter (data_declaration b inner) body.declarations;
  statements b inner body.statements;
  Option.iter (fun l -> indent b ind; str b "BACKWARD"; newline b; statements b inner l) body.backward;
  Option.iter (fun (h : error_handler) ->
      indent b ind; str b "ERROR";
      Option.iter (fun ns ->
          str b " (";
          List.iteri (fun i (n : recovery_error_number) ->
              if i > 0 then str b ", ";
              match n.it with
              | Error_number_literal s -> str b s
              | Error_number_name n -> name b n) ns;
          str b ")") h.error_numbers;
      newline b;
      statements b inner h.handler) body.error;
  Option.iter (fun l -> indent b ind; str b "UNDO"; newline b; statements b inner l) body.undo

let routine_declaration b ind (r : routine_declaration) =
  let local l = if l then str b "LOCAL " in
  match r.it with
  | Procedure_declaration p ->
      indent b ind; local p.local; str b "PROC "; identifier b p.name; parameters b p.parameters;
      newline b;
      routine_body b ind p.body;
      indent b ind; str b "ENDPROC"; newline b
  | Function_declaration f ->
      indent b ind; local f.local; str b "FUNC "; identifier b f.return_type; str b " ";
      identifier b f.name; parameters b f.parameters; newline b;
      routine_body b ind f.body;
      indent b ind; str b "ENDFUNC"; newline b
  | Trap_declaration t ->
      indent b ind; local t.local; str b "TRAP "; identifier b t.name; newline b;
      routine_body b ind t.body;
      indent b ind; str b "ENDTRAP"; newline b
  | Routine_comment c -> indent b ind; comment b c; newline b
  | RDN_placeholder -> indent b ind; str b "<RDN>"; newline b

(* ------------------------------------------------------------------ modules *)

let module_attribute (a : module_attribute) =
  match a.it with
  | SYSMODULE -> "SYSMODULE" | NOVIEW -> "NOVIEW" | NOSTEPIN -> "NOSTEPIN"
  | VIEWONLY -> "VIEWONLY" | READONLY -> "READONLY"

(* §9.2. The three lists are written in the grammar's order; in a parsed module a type or
   declaration comment is always followed by an item of its own list (§2.10: comments that no
   such item follows belong to the next list), so each comment is read back into its list. *)
let module_declaration (m : module_declaration) =
  let b = Buffer.create 4096 in
  Option.iter (fun lines ->
      (* The %%% header block of doc/dialect.md. *)
      str b "%%%"; newline b;
      List.iter (fun l -> str b l; newline b) lines;
      str b "%%%"; newline b) m.header;
  List.iter (fun c -> comment b c; newline b) m.prologue_comments;
  str b "MODULE "; identifier b m.module_name;
  (match m.attributes with
   | [] -> ()
   | attrs ->
       str b "(";
       List.iteri (fun i a -> if i > 0 then str b ", "; str b (module_attribute a)) attrs;
       str b ")");
  newline b;
  List.iter (type_definition b indent_step) m.type_definitions;
  List.iter (data_declaration b indent_step) m.data_declarations;
  List.iter (routine_declaration b indent_step) m.routine_declarations;
  str b "ENDMODULE"; newline b;
  Buffer.contents b

let expression e =
  let b = Buffer.create 64 in
  expression_text b e;
  Buffer.contents b

let statement s =
  let b = Buffer.create 64 in
  statement b 0 s;
  Buffer.contents b
