(* Calls and routines (§3.11, §4.6, ch. 5): the arguments bound to the parameters, a RAPID
   routine entered and left, an installed routine run through the host, late binding, routine
   data initialised. Why a module of its own: calls.mli. *)

open Configuration
open Store
open Event
open Outcome
module V = Value

(* What an activation costs by the model of Value.bytes, besides its data: a record, its frames
   and one slot per parameter and routine data object. *)
let activation_bytes (r : Ir.routine) = 256 + 16 * r.locals

(* Every argument bound, a RAPID routine is entered: a new activation, whose routine data is fresh
   (§2.21), within the call-depth limit and the memory budget. *)
let enter_routine cfg (cs : call_state) =
  let r = cs.callee in
  let depth = cfg.act.call_depth + 1 in
  if depth > cfg.limits.max_call_depth then begin
    cfg.focus <- F_done (Limits.call_depth_exceeded cfg.limits);
    (Rule.Call_depth_exceeded, [])
  end
  else if activation_bytes r > cfg.limits.max_memory - cfg.memory - cs.args_memory then begin
    (* The activation itself counts: a very deep recursion stays within the budget too. *)
    cfg.focus <- F_done (memory_exhausted cfg ("the call of " ^ r.name) (region_of_focus_stmt cfg));
    (Rule.Memory_exhausted, [])
  end
  else begin
    let slots = Array.make r.locals { box = [||]; idx = 0 } in
    Array.blit cs.args_slots 0 slots 0 (Array.length cs.args_slots);
    for i = Array.length cs.args_slots to r.locals - 1 do slots.(i) <- fresh_loc (V.Bool false) done;
    let act = activation ~routine:r ~slots ~present:cs.args_present ~kinds:cs.args_kinds
        ~module_data:cs.args_module_data ~caller:(Some cfg.act) ~return_to:cfg.stack ~caller_mark:cfg.mark in
    (* The in arguments' copies were checked against the budget when they were made. *)
    act.memory <- cs.args_memory + activation_bytes r;
    cfg.memory <- cfg.memory + act.memory;
    cfg.act <- act;
    (* Routine data is fresh for every call (§2.21): initialised, then the body runs. *)
    cfg.stack <- [ K_local_init (act, r.local_inits); K_seq (r.body, 0); K_routine_end ];
    cfg.mark <- [];
    cfg.focus <- F_next;
    (Rule.Call_enter, Routine_entered r.name
                   :: (if cfg.observe && Array.length r.parameters > 0 then
                         [ Observed (Called { routine = r.name; arguments = List.filter_map (fun x -> x)
                             (List.mapi (fun i (p : Ir.parameter) ->
                                  if i < Array.length cs.args_present && not cs.args_present.(i) then None
                                  else if p.p_switch then Some (p.p_name, None)
                                  else Some (p.p_name, Some (Observation.value (get slots.(i)))))
                                (Array.to_list r.parameters)) }) ]
                       else []))
  end

(* RETURN, or the end of a procedure or trap (§4.10): the caller's stack and mark come back, with
   a function's value in focus; from a trap, execution goes on where the interrupt came in. *)
let return_from cfg value =
  let act = cfg.act in
  match act.caller with
  | None -> (
      match next_phase cfg with
      | Some next -> (Rule.Return_entry, [ Routine_left act.routine.name; Routine_entered next.name ])
      | None when resume cfg -> (Rule.Return_entry, [ Routine_left act.routine.name ])
      | None ->
          cfg.focus <- F_done Ended;
          (Rule.Return_entry, [ Routine_left act.routine.name; Task_ended ]))
  | Some caller when act.routine.kind = Trap ->
      (* ch. 8: after ENDTRAP or RETURN, execution goes on where the interrupt came in. *)
      cfg.act <- caller; cfg.stack <- act.return_to; cfg.mark <- act.caller_mark;
      cfg.focus <- F_next;
      (Rule.Trap_end, [ Routine_left act.routine.name; Trap_left { trap = act.routine.name; time = cfg.host.now () } ])
  | Some caller ->
      release cfg act;
      cfg.act <- caller;
      cfg.stack <- act.return_to;
      cfg.mark <- act.caller_mark;
      (match act.routine.kind, value with
       | Function, Some v -> cfg.focus <- F_value v
       | _ -> cfg.focus <- F_next);
      ((match act.routine.kind with Function -> Rule.Return_function | _ -> Rule.Return_procedure),
       (match value with
        | Some v when cfg.observe && act.routine.kind = Function ->
            [ Observed (Returned { routine = act.routine.name; value = Observation.value v }) ]
        | _ -> [])
       @ [ Routine_left act.routine.name ])

(* The binding an alias argument has: a parameter passes on its own binding (§5.2). *)
let reference_kind cfg (p : Ir.place) (k : Ir.reference_kind) =
  let rec root = function
    | Ir.Whole s -> Some s
    | Element (p, _) | Component (p, _) -> root p
    | Unresolved _ -> None
  in
  match root p with
  | Some (Local i) when i < Array.length cfg.act.kinds -> cfg.act.kinds.(i)
  | _ -> k

(* What the world observed so far goes into the events before what a primitive does next, so
   that an effect is never seen before its cause (ErrWrite's entry, then the IError interrupt it
   makes occur). *)
let flush_world cfg events =
  match cfg.host.observations () with
  | [] -> ()
  | seen -> List.iter (fun o -> events := Controller o :: !events) seen

let call_context cfg (cs : call_state) : Installed_routine.context = {
  parameters = Installed_routine.parameter_names cs.callee;
  argument_label = Installed_routine.argument_label cfg.program cs.callee cs.call.arguments;
  book_error = cfg.host.book_error;
  error_number = (fun name -> error_number cfg name);
}

(* [Statements.exec], which comes after the calls: StartMoveRetry runs the RETRY statement's
   rule (R-7.6-b). *)
let exec_ref : (config -> Ir.stmt -> Rule.t * Event.t list) ref = ref (fun _ _ -> (Rule.Stuck, []))

(* The routine a late-bound name denotes (§4.6): "name1:name2" the routine name2 of module
   name1 (a LOCAL one too); a plain name by the scope rules of §5.3 from the calling module: its
   own routines, then the global ones. The routines of a name come from a table built once, so
   the look-up is O(1) in the size of the program. *)
(* A name's routines in increasing order: those of the shared table come first in the program. *)
let routines_named ((shared, own) : (string, int list) Hashtbl.t * (string, int list) Hashtbl.t) key =
  match Hashtbl.find_opt shared key with
  | None -> Hashtbl.find_opt own key
  | Some l -> (match Hashtbl.find_opt own key with None -> Some l | Some l' -> Some (l @ l'))

let late_routine cfg name =
  let module_name, routine_name =
    match String.index_opt name ':' with
    | Some i -> (Some (String.sub name 0 i), String.sub name (i + 1) (String.length name - i - 1))
    | None -> (None, name)
  in
  let same = Rapid_typing.Types.same_name in
  let here = cfg.act.routine.module_name in
  let candidates =
    Option.value (routines_named cfg.by_name (String.lowercase_ascii routine_name)) ~default:[] in
  let find pred = List.find_opt (fun i -> pred cfg.program.routines.(i)) candidates in
  match module_name with
  | Some m -> find (fun (r : Ir.routine) -> same r.module_name m)
  | None -> (
      match find (fun (r : Ir.routine) -> same r.module_name here) with
      | Some i -> Some i
      | None -> find (fun (r : Ir.routine) -> not r.local))

(* A call starts: its arguments are bound one by one, in order (§5.2). *)
let begin_call cfg (call : Ir.call) =
  match call.callee with
  | Unknown_routine name -> raise_ ~about:name cfg "ERR_REFUNKPRC"; Rule.Call_unknown
  | Routine i ->
      let callee = cfg.program.routines.(i) in
      let n = Array.length callee.parameters in
      push cfg (K_args { call; callee; args_slots = Array.make n (fresh_loc (V.Bool false));
                         args_present = Array.make n false; args_kinds = Array.make n Ir.Ref_other;
                         args_module_data = Array.make n false; args_memory = 0;
                         primitive_args = Array.make n Argument.Missing; next = 0 });
      cfg.focus <- F_next;
      Rule.Call_arguments

(* An installed routine, every argument bound, runs through the host: what it answers is the rule. *)
let call_primitive cfg (cs : call_state) name =
  if String.length name = 11 && String.lowercase_ascii name = "raisetouser" then Recovery.raise_to_user cfg cs else
  let events = ref [] in
  let before = if cfg.observe then Observation.references cs.primitive_args else [] in
  let entry = cfg.host.routine name in
  let outcome = match entry with
    | Some entry -> entry.call (call_context cfg cs) cs.primitive_args
    | None -> { Installed_routine.result = Not_modelled; events = []; new_move = None } in
  (* What the world observed before the call comes before what the call made observable (a
     routine that reaches the world has its observations among its events already). *)
  if outcome.events <> [] then begin
    flush_world cfg events;
    events := List.rev_append outcome.events !events
  end;
  (* Schema rapid-sem/2: the writes through its reference arguments, after its own events. *)
  List.iter (fun (box, idx) ->
      events := List.rev_append (observed_store cfg { box; idx } box.(idx)) !events) (Observation.changed before);
  (* A move remembers the routine that ran it: its asynchronous errors go there (§7.4, §7.6). *)
  (match outcome.new_move with
   | Some id -> Recent.add cfg.move_owners id cfg.act
   | None -> ());
  match outcome.result with
  | History_exhausted m ->
      (* The history --samples or rapid-sem motion keeps, beyond its budget (doc/motion.md). *)
      cfg.focus <- F_done (Outcome.motion_history_exhausted m cs.call.call_at);
      (Rule.Motion_history_exhausted, List.rev !events)
  | Wait { wait; first_poll } ->
      (* WaitUntil evaluates its condition again at every poll: the argument's expression. *)
      let cond = match entry with
        | Some entry when wait.poll <> None -> Installed_routine.condition_argument entry cs.callee cs.call.arguments
        | _ -> None in
      let now = cfg.host.now () in
      let next_poll = Rapid_observable.Wait.first_poll wait ~now first_poll in
      push cfg (K_wait { wait; cond; next_poll });
      cfg.focus <- F_next;
      (Rule.Wait_start, List.rev !events)
  | Returned v ->
      (match cs.callee.kind, v with
       | Function, Some v -> cfg.focus <- F_value v
       | Function, None -> raise_ cfg "ERR_FNCNORET"
       | _ -> cfg.focus <- F_next);
      (Rule.Call_primitive, List.rev !events)
  | Failed { error = name; at_move = true } ->
      (* §7.4: a \SyncLastMoveInst error, raised at the move instruction. *)
      cfg.focus <- F_raise { (error cfg name (region_of_focus_stmt cfg)) with asynchronous = true };
      (Rule.Async_error_at_move, List.rev !events)
  | Failed { error = name; at_move = false } -> raise_ cfg name; (Rule.Call_primitive_error, List.rev !events)
  | Stop_requested -> cfg.focus <- F_done Ended; (Rule.Call_primitive_stop, List.rev !events @ [ Task_ended ])
  | Exit_cycle_requested ->
      (* R-13-exitcycle1: every routine is abandoned as by EXIT, then the entry starts again. *)
      cfg.focus <- F_abandon Go_on_exit_cycle; (Rule.Call_primitive_exit_cycle, List.rev !events)
  | Call_by_name target -> (
      (* CallByVar: a late-bound call without arguments (§4.6). *)
      match late_routine cfg target with
      | None ->
          raise_ ~about:target cfg (Late_binding.unknown_procedure_error target);
          (Rule.Call_by_var_unknown, List.rev !events)
      | Some i when cfg.program.routines.(i).kind <> Procedure ->
          raise_ ~about:target cfg "ERR_CALLPROC"; (Rule.Call_by_var_mismatch, List.rev !events)
      | Some i -> (
          match Late_binding.bind cfg.program.routines.(i) ~kind:(reference_kind cfg) [||] with
          | Error name -> raise_ ~about:target cfg name; (Rule.Call_by_var_mismatch, List.rev !events)
          | Ok arguments ->
              let rule = begin_call cfg { Ir.callee = Routine i; arguments; call_at = cs.call.call_at } in
              ignore rule; (Rule.Call_by_var, List.rev !events)))
  | Not_modelled when cfg.stub_unmodelled ->
      (* --stub-unmodelled (doc/rulings.md R-13-i): the call does nothing; a function gives the
         initial value of its type (§2.22); VAR and INOUT arguments keep their values. *)
      let key = String.lowercase_ascii name in
      let first = not (Hashtbl.mem cfg.stubbed key) in
      if first then Hashtbl.replace cfg.stubbed key ();
      (match cs.callee.kind with
       | Function -> cfg.focus <- F_value (Installed_routine.stub_value cs.callee)
       | Procedure | Trap -> cfg.focus <- F_next);
      (Rule.Call_stubbed,
       List.rev !events @ (if first then [ Stubbed { routine = cs.callee.name; at = cs.call.call_at } ] else []))
  | Retry_requested -> (
      (* StartMoveRetry: StartMove, then the RETRY statement's rule; outside an error handler
         there is nothing to retry: StartMove alone (R-7.6-b). *)
      match cfg.act.handling with
      | In_handler _ ->
          let rule, more = !exec_ref cfg { Ir.s = Ir.Retry; sat = cs.call.call_at } in
          (rule, List.rev !events @ more)
      | _ -> cfg.focus <- F_next; (Rule.Call_primitive, List.rev !events))
  | Assertion_failed message ->
      (* rapid-sem test (R-test-b): the task stops at the call, as Stop does: no handler, no UNDO. *)
      cfg.focus <- F_done (Stopped { name = "ERR_ASSERT"; number = error_number cfg "ERR_ASSERT"; at = cs.call.call_at;
                                     chain = call_chain cfg.act; about = Some message });
      (Rule.Call_primitive_stop, List.rev !events)
  | Not_modelled ->
      cfg.focus <- F_done (Outcome.not_modelled cs.callee.name cs.call.call_at);
      (Rule.Call_not_modelled, List.rev !events)
  | Unanswered reason ->
      (* R-13-ui2: the scripted operator has no answer for this dialogue; the run ends there. *)
      cfg.focus <- F_done (Outcome.unanswered cs.callee.name reason cs.call.call_at);
      (Rule.Call_not_modelled, List.rev !events)

(* Does the place denote module data (a module variable), seen through the parameters it goes
   through? CONNECT needs it (§4.15). *)
let denotes_module_data cfg (p : Ir.place) =
  let rec root = function
    | Ir.Whole s -> Some s
    | Element (p, _) | Component (p, _) -> root p
    | Unresolved _ -> None
  in
  match root p with
  | Some (Global _) -> true
  | Some (Local i) -> i < Array.length cfg.act.module_data && cfg.act.module_data.(i)
  | None -> false

(* §3.11, §5.2: of mutually exclusive optional parameters at most one is present; two made
   present by conditional arguments is ERR_ARGDUPCND (ch. 12). The alternatives of one
   optional parameter stand together in the parameter list. *)
let duplicate_alternative cfg (cs : call_state) i =
  let params = cs.callee.parameters in
  let g = params.(i).p_group in
  g >= 0
  && (let present j =
        cs.args_present.(j)
        || (match cs.call.arguments.(j) with
            | Present_switch | By_value _ | By_reference _ -> true
            | Pass_on (Local k) -> k < Array.length cfg.act.present && cfg.act.present.(k)
            | Absent | Pass_on (Global _) -> false) in
      let rec around j step =
        j >= 0 && j < Array.length params && params.(j).p_group = g
        && (present j || around (j + step) step) in
      around (i - 1) (-1) || around (i + 1) 1)

(* §5.2, the two execution-error cells of the access-mode table: an INOUT parameter bound to a
   variable passed on to a PERS parameter, or bound to a persistent passed on to a VAR one. *)
let alias_allowed (p : Ir.parameter) (k : Ir.reference_kind) =
  match p.p_mode, k with
  | Mode_var, Ref_persistent -> Error "ERR_ARGNOTVAR"
  | Mode_pers, (Ref_variable | Ref_other) -> Error "ERR_ARGNOTPER"
  | _ -> Ok ()

(* The bytes the memory budget still holds for the arguments of a call in progress. *)
let args_room cfg (cs : call_state) = cfg.limits.max_memory - cfg.memory - cs.args_memory

(* §5.2: an in parameter is a copy of the argument's value; false when the budget does not hold
   the copy (the step that meets it says so: memory-exhausted). *)
let bind_value cfg (cs : call_state) v =
  let bytes = V.bytes v in
  if bytes > args_room cfg cs then false
  else begin
    let i = cs.next in
    cs.args_memory <- cs.args_memory + bytes;
    cs.args_slots.(i) <- fresh_loc (V.copy v);
    cs.args_present.(i) <- true;
    cs.primitive_args.(i) <- Argument.Value v;
    cs.next <- i + 1;
    true
  end

(* The arguments that need no step of their own are bound as soon as the call reaches them
   (§5.2): an absent optional parameter, a switch, a conditional argument [\p ? x] (§3.11), a
   literal. Then the call waits for the expression of a value argument (in focus), a reference
   argument, or, all bound, the call itself: each of these is a step. So does an argument that
   cannot be bound quietly: one the memory budget does not hold, a conditional argument that
   duplicates an alternative (ERR_ARGDUPCND). O(parameters), like the call state the call
   allocates. *)
let rec settle_arguments cfg (cs : call_state) =
  let i = cs.next in
  if i < Array.length cs.call.arguments then begin
    let p = cs.callee.parameters.(i) in
    let absent () =
      (* An absent parameter still has storage of its type (it cannot be used, §5.2). *)
      let bytes = V.shape_bytes p.p_default in
      if bytes <= args_room cfg cs then begin
        cs.next <- i + 1;
        cs.args_memory <- cs.args_memory + bytes;
        cs.args_slots.(i) <- fresh_loc (V.default_of p.p_default);
        settle_arguments cfg cs
      end
    in
    match cs.call.arguments.(i) with
    | Absent -> absent ()
    | Present_switch ->
        cs.next <- i + 1;
        cs.args_present.(i) <- true;
        cs.primitive_args.(i) <- Argument.Switch;
        settle_arguments cfg cs
    | Pass_on (Local j) when j < Array.length cfg.act.present && cfg.act.present.(j) ->
        if not (duplicate_alternative cfg cs i) then begin
          cs.next <- i + 1;
          cs.args_present.(i) <- true;
          cs.args_slots.(i) <- cfg.act.slots.(j);
          cs.args_kinds.(i) <- cfg.act.kinds.(j);
          cs.args_module_data.(i) <- j < Array.length cfg.act.module_data && cfg.act.module_data.(j);
          cs.primitive_args.(i) <- Argument.Location (cfg.act.slots.(j).box, cfg.act.slots.(j).idx, cfg.act.kinds.(j));
          settle_arguments cfg cs
        end
    | Pass_on _ -> absent ()
    | By_value { e = Literal v; _ } ->
        if bind_value cfg cs v then settle_arguments cfg cs else cfg.focus <- F_value v
    | By_value e -> cfg.focus <- F_expr e
    | By_reference _ -> ()
  end

(* §5.2: a VAR, PERS, INOUT or REF parameter is the argument's location. *)
let bind_alias cfg (cs : call_state) rest l =
  let i = cs.next in
  let p = cs.callee.parameters.(i) in
  match alias_allowed p cs.args_kinds.(i) with
  | Error name -> cfg.stack <- rest; raise_ cfg name; (Rule.Argument_alias_refused, [])
  | Ok () ->
      cs.args_slots.(i) <- l;
      cs.args_present.(i) <- true;
      cs.primitive_args.(i) <- Argument.Location (l.box, l.idx, cs.args_kinds.(i));
      cs.next <- i + 1;
      cfg.focus <- F_next;
      (Rule.Argument_alias, [])

(* A reference argument, an argument that cannot be bound quietly (see [settle_arguments]), or
   the call itself when every argument is bound (§5.2). *)
let next_argument cfg (cs : call_state) rest =
  let n = Array.length cs.call.arguments in
  if cs.next >= n then begin
    cfg.stack <- rest;
    match cs.callee.primitive with
    | Some name -> call_primitive cfg cs name
    | None -> enter_routine cfg cs
  end
  else
    let i = cs.next in
    let p = cs.callee.parameters.(i) in
    let unsettled () =
      cfg.focus <- F_done (Stuck "an argument left unsettled"); (Rule.Stuck, []) in
    match cs.call.arguments.(i) with
    | By_reference (place, k) ->
        cs.args_kinds.(i) <- reference_kind cfg place k;
        cs.args_module_data.(i) <- denotes_module_data cfg place;
        let l = static_loc cfg place in
        if l != no_loc then bind_alias cfg cs rest l
        else (cfg.focus <- F_place place; (Rule.Argument_reference, []))
    | Pass_on (Local j) when j < Array.length cfg.act.present && cfg.act.present.(j) ->
        if duplicate_alternative cfg cs i then begin
          cfg.stack <- rest; raise_ cfg "ERR_ARGDUPCND"; (Rule.Argument_pass_on_duplicate, [])
        end
        else unsettled ()
    | Absent | Pass_on _ when V.shape_bytes p.p_default > args_room cfg cs ->
        cfg.stack <- rest;
        cfg.focus <- F_done (memory_exhausted cfg ("the absent parameter " ^ p.p_name) (region_of_focus_stmt cfg));
        (Rule.Memory_exhausted, [])
    | Absent | Pass_on _ | Present_switch | By_value _ -> unsettled ()

(* ------------------------------------------------------------------ the frames of calls *)

(* The end of a routine's body: a procedure or trap returns (§4.10); a function has no RETURN. *)
let routine_end cfg =
  match cfg.act.routine.kind with
  | Function ->
      (* §5.5: a function ends with RETURN; falling off its end is ERR_FNCNORET, raised
         where the function was called (doc/rulings.md R-5.5). *)
      let act = cfg.act in
      (match act.caller with
       | None -> cfg.focus <- F_done (Stuck "a function as entry routine")
       | Some caller ->
           release cfg act;
           cfg.act <- caller; cfg.stack <- act.return_to; cfg.mark <- act.caller_mark;
           cfg.focus <- F_raise (error ~about:act.routine.name cfg "ERR_FNCNORET" (region_of_focus_stmt cfg)));
      (Rule.Function_no_return, [ Routine_left act.routine.name ])
  | Procedure | Trap -> return_from cfg None

(* Routine data with an initial value, at each call (§2.21, §2.22): the value is evaluated, then
   stored; the data without are initialised by settling, within the budget. *)
let local_init cfg (act : activation) (inits : (int * Ir.init) list) rest =
  match inits with
  | (_, Init_default shape) :: _ when V.shape_bytes shape > cfg.limits.max_memory - cfg.memory ->
      (* Settling initialises routine data the budget holds (see [Statements.settle]). *)
      cfg.focus <- F_done (memory_exhausted cfg ("the routine data of " ^ act.routine.name)
                             (match act.caller_mark with K_stmt (s, _) :: _ -> s.sat | _ -> act.routine.at));
      (Rule.Memory_exhausted, [])
  | (slot, Init_expr e) :: more ->
      act.slots.(slot) <- fresh_loc (V.Bool false);
      cfg.stack <- K_assign_store act.slots.(slot) :: K_local_init (act, more) :: rest;
      cfg.focus <- F_expr e; (Rule.Local_initial_value, [])
  | _ ->
      cfg.focus <- F_done (Stuck "routine data left unsettled"); (Rule.Stuck, [])

(* The name of a late-bound call has been evaluated (§4.6): the procedure it names is called. *)
let late_name cfg args at rest v =
  cfg.stack <- rest;
  match v with
  | V.String name -> (
      let found = late_routine cfg name in
      match found with
      | None -> raise_ ~about:name cfg (Late_binding.unknown_procedure_error name); (Rule.Call_late_unknown, [])
      | Some i when cfg.program.routines.(i).kind <> Procedure ->
          (* §4.6: late binding calls procedures only. *)
          raise_ ~about:name cfg "ERR_CALLPROC"; (Rule.Call_late_mismatch, [])
      | Some i -> (
          let r = cfg.program.routines.(i) in
          match Late_binding.bind r ~kind:(reference_kind cfg) args with
          | Error error_name -> raise_ ~about:name cfg error_name; (Rule.Call_late_mismatch, [])
          | Ok arguments ->
              (begin_call cfg { Ir.callee = Routine i; arguments; call_at = at }, [])))
  | _ -> raise_ cfg "ERR_CALLPROC"; (Rule.Call_late_mismatch, [])

let fit cfg shape rest v =
  cfg.stack <- rest;
  (* §3.10: an aggregate takes its parameter's type, when its members fit it. *)
  match V.conform shape v with
  | Some v -> cfg.focus <- F_value v; (Rule.Argument_fit, [])
  | None -> (match rest with K_args _ :: r -> cfg.stack <- r | _ -> ());
      raise_ cfg "ERR_CALLPROC"; (Rule.Argument_fit_refused, [])

(* Settling binds a value argument the budget holds (see [Statements.settle]). *)
let copy_exhausted cfg (cs : call_state) rest =
  cfg.stack <- rest;
  cfg.focus <- F_done (memory_exhausted cfg ("the copy for the parameter " ^ cs.callee.parameters.(cs.next).p_name)
                         (region_of_focus_stmt cfg));
  (Rule.Memory_exhausted, [])
