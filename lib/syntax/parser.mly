(* The grammar of RAPID modules: chapter 10 of the RAPID kernel manual, rule for rule.

   Every nonterminal below carries the name of the manual's rule it implements, and a comment
   naming the section that introduces the rule. doc/grammar.md maps every rule of chapter 10 to
   its nonterminal here.

   Where this file departs from the letter of chapter 10, it is for one of three reasons, each
   said again at the rule:

   1. Rules told apart only by what a name is bound to. <variable>, <persistent>, <constant> and
      <parameter> (§3.6-§3.9) are derived by the same token sequences; so are <entire variable>,
      <entire constant> and <entire persistent>. One nonterminal, [variable], derives all of
      them (the static semantics tells them apart); [parameter] is kept as a name for the one
      place where the manual allows only a parameter (conditional arguments, §3.11, §4.6).

   2. Comments (§2.10). A comment is an element of the list it stands in, and "a comment between
      the last data declaration and the first routine declaration belongs to the routine
      declaration list; between the last data declaration and the first statement, to the
      statement list". An LR(1) parser cannot decide that by looking one token ahead when
      several comments stand in a row, so each pair of consecutive lists is parsed by one
      right-recursive rule that reads the comments first and files them with the list of the
      item that follows them ([module_body], [routine_content]). Comments that no item
      follows go to the last list (routine declarations, statements). Inside RECORD..ENDRECORD
      a comment on a line of its own is refused unless it is the last line (§2.10); that is a
      matter of lines, checked in the action of [record_component_list].

   3. Words that are not reserved. TASK (§2.18) and switch (§5.2) are not in §2.4's list. The
      lexer gives TASK a token of its own, which [identifier] and [ident] accept wherever a name
      may stand; a parameter declared with the type name "switch" and no access mode or array
      part is a switch parameter. REF (ch. 11) is a token only in the installed environment.

   There are no precedence declarations: the grammar is stratified as in §3.1 and has no
   conflicts (menhir --explain reports none). *)

%{
open Ast

let region (startpos : Lexing.position) (endpos : Lexing.position) =
  Source.region !Parse_context.file startpos.pos_cnum endpos.pos_cnum

let at startpos endpos it = { it; at = region startpos endpos }

let required_argument startpos endpos name (e : expression) =
  let at = region startpos endpos in
  { it = Ast.required_argument name e at; at }

let refuse startpos endpos message =
  raise (Parse_context.Refused (region startpos endpos, message))

let is_word word (s : string) = String.lowercase_ascii s = word

(* [file_comments make cs items]: the comments [cs], made list elements by [make], followed by
   [items]. Tail-recursive: a generated module may hold a million comment lines. *)
let file_comments make cs items =
  List.rev_append (List.rev_map (fun (text, at) -> { it = make text; at }) cs) items

(* §2.10: inside RECORD..ENDRECORD a comment may not stand on a line of its own, except on the
   last line. [header_line] is the line of the record's name. Without --strict such comments
   are accepted (doc/dialect.md): RobotWare add-ins write a component's comment over lines. *)
let check_record_comments header_line items =
  if !Parse_context.strict then begin
  let line_of r = (Source.start r).line in
  let rec walk previous_line = function
    | [] -> ()
    | { it = Component_comment _; at } :: rest ->
        let alone = line_of at <> previous_line in
        let last = rest = [] in
        if alone && not last then
          raise (Parse_context.Refused (at,
            "a comment may not stand on a line of its own inside RECORD ... ENDRECORD, \
             except on the last line (§2.10)"));
        walk (line_of at) rest
    | { it = Record_component _; at } :: rest -> walk (Source.stop at).line rest
  in
  walk header_line items
  end
%}

%token <string> IDENT NUM COMMENT TASK
%token <Ast.string_literal> STRING
%token <string list> HEADER
%token ALIAS AND BACKWARD BREAK CASE CONNECT CONST CONTINUE DEFAULT DIV DO ELSE ELSEIF
%token ENDFOR ENDFUNC ENDIF ENDMODULE ENDPROC ENDRECORD ENDTEST ENDTRAP ENDWHILE ERROR
%token EXIT FALSE FOR FROM FUNC GOTO IF INOUT LOCAL MOD MODULE NOSTEPIN NOT NOVIEW OR
%token PERS PROC RAISE READONLY RECORD RETRY RETURN STEP SYSMODULE TEST THEN TO TRAP
%token TRUE TRYNEXT UNDO VAR VIEWONLY WHILE WITH XOR
%token REF
%token TDN_PH DDN_PH RDN_PH PAR_PH ALT_PH DIM_PH SMT_PH VAR_PH EIT_PH CSE_PH EXP_PH ARG_PH ID_PH
%token LBRACE RBRACE LPAREN RPAREN LBRACKET RBRACKET COMMA DOT EQ LT GT PLUS MINUS STAR
%token SLASH COLON SEMICOLON BACKSLASH QUESTION ASSIGN NE GE LE PERCENT BAR
%token EOF

%start <Ast.module_declaration> module_file

%%

(* A file holds one module, optionally preceded by a %%% header block and by comment lines
   (doc/dialect.md: generated programs start with a comment naming their tool). Under --strict
   Parse refuses both where they are read. *)
module_file:
  | header = HEADER? cs = comments m = module_declaration EOF
    { { m with header; prologue_comments = List.map fst cs } }

(* ---------------------------------------------------------------- §2.3 Identifiers *)

(* TASK is not reserved (§2.4): the lexer marks the word, which begins a task declaration
   (§2.18) where a data declaration may stand and is an identifier everywhere else. *)
identifier:
  | s = IDENT { at $startpos $endpos (Parse_context.ident s) }
  | s = TASK  { at $startpos $endpos (Parse_context.ident s) }
  | ID_PH     { at $startpos $endpos ID_placeholder }

ident:
  | s = IDENT { at $startpos $endpos s }
  | s = TASK  { at $startpos $endpos s }

(* ---------------------------------------------------------------- §9.2 Module declaration *)

module_declaration:
  | MODULE name = module_name attributes = loption(module_attribute_list)
    body = module_body ENDMODULE
    { let (type_definitions, data_declarations, routine_declarations) = body in
      { header = None; prologue_comments = []; module_name = name; attributes; type_definitions; data_declarations;
        routine_declarations; module_region = region $startpos $endpos } }

module_name:
  | i = identifier { i }

module_attribute_list:
  | LPAREN a = module_attribute rest = preceded(COMMA, module_attribute)* RPAREN { a :: rest }

module_attribute:
  | SYSMODULE { at $startpos $endpos Ast.SYSMODULE }
  | NOVIEW    { at $startpos $endpos Ast.NOVIEW }
  | NOSTEPIN  { at $startpos $endpos Ast.NOSTEPIN }
  | VIEWONLY  { at $startpos $endpos Ast.VIEWONLY }
  | READONLY  { at $startpos $endpos Ast.READONLY }

(* <type definition list> <data declaration list> <routine declaration list>, with each run of
   comments filed with the list of the item that follows it (see the head of this file). *)
module_body:
  | cs = comments
    { ([], [], file_comments (fun c -> Routine_comment c) cs []) }
  | cs = comments t = type_definition_item rest = module_body
    { let (ts, ds, rs) = rest in
      (file_comments (fun c -> Type_comment c) cs (t :: ts), ds, rs) }
  | cs = comments d = module_data_declarations
    { let (ds, rs) = d in ([], file_comments (fun c -> Declaration_comment c) cs ds, rs) }
  | cs = comments r = routine_declaration_item rs = routine_declaration_list
    { ([], [], file_comments (fun c -> Routine_comment c) cs (r :: rs)) }

module_data_declarations:
  | d = data_declaration_item cs = comments
    { ([d], file_comments (fun c -> Routine_comment c) cs []) }
  | d = data_declaration_item cs = comments d2 = module_data_declarations
    { let (ds, rs) = d2 in
      (d :: file_comments (fun c -> Declaration_comment c) cs ds, rs) }
  | d = data_declaration_item cs = comments r = routine_declaration_item rs = routine_declaration_list
    { ([d], file_comments (fun c -> Routine_comment c) cs (r :: rs)) }

comments:
  | (* empty *) { [] }
  | c = COMMENT cs = comments { (c, region $startpos(c) $endpos(c)) :: cs }

(* ---------------------------------------------------------------- §2.11 Type definitions *)

(* §2.11 <type definition> ::= [LOCAL] (<record definition> | <alias definition>) | <comment>
   | <TDN>. The comment alternative is taken by [module_body]. *)
type_definition_item:
  | local = local_option r = record_definition
    { let (name, components) = r in
      at $symbolstartpos $endpos (Record_definition { local; name; components }) }
  | local = local_option a = alias_definition
    { let (base, name) = a in at $symbolstartpos $endpos (Alias_definition { local; base; name }) }
  | TDN_PH { at $startpos $endpos TDN_placeholder }

local_option:
  | (* empty *) { false }
  | LOCAL { true }

(* §2.14 <record definition> ::= RECORD <identifier> <record component list> ENDRECORD *)
record_definition:
  | RECORD name = identifier components = record_component_list ENDRECORD
    { check_record_comments (Source.stop name.at).line components;
      if not (List.exists (function { it = Record_component _; _ } -> true | _ -> false) components) then
        refuse $startpos($4) $endpos($4)
          "expected a record component: a record definition has at least one (§2.14); found ENDRECORD";
      (name, components) }

(* §2.14 <record component list> ::= <record component definition> { <record component
   definition> }, with comments as elements (§2.10); a list of comments only is refused by
   [record_definition] at ENDRECORD, where the missing component was due. *)
record_component_list:
  | items = record_item+ { items }

record_item:
  | c = record_component_definition { c }
  | c = COMMENT { at $startpos $endpos (Component_comment c) }

(* §2.14 <record component definition> ::= <data type> <record component name> ';' *)
record_component_definition:
  | t = data_type n = record_component_name SEMICOLON
    { at $startpos $endpos (Record_component (t, n)) }

record_component_name:
  | i = identifier { i }

(* §2.15 <alias definition> ::= ALIAS <data type> <identifier> ';' *)
alias_definition:
  | ALIAS t = data_type name = identifier SEMICOLON { (t, name) }

(* §2.11 <data type> ::= <identifier> *)
data_type:
  | i = identifier { i }

(* ---------------------------------------------------------------- §2.18 Data declarations *)

(* §2.18 <data declaration> ::= [LOCAL] (<variable declaration> | <persistent declaration> |
   <constant declaration>) | TASK (<variable declaration> | <persistent declaration>) |
   <comment> | <DDN>. The comment alternative is taken by [module_body] and
   [routine_content]. *)
data_declaration_item:
  | local = local_option d = variable_declaration
    { d $symbolstartpos $endpos (if local then Local else Global) }
  | local = local_option d = persistent_declaration
    { d $symbolstartpos $endpos (if local then Local else Global) }
  | local = local_option d = constant_declaration
    { d $symbolstartpos $endpos (if local then Local else Global) }
  | TASK d = variable_declaration { d $startpos $endpos Task }
  | TASK d = persistent_declaration { d $startpos $endpos Task }
  | DDN_PH { at $startpos $endpos DDN_placeholder }

(* §2.22 <variable declaration> ::= VAR <data type> <variable definition> ';' *)
variable_declaration:
  | VAR data_type = data_type d = variable_definition SEMICOLON
    { let (name, dims, initial_value) = d in
      fun s e scope -> at s e (Data_declaration { scope; storage = Var; data_type; name; dims; initial_value }) }

(* §2.22 <variable definition> ::= <identifier> [ '{' <dim> { ',' <dim> } '}' ]
   [ ':=' <constant expression> ] *)
variable_definition:
  | name = identifier dims = loption(dimensions) init = preceded(ASSIGN, constant_expression)?
    { (name, dims, init) }

dimensions:
  | LBRACE d = dim ds = preceded(COMMA, dim)* RBRACE { d :: ds }

(* §2.22 <dim> ::= <constant expression> *)
dim:
  | e = constant_expression { e }

(* §2.23 <persistent declaration> ::= PERS <data type> <persistent definition> ';' *)
persistent_declaration:
  | PERS data_type = data_type d = persistent_definition SEMICOLON
    { let (name, dims, initial_value) = d in
      fun s e scope -> at s e (Data_declaration { scope; storage = Pers; data_type; name; dims; initial_value }) }

(* §2.23 <persistent definition> ::= <identifier> [ '{' <dim> { ',' <dim> } '}' ]
   [ ':=' <literal expression> ] *)
persistent_definition:
  | name = identifier dims = loption(dimensions) init = preceded(ASSIGN, literal_expression)?
    { (name, dims, init) }

(* §2.24 <constant declaration> ::= CONST <data type> <constant definition> ';' *)
constant_declaration:
  | CONST data_type = data_type d = constant_definition SEMICOLON
    { let (name, dims, initial_value) = d in
      fun s e scope -> at s e (Data_declaration { scope; storage = Const; data_type; name; dims;
                                                  initial_value = Some initial_value }) }

(* §2.24 <constant definition> ::= <identifier> [ '{' <dim> { ',' <dim> } '}' ]
   ':=' <constant expression> *)
constant_definition:
  | name = identifier dims = loption(dimensions) ASSIGN init = constant_expression
    { (name, dims, init) }

(* ---------------------------------------------------------------- §3 Expressions *)

(* §3.1 <expression> ::= <expr> | <EXP> *)
expression:
  | e = expr { e }
  | EXP_PH { at $startpos $endpos EXP_placeholder }

(* §3.1 <expr> ::= [ NOT ] <logical term> { ( OR | XOR ) <logical term> }
   NOT applies to the first logical term; OR and XOR then associate to the left. *)
expr:
  | t = logical_term { t }
  | NOT t = logical_term { at $startpos $endpos (Unary (Not, t.it, t.at)) }
  | e = expr op = or_operator t = logical_term { at $startpos $endpos (Binary (op, e, t)) }

or_operator:
  | OR { Or }
  | XOR { Xor }

(* §3.1 <logical term> ::= <relation> { AND <relation> } *)
logical_term:
  | r = relation { r }
  | t = logical_term AND r = relation { at $startpos $endpos (Binary (And, t, r)) }

(* §3.1 <relation> ::= <simple expr> [ <relop> <simple expr> ] *)
relation:
  | e = simple_expr { e }
  | l = simple_expr op = relop r = simple_expr { at $startpos $endpos (Binary (op, l, r)) }

(* §3.1 <simple expr> ::= [ <addop> ] <term> { <addop> <term> }
   The sign applies to the first term. *)
simple_expr:
  | t = term { t }
  | op = addop t = term
    { at $startpos $endpos (Unary ((match op with Plus -> Unary_plus | _ -> Unary_minus), t.it, t.at)) }
  | e = simple_expr op = addop t = term { at $startpos $endpos (Binary (op, e, t)) }

(* §3.1 <term> ::= <primary> { <mulop> <primary> } *)
term:
  | p = primary { p }
  | t = term op = mulop p = primary { at $startpos $endpos (Binary (op, t, p)) }

(* §3.1 <primary> ::= <literal> | <variable> | <persistent> | <constant> | <parameter>
   | <function call> | <aggregate> | '(' <expr> ')'
   (<variable>, <persistent>, <constant> and <parameter> are one nonterminal: see the head.) *)
primary:
  | l = literal { at $startpos $endpos l }
  | v = variable
    { at $startpos $endpos
        (match v.it with Entire s -> Parse_context.entire_reference s | r -> Data_reference r) }
  | f = function_call { at $startpos $endpos (Function_call f) }
  | a = aggregate { at $startpos $endpos (Ast.aggregate a) }
  | LPAREN e = expr RPAREN { e }

(* §3.1 *)
relop:
  | LT { Less }
  | LE { Less_equal }
  | EQ { Equal }
  | GT { Greater }
  | GE { Greater_equal }
  | NE { Not_equal }

addop:
  | PLUS { Plus }
  | MINUS { Minus }

mulop:
  | STAR { Mul }
  | SLASH { Div }
  | DIV { Int_div }
  | MOD { Modulo }

(* §3.2 <constant expression> ::= <expression> *)
constant_expression:
  | e = expression { e }

(* §3.3 <literal expression> ::= <expression> *)
literal_expression:
  | e = expression { e }

(* §3.4 <conditional expression> ::= <expression> *)
conditional_expression:
  | e = expression { e }

(* §3.5 <literal> ::= <num literal> | <string literal> | <bool literal> *)
literal:
  | n = NUM { Parse_context.num_literal n }
  | s = STRING { String_literal s }
  | b = bool_literal { Bool_literal b }

(* §2.6 <bool literal> ::= TRUE | FALSE *)
bool_literal:
  | TRUE { true }
  | FALSE { false }

(* §3.6 <variable> ::= <entire variable> | <variable element> | <variable component>
   (also §3.7 <persistent>, §3.8 <constant>, §3.9 <parameter>: see the head) *)
variable:
  | v = entire_variable { at $startpos $endpos (Entire v.it) }
  | v = variable_element { v }
  | v = variable_component { v }

(* §3.6 <entire variable> ::= <ident> *)
entire_variable:
  | i = ident { i }

(* §3.6 <variable element> ::= <entire variable> '{' <index list> '}' *)
variable_element:
  | v = entire_variable LBRACE l = index_list RBRACE { at $startpos $endpos (Element (v, l)) }

(* §3.6 <index list> ::= <expr> { ',' <expr> } *)
index_list:
  | e = expr es = preceded(COMMA, expr)* { e :: es }

(* §3.6 <variable component> ::= <variable> '.' <component name> *)
variable_component:
  | v = variable DOT c = component_name { at $startpos $endpos (Component (v, c)) }

(* §3.6 <component name> ::= <ident> *)
component_name:
  | i = ident { i }

(* §3.9 <parameter>, where only a parameter is allowed. *)
parameter:
  | v = variable { v }

(* §3.10 <aggregate> ::= '[' <expr> { ',' <expr> } ']' *)
aggregate:
  | LBRACKET e = expr es = preceded(COMMA, expr)* RBRACKET { e :: es }

(* §3.11 <function call> ::= <function> '(' [ <function argument list> ] ')' *)
function_call:
  | func = function_ LPAREN arguments = loption(function_argument_list) RPAREN
    { let (arguments, argument_regions) = Ast.argument_arrays arguments in
      { func; arguments; argument_regions } }

(* §3.11 <function> ::= <identifier> *)
function_:
  | i = identifier { i }

(* §3.11 <function argument list> ::= <first function argument> { <function argument> } *)
function_argument_list:
  | a = first_function_argument rest = function_argument* { a :: rest }

(* §3.11 <first function argument> ::= <required function argument>
   | <optional function argument> | <conditional function argument> *)
first_function_argument:
  | a = required_function_argument { a }
  | a = optional_function_argument { a }
  | a = conditional_function_argument { a }

(* §3.11 <function argument> ::= ',' <required function argument>
   | [','] <optional function argument> | [','] <conditional function argument> *)
function_argument:
  | COMMA a = required_function_argument { a }
  | a = optional_function_argument { a }
  | COMMA a = optional_function_argument { a }
  | a = conditional_function_argument { a }
  | COMMA a = conditional_function_argument { a }

(* §3.11 <required function argument> ::= [ <ident> ':=' ] <expr> *)
required_function_argument:
  | e = expr { required_argument $startpos $endpos None e }
  | n = ident ASSIGN e = expr
    { required_argument $startpos $endpos (Some { it = Parse_context.ident n.it; at = n.at }) e }

(* §3.11 <optional function argument> ::= '\' <ident> [ ':=' <expr> ] *)
optional_function_argument:
  | BACKSLASH n = ident v = preceded(ASSIGN, expr)?
    { at $startpos $endpos (Optional_argument ({ it = Parse_context.ident n.it; at = n.at }, v)) }

(* §3.11 <conditional function argument> ::= '\' <ident> '?' <parameter> *)
conditional_function_argument:
  | BACKSLASH n = ident QUESTION p = parameter
    { at $startpos $endpos (Conditional_argument ({ it = Parse_context.ident n.it; at = n.at }, p)) }

(* ---------------------------------------------------------------- §4 Statements *)

(* §4.3 <statement list> ::= { <statement> } *)
statement_list:
  | (* empty *) { [] }
  | s = statement rest = statement_list { s :: rest }

(* §4.1 <statement> ::= <simple statement> | <compound statement> | <label> | <comment>
   | <SMT> *)
statement:
  | s = statement_proper { s }
  | c = COMMENT { at $startpos $endpos (Statement_comment c) }

statement_proper:
  | s = simple_statement { s }
  | s = compound_statement { s }
  | l = label { l }
  | SMT_PH { at $startpos $endpos SMT_placeholder }

(* §4.1 <simple statement> *)
simple_statement:
  | s = assignment_statement
  | s = procedure_call
  | s = goto_statement
  | s = break_statement
  | s = continue_statement
  | s = return_statement
  | s = raise_statement
  | s = exit_statement
  | s = retry_statement
  | s = trynext_statement
  | s = connect_statement
    { at $startpos $endpos s }

(* §4.1 <compound statement> *)
compound_statement:
  | s = if_statement
  | s = compact_if_statement
  | s = for_statement
  | s = while_statement
  | s = test_statement
    { at $startpos $endpos s }

(* §4.4 <label> ::= <identifier> ':' *)
label:
  | i = identifier COLON { at $startpos $endpos (Label i) }

(* §4.5 <assignment statement> ::= <assignment target> ':=' <expression> ';' *)
assignment_statement:
  | t = assignment_target ASSIGN e = expression SEMICOLON { Assignment (t, e) }

(* §4.5 <assignment target> ::= <variable> | <persistent> | <parameter> | <VAR> *)
assignment_target:
  | v = variable { v }
  | VAR_PH { at $startpos $endpos VAR_placeholder }

(* §4.6 <procedure call> ::= <procedure> [ <procedure argument list> ] ';' *)
procedure_call:
  | p = procedure args = loption(procedure_argument_list) SEMICOLON
    { let (args, regions) = Ast.argument_arrays args in Procedure_call (p, args, regions) }

(* §4.6 <procedure> ::= <identifier> | '%' <expression> '%' *)
procedure:
  | i = identifier { Procedure_name i }
  | PERCENT e = expression PERCENT { Late_bound e }

(* §4.6 <procedure argument list> ::= <first procedure argument> { <procedure argument> } *)
procedure_argument_list:
  | a = first_procedure_argument rest = procedure_argument* { a :: rest }

(* §4.6 <first procedure argument> ::= <required procedure argument>
   | <optional procedure argument> | <conditional procedure argument> | <ARG> *)
first_procedure_argument:
  | a = required_procedure_argument { a }
  | a = optional_procedure_argument { a }
  | a = conditional_procedure_argument { a }
  | ARG_PH { at $startpos $endpos ARG_placeholder }

(* §4.6 <procedure argument> ::= ',' <required procedure argument>
   | [','] <optional procedure argument> | [','] <conditional procedure argument>
   | ',' <ARG> *)
procedure_argument:
  | COMMA a = required_procedure_argument { a }
  | a = optional_procedure_argument { a }
  | COMMA a = optional_procedure_argument { a }
  | a = conditional_procedure_argument { a }
  | COMMA a = conditional_procedure_argument { a }
  | COMMA ARG_PH { at $startpos($2) $endpos ARG_placeholder }

(* §4.6 <required procedure argument> ::= [ <identifier> ':=' ] <expression> *)
required_procedure_argument:
  | e = expression { required_argument $startpos $endpos None e }
  | n = identifier ASSIGN e = expression
    { required_argument $startpos $endpos (Some n) e }

(* §4.6 <optional procedure argument> ::= '\' <identifier> [ ':=' <expression> ] *)
optional_procedure_argument:
  | BACKSLASH n = identifier v = preceded(ASSIGN, expression)?
    { at $startpos $endpos (Optional_argument (n, v)) }
  | BACKSLASH CONTINUE v = preceded(ASSIGN, expression)?
    { (* ABB's RaiseToUser \Continue: CONTINUE is reserved (§2.4), so the word is read as the
         name of an optional argument here only, and not under --strict (doc/dialect.md,
         doc/rulings.md R-7.3-m). *)
      let n = at $startpos($2) $endpos($2) (Parse_context.ident "Continue") in
      if !Parse_context.strict then
        raise (Parse_context.Refused (n.at, "CONTINUE is a reserved word (§2.4): it cannot name an \
                                             optional argument; the manual's switch is \\Resume (§7.3)"));
      at $startpos $endpos (Optional_argument (n, v)) }

(* §4.6 <conditional procedure argument> ::= '\' <identifier> '?' ( <parameter> | <VAR> ) *)
conditional_procedure_argument:
  | BACKSLASH n = identifier QUESTION p = parameter
    { at $startpos $endpos (Conditional_argument (n, p)) }
  | BACKSLASH n = identifier QUESTION VAR_PH
    { at $startpos $endpos (Conditional_argument (n, at $startpos($4) $endpos VAR_placeholder)) }

(* §4.7 <goto statement> ::= GOTO <identifier> ';' *)
goto_statement:
  | GOTO i = identifier SEMICOLON { Goto i }

(* §4.8 <break statement> ::= BREAK ';' *)
break_statement:
  | BREAK SEMICOLON { Break }

(* §4.9 <continue statement> ::= CONTINUE ';' *)
continue_statement:
  | CONTINUE SEMICOLON { Continue }

(* §4.10 <return statement> ::= RETURN [ <expression> ] ';' *)
return_statement:
  | RETURN e = expression? SEMICOLON { Return e }

(* §4.11 <raise statement> ::= RAISE [ <error number> ] ';' *)
raise_statement:
  | RAISE e = error_number? SEMICOLON { Raise e }

(* §4.11 <error number> ::= <expression> *)
error_number:
  | e = expression { e }

(* §4.12 <exit statement> ::= EXIT ';' *)
exit_statement:
  | EXIT SEMICOLON { Exit }

(* §4.13 <retry statement> ::= RETRY ';' *)
retry_statement:
  | RETRY SEMICOLON { Retry }

(* §4.14 <trynext statement> ::= TRYNEXT ';' *)
trynext_statement:
  | TRYNEXT SEMICOLON { Trynext }

(* §4.15 <connect statement> ::= CONNECT <connect target> WITH <trap> ';' *)
connect_statement:
  | CONNECT t = connect_target WITH trap = trap SEMICOLON { Connect (t, trap) }

(* §4.15 <connect target> ::= <variable> | <parameter> | <VAR> *)
connect_target:
  | v = variable { v }
  | VAR_PH { at $startpos $endpos VAR_placeholder }

(* §4.15 <trap> ::= <identifier> *)
trap:
  | i = identifier { i }

(* §4.16 <if statement> ::= IF <conditional expression> THEN <statement list>
   { ELSEIF <conditional expression> THEN <statement list> | <EIT> }
   [ ELSE <statement list> ] ENDIF *)
if_statement:
  | IF condition = conditional_expression THEN then_branch = statement_list
    elseifs = elseif_clause* else_branch = preceded(ELSE, statement_list)? ENDIF
    { If { condition; then_branch; elseifs; else_branch } }

elseif_clause:
  | ELSEIF c = conditional_expression THEN l = statement_list { at $startpos $endpos (Elseif (c, l)) }
  | EIT_PH { at $startpos $endpos EIT_placeholder }

(* §4.17 <compact if statement> ::= IF <conditional expression> ( <simple statement> | <SMT> ) *)
compact_if_statement:
  | IF c = conditional_expression s = simple_statement { Compact_if (c, s) }
  | IF c = conditional_expression SMT_PH
    { Compact_if (c, at $startpos($3) $endpos SMT_placeholder) }

(* §4.18 <for statement> ::= FOR <loop variable> FROM <expression> TO <expression>
   [ STEP <expression> ] DO <statement list> ENDFOR *)
for_statement:
  | FOR loop_variable = loop_variable FROM from_ = expression TO to_ = expression
    step = preceded(STEP, expression)? DO body = statement_list ENDFOR
    { For { loop_variable; from_; to_; step; body } }

(* §4.18 <loop variable> ::= <identifier> *)
loop_variable:
  | i = identifier { i }

(* §4.19 <while statement> ::= WHILE <conditional expression> DO <statement list> ENDWHILE *)
while_statement:
  | WHILE c = conditional_expression DO body = statement_list ENDWHILE { While (c, body) }

(* §4.20 <test statement> ::= TEST <expression>
   { CASE <test value> { ',' <test value> } ':' <statement list> | <CSE> }
   [ DEFAULT ':' <statement list> ] ENDTEST *)
test_statement:
  | TEST test_expression = expression cases = case_clause*
    default = preceded(pair(DEFAULT, COLON), statement_list)? ENDTEST
    { Test { test_expression; cases; default } }

case_clause:
  | CASE v = test_value vs = preceded(COMMA, test_value)* COLON l = statement_list
    { at $startpos $endpos (Case (v :: vs, l)) }
  | CSE_PH { at $startpos $endpos CSE_placeholder }

(* §4.20 <test value> ::= <constant expression> *)
test_value:
  | e = constant_expression { e }

(* ---------------------------------------------------------------- §5 Routine declarations *)

routine_declaration_list:
  | cs = comments { file_comments (fun c -> Routine_comment c) cs [] }
  | cs = comments r = routine_declaration_item rest = routine_declaration_list
    { file_comments (fun c -> Routine_comment c) cs (r :: rest) }

(* §5.1 <routine declaration> ::= [LOCAL] (<procedure declaration> | <function declaration>
   | <trap declaration>) | <comment> | <RDN>. The comment alternative is taken by
   [routine_declaration_list]. *)
routine_declaration_item:
  | local = local_option d = procedure_declaration { at $symbolstartpos $endpos (d local) }
  | local = local_option d = function_declaration { at $symbolstartpos $endpos (d local) }
  | local = local_option d = trap_declaration { at $symbolstartpos $endpos (d local) }
  | RDN_PH { at $startpos $endpos RDN_placeholder }

(* §5.2 <parameter list> ::= <first parameter declaration> { <next parameter declaration> } *)
parameter_list:
  | p = first_parameter_declaration rest = next_parameter_declaration* { p :: rest }

(* §5.2 <first parameter declaration> ::= <parameter declaration>
   | <optional parameter declaration> | <PAR> *)
first_parameter_declaration:
  | p = parameter_declaration { { it = Required_parameter p; at = p.at } }
  | p = optional_parameter_declaration { p }
  | PAR_PH { at $startpos $endpos PAR_placeholder }

(* §5.2 <next parameter declaration> ::= ',' <parameter declaration>
   | [','] <optional parameter declaration> | ',' <PAR> *)
next_parameter_declaration:
  | COMMA p = parameter_declaration { { it = Required_parameter p; at = p.at } }
  | p = optional_parameter_declaration { p }
  | COMMA p = optional_parameter_declaration { p }
  | COMMA PAR_PH { at $startpos($2) $endpos PAR_placeholder }

(* §5.2 <optional parameter declaration> ::=
   '\' ( <parameter declaration> | <ALT> ) { '|' ( <parameter declaration> | <ALT> ) } *)
optional_parameter_declaration:
  | BACKSLASH a = alternative rest = preceded(BAR, alternative)*
    { at $startpos $endpos (Optional_parameter (a :: rest)) }

alternative:
  | p = parameter_declaration { { it = Alternative p; at = p.at } }
  | ALT_PH { at $startpos $endpos ALT_placeholder }

(* §5.2 <parameter declaration> ::= [ VAR | PERS | INOUT ] <data type> <identifier>
   [ '{' ( '*' { ',' '*' } | <DIM> ) '}' ] | 'switch' <identifier> *)
parameter_declaration:
  | mode = access_mode data_type = data_type name = identifier array = array_part
    { match mode, data_type.it, array with
      | In, Ident s, Not_array when is_word "switch" s -> at $symbolstartpos $endpos (Switch name)
      | _ -> at $symbolstartpos $endpos (Parameter { mode; data_type; name; array }) }

(* REF: only installed routines have it (ch. 11); the lexer makes the word a token only when it
   reads the installed environment. *)
access_mode:
  | (* empty *) { In }
  | VAR { Var_mode }
  | PERS { Pers_mode }
  | INOUT { Inout }
  | REF { Ref_mode }

array_part:
  | (* empty *) { Not_array }
  | LBRACE STAR stars = preceded(COMMA, STAR)* RBRACE { Conformant (1 + List.length stars) }
  | LBRACE DIM_PH RBRACE { DIM_placeholder }

(* §5.4 <procedure declaration> ::= PROC <procedure name> '(' [ <parameter list> ] ')'
   <data declaration list> <statement list> [ BACKWARD <statement list> ]
   [ ERROR [ <error number list> ] <statement list> ] [ UNDO <statement list> ] ENDPROC *)
procedure_declaration:
  | PROC name = procedure_name LPAREN parameters = loption(parameter_list) RPAREN
    content = routine_content backward = preceded(BACKWARD, statement_list)?
    error = error_clause? undo = preceded(UNDO, statement_list)? ENDPROC
    { let (declarations, statements) = content in
      fun local -> Procedure_declaration { local; name; parameters;
        body = { declarations; statements; backward; error; undo } } }

(* §5.4 <procedure name> ::= <identifier> *)
procedure_name:
  | i = identifier { i }

(* §5.4 <data declaration list> <statement list>, with comments filed as §2.10 says: a comment
   that no data declaration follows belongs to the statement list. *)
routine_content:
  | cs = comments { ([], file_comments (fun c -> Statement_comment c) cs []) }
  | cs = comments d = data_declaration_item rest = routine_content
    { let (ds, ss) = rest in
      (file_comments (fun c -> Declaration_comment c) cs (d :: ds), ss) }
  | cs = comments s = statement_proper rest = statement_list
    { ([], file_comments (fun c -> Statement_comment c) cs (s :: rest)) }

(* §5.5 <function declaration> ::= FUNC <data type> <function name>
   '(' [ <parameter list> ] ')' <data declaration list> <statement list>
   [ ERROR [ <error number list> ] <statement list> ] [ UNDO <statement list> ] ENDFUNC *)
function_declaration:
  | FUNC return_type = data_type name = function_name
    LPAREN parameters = loption(parameter_list) RPAREN
    content = routine_content error = error_clause? undo = preceded(UNDO, statement_list)?
    ENDFUNC
    { let (declarations, statements) = content in
      fun local -> Function_declaration { local; return_type; name; parameters;
        body = { declarations; statements; backward = None; error; undo } } }

(* §5.5 <function name> ::= <identifier> *)
function_name:
  | i = identifier { i }

(* §5.6 <trap declaration> ::= TRAP <trap name> <data declaration list> <statement list>
   [ ERROR [ <error number list> ] <statement list> ] [ UNDO <statement list> ] ENDTRAP *)
trap_declaration:
  | TRAP name = trap_name content = routine_content error = error_clause?
    undo = preceded(UNDO, statement_list)? ENDTRAP
    { let (declarations, statements) = content in
      fun local -> Trap_declaration { local; name;
        body = { declarations; statements; backward = None; error; undo } } }

(* §5.6 <trap name> ::= <identifier> *)
trap_name:
  | i = identifier { i }

(* ERROR [ <error number list> ] <statement list> *)
error_clause:
  | ERROR error_numbers = error_number_list? handler = statement_list
    { { error_numbers; handler } }

(* §7.2 <error number list> ::= '(' <error number> { ',' <error number> } ')' *)
error_number_list:
  | LPAREN n = recovery_error_number ns = preceded(COMMA, recovery_error_number)* RPAREN
    { n :: ns }

(* §7.2 <error number> ::= <num literal> | <entire constant> | <entire variable>
   | <entire persistent>. Named apart from §4.11's <error number> ::= <expression>. *)
recovery_error_number:
  | n = NUM { at $startpos $endpos (Error_number_literal n) }
  | i = entire_variable { at $startpos $endpos (Error_number_name i) }
