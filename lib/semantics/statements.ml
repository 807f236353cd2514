(* Statements and expressions (ch. 3, ch. 4), the step's dispatch on what is in focus and on the
   frame on top, and settling. Why a module of its own: statements.mli. *)

open Rapid_syntax
open Configuration
open Store
open Event
open Outcome
module V = Value

(* The statements of a statement list, one by one. *)
let rec exec cfg (s : Ir.stmt) =
  match Recovery.kept_exit cfg s with Some r -> r | None -> exec_statement cfg s

and exec_statement cfg (s : Ir.stmt) =
  (* The simple statement of a compact IF is part of the IF: the IF is the statement that RETRY
     and TRYNEXT refer to (§4.17, §7.1). *)
  let part_of_compact_if = cfg.unmarked in
  cfg.unmarked <- false;
  let mark_here () =
    if not part_of_compact_if then (push cfg (K_stmt (s, cfg.mark)); cfg.mark <- cfg.stack) in
  match s.s with
  | Label -> cfg.focus <- F_next; (Rule.Label, [])
  | Placeholder_statement -> mark_here (); raise_ cfg "ERR_EXECPHR"; (Rule.Execute_placeholder, [])
  | Assign (p, e) ->
      mark_here ();
      let l = static_loc cfg p in
      if l != no_loc then (push cfg (K_assign_store l); cfg.focus <- F_expr e)
      else (push cfg (K_assign_value e); cfg.focus <- F_place p);
      (Rule.Assign, [])
  | Call_procedure c -> mark_here (); (Calls.begin_call cfg c, [])
  | Call_late (e, args) ->
      mark_here ();
      push cfg (K_late_name (args, s.sat));
      cfg.focus <- F_expr e;
      (Rule.Call_late, [])
  | Goto (block, index) ->
      (* §4.7: the label's statement list is this one or one that encloses it: unwind to it. *)
      let rec unwind = function
        | K_seq (b, _) :: rest when b.Ir.id = block ->
            cfg.stack <- K_seq (b, index) :: rest; cfg.focus <- F_next
        | K_stmt (_, prev) :: rest -> cfg.mark <- prev; unwind rest
        | _ :: rest -> unwind rest
        | [] -> cfg.focus <- F_done (Stuck "GOTO to a label not in an enclosing statement list")
      in
      unwind cfg.stack;
      (Rule.Goto, [])
  | Break | Continue ->
      (* §4.8, §4.9: to the innermost loop of the routine. *)
      let rec unwind = function
        | (K_while_body (c, b)) :: rest ->
            if s.s = Break then (cfg.stack <- rest; cfg.focus <- F_next)
            else (cfg.stack <- K_while_test (c, b) :: rest; cfg.focus <- F_expr c)
        | (K_for_body _ as loop) :: rest ->
            if s.s = Break then cfg.stack <- rest else cfg.stack <- loop :: rest;
            cfg.focus <- F_next
        | K_stmt (_, prev) :: rest -> cfg.mark <- prev; unwind rest
        | _ :: rest -> unwind rest
        | [] -> cfg.focus <- F_done (Stuck "BREAK or CONTINUE outside a loop")
      in
      unwind cfg.stack;
      ((if s.s = Break then Rule.Break else Rule.Continue), [])
  | Return None -> Calls.return_from cfg None
  | Return (Some e) -> mark_here (); push cfg K_return_value; cfg.focus <- F_expr e; (Rule.Return_value, [])
  | Raise None -> (
      match cfg.act.handling with
      | In_handler (e, _) -> (
          match cfg.act.caller with
          | None -> Recovery.stop cfg e Rule.Raise_again_unhandled
          | Some _ ->
              cfg.focus <- F_search ({ e with searched = false }, cfg.act.recovery_up);
              (Rule.Raise_again, []))
      | _ -> cfg.focus <- F_done (Stuck "RAISE without a number outside an error handler"); (Rule.Stuck, []))
  | Raise (Some e) -> mark_here (); push cfg K_raise_value; cfg.focus <- F_expr e; (Rule.Raise_number, [])
  | Exit -> cfg.focus <- F_abandon Go_on_exit; (Rule.Exit, [])
  | Retry -> (
      let resumed = Recovery.resume_nostepin cfg in
      let named (rule, events) = ((if resumed && rule = Rule.Retry then Rule.Resume_retry else rule), events) in
      named @@
      match cfg.act.handling with
      | In_handler (e, point) ->
          let act = cfg.act in
          act.retries <- act.retries + 1;
          if act.retries > cfg.limits.retry_limit then begin
            act.handling <- Body;
            act.retries <- 0;
            (* §7.1: the error is beyond recovery: ERR_EXCRTYMAX, at the RETRY, in the handler,
               goes to the system error handler. *)
            cfg.focus <- F_raise { (error ~about:(Outcome.retries_beyond cfg.limits.retry_limit) cfg "ERR_EXCRTYMAX"
                                      s.sat) with searched = true };
            act.handling <- In_handler (e, point);
            (Rule.Retry_limit, [])
          end
          else begin
            act.handling <- Body;
            (match Recovery.statement_point point with
             | K_stmt (st, prev) :: rest ->
                 act.retried <- Some st;
                 cfg.stack <- rest; cfg.mark <- prev; cfg.focus <- F_stmt st
             | K_seq _ :: _ ->
                 (* R-7.2-m: no statement caused the error; the point of response is taken again. *)
                 act.retried <- None;
                 cfg.stack <- point; cfg.mark <- []; cfg.focus <- F_next
             | _ -> cfg.focus <- F_done (Stuck "RETRY without a statement to retry"));
            (Rule.Retry, [ Observed (Retried cfg.act.routine.name) ])
          end
      | _ -> cfg.focus <- F_done (Stuck "RETRY outside an error handler"); (Rule.Stuck, []))
  | Trynext -> (
      let resumed = Recovery.resume_nostepin cfg in
      let named (rule, events) = ((if resumed && rule = Rule.Trynext then Rule.Resume_trynext else rule), events) in
      named @@
      match cfg.act.handling with
      | In_handler ({ asynchronous = true; _ }, _) ->
          (* §7.4: "in this case TRYNEXT executes as RETRY", for the system can restart from
             where the error occurred (R-7.4-m). *)
          exec cfg { s with s = Retry }
      | In_handler (_, point) ->
          cfg.act.handling <- Body;
          (match Recovery.statement_point point with
           | K_stmt (_, prev) :: rest -> cfg.stack <- rest; cfg.mark <- prev; cfg.focus <- F_next
           | K_seq _ :: _ -> cfg.stack <- point; cfg.mark <- []; cfg.focus <- F_next  (* R-7.2-m *)
           | _ -> cfg.focus <- F_done (Stuck "TRYNEXT without a statement"));
          (Rule.Trynext, [ Observed (Tried_next cfg.act.routine.name) ])
      | _ -> cfg.focus <- F_done (Stuck "TRYNEXT outside an error handler"); (Rule.Stuck, []))
  | Connect (p, trap) -> mark_here (); push cfg (K_connect_target (trap, p)); cfg.focus <- F_place p; (Rule.Connect, [])
  | If (c, t, f) -> mark_here (); push cfg (K_if (t, f)); cfg.focus <- F_expr c; (Rule.If, [])
  | Elseif (c, t, f) ->
      (* Marked for the error's place (the ELSEIF); RETRY and TRYNEXT go to its IF. *)
      mark_here (); push cfg (K_if (t, f)); cfg.focus <- F_expr c; (Rule.Elseif, [])
  | Compact_if (c, inner) ->
      mark_here (); push cfg (K_compact_if inner); cfg.focus <- F_expr c; (Rule.Compact_if, [])
  | While (c, b) -> mark_here (); push cfg (K_while_test (c, b)); cfg.focus <- F_expr c; (Rule.While, [])
  | For f -> mark_here (); push cfg (K_for_from f); cfg.focus <- F_expr f.from_; (Rule.For, [])
  | Test (e, cases, default) ->
      mark_here (); push cfg (K_test_subject (cases, default)); cfg.focus <- F_expr e; (Rule.Test, [])

let () = Calls.exec_ref := exec

(* §4.18: is the loop variable still in its range? *)
let for_in_range v t step =
  match v, t, step with
  | V.Num v, V.Num t, V.Num s -> if s >= 0. then v <= t else v >= t
  | _ -> false

(* A statement has completed: the frame on top continues. *)
let next_frame cfg =
  match cfg.stack with
  | (K_stmt _ | K_seq _) :: _ ->
      cfg.focus <- F_done (Stuck "a configuration left unsettled (a completed statement or the next one of a list)");
      (Rule.Stuck, [])
  | K_while_body (c, b) :: rest ->
      cfg.stack <- K_while_test (c, b) :: rest; cfg.focus <- F_expr c; (Rule.While_again, [])
  | K_for_body (f, t, step) :: rest ->
      (* §4.18: the loop variable steps on; TO and STEP were evaluated once. *)
      let slot = cfg.act.slots.(f.variable) in
      let v = match get slot, step with
        | V.Num cur, V.Num d -> V.num (cur +. d) | other, _ -> other in
      set slot v;
      if for_in_range v t step then
        (cfg.stack <- K_seq (f.loop_body, 0) :: cfg.stack; (Rule.For_step, observed_store cfg slot v))
      else (cfg.stack <- rest; (Rule.For_done, []))
  | K_routine_end :: _ -> Calls.routine_end cfg
  | K_handler_end :: _ -> Recovery.handler_end cfg
  | K_undo_end after :: _ -> Recovery.leave_abandoned cfg after Rule.Undo_done Rule.Undo_done_entry
  | K_local_init (act, inits) :: rest -> Calls.local_init cfg act inits rest
  | K_args cs :: rest -> Calls.next_argument cfg cs rest
  | K_backward_end :: rest ->
      (* §6.2: the BACKWARD handler has returned: the program pointer is at the call (Backward). *)
      cfg.stack <- rest; cfg.backward_depth <- -1; cfg.host.set_backward false;
      (Rule.Backward_end, [])
  | K_task_end :: _ -> cfg.focus <- F_done (Stuck "the bottom of the stack reached"); (Rule.Stuck, [])
  | f :: _ ->
      cfg.focus <- F_done (Stuck ("a statement completed over the frame " ^ frame_kind f));
      (Rule.Stuck, [])
  | [] -> cfg.focus <- F_done (Stuck "empty stack"); (Rule.Stuck, [])

(* Something has completed: at a statement point (the entry of a statement, a new round of a loop)
   and after the last statement of a list, the points of response of ch. 8 come first; a wait
   takes its own step; else the frame on top continues. *)
let next cfg =
  let statement_point = match cfg.stack with
    | K_seq (b, i) :: _ -> i < Array.length b.Ir.body
    | (K_while_body _ | K_for_body _) :: _ -> true
    | _ -> false in
  if statement_point then begin
    (* Each statement entered, and each new round of a loop, takes the statement time; once:
       settling may have charged it already and stopped here (see [settle]). *)
    if cfg.charged then cfg.charged <- false else cfg.host.statement ();
    if cfg.host.now () > cfg.host.max_time then Waits.time_exhausted cfg Rule.Time_limit
    else match Waits.serve_interrupt cfg with Some r -> r | None -> next_frame cfg
  end
  else match cfg.stack with
    | K_wait ws :: rest -> Waits.wait_step cfg ws rest
    | K_seq _ :: _ -> (
        (* ch. 8: "after the last statement of a statement list" is a point of response too. *)
        match Waits.serve_interrupt cfg with Some r -> r | None -> next_frame cfg)
    | _ -> next_frame cfg

let start_loop cfg (f : Ir.for_loop) from t step rest =
  set cfg.act.slots.(f.variable) from;
  cfg.focus <- F_next;
  if for_in_range from t step then begin
    cfg.stack <- K_seq (f.loop_body, 0) :: K_for_body (f, t, step) :: rest;
    (Rule.For_enter, observed_store cfg cfg.act.slots.(f.variable) from)
  end
  else (cfg.stack <- rest; (Rule.For_empty, []))

(* A value in focus: the frame on top takes it. *)
let value_step cfg v =
  match cfg.stack with
  | K_assign_store l :: rest -> (
      match get l with
      | V.Handle h when String.length (V.handle_kind h) > 6 && String.sub (V.handle_kind h) 0 6 = "signal" -> (
          (* §2.16: assigning to an output signal sets it. *)
          cfg.stack <- rest;
          match cfg.host.write_signal (V.Handle h) v with
          | Ok () -> cfg.focus <- F_next; (Rule.Store_signal, [])
          | Error "" -> cfg.focus <- F_done (Stuck "a signal assigned a value that is not a num"); (Rule.Stuck, [])
          | Error name -> raise_ cfg name; (Rule.Store_signal, []))
      | _ -> set l v; cfg.stack <- rest; cfg.focus <- F_next; (Rule.Store, observed_store cfg l v))
  | K_poll ws :: K_wait _ :: rest -> Waits.poll_value cfg ws rest v
  | K_read :: _ -> cfg.focus <- F_done (Stuck "a value where a place was read"); (Rule.Stuck, [])
  | K_unary (op, _) :: rest -> (
      cfg.stack <- rest;
      match Arith.unary op v with
      | Ok r -> cfg.focus <- F_value r; (Rule.Unary, [])
      | Error name -> cfg.focus <- F_done (Stuck ("a unary operation failed: " ^ name)); (Rule.Stuck, []))
  | K_binary_right (op, a, _) :: rest -> (
      cfg.stack <- rest;
      match Arith.binary op a v with
      | Ok r -> cfg.focus <- F_value r; (Rule.Binary, [])
      | Error name -> raise_ cfg name; (Rule.Binary_error, []))
  | K_and b :: rest -> (
      cfg.stack <- rest;
      match bool_of v with
      | Some false -> cfg.focus <- F_value v; (Rule.And_short, [])
      | _ -> cfg.focus <- F_expr b; (Rule.And_right, []))
  | K_or b :: rest -> (
      cfg.stack <- rest;
      match bool_of v with
      | Some true -> cfg.focus <- F_value v; (Rule.Or_short, [])
      | _ -> cfg.focus <- F_expr b; (Rule.Or_right, []))
  | K_aggregate (es, acc, i, kind) :: rest ->
      acc.(i) <- v;
      if i + 1 < Array.length es then begin
        cfg.stack <- K_aggregate (es, acc, i + 1, kind) :: rest; cfg.focus <- F_expr es.(i + 1);
        (Rule.Aggregate_next, [])
      end
      else begin
        cfg.stack <- rest;
        cfg.focus <- F_value (match kind with Record_value -> V.Record acc | Array_value -> V.Array acc);
        (Rule.Aggregate, [])
      end
  | K_if (t, f) :: rest -> (
      match bool_of v with
      | Some true -> cfg.stack <- K_seq (t, 0) :: rest; cfg.focus <- F_next; (Rule.If_true, [])
      | _ -> cfg.stack <- K_seq (f, 0) :: rest; cfg.focus <- F_next; (Rule.If_false, []))
  | K_compact_if inner :: rest -> (
      cfg.stack <- rest;
      match bool_of v with
      | Some true -> cfg.unmarked <- true; cfg.focus <- F_stmt inner; (Rule.Compact_if_true, [])
      | _ -> cfg.focus <- F_next; (Rule.Compact_if_false, []))
  | K_while_test (c, b) :: rest -> (
      match bool_of v with
      | Some true ->
          cfg.stack <- K_seq (b, 0) :: K_while_body (c, b) :: rest; cfg.focus <- F_next; (Rule.While_true, [])
      | _ -> cfg.stack <- rest; cfg.focus <- F_next; (Rule.While_false, []))
  | K_for_to (f, from) :: rest -> (
      match f.step with
      | Some _ -> cfg.focus <- F_done (Stuck "a FOR bound left unsettled"); (Rule.Stuck, [])
      | None ->
          (* §4.18: the default step is 1, or -1 when the range decreases. *)
          let step = match from, v with V.Num a, V.Num b when a > b -> V.num (-1.) | _ -> V.num 1. in
          start_loop cfg f from v step rest)
  | K_for_step (f, from, t) :: rest -> start_loop cfg f from t v rest
  | K_test_subject (cases, default) :: rest ->
      if Array.length cases = 0 then
        (cfg.stack <- K_seq (default, 0) :: rest; cfg.focus <- F_next; (Rule.Test_default, []))
      else (cfg.stack <- K_test_value (v, cases, default, 0, 0) :: rest;
            cfg.focus <- F_expr (fst cases.(0)).(0); (Rule.Test_subject, []))
  | K_test_value (subject, cases, default, ci, vi) :: rest ->
      (* §4.20: the first test value equal to the test expression selects its list. *)
      if V.equal subject v then
        (cfg.stack <- K_seq (snd cases.(ci), 0) :: rest; cfg.focus <- F_next; (Rule.Test_match, []))
      else begin
        let ci, vi = if vi + 1 < Array.length (fst cases.(ci)) then (ci, vi + 1) else (ci + 1, 0) in
        if ci >= Array.length cases then
          (cfg.stack <- K_seq (default, 0) :: rest; cfg.focus <- F_next; (Rule.Test_default, []))
        else (cfg.stack <- K_test_value (subject, cases, default, ci, vi) :: rest;
              cfg.focus <- F_expr (fst cases.(ci)).(vi); (Rule.Test_next, []))
      end
  | K_return_value :: _ -> Calls.return_from cfg (Some v)
  | K_raise_value :: rest -> (
      cfg.stack <- rest;
      (* §4.11: the error number is an integer in 1..90 (or one booked with BookErrNo). *)
      match num_of v with
      | Some f -> (
          match to_int f with
          | Some n when (n >= 1 && n <= 90) || cfg.host.booked n -> (
              let e = error_of_number cfg n (region_of_focus_stmt cfg) in
              match cfg.act.handling, cfg.act.caller with
              | In_handler _, None ->
                  (* R-4.11-handler1 (doc/dialect.md): in an error handler the new error leaves
                     the routine, as RAISE; makes the error in hand leave it (raise-again). *)
                  let rule, events = Recovery.stop cfg e Rule.Raise_new_unhandled in
                  (rule, Error_raised { name = e.name; number = e.number; at = e.err_at } :: events)
              | In_handler _, Some _ ->
                  cfg.focus <- F_search (e, cfg.act.recovery_up);
                  (Rule.Raise_new, [ Error_raised { name = e.name; number = e.number; at = e.err_at } ])
              | _ -> cfg.focus <- F_raise e; (Rule.Raise, []))
          | _ ->
              let in_handler = match cfg.act.handling with In_handler _ -> true | _ -> false in
              raise_ ~about:(Raise_number.refusal cfg.program ~in_handler f) cfg "ERR_ILLRAISE";
              (Rule.Raise_illegal, []))
      | None -> raise_ cfg "ERR_ILLRAISE"; (Rule.Raise_illegal, []))
  | K_late_name (args, at) :: rest -> Calls.late_name cfg args at rest v
  | K_fit shape :: rest -> Calls.fit cfg shape rest v
  (* Settling binds a value argument the budget holds (see [settle]). *)
  | K_args cs :: rest when V.bytes v > Calls.args_room cfg cs -> Calls.copy_exhausted cfg cs rest
  | K_element_index (l, idx, i, at) :: rest -> (
      (* §3.6: an index is an integer within the array's dimension (ERR_OUTOFBND). *)
      match get l, num_of v with
      | V.Array elems, Some f -> (
          match to_int f with
          | Some k when k >= 1 && k <= Array.length elems ->
              let l' = { box = elems; idx = k - 1 } in
              if i + 1 < Array.length idx then begin
                cfg.stack <- K_element_index (l', idx, i + 1, at) :: rest; cfg.focus <- F_expr idx.(i + 1);
                (Rule.Index_next, [])
              end
              else (cfg.stack <- rest; cfg.focus <- F_loc l'; (Rule.Element, []))
          | Some _ ->
              cfg.stack <- rest; raise_ ~about:(Outcome.index_outside f (Array.length elems)) cfg "ERR_OUTOFBND";
              (Rule.Index_out_of_bounds, [])
          | None -> cfg.stack <- rest; raise_ cfg "ERR_NOTINTVAL"; (Rule.Index_not_integer, []))
      | _ ->
          cfg.stack <- rest; cfg.focus <- F_done (Stuck "an index into a value that is not an array");
          (Rule.Stuck, []))
  | _ -> cfg.focus <- F_done (Stuck "a value with no frame to take it"); (Rule.Stuck, [])

(* A location in focus: the frame on top takes it. *)
let loc_step cfg l =
  match cfg.stack with
  | K_args cs :: rest -> Calls.bind_alias cfg cs rest l
  | K_connect_target (trap, target) :: rest -> (
      cfg.stack <- rest;
      (* §4.15: the target "must be (or denote) a module variable (not a routine variable)":
         through a VAR or INOUT parameter, what the parameter denotes (ERR_CNTNOTVAR). A
         connected interrupt number cannot be connected again (ERR_ALRDYCNT); one freed by
         IDelete can (R-8-f). *)
      match get l with
      | _ when Calls.reference_kind cfg target Ref_variable = Ref_persistent
               || not (Calls.denotes_module_data cfg target) ->
          raise_ cfg "ERR_CNTNOTVAR"; (Rule.Connect_not_variable, [])
      | V.Num n when n <> 0. && Float.is_integer n && cfg.host.connected (int_of_float n) ->
          raise_ cfg "ERR_ALRDYCNT"; (Rule.Connect_again, [])
      | _ -> (
          match cfg.host.connect ~trap with
          | Ok n ->
              set l (V.num (float_of_int n)); cfg.focus <- F_next;
              (Rule.Connect_allocate, observed_store cfg l (get l))
          | Error name -> raise_ cfg name; (Rule.Connect_inomax, [])))
  | K_read_signal :: rest -> (
      cfg.stack <- rest;
      (* §2.16: a signal in value context is its value. *)
      match cfg.host.read_signal (get l) with
      | Ok v -> cfg.focus <- F_value v; (Rule.Signal_value, [])
      | Error name -> raise_ cfg name; (Rule.Signal_not_connected, []))
  | _ -> cfg.focus <- F_done (Stuck "a location with no frame to take it"); (Rule.Stuck, [])

(* A place in focus between steps is one settling could not locate (see [settle]). *)
let place_step cfg (p : Ir.place) =
  match p with
  | Whole (Local i) when i < Array.length cfg.act.present && not cfg.act.present.(i) ->
      (* §5.2: the value of an absent optional parameter cannot be used (ERR_NOTPRES). *)
      (match cfg.stack with _ :: rest -> cfg.stack <- rest | [] -> ());
      raise_ cfg "ERR_NOTPRES"; (Rule.Place_absent, [])
  | Unresolved name -> raise_ ~about:name cfg "ERR_REFUNKDAT"; (Rule.Place_unknown, [])
  | _ -> cfg.focus <- F_done (Stuck "a place left unsettled"); (Rule.Stuck, [])

(* An expression in focus begins its evaluation. *)
let expr_step cfg (e : Ir.expr) =
  match e.e with
  | Literal _ -> cfg.focus <- F_done (Stuck "a literal left unsettled"); (Rule.Stuck, [])
  | Read p ->
      let l = static_loc cfg p in
      if l != no_loc then (cfg.focus <- F_value (get l); (Rule.Read, []))
      else (push cfg K_read; cfg.focus <- F_place p; (Rule.Read_place, []))
  | Read_signal p -> push cfg K_read_signal; cfg.focus <- F_place p; (Rule.Read_signal, [])
  | Unary (op, a) -> push cfg (K_unary (op, e)); cfg.focus <- F_expr a; (Rule.Unary_operand, [])
  | Binary (op, a, b) -> push cfg (K_binary_left (op, b, e)); cfg.focus <- F_expr a; (Rule.Binary_operands, [])
  | And (a, b) -> push cfg (K_and b); cfg.focus <- F_expr a; (Rule.And, [])
  | Or (a, b) -> push cfg (K_or b); cfg.focus <- F_expr a; (Rule.Or, [])
  | Aggregate (es, kind) ->
      push cfg (K_aggregate (es, Array.make (Array.length es) (V.Bool false), 0, kind));
      cfg.focus <- F_expr es.(0); (Rule.Aggregate_first, [])
  | Call c -> (
      match c.callee with
      | Unknown_routine name -> raise_ ~about:name cfg "ERR_REFUNKFUN"; (Rule.Call_unknown_function, [])
      | Routine _ -> (Calls.begin_call cfg c, []))
  | Placeholder ->
      (* In an initial value of routine data no statement is in progress: the placeholder's own
         place (R-7.1-w). *)
      if cfg.mark = [] && initialising cfg cfg.act then cfg.focus <- F_raise (error cfg "ERR_EXECPHR" e.at)
      else raise_ cfg "ERR_EXECPHR";
      (Rule.Execute_placeholder, [])
  | Fitted (a, shape) -> push cfg (K_fit shape); cfg.focus <- F_expr a; (Rule.Argument_aggregate, [])

(* After every step, the administrative moves that neither inspect nor change anything a program
   can observe are made at once, so that the next step is a redex a programmer would name
   (doc/semantics.md, "Settling"): a literal is a value; the left operand's value moves on to
   the right operand, a FOR bound's to the next bound; an argument's value is bound and the
   call moves on to the next argument; a place is located down to its first index expression;
   a located place under a read is read, under a component its component located, under an
   assignment the value evaluated; a completed statement, and a finished statement list, are
   popped (the mark returns to the enclosing statement, and a statement completed after RETRY
   resets the RETRY count); routine data without initial value is initialised; the next
   statement of a list is put in focus. Each move consumes a literal, a frame, a part of a
   place, an argument or a routine datum, and the frames popped at once are those of statements
   ending together, so this is bounded by the program's text, never by the run's stacks.
   Settling stops where a step has something to say: an argument or routine datum the memory
   budget does not hold (memory-exhausted), a conditional argument duplicating an alternative
   (ERR_ARGDUPCND), and the points of response of ch. 8 where the time limit is passed or an
   interrupt is taken (time-limit, interrupt-serve). *)
let rec settle cfg =
  match cfg.focus with
  | F_expr { e = Literal v; _ } -> cfg.focus <- F_value v; settle cfg
  | F_value v -> (
      match cfg.stack with
      | K_binary_left (op, b, at) :: rest ->
          cfg.stack <- K_binary_right (op, v, at) :: rest; cfg.focus <- F_expr b; settle cfg
      | K_args cs :: _ -> if Calls.bind_value cfg cs v then (cfg.focus <- F_next; settle cfg)
      (* FROM, then TO, then STEP (§4.18): each value moves on to the next bound. *)
      | K_for_from f :: rest -> cfg.stack <- K_for_to (f, v) :: rest; cfg.focus <- F_expr f.to_; settle cfg
      | K_for_to (f, from) :: rest when f.step <> None ->
          cfg.stack <- K_for_step (f, from, v) :: rest;
          cfg.focus <- F_expr (Option.get f.step); settle cfg
      | _ -> ())
  | F_loc l -> (
      match cfg.stack with
      | K_read :: rest -> cfg.stack <- rest; cfg.focus <- F_value (get l); settle cfg
      | K_component k :: rest -> (
          match get l with
          | V.Record comps -> cfg.stack <- rest; cfg.focus <- F_loc { box = comps; idx = k }; settle cfg
          | _ -> ())
      | K_assign_value e :: rest -> cfg.stack <- K_assign_store l :: rest; cfg.focus <- F_expr e; settle cfg
      | K_element_base (idx, at) :: rest ->
          cfg.stack <- K_element_index (l, idx, 0, at) :: rest; cfg.focus <- F_expr idx.(0); settle cfg
      | _ -> ())
  (* A place is located down to its first index expression, or to its location. *)
  | F_place p -> (
      match p with
      | Whole _ | Component _ -> (
          let l = static_loc cfg p in
          if l != no_loc then (cfg.focus <- F_loc l; settle cfg)
          else match p with
            | Component (q, k) -> push cfg (K_component k); cfg.focus <- F_place q; settle cfg
            | _ -> ()  (* an absent parameter: place-absent is a step *))
      | Element (q, idx) ->
          let l = static_loc cfg q in
          if l != no_loc then push cfg (K_element_index (l, idx, 0, Source.no_region))
          else push cfg (K_element_base (idx, Source.no_region));
          (* [else]: not reached by a checked program (a record component is never an array,
             §2.14); kept so that the machine needs no such assumption. *)
          cfg.focus <- (if l != no_loc then F_expr idx.(0) else F_place q);
          settle cfg
      | Unresolved _ -> ())
  | F_next -> (
      match cfg.stack with
      | K_stmt (s, prev) :: rest ->
          cfg.stack <- rest; cfg.mark <- prev;
          (match cfg.act.retried with
           | Some r when r == s -> cfg.act.retries <- 0; cfg.act.retried <- None
           | _ -> ());
          settle cfg
      (* ch. 8: entering a statement takes the statement time, and it and the end of a
         statement list are points of response to interrupts. Settling passes through them
         when nothing happens there; otherwise it stops, and the step [next] makes: the time
         limit, or the interrupt served (taken here, held for it). *)
      | K_seq (b, i) :: rest ->
          if i < Array.length b.body then begin
            cfg.host.statement ();
            if cfg.host.now () > cfg.host.max_time || Waits.interrupt_taken cfg then cfg.charged <- true
            else (cfg.stack <- K_seq (b, i + 1) :: rest; cfg.focus <- F_stmt (Array.unsafe_get b.body i))
          end
          else if not (Waits.interrupt_taken cfg) then (cfg.stack <- rest; settle cfg)
      | K_args cs :: _ -> Calls.settle_arguments cfg cs  (* a literal argument is bound there *)
      | K_local_init (act, inits) :: rest -> (
          match inits with
          | [] -> cfg.stack <- rest; settle cfg
          | (slot, Init_default shape) :: more ->
              (* Routine data is counted in the memory budget while its routine is active;
                 beyond it, the step says so (memory-exhausted). *)
              if charge cfg act (V.shape_bytes shape) then begin
                act.slots.(slot) <- fresh_loc (V.default_of shape);
                cfg.stack <- K_local_init (act, more) :: rest; settle cfg
              end
          | (_, Init_expr _) :: _ -> ())
      | _ -> ())
  | _ -> ()
