(* The located syntax tree of a RAPID module (manual chapter 10).

   Each node is a [located] value: its content and the region of source it was read from.
   Constructors follow the grammar's rules and carry the manual's names; where chapter 10 has
   a rule that is told apart from another only by what a name is bound to (§3.6-§3.9), the tree
   has one constructor and the static semantics tells them apart. Comments are list elements,
   exactly where §2.10 puts them. Identifiers keep their spelling; reserved words do not (the
   printer writes them in upper case).

   Size. A CAD module is mostly calls with aggregates of numbers, and its tree stays alive
   while the module is checked and run, so the expression part of the tree is kept small
   (bench/README.md, "Memory: where it goes"):
   - a child whose region is held elsewhere gets no [located] record of its own: aggregate
     members and call arguments are two arrays (contents, regions), a unary operand and a
     required argument's expression are a pair of fields, and a reference that is an
     expression has the expression's region. [members], [arguments], [operand] and
     [reference] rebuild the [located] values, for the code that wants them;
   - nodes without a region are shared within a parse (Parse_context): short numeric
     literals, [Ident] and [Data_reference (Entire _)] nodes. Nothing may compare nodes by
     physical equality or mutate them.
   Every node still has its region. *)

type region = Source.region
type 'a located = { it : 'a; at : region }

(* §2.3 <ident>: a name as written. *)
type name = string located

(* §2.3 <identifier> ::= <ident> | <ID> *)
type identifier = identifier_desc located
and identifier_desc =
  | Ident of string
  | ID_placeholder

(* §2.5 <num literal>: the text as written; its exact value is [Literal_value.num_value]. *)
type num_literal = string

(* §2.7 <string literal>: [raw] is the text between the quotes as written; [bytes] is the
   value, UTF-8 with character codes replaced by the byte they name. *)
type string_literal = { raw : string; bytes : string }

(* §3.12 operators; the unary ones are the sign of a <simple expr> and NOT of an <expr>. *)
type unary_operator = Unary_plus | Unary_minus | Not
type binary_operator =
  | Mul | Div | Int_div | Modulo          (* <mulop>: * / DIV MOD *)
  | Plus | Minus                          (* <addop> *)
  | Less | Less_equal | Equal | Greater | Greater_equal | Not_equal   (* <relop> *)
  | And                                   (* <logical term> *)
  | Or | Xor                              (* <expr> *)

type expression = expression_desc located
and expression_desc =
  (* §3.5 <literal>: one constructor per kind of literal rather than a [Literal] wrapper, which
     cost a block per literal (a CAD module is mostly numeric literals; bench/README.md). *)
  | Num_literal of num_literal
  | String_literal of string_literal
  | Bool_literal of bool
  (* §3.6-§3.9. The reference's region is the expression's (a <primary> that is a reference is
     nothing else), so it has no [located] record of its own here; [reference] rebuilds one. *)
  | Data_reference of data_reference_desc
  | Function_call of function_call                    (* §3.11 *)
  (* §3.10. The members' contents and their regions in two arrays of the same length, rather
     than a list or array of [located] records: a member costs two words instead of four (a
     list cell cost three more), and aggregates of numbers are most of a CAD module
     (bench/README.md). Never empty. [members] gives the members as expressions. *)
  | Aggregate of expression_desc array * region array
  (* §3.1. The operand's contents and region, without a [located] record of their own: a
     negative number in an aggregate (-0.70711) costs two words less. [operand] rebuilds it. *)
  | Unary of unary_operator * expression_desc * region
  | Binary of binary_operator * expression * expression   (* §3.1 *)
  | EXP_placeholder                                   (* §3.1 <EXP> *)

(* §3.6 <variable>, and §3.7 <persistent>, §3.8 <constant>, §3.9 <parameter>, which follow it
   rule for rule. <VAR> stands for a data object reference where §4.5, §4.6 and §4.15 allow it. *)
and data_reference = data_reference_desc located
and data_reference_desc =
  (* <entire variable>: the name, whose region is the reference's own (they are the same
     stretch of text), so that the most common reference is not three records deep. *)
  | Entire of string
  | Element of name * expression list                 (* <variable element> *)
  | Component of data_reference * name                (* <variable component> *)
  | VAR_placeholder                                   (* <VAR> *)

(* §3.11 <function call> *)
and function_call = {
  func : identifier;
  arguments : argument_desc array;
  argument_regions : region array;
}

(* Argument lists are held like aggregates' members: contents and regions in two arrays, two
   words an argument where a list of [located] records took seven; CAD modules are mostly
   calls (bench/README.md). [arguments] gives them as [argument]s. *)

(* §3.11 and §4.6: required, optional and conditional arguments. The comma that may precede an
   optional or conditional argument is layout, not structure. *)
and argument = argument_desc located
and argument_desc =
  (* [ name ':=' ] expression; the expression's contents and region without a [located] record
     of their own, as in [Unary] ([argument_value] rebuilds it). *)
  | Required_argument of identifier option * expression_desc * region
  (* A required argument without a name whose region is its expression's: nearly every argument
     (not one in parentheses, "P (a);", whose region includes them). Two words instead of four;
     [required_argument] chooses the form, the dump does not tell them apart. *)
  | Positional_argument of expression_desc
  | Optional_argument of identifier * expression option    (* '\' name [ ':=' expression ] *)
  | Conditional_argument of identifier * data_reference    (* '\' name '?' parameter *)
  | ARG_placeholder                                         (* <ARG>, procedure calls only *)

(* §4.6 <procedure> *)
type procedure =
  | Procedure_name of identifier
  | Late_bound of expression                          (* '%' expression '%' *)

type statement = statement_desc located
and statement_desc =
  | Assignment of data_reference * expression         (* §4.5 *)
  | Procedure_call of procedure * argument_desc array * region array   (* §4.6 *)
  | Goto of identifier                                (* §4.7 *)
  | Break                                             (* §4.8 *)
  | Continue                                          (* §4.9 *)
  | Return of expression option                       (* §4.10 *)
  | Raise of expression option                        (* §4.11 *)
  | Exit                                              (* §4.12 *)
  | Retry                                             (* §4.13 *)
  | Trynext                                           (* §4.14 *)
  | Connect of data_reference * identifier            (* §4.15 *)
  | If of if_statement                                (* §4.16 *)
  | Compact_if of expression * statement              (* §4.17 *)
  | For of for_statement                              (* §4.18 *)
  | While of expression * statement list              (* §4.19 *)
  | Test of test_statement                            (* §4.20 *)
  | Label of identifier                               (* §4.4 *)
  | Statement_comment of string                       (* §2.10, text after '!' *)
  | SMT_placeholder                                   (* §2.9 *)

and if_statement = {
  condition : expression;
  then_branch : statement list;
  elseifs : elseif_clause list;
  else_branch : statement list option;
}
and elseif_clause = elseif_desc located
and elseif_desc =
  | Elseif of expression * statement list
  | EIT_placeholder

and for_statement = {
  loop_variable : identifier;
  from_ : expression;
  to_ : expression;
  step : expression option;
  body : statement list;
}

and test_statement = {
  test_expression : expression;
  cases : case_clause list;
  default : statement list option;
}
and case_clause = case_desc located
and case_desc =
  | Case of expression list * statement list
  | CSE_placeholder

(* §2.18 *)
type storage = Var | Pers | Const
type declaration_scope = Global | Local | Task

type data_declaration = data_declaration_desc located
and data_declaration_desc =
  | Data_declaration of {
      scope : declaration_scope;
      storage : storage;
      data_type : identifier;
      name : identifier;
      dims : expression list;          (* empty: not an array *)
      initial_value : expression option;
    }
  | Declaration_comment of string
  | DDN_placeholder

(* §2.11 - §2.15 *)
type record_component = record_component_desc located
and record_component_desc =
  | Record_component of identifier * identifier       (* data type, component name *)
  | Component_comment of string

type type_definition = type_definition_desc located
and type_definition_desc =
  | Record_definition of { local : bool; name : identifier; components : record_component list }
  | Alias_definition of { local : bool; base : identifier; name : identifier }
  | Type_comment of string
  | TDN_placeholder

(* §5.2 *)
type access_mode = In | Var_mode | Pers_mode | Inout | Ref_mode   (* REF: installed routines only (ch. 11) *)

type array_parameter =
  | Not_array
  | Conformant of int                                 (* '{' '*' { ',' '*' } '}' *)
  | DIM_placeholder

type parameter_declaration = parameter_declaration_desc located
and parameter_declaration_desc =
  | Parameter of {
      mode : access_mode;
      data_type : identifier;
      name : identifier;
      array : array_parameter;
    }
  | Switch of identifier

type alternative = alternative_desc located
and alternative_desc =
  | Alternative of parameter_declaration
  | ALT_placeholder

type parameter = parameter_desc located
and parameter_desc =
  | Required_parameter of parameter_declaration
  | Optional_parameter of alternative list            (* '\' alt { '|' alt } *)
  | PAR_placeholder

(* §7.2 <error number> of an error number list. *)
type recovery_error_number = recovery_error_number_desc located
and recovery_error_number_desc =
  | Error_number_literal of num_literal
  | Error_number_name of name

type error_handler = {
  error_numbers : recovery_error_number list option;   (* Some: an error recovery point *)
  handler : statement list;
}

type routine_body = {
  declarations : data_declaration list;
  statements : statement list;
  backward : statement list option;                   (* procedures only, §6.2 *)
  error : error_handler option;
  undo : statement list option;
}

(* §5.1 *)
type routine_declaration = routine_declaration_desc located
and routine_declaration_desc =
  | Procedure_declaration of {
      local : bool; name : identifier; parameters : parameter list; body : routine_body }
  | Function_declaration of {
      local : bool; return_type : identifier; name : identifier;
      parameters : parameter list; body : routine_body }
  | Trap_declaration of { local : bool; name : identifier; body : routine_body }
  | Routine_comment of string
  | RDN_placeholder

(* §9.2 *)
type module_attribute = module_attribute_desc located
and module_attribute_desc = SYSMODULE | NOVIEW | NOSTEPIN | VIEWONLY | READONLY

type module_declaration = {
  header : string list option;   (* the lines of a %%% header block (doc/dialect.md) *)
  prologue_comments : string list;   (* comment lines before MODULE, text after '!' (doc/dialect.md) *)
  module_name : identifier;
  attributes : module_attribute list;
  type_definitions : type_definition list;
  data_declarations : data_declaration list;
  routine_declarations : routine_declaration list;
  module_region : region;
}

(* The data reference that the expression [e], [Data_reference d], is. *)
let reference (e : expression) (d : data_reference_desc) : data_reference = { it = d; at = e.at }

(* The aggregate of the members [es] (§3.10), and back. *)
(* The two arrays of a list of located values, filled from the list itself: through an array of
   the records first, each list was copied three times (deeply nested aggregates have one a
   level). *)
let split_located (l : 'a located list) : 'a array * region array =
  match l with
  | [] -> ([||], [||])
  | first :: _ ->
      let n = List.length l in
      let its = Array.make n first.it and ats = Array.make n first.at in
      List.iteri (fun i x -> Array.unsafe_set its i x.it; Array.unsafe_set ats i x.at) l;
      (its, ats)

let aggregate (es : expression list) : expression_desc =
  let descs, regions = split_located es in
  Aggregate (descs, regions)

let members (descs : expression_desc array) (regions : region array) : expression array =
  Array.mapi (fun i it -> { it; at = regions.(i) }) descs

(* The expression a [Unary] node or a [Required_argument] holds as contents and region. *)
let operand (it : expression_desc) (at : region) : expression = { it; at }

(* The arguments [args] as a call holds them, and back. *)
let argument_arrays (args : argument list) : argument_desc array * region array = split_located args

let arguments (descs : argument_desc array) (regions : region array) : argument array =
  Array.mapi (fun i it -> { it; at = regions.(i) }) descs

let call_arguments (f : function_call) = arguments f.arguments f.argument_regions

(* The required argument [name := e] or [e] whose region is [at]. *)
let required_argument (name : identifier option) (e : expression) (at : region) : argument_desc =
  match name with
  | None when e.at = at -> Positional_argument e.it
  | _ -> Required_argument (name, e.it, e.at)

(* The expression an argument gives, if any: a required argument's, an optional one's value. *)
let argument_value (a : argument) : expression option =
  match a.it with
  | Required_argument (_, it, at) -> Some { it; at }
  | Positional_argument it -> Some { it; at = a.at }
  | Optional_argument (_, e) -> e
  | Conditional_argument _ | ARG_placeholder -> None
