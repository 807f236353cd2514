(** The tables of the RAPID kernel manual that the static semantics uses, as data, cell by cell
    (../shared/reference/tables.md). The judgement reads them; test/test_tables.ml checks every
    cell. *)

(** {1 §2.13 Atomic built-in types} *)

type atomic_row = {
  atomic : Types.data_type;
  integer_min : Z.t;   (** the exact integer sub-domain (§2.13) *)
  integer_max : Z.t;
}

val atomic_types : atomic_row list
(** num, dnum, bool, string; the last two have an empty integer sub-domain (min > max). *)

(** {1 §2.14, §2.15 Built-in records and aliases} *)

val builtin_records : (string * (string * string) list) list
(** pos, orient, pose and their components (name, type name), in order. *)

val builtin_aliases : (string * string) list
(** errnum and intnum, both aliases of num. *)

(** {1 §2.16 Value classes} *)

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

val declaration_table : (declaration_kind * (Types.value_class * cell) list) list
(** Which object declarations are legal for which value class (§2.16, first table). *)

val declaration_cell : declaration_kind -> Types.value_class -> cell

type reference_kind =
  | Target                  (** target of an assignment or connect statement *)
  | Argument                (** an argument; non-value and semi-value only to var or ref *)
  | Expression_operand      (** an object used in an expression *)

val reference_table : (reference_kind * (Types.value_class * cell) list) list
(** §2.16, second table. For semi-value objects as target and in expressions the cell is
    legal with the associated value type; for non-value and semi-value arguments it is legal
    only for var and ref parameters: the judgement applies both footnotes. *)

val reference_cell : reference_kind -> Types.value_class -> cell

(** {1 §2.22, §2.23 Initial values} *)

type initial_value = Zero | False_value | Empty_string | All_bits_zero

val initial_value : Types.data_type -> initial_value option
(** For atomic types (records and arrays are component-wise and element-wise); [None] for a
    record or anytype. *)

(** {1 §3.12 Operators} *)

type operand =
  | O_num | O_dnum | O_pos | O_orient | O_string | O_bool
  | O_any_value    (** = and <>: any value type, both operands of equal type *)

type operator_note =
  | Exact_integer       (** (a) integer representation kept in the sub-domain *)
  | Integer_operands    (** (b) operands must represent integer values *)
  | Natural_operands    (** (c) operands must represent integer values >= 0 *)
  | Alias_base_result   (** (d) an alias operand gives a result of the base type *)

type binary_row = {
  op : Rapid_syntax.Ast.binary_operator;
  operation : string;           (** the manual's name of the operation *)
  left : operand;
  right : operand;
  result : operand;
  notes : operator_note list;
}

val binary_operators : binary_row list

type unary_row = {
  unary : Rapid_syntax.Ast.unary_operator;
  unary_operation : string;
  operand : operand;
  unary_result : operand;
  unary_notes : operator_note list;
}

val unary_operators : unary_row list

val operator_symbol : Rapid_syntax.Ast.binary_operator -> string
val unary_symbol : Rapid_syntax.Ast.unary_operator -> string

(** {1 §5.2 Access modes} *)

type access_mode = Mode_in | Mode_var | Mode_pers | Mode_inout | Mode_ref

type argument_kind =
  | Arg_constant
  | Arg_readonly_variable      (** FOR loop variable, ERRNO, INTNO *)
  | Arg_variable
  | Arg_persistent
  | Arg_parameter_in
  | Arg_parameter_var
  | Arg_parameter_pers
  | Arg_parameter_inout        (** an inout parameter: its binding is known only at run time *)
  | Arg_other_expression

val access_table : (argument_kind * (access_mode * cell) list) list
(** The table of §5.2, with the two rows for an inout parameter folded into one: its cells are
    legal where both bindings are legal and [Execution_error] where one binding is legal and the
    other an execution error. *)

val access_cell : argument_kind -> access_mode -> cell

(** {1 §9.2 Module attributes} *)

val attribute_order : Rapid_syntax.Ast.module_attribute_desc list
(** SYSMODULE, NOVIEW, NOSTEPIN, VIEWONLY, READONLY: the order attributes must be written in. *)

val attribute_exclusions :
  (Rapid_syntax.Ast.module_attribute_desc * Rapid_syntax.Ast.module_attribute_desc) list
(** Pairs that may not appear together. *)

val attribute_name : Rapid_syntax.Ast.module_attribute_desc -> string

(** {1 ch. 13 Look-up order} *)

type level = Own_routine | Own_module | Global_in_program | Installed

type place =
  | Routine_in_user_module       (** a routine declared in a user or system module *)
  | Module_level_in_user_module  (** data or routine declared there (module level) *)
  | Routine_in_installed_module  (** a routine declared in a user-installed module *)
  | Module_level_in_installed_module
  | Installed_object

val lookup_order : (place * level list) list
(** The levels searched, in order, for a name used at each place. *)
