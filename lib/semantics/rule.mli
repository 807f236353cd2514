(** The rules of the machine: one constructor per rule of doc/semantics.md ("Rules", and
    "Backward execution"), named as the doc names it ([wait-start] is [Wait_start]), grouped as
    the doc groups them, with the manual's sections. A step answers the rule it applied as a
    constructor, so that a misspelt rule does not compile; [name] gives the doc's name, the
    string [Machine.step] answers, the trace prints and the fuzzer counts. A module of its own
    so that every part of the machine names the rules alike and [all] is derived from the type
    in one place. *)

type t =
  (* Statement lists and statements (§4.1-§4.3) *)
  | Label                           (** §4.4 *)
  | Execute_placeholder             (** §2.9 *)
  (* Assignment (§4.5) *)
  | Assign
  | Store
  | Store_signal                    (** §2.16 *)
  (* Expressions (§3.1-§3.12) *)
  | Read
  | Read_place
  | Read_signal                     (** §2.16 *)
  | Signal_value
  | Signal_not_connected
  | Unary_operand                   (** §3.12 *)
  | Unary
  | Binary_operands                 (** §3.1, §3.12 *)
  | Binary
  | Binary_error
  | And                             (** §3.1 *)
  | And_short
  | And_right
  | Or
  | Or_short
  | Or_right
  | Aggregate_first                 (** §3.10 *)
  | Aggregate_next
  | Aggregate
  (* Places (§3.6-§3.9) *)
  | Element                         (** §3.6 *)
  | Index_next
  | Place_absent                    (** §5.2 *)
  | Index_out_of_bounds
  | Index_not_integer               (** R-3.6 *)
  | Place_unknown
  (* Calls (§3.11, §4.6, §5.2-§5.6) *)
  | Call_arguments                  (** §5.2 *)
  | Argument_alias
  | Argument_reference
  | Argument_alias_refused
  | Argument_pass_on_duplicate      (** §3.11, §5.2, ch. 12 *)
  | Argument_aggregate              (** §3.10, §4.6 *)
  | Argument_fit
  | Argument_fit_refused
  | Call_enter                      (** §2.21 *)
  | Local_initial_value             (** §2.21, §2.22 *)
  | Call_depth_exceeded             (** §1.4 *)
  | Memory_exhausted                (** §1.4 *)
  | Call_primitive
  | Call_primitive_error
  | Call_primitive_stop
  | Call_primitive_exit_cycle       (** ExitCycle, R-13-exitcycle1 *)
  | Call_not_modelled
  | Call_stubbed                    (** R-13-i *)
  | Call_unknown
  | Call_unknown_function
  | Call_late                       (** §4.6 *)
  | Call_late_unknown
  | Call_late_mismatch
  | Call_by_var
  | Call_by_var_unknown
  | Call_by_var_mismatch
  | Return_value                    (** §4.10 *)
  | Return_procedure
  | Return_function
  | Return_entry
  | Function_no_return              (** §5.5 *)
  (* Control (§4.7-§4.20) *)
  | Goto                            (** §4.7 *)
  | Break                           (** §4.8 *)
  | Continue                        (** §4.9 *)
  | If                              (** §4.16 *)
  | If_true
  | If_false
  | Elseif                          (** §4.16, §4.13, §4.14 *)
  | Compact_if                      (** §4.17 *)
  | Compact_if_true
  | Compact_if_false
  | While                           (** §4.19 *)
  | While_true
  | While_false
  | While_again
  | For                             (** §4.18 *)
  | For_enter
  | For_empty
  | For_step
  | For_done
  | Test                            (** §4.20 *)
  | Test_subject
  | Test_next
  | Test_match
  | Test_default
  | Connect                         (** §4.15 *)
  | Connect_allocate
  | Connect_again
  | Connect_inomax
  | Connect_not_variable            (** §4.15, ch. 12 *)
  | Exit                            (** §4.12 *)
  (* The controller: time, waits and interrupts (ch. 8, doc/controller.md) *)
  | Time_limit
  | Interrupt_serve                 (** ch. 8 *)
  | Trap_end
  | Raise_in_trap                   (** R-8-e *)
  | Wait_start
  | Wait_done
  | Wait_timeout
  | Wait_advance
  | Wait_yield                      (** ch. 14 *)
  | Wait_poll
  | Wait_poll_true
  | Wait_poll_false
  | Wait_deadlock
  | Wait_time_limit
  | Async_error                     (** §7.4, §7.6 *)
  | Async_error_unhandled           (** §7.6 step 5 *)
  | Async_retry_resume              (** §7.4 *)
  | Async_trynext_resume
  | Async_handler_leave
  | Async_exit
  | Async_error_at_move
  (* Errors (ch. 7) *)
  | Raise_number                    (** §4.11 *)
  | Raise
  | Raise_illegal
  | Raise_handle                    (** §7.1 *)
  | Raise_in_handler
  | Raise_unhandled
  | Longjump_search_start           (** §7.1, §7.2 *)
  | Longjump_search
  | Longjump_found
  | Raise_propagate
  | Raise_again                     (** §4.11, §7.1 *)
  | Raise_again_unhandled
  | Raise_new                       (** §4.11, §7.1; the dialect's, R-4.11-handler1 *)
  | Raise_new_unhandled
  | Abandon                         (** §7.2, §1.2 *)
  | Abandon_entry
  | Undo_run
  | Undo_done
  | Undo_done_entry
  | Cycle_restart                   (** R-13-exitcycle1 *)
  | Retry                           (** §4.13 *)
  | Retry_limit                     (** §7.1 *)
  | Trynext                         (** §4.14 *)
  | Handler_end                     (** §7.1 *)
  (* The user level: NOSTEPIN routines and RaiseToUser (§7.3) *)
  | Raise_to_user_break_off         (** R-7.3-q *)
  | Raise_to_user_continue          (** R-7.3-p *)
  | Resume_retry
  | Resume_trynext
  | Raise_to_user_no_user_level     (** R-7.3-n *)
  | Raise_to_user_unhandled
  | Raise_to_user_illegal           (** §4.11, R-7.3-q *)
  | Raise_to_user_misplaced         (** R-7.3-n *)
  (* Not rules: what [step] answers after the end, and a configuration no rule applies to (a
     bug of rapid-sem) *)
  | Done
  | Stuck
  (* Backward execution (ch. 6): the first three are [Machine.backward]'s, the others [step]'s *)
  | Backward_noop                   (** §6.1 *)
  | Backward_call                   (** §6.1, §6.2 *)
  | Backward_move                   (** §6.1, R-6.1-move *)
  | Backward_end                    (** §6.2 *)
  | Raise_in_backward               (** §6.1 *)
  (* Not in doc/semantics.md, nor in [Machine.rule_names]: a call whose motion history (kept for
     --samples and rapid-sem motion) outgrows its budget ends the run (doc/motion.md) *)
  | Motion_history_exhausted

val name : t -> string
(** The rule's name in doc/semantics.md: the constructor's, in lower case with hyphens. *)

val all : t list
(** Every rule, each once: those of [Machine.rule_names] in the order it has always had (the
    coverage reports of the fuzzer list them so), [Done] and [Stuck] last; then those of
    backward execution, then [Motion_history_exhausted]. Derived from an exhaustive match on
    [t]: a constructor added to [t] and not listed there does not compile. *)

val backward : t -> bool
(** A rule of backward execution (doc/semantics.md, "Backward execution"), which
    [Machine.rule_names] leaves to [Machine.backward_rule_names]. *)

val listed : t -> bool
(** In [Machine.rule_names]: not [backward], not [Motion_history_exhausted]. *)
