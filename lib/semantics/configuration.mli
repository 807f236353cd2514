(* The configuration of the machine (doc/semantics.md, "Configuration"): the control (a focus:
   an expression, statement or place, a value, an error in flight), the store (module data and
   the activations of routines), and a flat stack of continuation frames, one per pending piece
   of work. Types only, shared by every part of the machine (Store, Recovery, Calls, Waits,
   Statements, Backward, Machine), which is why they are in an interface of their own with no
   implementation; outside lib/semantics the configuration is abstract (Machine.config).

   The stack is an immutable list of frames, so that capturing "the statement that caused the
   error" for RETRY and TRYNEXT (§7.1) is keeping a pointer; the few expression frames that
   accumulate values (aggregates, arguments) are mutable, and are never captured: RETRY
   restarts a statement from the beginning. *)

open Rapid_syntax

type loc = { box : Value.t array; idx : int }

(* An error in flight: [chain] is the call chain where it occurred, innermost first, which the
   system error handler reports even after the error has been propagated: computed only then,
   so that raising an error costs O(1) at any call depth. [about] is the name the error is
   about (the unknown data object or routine, the function without RETURN). *)
type err = { name : string; number : int; err_at : Source.region; searched : bool;
             chain : string list Lazy.t; about : string option;
             asynchronous : bool  (* §7.4: TRYNEXT executes as RETRY *) }

type activation = {
  routine : Ir.routine;
  slots : loc array;
  present : bool array;                 (* per parameter *)
  kinds : Ir.reference_kind array;      (* per parameter: what an alias parameter denotes *)
  module_data : bool array;             (* per parameter: the alias denotes module data (§4.15) *)
  caller : activation option;
  recovery_up : activation option;      (* the nearest caller with an error recovery point (§7.2) *)
  mutable memory : int;                 (* bytes of RAPID data this activation holds *)
  return_to : frame list;               (* the caller's stack at the call *)
  caller_mark : frame list;
  call_depth : int;
  mutable handling : handling;
  mutable retries : int;
  mutable retried : Ir.stmt option;
  trap_level : bool;                    (* a trap, or a routine a trap called (§7.2, ch. 8) *)
  mutable resume : activation option;
      (* RaiseToUser \Continue (§7.3): the NOSTEPIN routine whose error this routine's handler
         handles at user level; RETRY and TRYNEXT there go on in it *)
}

and handling =
  | Body
  | In_handler of err * frame list      (* the error, and the stack at the statement that caused it *)
  | In_undo

(* What comes after an UNDO handler, or after abandoning a routine that has none. *)
and after_abandon =
  | Go_on_exit                          (* EXIT: abandon every routine (§4.12, §7.2) *)
  | Go_on_exit_cycle                    (* ExitCycle: abandon every routine, start the entry again *)
  | Go_on_propagate of err              (* raise the error again at the call point (§7.1) *)
  | Go_on_long_jump of err * activation (* unwind down to the error recovery point (§7.2) *)
  | Go_on_in_handler of Ir.stmt * activation
      (* §7.4: a handler that took an asynchronous error ends with RAISE or RETURN: the
         program pointer's routines above it are abandoned, then the statement runs there *)

and frame =
  | K_seq of Ir.block * int             (* the rest of a statement list *)
  | K_stmt of Ir.stmt * frame list      (* a statement in progress, and the previous mark *)
  | K_assign_value of Ir.expr
  | K_assign_store of loc
  | K_if of Ir.block * Ir.block
  | K_compact_if of Ir.stmt
  | K_while_test of Ir.expr * Ir.block
  | K_while_body of Ir.expr * Ir.block
  | K_for_from of Ir.for_loop
  | K_for_to of Ir.for_loop * Value.t                   (* FROM evaluated *)
  | K_for_step of Ir.for_loop * Value.t * Value.t           (* FROM and TO evaluated *)
  | K_for_body of Ir.for_loop * Value.t * Value.t           (* TO and STEP: the body runs *)
  | K_test_subject of (Ir.expr array * Ir.block) array * Ir.block
  | K_test_value of Value.t * (Ir.expr array * Ir.block) array * Ir.block * int * int
  | K_return_value
  | K_raise_value
  | K_connect_target of int * Ir.place
  | K_fit of Value.shape                (* an aggregate argument takes its parameter's type *)
  | K_late_name of Ir.late_argument array * Source.region
  | K_read
  | K_unary of Arith.unary * Ir.expr               (* the whole expression, for the trace *)
  | K_binary_left of Arith.binary * Ir.expr * Ir.expr   (* the right operand; the whole *)
  | K_binary_right of Arith.binary * Value.t * Ir.expr
  | K_and of Ir.expr
  | K_or of Ir.expr
  | K_aggregate of Ir.expr array * Value.t array * int * Ir.aggregate_kind
  | K_component of int
  | K_element_base of Ir.expr array * Source.region
  | K_element_index of loc * Ir.expr array * int * Source.region
  | K_args of call_state
  | K_local_init of activation * (int * Ir.init) list
  | K_routine_end                       (* falling off the end of a routine body *)
  | K_handler_end                       (* falling off the end of an error handler (§7.1) *)
  | K_undo_end of after_abandon
  | K_task_end
  | K_wait of wait_state                (* a waiting instruction (doc/controller.md) *)
  | K_poll of wait_state                (* WaitUntil: its condition is being evaluated *)
  | K_read_signal
  | K_backward_end                      (* the end of a BACKWARD handler's run (ch. 6) *)

and wait_state = { wait : Rapid_observable.Wait.t; cond : Ir.expr option; mutable next_poll : float }

and call_state = {
  call : Ir.call;
  callee : Ir.routine;
  args_slots : loc array;
  args_present : bool array;
  args_kinds : Ir.reference_kind array;
  args_module_data : bool array;
  mutable args_memory : int;            (* bytes of the in arguments' copies *)
  primitive_args : Argument.t array;
  mutable next : int;
}

(* §7.4: an asynchronous error handled while the program pointer is elsewhere keeps the program
   pointer where it was: [handler] runs its error handler, and RETRY or TRYNEXT there resume
   [pp_act] with its stack as they were. *)
type kept = { handler : activation; pp_act : activation; pp_stack : frame list; pp_mark : frame list }

type focus =
  | F_expr of Ir.expr
  | F_value of Value.t
  | F_place of Ir.place
  | F_loc of loc
  | F_stmt of Ir.stmt
  | F_next
  | F_raise of err
  | F_search of err * activation option (* the long-jump search of §7.2 *)
  | F_abandon of after_abandon          (* leave the current activation, running its UNDO *)
  | F_done of Outcome.t

(* What an event routine the debugger interposes (a STEP, START, RESTART or STOP routine of a
   controller backup, doc/rulings.md R-bk-11) finds and gives back: the task's control as it
   stood. *)
type resume = {
  r_act : activation; r_stack : frame list; r_mark : frame list; r_focus : focus; r_unmarked : bool;
  r_kept : kept list; r_charged : bool; r_held : (int * int) option; r_phases : (Ir.routine * bool) list;
  r_at_entry : bool;
}

and config = {
  program : Ir.program;
  limits : Limits.t;
  globals : loc array;
  mutable act : activation;
  mutable stack : frame list;
  mutable mark : frame list;            (* the stack at the innermost statement in progress *)
  mutable focus : focus;
  mutable count : int;
  mutable memory : int;                 (* bytes of RAPID data: module data and activations *)
  by_name : (string, int list) Hashtbl.t * (string, int list) Hashtbl.t;
      (* routines by lower-case name, for late binding: the leading routines shared with other
         programs (the installed ones), then the program's own (Calls.routines_named) *)
  (* Later issues: the user execution level, the motion queue, other tasks. The trap level is
     the activation's; the interrupt numbers and queue are the world's. *)
  mutable unmarked : bool;              (* the next statement is part of a compact IF (§4.17) *)
  host : Host.t;                        (* the world around the program: its controller and motion *)
  stub_unmodelled : bool;               (* --stub-unmodelled: unmodelled routines are no-ops *)
  stubbed : (string, unit) Hashtbl.t;   (* the routines already reported as stubbed *)
  move_owners : (int, activation) Recent.t;  (* recent moves and the activation that ran each *)
  mutable kept : kept list;             (* asynchronous errors in their handlers (§7.4) *)
  mutable backward_depth : int;         (* the call depth of a BACKWARD handler running, or -1 (ch. 6) *)
  (* Settling stops at a point of response (ch. 8) where something happens: the statement time
     already charged there, the interrupt already taken from the queue, for the step to serve. *)
  mutable charged : bool;
  mutable held : (int * int) option;
  (* ch. 14: one of several tasks on one clock: a wait with nothing to do yields to the other
     tasks (the scheduler moves the clock) instead of moving the clock itself. *)
  cooperative : bool;
  mutable wake : float option;          (* the time the last wait-yield gave, if any *)
  observe : bool;                       (* the run observes store writes, arguments, values (schema rapid-sem/2) *)
  mutable entered : bool;               (* the entry routine's routine-entered has been said *)
  mutable propagated : bool;            (* the error in focus arrives by propagation (§7.1) *)
  (* A controller backup's event routines (doc/rulings.md R-bk-8): the routines the task runs
     after the current one, each with whether it is the entry routine; whether the current one
     is. *)
  mutable phases : (Ir.routine * bool) list;
  mutable at_entry : bool;
  mutable resumes : resume list;        (* the control an interposed event routine gives back *)
}
