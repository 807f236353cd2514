(* Errors and error recovery (ch. 7): an error in flight, its handler, propagation, the long
   jump, UNDO handlers and abandoned routines, the user level of NOSTEPIN routines and
   RaiseToUser (§7.3), and the asynchronous errors of the motion (§7.4, §7.6). Why a module of
   its own: recovery.mli. *)

open Configuration
open Store
open Event
open Outcome
module V = Value

(* §7.2: a move instruction whose wait an error or a long jump leaves is cancelled, and with it
   the rest of its path (doc/motion.md, M-abandon). *)
let waits_left cfg =
  List.iter (function
      | K_wait ws -> cfg.host.wait_abandoned ws.wait
      | _ -> ()) cfg.stack

(* §7.1: the error handler of the current routine takes control. *)
let handle cfg (e : err) =
  let act = cfg.act in
  match act.routine.error with
  | None -> assert false
  | Some h ->
      waits_left cfg;
      (* R-7.2-m: an error a long jump brings between two statements of the routine's body (a
         trap served at a point of response), no statement of it in progress, keeps the stack
         of that point: RETRY and TRYNEXT go on from there. *)
      let point = match cfg.mark, cfg.stack with
        | [], (K_seq _ :: _ as at_point) -> at_point
        | mark, _ -> mark in
      act.handling <- In_handler (e, point);
      set_errno cfg e.number;
      cfg.stack <- [ K_seq (h.handler, 0); K_handler_end ];
      cfg.mark <- [];
      cfg.focus <- F_next;
      (Rule.Raise_handle, [ Error_handled { name = e.name; routine = act.routine.name } ])

(* §7.3: the user level of a routine of a NOSTEPIN module: the first routine above it in the
   call chain that is not one (a trap's caller is no call: none across it), with the mark of its
   call that led into the NOSTEPIN routines. *)
let user_call (act : activation) =
  let rec go (a : activation) =
    match a.caller with
    | Some c when a.routine.kind <> Trap -> if c.routine.nostepin then go c else Some (c, a.caller_mark)
    | _ -> None in
  if act.routine.nostepin then go act else None

let region_of_mark (a : activation) = function K_stmt (s, _) :: _ -> s.Ir.sat | _ -> a.routine.at

(* An error is reported at the user level (§7.3, R-7.3-o): the call in user code, and the call
   chain from there. *)
let at_user_level (act : activation) (e : err) =
  match user_call act with
  | Some (user, mark) -> { e with err_at = region_of_mark user mark; chain = lazy (call_chain user) }
  | None -> e

(* The system error handler stops the task (§7.1), reporting the error at the user level. *)
let stop cfg (e : err) rule =
  let e = at_user_level cfg.act e in
  cfg.focus <- F_done (Stopped { name = e.name; number = e.number; at = e.err_at; chain = Lazy.force e.chain;
                                 about = e.about });
  (rule, [])

(* An error in flight in the current activation (§7.1, §7.2). *)
let raise_step cfg (e : err) =
  let act = cfg.act in
  match act.handling, act.routine.error with
  | _ when cfg.backward_depth >= 0 && act.call_depth >= cfg.backward_depth ->
      (* §6.1: an error while a BACKWARD handler runs cannot be handled by an error handler. *)
      stop cfg e Rule.Raise_in_backward
  | (In_handler _ | In_undo), _ -> stop cfg e Rule.Raise_in_handler
  | Body, Some _ when not (initialising cfg act) -> handle cfg e
  | Body, _ -> (
      match act.caller with
      | None -> stop cfg e Rule.Raise_unhandled
      | Some _ when act.routine.kind = Trap && e.searched ->
          (* An error that leaves a trap goes to the system error handler: there is no call
             point to raise it at (installed-facts.md section 6, R-8-e). *)
          stop cfg e Rule.Raise_in_trap
      | Some caller ->
          ignore caller;
          (* §7.2: only the routines with an error recovery point are searched. *)
          if e.searched then (cfg.focus <- F_abandon (Go_on_propagate e); (Rule.Raise_propagate, []))
          else (cfg.focus <- F_search (e, act.recovery_up); (Rule.Longjump_search_start, [])))

(* §7.2: the routine has an error recovery point whose list names the error (or
   LONG_JMP_ALL_ERR). *)
let recovery_point cfg (a : activation) (e : err) =
  match a.routine.error with
  | Some { recovery = Some numbers; all_errors; _ } ->
      all_errors
      || List.exists (function
          | Ir.Number n -> n = e.number
          | Object s ->
              let l = match s with Global i -> cfg.globals.(i) | Local i -> a.slots.(i) in
              (match get l with V.Num f -> Float.of_int e.number = f | _ -> false)) numbers
  | _ -> false

(* "The statement that caused the error" (§4.13, §4.14): an error in an ELSEIF condition is the
   IF statement's, which the ELSEIF's mark leads to (one mark per ELSEIF of the statement). *)
let rec statement_point = function
  | K_stmt ({ s = Elseif _; _ }, prev) :: _ -> statement_point prev
  | point -> point

(* RETRY and TRYNEXT in an error handler at user level that RaiseToUser \Continue entered go on
   in the NOSTEPIN routine whose error it was, as that routine's own would (§7.3). *)
let resume_nostepin cfg =
  match cfg.act.handling, cfg.act.resume with
  | In_handler _, Some inner ->
      let user = cfg.act in
      user.resume <- None; user.handling <- Body; cfg.act <- inner; true
  | _ -> false

(* §7.4: the handler of an asynchronous error taken while the program pointer was elsewhere
   (a kept program pointer): RETRY and TRYNEXT go on from where the program pointer was; RAISE,
   RETURN and EXIT first abandon the routines the program pointer is in above the handler's
   (their UNDO handlers run), then act as in any handler. *)
let kept_exit cfg (s : Ir.stmt) =
  if cfg.kept = [] then None
  else
    match List.find_opt (fun k -> k.handler == cfg.act) cfg.kept, s.s with
    | None, _ -> None
    | Some k, (Retry | Trynext | Raise _ | Return _ | Exit) -> (
        cfg.kept <- List.filter (fun k' -> k' != k) cfg.kept;
        let restore () = cfg.act <- k.pp_act; cfg.stack <- k.pp_stack; cfg.mark <- k.pp_mark in
        match s.s with
        | Retry | Trynext ->
            k.handler.handling <- Body;
            restore ();
            cfg.focus <- F_next;
            Some ((if s.s = Retry then Rule.Async_retry_resume else Rule.Async_trynext_resume), [])
        | Exit -> restore (); cfg.focus <- F_abandon Go_on_exit; Some (Rule.Async_exit, [])
        | _ when k.pp_act == k.handler ->
            (* The program pointer's own routine: its statement in progress is left as by any
               error (a move instruction's path with it, §7.6 example 3). *)
            restore (); waits_left cfg; None
        | _ ->
            restore ();
            cfg.focus <- F_abandon (Go_on_in_handler (s, k.handler));
            Some (Rule.Async_handler_leave, []))
    | Some _, _ -> None

(* §7.1: reaching the end of an error handler calls the system error handler. *)
let handler_end cfg =
  match cfg.act.handling with
  | In_handler (e, _) -> stop cfg e Rule.Handler_end
  | _ -> cfg.focus <- F_done (Stuck "end of a handler not in a handler"); (Rule.Stuck, [])

(* The activation of an abandoned routine is popped (§7.2): what made it abandoned goes on in
   the caller. *)
let leave_abandoned cfg after rule rule_entry =
  let act = cfg.act in
  match act.caller with
  | None when (match after with Go_on_exit_cycle -> true | _ -> false) && not cfg.at_entry -> (
      (* R-bk-8: ExitCycle in an event routine ends it; the task's sequence goes on. *)
      let routine = act.routine in
      match next_phase cfg with
      | Some next -> (Rule.Cycle_restart, [ Routine_left routine.name; Routine_entered next.name ])
      | None when resume cfg -> (Rule.Cycle_restart, [ Routine_left routine.name ])
      | None -> cfg.focus <- F_done Ended; (rule_entry, [ Routine_left routine.name; Task_ended ]))
  | None when (match after with Go_on_exit_cycle -> true | _ -> false) ->
      (* R-13-exitcycle1: the next cycle, a new activation of the entry routine (its routine
         data initialised again); module data, interrupts, files and the clock are kept. *)
      release cfg act;
      let routine = act.routine in
      let slots = Array.init routine.locals (fun _ -> fresh_loc (V.Bool false)) in
      let fresh = activation ~routine ~slots ~present:[||] ~kinds:[||] ~module_data:[||] ~caller:None
          ~return_to:[ K_task_end ] ~caller_mark:[] in
      cfg.act <- fresh;
      cfg.stack <- [ K_local_init (fresh, routine.local_inits); K_seq (routine.body, 0); K_routine_end; K_task_end ];
      cfg.mark <- [];
      cfg.kept <- [];
      cfg.focus <- F_next;
      (Rule.Cycle_restart, [ Routine_left routine.name; Routine_entered routine.name ])
  | None -> cfg.focus <- F_done Ended; (rule_entry, [ Task_ended ])
  | Some caller ->
      release cfg act;
      cfg.act <- caller; cfg.stack <- act.return_to; cfg.mark <- act.caller_mark;
      (* An error leaving NOSTEPIN routines for the user level is the call's there (R-7.3-o). *)
      let leaves_nostepin = act.routine.nostepin && not caller.routine.nostepin && act.routine.kind <> Trap in
      let relocate (e : err) = { e with err_at = region_of_focus_stmt cfg; chain = lazy (call_chain caller) } in
      let after = match after with
        | Go_on_propagate e when leaves_nostepin -> Go_on_propagate (relocate e)
        | Go_on_long_jump (e, target) when leaves_nostepin -> Go_on_long_jump (relocate e, target)
        | other -> other in
      (match after with
       | Go_on_exit -> cfg.focus <- F_abandon Go_on_exit
       | Go_on_exit_cycle -> cfg.focus <- F_abandon Go_on_exit_cycle
       | Go_on_propagate e -> cfg.focus <- F_raise { e with searched = true }; cfg.propagated <- true
       | Go_on_long_jump (e, target) ->
           if cfg.act == target then cfg.focus <- F_raise { e with searched = true }
           else cfg.focus <- F_abandon after
       | Go_on_in_handler (s, target) ->
           if cfg.act == target then cfg.focus <- F_stmt s else cfg.focus <- F_abandon after);
      (rule, Routine_left act.routine.name
             :: (if act.routine.kind = Trap then [ Trap_left { trap = act.routine.name; time = cfg.host.now () } ]
                 else [])
             @ (match after with
                 | Go_on_propagate e -> [ Observed (Propagated { name = e.name; number = e.number;
                                                                 routine = act.routine.name;
                                                                 caller = caller.routine.name }) ]
                 | _ -> []))

(* §7.4 (\SyncOrgMoveInst), §7.6 (collisions): an asynchronous error is raised when the program
   pointer waits (a move instruction, a waiting instruction), at that statement; not at trap
   level: after the trap (R-7.4-a). Its handler is looked for in the order of §7.6: the routine
   whose move instruction made the robot's path and up the call chain from it (steps 1-2; when
   that call was abandoned, a \SyncOrgMoveInst error goes one step up, to its caller, §7.4),
   then the program pointer's routine and up (steps 3-4); none: the system error handler
   (step 5). The handler runs with the program pointer kept where it was (R-7.4-m). *)
let serve_async_error cfg =
  if cfg.act.trap_level then None
  else
    match cfg.host.motion_error () with
    | None -> None
    | Some { error = name; move; handled } ->
        let e = { (error cfg name (region_of_focus_stmt cfg)) with searched = true; asynchronous = true } in
        let raised = Error_raised { name = e.name; number = e.number; at = e.err_at } in
        let owner = match move with Some id -> Recent.find_opt cfg.move_owners id | None -> None in
        let rec in_chain a = function None -> false | Some b -> b == a || in_chain a b.caller in
        let rec up acc = function None -> List.rev acc | Some b -> up (b :: acc) b.caller in
        let rec live = function
          | None -> []
          | Some b -> if in_chain b (Some cfg.act) then up [] (Some b) else live b.caller in
        let from_motion = match owner with
          | Some a when in_chain a (Some cfg.act) -> up [] (Some a)
          | Some a when name <> "ERR_COLL_STOP" -> live a.caller
          | _ -> [] in
        let takes (a : activation) =
          a.routine.error <> None && (match a.handling with Body -> true | In_handler _ | In_undo -> false) in
        match (if handled then List.find_opt takes (from_motion @ up [] (Some cfg.act)) else None) with
        | None ->
            let rule, events = stop cfg e Rule.Async_error_unhandled in
            Some (rule, raised :: events)
        | Some h ->
            cfg.kept <- { handler = h; pp_act = cfg.act; pp_stack = cfg.stack; pp_mark = cfg.mark } :: cfg.kept;
            let hd = Option.get h.routine.error in
            h.handling <- In_handler (e, []);
            set_errno cfg e.number;
            cfg.act <- h;
            cfg.stack <- [ K_seq (hd.handler, 0); K_handler_end ];
            cfg.mark <- [];
            cfg.focus <- F_next;
            Some (Rule.Async_error, [ raised; Error_handled { name = e.name; routine = h.routine.name } ])

(* Leaving the current activation because of EXIT, a propagated error or a long jump: its UNDO
   handler runs first (§7.2, §1.2). *)
let abandon_step cfg after =
  (* Without an UNDO handler to run, the routine is left in this step (settling: nothing runs
     in between). *)
  let act = cfg.act in
  waits_left cfg;
  match act.routine.undo, act.handling with
  | Some undo, (Body | In_handler _) ->
      act.handling <- In_undo;
      cfg.stack <- [ K_seq (undo, 0); K_undo_end after ];
      cfg.mark <- [];
      cfg.focus <- F_next;
      (Rule.Undo_run, [ Undo_run act.routine.name ])
  | _ -> leave_abandoned cfg after Rule.Abandon Rule.Abandon_entry

(* §7.2: the long jump looks for an error recovery point from the routine where the error
   arrives up the call chain; found, every routine in between is abandoned (UNDO first); not
   found, the error is raised again at the call point, an ordinary propagation. *)
let search_step cfg (e : err) candidate =
  match candidate with
  | Some a when recovery_point cfg a e ->
      cfg.focus <- F_abandon (Go_on_long_jump ({ e with searched = true }, a)); (Rule.Longjump_found, [])
  | Some a -> cfg.focus <- F_search (e, a.recovery_up); (Rule.Longjump_search, [])
  | None when cfg.act.routine.kind = Trap -> stop cfg e Rule.Raise_in_trap
  | None -> cfg.focus <- F_abandon (Go_on_propagate { e with searched = true }); (Rule.Raise_propagate, [])

(* ------------------------------------------------------------------ the user level *)

(* RaiseToUser (§7.3; ABB's RaiseToUser), in the error handler of a routine of a NOSTEPIN
   module: the error in hand, or \ErrorNumber's, goes to the error handler of the user level.
   \BreakOff abandons the NOSTEPIN routines up to it (their UNDO handlers run, but not this
   routine's: R-7.3-q) and the error is the user routine's, raised at its call; \Continue
   (\Resume) keeps them: the user's handler runs, and its RETRY or TRYNEXT goes on in this
   routine as its own would (R-7.3-p). No user level, or one without an error handler (or in a
   handler already): the system error handler. *)
let raise_to_user cfg (cs : call_state) =
  let act = cfg.act in
  let arg name =
    let found = ref Argument.Missing in
    Array.iteri (fun i (p : Ir.parameter) ->
        if String.lowercase_ascii p.p_name = name && i < Array.length cs.primitive_args then
          found := cs.primitive_args.(i)) cs.callee.parameters;
    !found in
  let present name = arg name <> Argument.Missing in
  match act.handling with
  | In_handler (e, _) when act.routine.nostepin && act.routine.kind <> Trap -> (
      let number = match arg "errornumber" with
        | Argument.Missing -> Some e.number
        | Value v -> (
            match Option.bind (num_of v) to_int with
            | Some n when (n >= 1 && n <= 90) || cfg.host.booked n
                          || List.exists (fun (_, m) -> m = n) cfg.program.error_numbers -> Some n
            | _ -> None)
        | _ -> None in
      match number with
      | None -> raise_ cfg "ERR_ILLRAISE"; (Rule.Raise_to_user_illegal, [])
      | Some n -> (
          let e' = { (error_of_number cfg n e.err_at) with searched = true } in
          match user_call act with
          | None -> stop cfg e' Rule.Raise_to_user_no_user_level
          | Some (user, mark) -> (
              let e' = { e' with err_at = region_of_mark user mark; chain = lazy (call_chain user) } in
              match user.routine.error, user.handling with
              | Some h, Body when present "breakoff" ->
                  (* This routine is left without its UNDO handler; those above it run theirs. *)
                  let rule, events =
                    leave_abandoned cfg (Go_on_long_jump (e', user)) Rule.Raise_to_user_break_off
                      Rule.Raise_to_user_break_off in
                  ignore h;
                  (rule, events)
              | Some h, Body ->
                  user.resume <- Some act;
                  user.handling <- In_handler (e', mark);
                  set_errno cfg n;
                  cfg.act <- user;
                  cfg.stack <- [ K_seq (h.handler, 0); K_handler_end ];
                  cfg.mark <- [];
                  cfg.focus <- F_next;
                  (Rule.Raise_to_user_continue,
                   [ Error_raised { name = e'.name; number = n; at = e'.err_at };
                     Error_handled { name = e'.name; routine = user.routine.name } ])
              | _ -> stop cfg e' Rule.Raise_to_user_unhandled)))
  | _ ->
      (* A call the checker cannot see (late binding): there is no error of a NOSTEPIN routine
         to hand on (R-7.3-n). *)
      cfg.focus <- F_done (Stopped { name = "ERR_ILLRAISE"; number = error_number cfg "ERR_ILLRAISE";
                                     at = cs.call.call_at; chain = call_chain act; about = Some "RaiseToUser" });
      (Rule.Raise_to_user_misplaced, [])
