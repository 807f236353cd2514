(* The rules of doc/semantics.md; rule.mli says what each group is. Warning 8 (a match that is
   not exhaustive) is an error in this file: [name] and [after] name every rule. *)
[@@@ocaml.warning "+8+11"]
[@@@ocaml.warnerror "+8+11"]

type t =
  (* Statement lists and statements *)
  | Label | Execute_placeholder
  (* Assignment *)
  | Assign | Store | Store_signal
  (* Expressions *)
  | Read | Read_place | Read_signal | Signal_value | Signal_not_connected | Unary_operand | Unary
  | Binary_operands | Binary | Binary_error | And | And_short | And_right | Or | Or_short
  | Or_right | Aggregate_first | Aggregate_next | Aggregate
  (* Places *)
  | Element | Index_next | Place_absent | Index_out_of_bounds | Index_not_integer | Place_unknown
  (* Calls *)
  | Call_arguments | Argument_alias | Argument_reference | Argument_alias_refused
  | Argument_pass_on_duplicate | Argument_aggregate | Argument_fit | Argument_fit_refused
  | Call_enter | Local_initial_value | Call_depth_exceeded | Memory_exhausted | Call_primitive
  | Call_primitive_error | Call_primitive_stop | Call_primitive_exit_cycle | Call_not_modelled | Call_stubbed
  | Call_unknown
  | Call_unknown_function | Call_late | Call_late_unknown | Call_late_mismatch | Call_by_var
  | Call_by_var_unknown | Call_by_var_mismatch | Return_value | Return_procedure | Return_function
  | Return_entry | Function_no_return
  (* Control *)
  | Goto | Break | Continue | If | If_true | If_false | Elseif | Compact_if | Compact_if_true
  | Compact_if_false | While | While_true | While_false | While_again | For | For_enter | For_empty
  | For_step | For_done | Test | Test_subject | Test_next | Test_match | Test_default | Connect
  | Connect_allocate | Connect_again | Connect_inomax | Connect_not_variable | Exit
  (* The controller *)
  | Time_limit | Interrupt_serve | Trap_end | Raise_in_trap | Wait_start | Wait_done | Wait_timeout
  | Wait_advance | Wait_yield | Wait_poll | Wait_poll_true | Wait_poll_false | Wait_deadlock
  | Wait_time_limit | Async_error | Async_error_unhandled | Async_retry_resume
  | Async_trynext_resume | Async_handler_leave | Async_exit | Async_error_at_move
  (* Errors *)
  | Raise_number | Raise | Raise_illegal | Raise_handle | Raise_in_handler | Raise_unhandled
  | Longjump_search_start | Longjump_search | Longjump_found | Raise_propagate | Raise_again
  | Raise_again_unhandled | Raise_new | Raise_new_unhandled | Abandon | Abandon_entry | Undo_run | Undo_done
  | Undo_done_entry | Cycle_restart
  | Retry | Retry_limit | Trynext | Handler_end
  (* The user level *)
  | Raise_to_user_break_off | Raise_to_user_continue | Resume_retry | Resume_trynext
  | Raise_to_user_no_user_level | Raise_to_user_unhandled | Raise_to_user_illegal
  | Raise_to_user_misplaced
  (* Not rules *)
  | Done | Stuck
  (* Backward execution *)
  | Backward_noop | Backward_call | Backward_move | Backward_end | Raise_in_backward
  (* Not in doc/semantics.md *)
  | Motion_history_exhausted

let name = function
  | Label -> "label"
  | Execute_placeholder -> "execute-placeholder"
  | Assign -> "assign"
  | Store -> "store"
  | Store_signal -> "store-signal"
  | Read -> "read"
  | Read_place -> "read-place"
  | Read_signal -> "read-signal"
  | Signal_value -> "signal-value"
  | Signal_not_connected -> "signal-not-connected"
  | Unary_operand -> "unary-operand"
  | Unary -> "unary"
  | Binary_operands -> "binary-operands"
  | Binary -> "binary"
  | Binary_error -> "binary-error"
  | And -> "and"
  | And_short -> "and-short"
  | And_right -> "and-right"
  | Or -> "or"
  | Or_short -> "or-short"
  | Or_right -> "or-right"
  | Aggregate_first -> "aggregate-first"
  | Aggregate_next -> "aggregate-next"
  | Aggregate -> "aggregate"
  | Element -> "element"
  | Index_next -> "index-next"
  | Place_absent -> "place-absent"
  | Index_out_of_bounds -> "index-out-of-bounds"
  | Index_not_integer -> "index-not-integer"
  | Place_unknown -> "place-unknown"
  | Call_arguments -> "call-arguments"
  | Argument_alias -> "argument-alias"
  | Argument_reference -> "argument-reference"
  | Argument_alias_refused -> "argument-alias-refused"
  | Argument_pass_on_duplicate -> "argument-pass-on-duplicate"
  | Argument_aggregate -> "argument-aggregate"
  | Argument_fit -> "argument-fit"
  | Argument_fit_refused -> "argument-fit-refused"
  | Call_enter -> "call-enter"
  | Local_initial_value -> "local-initial-value"
  | Call_depth_exceeded -> "call-depth-exceeded"
  | Memory_exhausted -> "memory-exhausted"
  | Call_primitive -> "call-primitive"
  | Call_primitive_error -> "call-primitive-error"
  | Call_primitive_stop -> "call-primitive-stop"
  | Call_primitive_exit_cycle -> "call-primitive-exit-cycle"
  | Call_not_modelled -> "call-not-modelled"
  | Call_stubbed -> "call-stubbed"
  | Call_unknown -> "call-unknown"
  | Call_unknown_function -> "call-unknown-function"
  | Call_late -> "call-late"
  | Call_late_unknown -> "call-late-unknown"
  | Call_late_mismatch -> "call-late-mismatch"
  | Call_by_var -> "call-by-var"
  | Call_by_var_unknown -> "call-by-var-unknown"
  | Call_by_var_mismatch -> "call-by-var-mismatch"
  | Return_value -> "return-value"
  | Return_procedure -> "return-procedure"
  | Return_function -> "return-function"
  | Return_entry -> "return-entry"
  | Function_no_return -> "function-no-return"
  | Goto -> "goto"
  | Break -> "break"
  | Continue -> "continue"
  | If -> "if"
  | If_true -> "if-true"
  | If_false -> "if-false"
  | Elseif -> "elseif"
  | Compact_if -> "compact-if"
  | Compact_if_true -> "compact-if-true"
  | Compact_if_false -> "compact-if-false"
  | While -> "while"
  | While_true -> "while-true"
  | While_false -> "while-false"
  | While_again -> "while-again"
  | For -> "for"
  | For_enter -> "for-enter"
  | For_empty -> "for-empty"
  | For_step -> "for-step"
  | For_done -> "for-done"
  | Test -> "test"
  | Test_subject -> "test-subject"
  | Test_next -> "test-next"
  | Test_match -> "test-match"
  | Test_default -> "test-default"
  | Connect -> "connect"
  | Connect_allocate -> "connect-allocate"
  | Connect_again -> "connect-again"
  | Connect_inomax -> "connect-inomax"
  | Connect_not_variable -> "connect-not-variable"
  | Exit -> "exit"
  | Time_limit -> "time-limit"
  | Interrupt_serve -> "interrupt-serve"
  | Trap_end -> "trap-end"
  | Raise_in_trap -> "raise-in-trap"
  | Wait_start -> "wait-start"
  | Wait_done -> "wait-done"
  | Wait_timeout -> "wait-timeout"
  | Wait_advance -> "wait-advance"
  | Wait_yield -> "wait-yield"
  | Wait_poll -> "wait-poll"
  | Wait_poll_true -> "wait-poll-true"
  | Wait_poll_false -> "wait-poll-false"
  | Wait_deadlock -> "wait-deadlock"
  | Wait_time_limit -> "wait-time-limit"
  | Async_error -> "async-error"
  | Async_error_unhandled -> "async-error-unhandled"
  | Async_retry_resume -> "async-retry-resume"
  | Async_trynext_resume -> "async-trynext-resume"
  | Async_handler_leave -> "async-handler-leave"
  | Async_exit -> "async-exit"
  | Async_error_at_move -> "async-error-at-move"
  | Raise_number -> "raise-number"
  | Raise -> "raise"
  | Raise_illegal -> "raise-illegal"
  | Raise_handle -> "raise-handle"
  | Raise_in_handler -> "raise-in-handler"
  | Raise_unhandled -> "raise-unhandled"
  | Longjump_search_start -> "longjump-search-start"
  | Longjump_search -> "longjump-search"
  | Longjump_found -> "longjump-found"
  | Raise_propagate -> "raise-propagate"
  | Raise_again -> "raise-again"
  | Raise_again_unhandled -> "raise-again-unhandled"
  | Raise_new -> "raise-new"
  | Raise_new_unhandled -> "raise-new-unhandled"
  | Abandon -> "abandon"
  | Abandon_entry -> "abandon-entry"
  | Undo_run -> "undo-run"
  | Undo_done -> "undo-done"
  | Undo_done_entry -> "undo-done-entry"
  | Cycle_restart -> "cycle-restart"
  | Retry -> "retry"
  | Retry_limit -> "retry-limit"
  | Trynext -> "trynext"
  | Handler_end -> "handler-end"
  | Raise_to_user_break_off -> "raise-to-user-break-off"
  | Raise_to_user_continue -> "raise-to-user-continue"
  | Resume_retry -> "resume-retry"
  | Resume_trynext -> "resume-trynext"
  | Raise_to_user_no_user_level -> "raise-to-user-no-user-level"
  | Raise_to_user_unhandled -> "raise-to-user-unhandled"
  | Raise_to_user_illegal -> "raise-to-user-illegal"
  | Raise_to_user_misplaced -> "raise-to-user-misplaced"
  | Done -> "done"
  | Stuck -> "stuck"
  | Backward_noop -> "backward-noop"
  | Backward_call -> "backward-call"
  | Backward_move -> "backward-move"
  | Backward_end -> "backward-end"
  | Raise_in_backward -> "raise-in-backward"
  | Motion_history_exhausted -> "motion-history-exhausted"

(* Each rule and the one after it in [all]: those of the step in the order of the list
   Machine.rule_names has always had (the fuzzer's coverage reports list the rules in it), Done
   and Stuck, then the rules of backward execution and motion-history-exhausted. A rule added to
   [t] needs its arm here, or this does not compile; the arm before it must lead to it, or [all]
   misses it (test/test_semantics.ml then finds the rule of doc/semantics.md the machine lacks). *)
let after = function
  | Label -> Some Execute_placeholder
  | Execute_placeholder -> Some Assign
  | Assign -> Some Store
  | Store -> Some Call_arguments
  | Call_arguments -> Some Argument_reference
  | Argument_reference -> Some Argument_alias
  | Argument_alias -> Some Argument_alias_refused
  | Argument_alias_refused -> Some Call_enter
  | Call_enter -> Some Argument_pass_on_duplicate
  | Argument_pass_on_duplicate -> Some Argument_aggregate
  | Argument_aggregate -> Some Argument_fit
  | Argument_fit -> Some Argument_fit_refused
  | Argument_fit_refused -> Some Elseif
  | Elseif -> Some Connect_not_variable
  | Connect_not_variable -> Some Memory_exhausted
  | Memory_exhausted -> Some Call_primitive
  | Call_primitive -> Some Call_primitive_error
  | Call_primitive_error -> Some Call_primitive_stop
  | Call_primitive_stop -> Some Call_primitive_exit_cycle
  | Call_primitive_exit_cycle -> Some Call_by_var
  | Call_by_var -> Some Call_by_var_unknown
  | Call_by_var_unknown -> Some Call_by_var_mismatch
  | Call_by_var_mismatch -> Some Call_not_modelled
  | Call_not_modelled -> Some Call_stubbed
  | Call_stubbed -> Some Call_depth_exceeded
  | Call_depth_exceeded -> Some Call_unknown
  | Call_unknown -> Some Call_unknown_function
  | Call_unknown_function -> Some Call_late
  | Call_late -> Some Call_late_unknown
  | Call_late_unknown -> Some Call_late_mismatch
  | Call_late_mismatch -> Some Return_procedure
  | Return_procedure -> Some Return_function
  | Return_function -> Some Return_entry
  | Return_entry -> Some Return_value
  | Return_value -> Some Function_no_return
  | Function_no_return -> Some Goto
  | Goto -> Some Break
  | Break -> Some Continue
  | Continue -> Some If
  | If -> Some If_true
  | If_true -> Some If_false
  | If_false -> Some Compact_if
  | Compact_if -> Some Compact_if_true
  | Compact_if_true -> Some Compact_if_false
  | Compact_if_false -> Some While
  | While -> Some While_true
  | While_true -> Some While_false
  | While_false -> Some While_again
  | While_again -> Some For
  | For -> Some For_enter
  | For_enter -> Some For_empty
  | For_empty -> Some For_step
  | For_step -> Some For_done
  | For_done -> Some Test
  | Test -> Some Test_subject
  | Test_subject -> Some Test_next
  | Test_next -> Some Test_match
  | Test_match -> Some Test_default
  | Test_default -> Some Connect
  | Connect -> Some Connect_allocate
  | Connect_allocate -> Some Connect_again
  | Connect_again -> Some Exit
  | Exit -> Some Raise_number
  | Raise_number -> Some Raise
  | Raise -> Some Raise_illegal
  | Raise_illegal -> Some Raise_again
  | Raise_again -> Some Raise_again_unhandled
  | Raise_again_unhandled -> Some Raise_new
  | Raise_new -> Some Raise_new_unhandled
  | Raise_new_unhandled -> Some Raise_handle
  | Raise_handle -> Some Raise_in_handler
  | Raise_in_handler -> Some Raise_unhandled
  | Raise_unhandled -> Some Raise_propagate
  | Raise_propagate -> Some Longjump_search_start
  | Longjump_search_start -> Some Longjump_search
  | Longjump_search -> Some Longjump_found
  | Longjump_found -> Some Abandon
  | Abandon -> Some Abandon_entry
  | Abandon_entry -> Some Undo_run
  | Undo_run -> Some Undo_done
  | Undo_done -> Some Undo_done_entry
  | Undo_done_entry -> Some Cycle_restart
  | Cycle_restart -> Some Retry
  | Retry -> Some Retry_limit
  | Retry_limit -> Some Trynext
  | Trynext -> Some Handler_end
  | Handler_end -> Some Read_place
  | Read_place -> Some Read
  | Read -> Some Read_signal
  | Read_signal -> Some Place_absent
  | Place_absent -> Some Place_unknown
  | Place_unknown -> Some Index_next
  | Index_next -> Some Element
  | Element -> Some Index_out_of_bounds
  | Index_out_of_bounds -> Some Index_not_integer
  | Index_not_integer -> Some Unary_operand
  | Unary_operand -> Some Unary
  | Unary -> Some Binary_operands
  | Binary_operands -> Some Binary
  | Binary -> Some Binary_error
  | Binary_error -> Some And
  | And -> Some And_short
  | And_short -> Some And_right
  | And_right -> Some Or
  | Or -> Some Or_short
  | Or_short -> Some Or_right
  | Or_right -> Some Aggregate_first
  | Aggregate_first -> Some Aggregate_next
  | Aggregate_next -> Some Aggregate
  | Aggregate -> Some Local_initial_value
  | Local_initial_value -> Some Trap_end
  | Trap_end -> Some Interrupt_serve
  | Interrupt_serve -> Some Time_limit
  | Time_limit -> Some Wait_start
  | Wait_start -> Some Wait_done
  | Wait_done -> Some Wait_timeout
  | Wait_timeout -> Some Wait_advance
  | Wait_advance -> Some Wait_yield
  | Wait_yield -> Some Wait_poll
  | Wait_poll -> Some Wait_poll_true
  | Wait_poll_true -> Some Wait_poll_false
  | Wait_poll_false -> Some Wait_deadlock
  | Wait_deadlock -> Some Wait_time_limit
  | Wait_time_limit -> Some Async_error
  | Async_error -> Some Signal_value
  | Signal_value -> Some Signal_not_connected
  | Signal_not_connected -> Some Store_signal
  | Store_signal -> Some Connect_inomax
  | Connect_inomax -> Some Raise_in_trap
  | Raise_in_trap -> Some Async_error_unhandled
  | Async_error_unhandled -> Some Async_retry_resume
  | Async_retry_resume -> Some Async_trynext_resume
  | Async_trynext_resume -> Some Async_exit
  | Async_exit -> Some Async_handler_leave
  | Async_handler_leave -> Some Async_error_at_move
  | Async_error_at_move -> Some Raise_to_user_continue
  | Raise_to_user_continue -> Some Raise_to_user_break_off
  | Raise_to_user_break_off -> Some Raise_to_user_no_user_level
  | Raise_to_user_no_user_level -> Some Raise_to_user_unhandled
  | Raise_to_user_unhandled -> Some Raise_to_user_illegal
  | Raise_to_user_illegal -> Some Raise_to_user_misplaced
  | Raise_to_user_misplaced -> Some Resume_retry
  | Resume_retry -> Some Resume_trynext
  | Resume_trynext -> Some Done
  | Done -> Some Stuck
  | Stuck -> Some Backward_noop
  | Backward_noop -> Some Backward_call
  | Backward_call -> Some Backward_move
  | Backward_move -> Some Backward_end
  | Backward_end -> Some Raise_in_backward
  | Raise_in_backward -> Some Motion_history_exhausted
  | Motion_history_exhausted -> None

let all =
  (* the rules met, in a table: a list's memq made this check quadratic at every start *)
  let seen = Hashtbl.create 256 in
  let rec from r acc =
    if Hashtbl.mem seen r then invalid_arg ("Rule.after comes back to " ^ name r)
    else begin
      Hashtbl.add seen r ();
      match after r with Some next -> from next (r :: acc) | None -> List.rev (r :: acc)
    end in
  from Label []

let backward = function
  | Backward_noop | Backward_call | Backward_move | Backward_end | Raise_in_backward -> true
  | _ -> false

let listed r = not (backward r || r = Motion_history_exhausted)
