open Rapid_syntax

(* §2.13 *)
type atomic_row = { atomic : Types.data_type; integer_min : Z.t; integer_max : Z.t }

let atomic_types = [
  { atomic = Num; integer_min = Z.of_int (-8388607); integer_max = Z.of_int 8388608 };
  { atomic = Dnum; integer_min = Z.of_string "-4503599627370496";
    integer_max = Z.of_string "4503599627370496" };
  { atomic = Bool; integer_min = Z.one; integer_max = Z.zero };
  { atomic = String; integer_min = Z.one; integer_max = Z.zero };
]

(* §2.14 *)
let builtin_records = [
  ("pos", [ ("x", "num"); ("y", "num"); ("z", "num") ]);
  ("orient", [ ("q1", "num"); ("q2", "num"); ("q3", "num"); ("q4", "num") ]);
  ("pose", [ ("trans", "pos"); ("rot", "orient") ]);
]

(* §2.15 *)
let builtin_aliases = [ ("errnum", "num"); ("intnum", "num") ]

(* §2.16 *)
type cell = Legal | Illegal | Not_applicable | Execution_error

type declaration_kind =
  | Constant
  | Persistent
  | Variable_initialised
  | Variable_uninitialised
  | Parameter_in
  | Parameter_var
  | Parameter_pers
  | Parameter_ref
  | Parameter_inout_var
  | Parameter_inout_pers
  | Function_return

let row value non_value semi_value =
  [ (Types.Value, value); (Types.Non_value, non_value); (Types.Semi_value, semi_value) ]

(* §2.16, object declarations: value, non-value, semi-value. *)
let declaration_table = [
  (Constant, row Legal Illegal Not_applicable);
  (Persistent, row Legal Illegal Not_applicable);
  (Variable_initialised, row Legal Illegal Not_applicable);
  (Variable_uninitialised, row Legal Legal Legal);
  (Parameter_in, row Legal Illegal Illegal);
  (Parameter_var, row Legal Legal Legal);
  (Parameter_pers, row Legal Illegal Illegal);
  (Parameter_ref, row Legal Legal Legal);
  (Parameter_inout_var, row Legal Illegal Illegal);
  (Parameter_inout_pers, row Legal Illegal Illegal);
  (Function_return, row Legal Illegal Illegal);
]

let declaration_cell kind cls = List.assoc cls (List.assoc kind declaration_table)

type reference_kind = Target | Argument | Expression_operand

(* §2.16, object references. Footnote ii: a semi-value object is used with its associated value
   type; footnote iii: non-value and semi-value arguments go to var or ref parameters only. *)
let reference_table = [
  (Target, row Legal Illegal Legal);
  (Argument, row Legal Legal Legal);
  (Expression_operand, row Legal Illegal Legal);
]

let reference_cell kind cls = List.assoc cls (List.assoc kind reference_table)

(* §2.22, §2.23 *)
type initial_value = Zero | False_value | Empty_string | All_bits_zero

let initial_value : Types.data_type -> initial_value option = function
  | Num | Dnum -> Some Zero
  | Bool -> Some False_value
  | String -> Some Empty_string
  | Installed_atomic _ -> Some All_bits_zero
  | Record _ | Anytype -> None

(* §3.12 *)
type operand = O_num | O_dnum | O_pos | O_orient | O_string | O_bool | O_any_value

type operator_note = Exact_integer | Integer_operands | Natural_operands | Alias_base_result

type binary_row = {
  op : Ast.binary_operator;
  operation : string;
  left : operand;
  right : operand;
  result : operand;
  notes : operator_note list;
}

let binary op operation left right result notes = { op; operation; left; right; result; notes }

(* The rows of §3.12 in the manual's order. The row "dnum + num" of the extraction is read as
   "dnum + dnum" (tables.md): every other dnum row takes two dnum operands, and the text says
   an operator on operands of types other than those listed is a type error. *)
let binary_operators = [
  binary Mul "multiplication" O_num O_num O_num [ Exact_integer ];
  binary Mul "multiplication" O_dnum O_dnum O_dnum [ Exact_integer ];
  binary Mul "scalar vector product" O_num O_pos O_pos [];
  binary Mul "scalar vector product" O_pos O_num O_pos [];
  binary Mul "cross product" O_pos O_pos O_pos [];
  binary Mul "linking of rotations" O_orient O_orient O_orient [];
  binary Div "division" O_num O_num O_num [];
  binary Div "division" O_dnum O_dnum O_dnum [];
  binary Div "scalar vector division" O_pos O_num O_pos [];
  binary Int_div "integer division" O_num O_num O_num [ Integer_operands ];
  binary Int_div "integer division" O_dnum O_dnum O_dnum [ Natural_operands ];
  binary Modulo "integer modulo" O_num O_num O_num [ Integer_operands ];
  binary Modulo "integer modulo" O_dnum O_dnum O_dnum [ Natural_operands ];
  binary Plus "addition" O_num O_num O_num [ Exact_integer ];
  binary Plus "addition" O_dnum O_dnum O_dnum [ Exact_integer ];
  binary Plus "vector addition" O_pos O_pos O_pos [];
  binary Plus "string concatenation" O_string O_string O_string [];
  binary Minus "subtraction" O_num O_num O_num [ Exact_integer ];
  binary Minus "subtraction" O_dnum O_dnum O_dnum [ Exact_integer ];
  binary Minus "vector subtraction" O_pos O_pos O_pos [];
  binary Less "less than" O_num O_num O_bool [];
  binary Less "less than" O_dnum O_dnum O_bool [];
  binary Less_equal "less than or equal to" O_num O_num O_bool [];
  binary Less_equal "less than or equal to" O_dnum O_dnum O_bool [];
  binary Equal "equal to" O_any_value O_any_value O_bool [];
  binary Greater_equal "greater than or equal to" O_num O_num O_bool [];
  binary Greater_equal "greater than or equal to" O_dnum O_dnum O_bool [];
  binary Greater "greater than" O_num O_num O_bool [];
  binary Greater "greater than" O_dnum O_dnum O_bool [];
  binary Not_equal "not equal to" O_any_value O_any_value O_bool [];
  binary And "and" O_bool O_bool O_bool [];
  binary Xor "exclusive or" O_bool O_bool O_bool [];
  binary Or "or" O_bool O_bool O_bool [];
]

type unary_row = {
  unary : Ast.unary_operator;
  unary_operation : string;
  operand : operand;
  unary_result : operand;
  unary_notes : operator_note list;
}

let unary unary unary_operation operand unary_result unary_notes =
  { unary; unary_operation; operand; unary_result; unary_notes }

let unary_operators = [
  unary Unary_plus "unary plus; keep sign" O_num O_num [ Exact_integer; Alias_base_result ];
  unary Unary_plus "unary plus; keep sign" O_dnum O_dnum [ Exact_integer; Alias_base_result ];
  unary Unary_plus "unary plus; keep sign" O_pos O_pos [ Alias_base_result ];
  unary Unary_minus "unary minus; change sign" O_num O_num [ Exact_integer; Alias_base_result ];
  unary Unary_minus "unary minus; change sign" O_dnum O_dnum [ Exact_integer; Alias_base_result ];
  unary Unary_minus "unary minus; change sign" O_pos O_pos [ Alias_base_result ];
  unary Not "negation" O_bool O_bool [];
]

let operator_symbol : Ast.binary_operator -> string = function
  | Mul -> "*" | Div -> "/" | Int_div -> "DIV" | Modulo -> "MOD" | Plus -> "+" | Minus -> "-"
  | Less -> "<" | Less_equal -> "<=" | Equal -> "=" | Greater -> ">" | Greater_equal -> ">="
  | Not_equal -> "<>" | And -> "AND" | Or -> "OR" | Xor -> "XOR"

let unary_symbol : Ast.unary_operator -> string = function
  | Unary_plus -> "+" | Unary_minus -> "-" | Not -> "NOT"

(* §5.2 *)
type access_mode = Mode_in | Mode_var | Mode_pers | Mode_inout | Mode_ref

type argument_kind =
  | Arg_constant
  | Arg_readonly_variable
  | Arg_variable
  | Arg_persistent
  | Arg_parameter_in
  | Arg_parameter_var
  | Arg_parameter_pers
  | Arg_parameter_inout
  | Arg_other_expression

let modes in_ var pers inout ref =
  [ (Mode_in, in_); (Mode_var, var); (Mode_pers, pers); (Mode_inout, inout); (Mode_ref, ref) ]

(* The manual's rows "parameter: inout var" and "parameter: inout pers" differ only in the var
   and pers columns, where one binding is legal and the other an execution error: folded, both
   cells are execution errors, decided when the call runs. *)
let access_table = [
  (Arg_constant, modes Legal Illegal Illegal Illegal Legal);
  (Arg_readonly_variable, modes Legal Illegal Illegal Illegal Legal);
  (Arg_variable, modes Legal Legal Illegal Legal Legal);
  (Arg_persistent, modes Legal Illegal Legal Legal Legal);
  (Arg_parameter_in, modes Legal Legal Illegal Legal Legal);
  (Arg_parameter_var, modes Legal Legal Illegal Legal Legal);
  (Arg_parameter_pers, modes Legal Illegal Legal Legal Legal);
  (Arg_parameter_inout, modes Legal Execution_error Execution_error Legal Legal);
  (Arg_other_expression, modes Legal Illegal Illegal Illegal Illegal);
]

let access_cell kind mode = List.assoc mode (List.assoc kind access_table)

(* §9.2 *)
let attribute_order : Ast.module_attribute_desc list =
  [ SYSMODULE; NOVIEW; NOSTEPIN; VIEWONLY; READONLY ]

let attribute_exclusions : (Ast.module_attribute_desc * Ast.module_attribute_desc) list =
  [ (NOVIEW, NOSTEPIN); (NOVIEW, VIEWONLY); (NOVIEW, READONLY); (VIEWONLY, READONLY) ]

let attribute_name : Ast.module_attribute_desc -> string = function
  | SYSMODULE -> "SYSMODULE" | NOVIEW -> "NOVIEW" | NOSTEPIN -> "NOSTEPIN"
  | VIEWONLY -> "VIEWONLY" | READONLY -> "READONLY"

(* ch. 13 *)
type level = Own_routine | Own_module | Global_in_program | Installed

type place =
  | Routine_in_user_module
  | Module_level_in_user_module
  | Routine_in_installed_module
  | Module_level_in_installed_module
  | Installed_object

let lookup_order = [
  (Routine_in_user_module, [ Own_routine; Own_module; Global_in_program; Installed ]);
  (Module_level_in_user_module, [ Own_module; Global_in_program; Installed ]);
  (Routine_in_installed_module, [ Own_routine; Own_module; Installed ]);
  (Module_level_in_installed_module, [ Own_module; Installed ]);
  (Installed_object, [ Installed ]);
]
