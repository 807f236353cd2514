(* The program the machine runs: the syntax tree after the static semantics, with every name
   resolved to where its object lives (a slot of the routine's activation or of the task's
   module data), every operator to its row of §3.12, every argument to its parameter. Nodes
   keep their source region for errors and the trace. *)

open Rapid_syntax

type region = Source.region

(* Where a data object lives. *)
type slot =
  | Local of int            (* the current activation: parameters, routine data, loop variables *)
  | Global of int           (* module data of the task, and the installed data *)

(* A reference to a data object or a part of it (§3.6-§3.9). *)
type place =
  | Whole of slot
  | Element of place * expr array           (* indexes, each num *)
  | Component of place * int                 (* component index in its record *)
  | Unresolved of string                     (* a name that was neither declared nor installed *)

and expr = { e : expr_desc; at : region }

and expr_desc =
  | Literal of Value.t
  | Read of place                            (* a data object's value *)
  | Read_signal of place                     (* a semi-value object in value context (§2.16) *)
  | Unary of Arith.unary * expr
  | Binary of Arith.binary * expr * expr
  | And of expr * expr                       (* short-circuit, §3.1 *)
  | Or of expr * expr
  | Aggregate of expr array * aggregate_kind
  | Call of call                             (* a function call, §3.11 *)
  | Placeholder                              (* <EXP>: executing it is ERR_EXECPHR (§2.9) *)
  | Fitted of expr * Value.shape             (* an aggregate argument of a late-bound call: it
                                                takes its parameter's type if it fits (§3.10) *)

and aggregate_kind = Record_value | Array_value

(* How each parameter of the callee gets its argument (§5.2): the callee's parameters are
   numbered in declaration order, alternatives included. *)
and argument =
  | Absent                                   (* an optional parameter left out *)
  | Present_switch                           (* \switch *)
  | By_value of expr                         (* in parameter: a copy *)
  | By_reference of place * reference_kind   (* var, pers, inout, ref: an alias *)
  | Pass_on of slot                          (* \p ? x: present iff x is (§3.11) *)

and reference_kind = Ref_variable | Ref_persistent | Ref_constant | Ref_other

and call = {
  callee : routine_ref;
  arguments : argument array;                (* one per parameter of the callee *)
  call_at : region;
}

and routine_ref =
  | Routine of int                           (* index in the program's routine table *)
  | Unknown_routine of string                (* neither declared nor installed *)

type stmt = { s : stmt_desc; sat : region }

and stmt_desc =
  | Assign of place * expr
  | Call_procedure of call
  | Call_late of expr * late_argument array  (* % e % args: bound when it runs (§4.6) *)
  | Goto of int * int                        (* the label's statement list and index in it *)
  | Break
  | Continue
  | Return of expr option
  | Raise of expr option
  | Exit
  | Retry
  | Trynext
  | Connect of place * int                   (* the trap's routine index *)
  | If of expr * block * block
  | Elseif of expr * block * block           (* an ELSEIF clause: part of its IF statement, which
                                                RETRY and TRYNEXT refer to (§4.13, §4.16) *)
  | Compact_if of expr * stmt                (* one statement with its condition (§4.17) *)
  | For of for_loop
  | While of expr * block
  | Test of expr * (expr array * block) array * block
  | Label                                    (* a "no-operation" statement (§4.4) *)
  | Placeholder_statement                    (* <SMT> *)

(* A statement list, with an identity for GOTO. *)
and block = { id : int; body : stmt array }

and for_loop = {
  variable : int;                            (* local slot of the loop variable *)
  from_ : expr;
  to_ : expr;
  step : expr option;
  loop_body : block;
}

and late_argument = {
  late_name : string option;                 (* for optional and named arguments *)
  late_optional : bool;                      (* written \name: an optional, switch or conditional
                                                argument, bound by name (§3.11) *)
  late_value : late_value;
  late_kind : reference_kind;                (* what a data reference argument denotes *)
  late_type : late_type;                     (* what the call's parameter must be (§5.2) *)
  late_read_only : bool;                     (* a loop variable, ERRNO, INTNO (§5.2 table, i) *)
}

and late_value =
  | Late_expr of expr
  | Late_switch
  | Late_conditional of slot option          (* \p ? x: x's slot, [None] for an unknown name *)

(* The static type of a late-bound argument, which the binding compares with the parameter's
   when the call runs (§3.11, §5.2: equal types). *)
and late_type =
  | Late_typed of Rapid_typing.Types.object_type
  | Late_numeric of expr                     (* a numeric literal expression: its dnum reading,
                                                for a dnum parameter (§2.5, R-2.5-b) *)
  | Late_untyped                             (* an aggregate (typed by its parameter, §3.10), or
                                                a name neither declared nor installed *)

type routine_kind = Procedure | Function | Trap

type parameter = {
  p_name : string;
  p_mode : Rapid_typing.Tables.access_mode;
  p_optional : bool;
  p_switch : bool;
  p_default : Value.shape;                   (* shape of an absent parameter's type *)
  p_type : Rapid_typing.Types.object_type option;  (* [None] for a switch *)
  p_group : int;                             (* optional parameters: the alternatives of one
                                                slot share it (§5.2); -1 for a required one *)
}

(* An error number of an error recovery point (§7.2): a literal, or a data object read when the
   error arrives (a number booked with BookErrNo at run time). *)
type recovery_number = Number of int | Object of slot

type error_handler = {
  recovery : recovery_number list option;    (* an error recovery point's numbers (§7.2) *)
  all_errors : bool;                         (* LONG_JMP_ALL_ERR in the list *)
  handler : block;
}

type routine = {
  name : string;
  module_name : string;
  kind : routine_kind;
  parameters : parameter array;
  locals : int;                              (* slots of an activation, parameters first *)
  local_inits : (int * init) list;           (* routine data, initialised at each call (§2.21) *)
  body : block;
  backward : block option;
  error : error_handler option;
  undo : block option;
  primitive : string option;                 (* an installed routine bound to a primitive *)
  stub_result : Value.shape option;          (* a function's result type, whose initial value is what
                                                --stub-unmodelled returns (§2.22) *)
  local : bool;                              (* LOCAL: visible in its module only (§5.3) *)
  at : region;
  nostepin : bool;                           (* of a NOSTEPIN (or NOVIEW) module: below the user
                                                level (§7.3, §9.4, R-9.4-a) *)
}

(* The initial value of a data object: a constant expression, or the type's initial value
   (§2.22, §2.23). *)
and init = Init_expr of expr | Init_default of Value.shape

type global = {
  g_name : string;
  g_module : string;
  g_init : init;
  g_read_only : bool;                        (* ERRNO, INTNO (ch. 12) *)
  g_at : region;                             (* its declaration, for a memory budget exceeded *)
}

(* The static types of the data references a call gives for anytype parameters, by the name of
   the type (aliases replaced, §2.15), one entry per parameter ([None]: no such argument): the
   RAPID Message Queue sends data with its type's name and receives it by that name (ABB's
   RMQSendMessage, RMQGetMsgData; doc/rulings.md R-14-rmq4). The key is the call's arguments
   array, which the lowering makes once per call and the engines pass on as they find it in the
   call: compared physically. *)
module Argument_types = Hashtbl.Make (struct
    type t = argument array
    let equal = ( == )
    let hash = Hashtbl.hash
  end)

type program = {
  routines : routine array;
  globals : global array;
  errno : int;                               (* the global slot of ERRNO *)
  intno : int;
  error_numbers : (string * int) list;       (* ERR_ names of the installed environment *)
  entry_points : (string * int) list;        (* procedures without parameters, by name *)
  names : names;                             (* for the trace only: the machine never reads them *)
  argument_types : string option array Argument_types.t;
}

(* The names a trace writes places with: the lowering resolves names to slots and components to
   indexes, so it keeps the names beside the program for rapid-sem trace. *)
and names = {
  local_names : string array array;          (* per routine: the name of each local slot *)
  component_names : (name_key, string) Hashtbl.t;
  argument_texts : string Source.Table.t;
      (* an in argument that is no data name (Offs(p, 0, 0, 50), a local's name), as written, by
         the region of its expression: what the motion's output names a programmed point by *)
}

(* A component of a data object: the routine whose activation holds it (-1 for module data),
   the object's slot, and the path from it: component indexes, -1 for an array element. *)
and name_key = int * slot * int list
