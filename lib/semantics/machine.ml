(* The machine (machine.mli): a configuration started, stepped and viewed. The rules are in the
   parts, by chapter of the manual: Statements (ch. 3, 4; settling), Calls (ch. 5, §4.6),
   Recovery (ch. 7), Waits (ch. 8), Backward (ch. 6); Store holds what they share and
   Configuration the configuration's types. A step answers a Rule.t; [step] its name. *)

open Rapid_syntax
open Configuration
open Store
open Event
open Outcome
module V = Value

(* The neutral types of a run (lib/runtime). *)
type event = Event.t
type outcome = Outcome.t
type limits = Limits.t

type config = Configuration.config

(* ------------------------------------------------------------------ start *)

(* Routines by lower-case name, built once: a late-bound call looks its name up in O(1). The
   table is only read, so the runs of one program share it: the last one built is kept, keyed
   by the program's routine array compared physically (a fuzzer runs each program three times). *)
let last_by_name : (Ir.routine array * ((string, int list) Hashtbl.t * (string, int list) Hashtbl.t)) option ref =
  ref None

(* The leading routines that a program shares physically with the one before it (the installed
   ones, lowered once and numbered first for every task: Lower), with their table: the routine
   array they were found in, how many, the table. A program that starts with the same routines
   has that table and one of its own routines after them (a copy of the shared table, made for
   every program, was 1 % of a fuzzing campaign). *)
let shared_by_name : (Ir.routine array * int * (string, int list) Hashtbl.t) option ref = ref None

(* Routines [from] to [until - 1], in increasing order, each index after those of its name
   already there: a name's list is in increasing order. *)
let add_routines t (routines : Ir.routine array) ~from ~until =
  for i = from to until - 1 do
    let key = String.lowercase_ascii routines.(i).name in
    Hashtbl.replace t key (Option.value (Hashtbl.find_opt t key) ~default:[] @ [ i ])
  done

let common_prefix (a : Ir.routine array) (b : Ir.routine array) =
  let n = min (Array.length a) (Array.length b) in
  let rec go i = if i < n && a.(i) == b.(i) then go (i + 1) else i in
  go 0

let no_routines : (string, int list) Hashtbl.t = Hashtbl.create 1

let routines_by_name (program : Ir.program) =
  let routines = program.routines in
  let count = Array.length routines in
  match !last_by_name with
  | Some (r, t) when r == routines -> t
  | previous ->
      let t =
        match !shared_by_name with
        | Some (a, n, shared) when n <= count && common_prefix a routines >= n ->
            let own = Hashtbl.create (2 * (count - n) + 1) in
            add_routines own routines ~from:n ~until:count;
            (shared, own)
        | _ ->
            let t = Hashtbl.create (2 * count + 1) in
            add_routines t routines ~from:0 ~until:count;
            (match previous with
             | Some (r, _) ->
                 let n = common_prefix r routines in
                 if n > 0 then begin
                   let shared = Hashtbl.create (2 * n + 1) in
                   add_routines shared routines ~from:0 ~until:n;
                   shared_by_name := Some (routines, n, shared)
                 end
             | None -> ());
            (no_routines, t) in
      last_by_name := Some (routines, t);
      t

let routine_index_in by_name name =
  match Calls.routines_named by_name (String.lowercase_ascii name) with Some (i :: _) -> Some i | _ -> None

(* The routines a task runs one after the other (R-bk-8): the event routines [before], the entry
   routine, the event routines [after]; each a procedure without parameters. *)
let phase_routine program by_name ~is_entry name =
  match routine_index_in by_name name with
  | None when is_entry -> Error (Task_rules.no_entry program name)
  | None -> Error (Task_rules.not_an_event_routine program name)
  | Some i ->
      let r = program.Ir.routines.(i) in
      if r.kind <> Procedure || Array.length r.parameters > 0 then
        Error (if is_entry then
                 Printf.sprintf "%s is not a procedure without parameters: it cannot be the entry routine (§9.1)" name
               else Task_rules.not_an_event_routine program name)
      else Ok (r, is_entry)

let sequence program by_name ~before ~entry ~after =
  Task_rules.sequence ~find:(phase_routine program by_name) ~before ~entry ~after

let start ?(limits = Limits.default) ?(stub_unmodelled = false) ?(cooperative = false)
    ?(observe = false) ?(before = []) ?(after = []) ~(host : Host.t) (program : Ir.program) ~entry =
  let program = host.prepare program in
  let by_name = routines_by_name program in
  match sequence program by_name ~before ~entry ~after with
  | Error m -> Error m
  | Ok [] -> Error (Task_rules.no_entry program entry)
  | Ok ((routine, at_entry) :: phases) ->
      begin
        (* §2.21: module data first takes its type's initial value, within the memory budget. *)
        let memory = ref 0 in
        let too_big = ref None in
        (* Filled in place rather than by Array.map: an array of hundreds made from a fresh
           first element forces a minor collection (the runtime's caml_make_vect), at every
           start. *)
        let globals = Array.make (Array.length program.globals) no_loc in
        Array.iteri (fun i (g : Ir.global) ->
            globals.(i) <-
              (match g.g_init with
               | Init_default shape when !too_big = None ->
                   let bytes = V.shape_bytes shape in
                   if bytes > limits.max_memory - !memory then (too_big := Some g; fresh_loc (V.Bool false))
                   else (memory := !memory + bytes; fresh_loc (V.default_of shape))
               | _ -> fresh_loc (V.Bool false)))
          program.globals;
        (* §2.21: module data is static, initialised when its module is loaded, before the task
           runs: constant and literal expressions (§3.2, §3.3), evaluated here, not as steps. *)
        let rec eval (e : Ir.expr) : (V.t, string) result =
          match e.e with
          | Literal v -> Ok v
          | Read (Whole (Global i)) -> Ok (get globals.(i))
          (* An unknown name (--allow-unknown) is ERR_REFUNKDAT wherever it is read, here as in
             a statement and in the closure engine. *)
          | Read (Unresolved _) -> Error "ERR_REFUNKDAT"
          | Read (Component (p, k)) -> (
              match eval { e with e = Read p } with
              | Ok (V.Record cs) -> Ok cs.(k)
              | Ok _ -> Error "ERR_REFUNKDAT" | Error m -> Error m)
          | Read (Element (p, idx)) -> (
              match eval { e with e = Read p } with
              | Ok v ->
                  Array.fold_left (fun acc (ie : Ir.expr) ->
                      match acc, eval ie with
                      | Ok (V.Array es), Ok (V.Num f)
                        when Float.is_integer f && f >= 1. && int_of_float f <= Array.length es ->
                          Ok es.(int_of_float f - 1)
                      | Error m, _ | _, Error m -> Error m
                      | _ -> Error "ERR_OUTOFBND") (Ok v) idx
              | Error m -> Error m)
          | Read _ | Read_signal _ | Call _ | Placeholder | And _ | Or _ | Fitted _ -> Error "ERR_EXECPHR"
          | Unary (op, a) -> Result.bind (eval a) (Arith.unary op)
          | Binary (op, a, b) -> Result.bind (eval a) (fun x -> Result.bind (eval b) (Arith.binary op x))
          | Aggregate (es, kind) ->
              let vs = Array.map eval es in
              (match Array.find_opt Result.is_error vs with
               | Some (Error m) -> Error m
               | _ ->
                   let vs = Array.map (function Ok v -> v | Error _ -> V.Bool false) vs in
                   Ok (match kind with Record_value -> V.Record vs | Array_value -> V.Array vs))
        in
        let failed = ref None in
        Array.iteri (fun i (g : Ir.global) ->
            match g.g_init with
            | Init_expr e when !failed = None && !too_big = None -> (
                match eval e with
                | Ok v -> memory := !memory + V.bytes v; set globals.(i) v
                | Error name -> failed := Some (Printf.sprintf "the initial value of %s: %s" g.g_name name))
            | _ -> ()) program.globals;
        match !failed with
        | Some m -> Error m
        | None ->
        let slots = Array.init routine.locals (fun _ -> fresh_loc (V.Bool false)) in
        let act = activation ~routine ~slots ~present:[||] ~kinds:[||] ~module_data:[||] ~caller:None
            ~return_to:[ K_task_end ] ~caller_mark:[] in
        let cfg = {
          program; limits; globals; act; stack = [ K_task_end ]; mark = []; focus = F_next;
          count = 0; memory = !memory; by_name; unmarked = false; host;
          stub_unmodelled; stubbed = Hashtbl.create 8; move_owners = Recent.create Limits.move_owners; kept = [];
          backward_depth = -1; charged = false; held = None; cooperative; wake = None;
          observe; entered = false; propagated = false; phases; at_entry; resumes = [];
        } in
        cfg.stack <- [ K_local_init (act, routine.local_inits); K_seq (routine.body, 0); K_routine_end; K_task_end ];
        (match !too_big with
         | Some g -> cfg.focus <- F_done (memory_exhausted cfg ("the initial value of " ^ g.g_name) g.g_at)
         | None -> Statements.settle cfg);
        Ok cfg
      end

(* R-bk-11: the debugger's events (a step, a start, a restart, a stop) run their routines where
   the program pointer is, one after the other, each in a new activation; the control comes back
   when the last has ended. *)
let interpose cfg names =
  match names with
  | [] -> Ok []
  | _ -> (
      let found = List.fold_right (fun name acc ->
          match phase_routine cfg.program cfg.by_name ~is_entry:false name, acc with
          | Ok (r, _), Ok rs -> Ok (r :: rs)
          | Error m, _ | _, Error m -> Error m) names (Ok []) in
      match found with
      | Error m -> Error m
      | Ok routines ->
          cfg.resumes <- { r_act = cfg.act; r_stack = cfg.stack; r_mark = cfg.mark; r_focus = cfg.focus;
                           r_unmarked = cfg.unmarked; r_kept = cfg.kept; r_charged = cfg.charged; r_held = cfg.held;
                           r_phases = cfg.phases; r_at_entry = cfg.at_entry } :: cfg.resumes;
          cfg.phases <- List.map (fun r -> (r, false)) routines;
          cfg.at_entry <- false;
          cfg.unmarked <- false; cfg.charged <- false; cfg.held <- None;
          (* The current activation stays the resumed one's: next_phase must not release it. *)
          let saved = cfg.act in
          cfg.act <- { saved with memory = 0; resume = None };
          match Store.next_phase cfg with
          | None -> Ok []
          | Some r -> Statements.settle cfg; Ok [ Routine_entered r.name ])

let in_event_routine cfg = (not cfg.at_entry) || cfg.resumes <> []
let interposed cfg = List.length cfg.resumes

(* ------------------------------------------------------------------ the step *)

let step_unguarded cfg =
  match cfg.focus with
  | F_next -> Statements.next cfg
  | F_stmt s -> Statements.exec cfg s
  | F_expr e -> Statements.expr_step cfg e
  | F_value v -> Statements.value_step cfg v
  | F_place p -> Statements.place_step cfg p
  | F_loc l -> Statements.loc_step cfg l
  | F_raise e ->
      (* §7.1: an error raised again at the call point after propagation was said by the
         propagation (schema rapid-sem/2: one error-raised, then error-propagated per level). *)
      let again = cfg.propagated in
      cfg.propagated <- false;
      let rule, events = Recovery.raise_step cfg e in
      (rule, if again then events else Error_raised { name = e.name; number = e.number; at = e.err_at } :: events)
  | F_search (e, c) -> Recovery.search_step cfg e c
  | F_abandon after -> Recovery.abandon_step cfg after
  | F_done _ -> (Rule.Done, [])

(* A value of the wrong type for an operation is excluded by the static semantics: meeting one
   is a bug of rapid-sem, reported as a stuck configuration. The rule is answered as [answer]
   makes it: [step_rule] the constructor, [step] its name, with no second pair made a step. *)
let step_as answer cfg =
  cfg.count <- cfg.count + 1;
  (* The entry routine is entered with the first step (schema rapid-sem/2). *)
  let entry = if cfg.entered then [] else (cfg.entered <- true; [ Routine_entered cfg.act.routine.name ]) in
  let rule, events =
    try let r = step_unguarded cfg in Statements.settle cfg; r with
    | Value.Type_mismatch m -> cfg.focus <- F_done (Stuck ("a value of the wrong type: " ^ m)); (Rule.Stuck, [])
    | Invalid_argument m -> cfg.focus <- F_done (Stuck ("invalid argument: " ^ m)); (Rule.Stuck, [])
  in
  let events = match entry with [] -> events | _ -> entry @ events in
  (* What the world did during the step (signal changes, interrupts), with its times: mostly
     while the clock moved on, at the start of the step, or as settling entered a statement. *)
  let events = match cfg.host.observations () with
    | [] -> events
    | seen -> List.map (fun o -> Controller o) seen @ events in
  (* The motion: moves planned, begun and ended as the clock passes them; at the end of the
     task, what the robot still does. *)
  let moved = match cfg.focus with
    | F_done Ended -> let rest = cfg.host.motion_finish () in cfg.host.motion_events () @ rest
    | _ -> cfg.host.motion_events () in
  match moved with
  | [] -> (answer rule, events)
  | moved -> (answer rule, events @ List.map (fun e -> Motion e) moved)

let step_rule cfg = step_as Fun.id cfg
let step cfg = step_as Rule.name cfg

let host cfg = cfg.host
let trap_level cfg = cfg.act.trap_level

let outcome cfg = match cfg.focus with F_done o -> o | _ -> Running
let steps cfg = cfg.count
let depth cfg = cfg.act.call_depth

let focus_region cfg =
  match cfg.focus with
  | F_expr e -> e.at
  | F_stmt s -> s.sat
  | F_raise e | F_search (e, _) -> e.err_at
  | _ -> (
      match cfg.stack with
      | (K_binary_right (_, _, e) | K_unary (_, e)) :: _ -> e.at
      | K_args cs :: _ -> cs.call.call_at
      | _ -> (match cfg.mark with K_stmt (s, _) :: _ -> s.sat | _ -> cfg.act.routine.at))

let focus_kind cfg =
  match cfg.focus with
  | F_expr _ -> "expression" | F_value _ -> "value" | F_place _ -> "place" | F_loc _ -> "location"
  | F_stmt _ -> "statement" | F_next -> "next" | F_raise _ -> "error" | F_search _ -> "search"
  | F_abandon _ -> "abandon" | F_done _ -> "done"

let stack_view cfg =
  let rec take n = function
    | [] -> []
    | _ when n = 0 -> [ "..." ]
    | f :: rest -> frame_kind f :: take (n - 1) rest
  in
  take 8 cfg.stack

let rule_names = List.map Rule.name (List.filter Rule.listed Rule.all)

(* ------------------------------------------------------------------ views, for the trace *)

(* Computed only when the trace asks: running never builds them. *)

type location = loc

type focus_view =
  | Statement of Ir.stmt
  | Expression of Ir.expr
  | Place of Ir.place
  | Location of location
  | Value of V.t
  | Next
  | Error of { name : string; number : int; at : Source.region }
  | Search of string option
  | Abandon
  | End

type argument_view =
  | Bound_value of V.t
  | Bound_alias of location
  | Absent_argument
  | Switch_argument
  | Not_bound

type frame_view =
  | Binary_right of Arith.binary * V.t
  | Unary_operand of Arith.unary
  | And_right
  | Or_right
  | Aggregate_member of Ir.aggregate_kind * V.t array * int
  | Store of location * Ir.stmt option
  | Assign_target of Ir.stmt option
  | Condition of Ir.stmt option
  | For_bound of Ir.for_loop * V.t list
  | For_body of Ir.for_loop
  | While_body of Ir.expr
  | Test_value of V.t option
  | Return_value
  | Raise_value
  | Late_name
  | Element_index of location * int * int * bool
  | Call_arguments of { callee : Ir.routine; call : Ir.call; arguments : argument_view array; next : int }
  | Routine_end
  | Local_init of (int * Ir.init) list
  | Other_frame of string

let focus_view cfg =
  match cfg.focus with
  | F_stmt s -> Statement s
  | F_expr e -> Expression e
  | F_place p -> Place p
  | F_loc l -> Location l
  | F_value v -> Value v
  | F_next -> Next
  | F_raise e -> Error { name = e.name; number = e.number; at = e.err_at }
  | F_search (_, a) -> Search (Option.map (fun a -> a.routine.Ir.name) a)
  | F_abandon _ -> Abandon
  | F_done _ -> End

let statement_below = function K_stmt (s, _) :: _ -> Some s | _ -> None

let frame_view cfg =
  match cfg.stack with
  | [] -> Other_frame "empty"
  | f :: below -> (
      match f with
      | K_binary_right (op, v, _) -> Binary_right (op, v)
      | K_unary (op, _) -> Unary_operand op
      | K_and _ -> And_right
      | K_or _ -> Or_right
      | K_aggregate (_, acc, i, kind) -> Aggregate_member (kind, acc, i)
      | K_assign_store l -> Store (l, statement_below below)
      | K_assign_value _ -> Assign_target (statement_below below)
      | K_if _ | K_compact_if _ | K_while_test _ -> Condition (statement_below below)
      | K_for_from f -> For_bound (f, [])
      | K_for_to (f, from) -> For_bound (f, [ from ])
      | K_for_step (f, from, t) -> For_bound (f, [ from; t ])
      | K_for_body (f, _, _) -> For_body f
      | K_while_body (c, _) -> While_body c
      | K_test_subject _ -> Test_value None
      | K_test_value (v, _, _, _, _) -> Test_value (Some v)
      | K_return_value -> Return_value
      | K_raise_value -> Raise_value
      | K_late_name _ -> Late_name
      | K_element_index (l, idx, i, _) ->
          Element_index (l, i, Array.length idx, (match below with K_read :: _ -> true | _ -> false))
      | K_args cs ->
          let arguments = Array.mapi (fun i (a : Ir.argument) ->
              if i >= cs.next then Not_bound
              else match a with
                | Absent -> Absent_argument
                | Present_switch -> Switch_argument
                | Pass_on _ when not cs.args_present.(i) -> Absent_argument
                | By_value _ -> Bound_value (get cs.args_slots.(i))
                | By_reference _ | Pass_on _ -> Bound_alias cs.args_slots.(i)) cs.call.arguments in
          Call_arguments { callee = cs.callee; call = cs.call; arguments; next = cs.next }
      | K_routine_end -> Routine_end
      | K_local_init (_, inits) -> Local_init inits
      | f -> Other_frame (frame_kind f))

let location_value = get

(* Where a location is: searched from the current activation's slots, then the module data, by
   identity of the storage; the path runs from the data object to the location. *)
type path_step = Observation.step = Index of int | Component_of of int

let location_path cfg (l : location) =
  let within v _ = Observation.path_within (l.box, l.idx) v in
  let search roots slot =
    let rec go i =
      if i >= Array.length roots then None
      else
        let r = roots.(i) in
        if r.box == l.box && r.idx = l.idx then Some (slot i, [])
        else match within (get r) [] with
          | Some path -> Some (slot i, path)
          | None -> go (i + 1)
    in
    go 0
  in
  match search cfg.act.slots (fun i -> Ir.Local i) with
  | Some p -> Some p
  | None -> search cfg.globals (fun i -> Ir.Global i)

let place_value cfg p =
  let l = static_loc cfg p in
  if l == no_loc then None else Some (get l)

let slot_value cfg = function
  | Ir.Local i -> if i < Array.length cfg.act.slots then Some (get cfg.act.slots.(i)) else None
  | Global i -> Some (get cfg.globals.(i))

let current_routine cfg = cfg.act.routine
let current_statement cfg = statement_below cfg.mark
let program cfg = cfg.program

(* The values computed so far within the innermost statement in progress, each with the region
   of the expression it is the value of: the statement as it stands, for the trace. The frames
   from the top down to the statement's are walked: for the trace only. *)
let computed_values cfg =
  let stmt_expr pick = match cfg.mark with K_stmt (s, _) :: _ -> pick s.Ir.s | _ -> None in
  (* The expression whose value the frame on top waits for: the focus's value is its. *)
  let awaited = function
    | K_binary_right (_, _, { e = Binary (_, _, b); _ }) -> Some b
    | K_unary (_, { e = Unary (_, a); _ }) -> Some a
    | K_assign_store _ -> stmt_expr (function Ir.Assign (_, e) -> Some e | _ -> None)
    | K_if _ | K_compact_if _ | K_while_test _ ->
        stmt_expr (function Ir.If (c, _, _) | Compact_if (c, _) | While (c, _) -> Some c | _ -> None)
    | K_return_value -> stmt_expr (function Ir.Return (Some e) -> Some e | _ -> None)
    | K_raise_value -> stmt_expr (function Ir.Raise (Some e) -> Some e | _ -> None)
    | K_late_name _ -> stmt_expr (function Ir.Call_late (e, _) -> Some e | _ -> None)
    | K_test_subject _ -> stmt_expr (function Ir.Test (e, _, _) -> Some e | _ -> None)
    | K_test_value (_, cases, _, ci, vi) -> Some (fst cases.(ci)).(vi)
    | K_aggregate (es, _, i, _) -> Some es.(i)
    | K_element_index (_, idx, i, _) -> Some idx.(i)
    | K_for_from f -> Some f.from_
    | K_for_to (f, _) -> Some f.to_
    | K_for_step (f, _, _) -> Option.map Fun.id f.step
    | _ -> None
  in
  let held = function
    | K_binary_right (_, v, { e = Binary (_, a, _); _ }) -> [ (a.at, v) ]
    | K_aggregate (es, acc, i, _) -> List.init i (fun j -> (es.(j).at, acc.(j)))
    | K_args cs ->
        List.concat (List.init (min cs.next (Array.length cs.call.arguments)) (fun j ->
            match cs.call.arguments.(j) with
            | By_value e when cs.args_present.(j) -> [ (e.at, get cs.args_slots.(j)) ]
            | _ -> []))
    | K_test_value (v, _, _, _, _) -> (
        match stmt_expr (function Ir.Test (e, _, _) -> Some e | _ -> None) with
        | Some e -> [ (e.at, v) ] | None -> [])
    | _ -> []
  in
  let rec walk acc = function
    | [] | K_stmt _ :: _ -> acc
    | f :: rest -> walk (held f @ acc) rest
  in
  let from_frames = walk [] cfg.stack in
  match cfg.focus, cfg.stack with
  | F_value v, f :: _ -> (
      match awaited f with Some e -> (e.at, v) :: from_frames | None -> from_frames)
  | _ -> from_frames

(* --save (Persistent_save): the values of the task's module data at the end of a run. *)
let module_data cfg =
  Array.to_list (Array.mapi (fun i (g : Ir.global) -> (g.g_module, g.g_name, get cfg.globals.(i))) cfg.program.globals)

(* ------------------------------------------------------------------ the debugger's views *)

(* The program pointer stands at the statements of statement lists: the simple statement of a
   compact IF is part of its IF (§4.17), and so not a place of its own. *)
let pointer_statement cfg =
  match cfg.focus, cfg.stack with
  | F_stmt s, K_seq (b, j) :: _ when j >= 1 && j <= Array.length b.body && b.body.(j - 1) == s -> Some s
  | _ -> None

let test_case cfg = match cfg.stack with K_test_value (_, _, _, ci, _) :: _ -> Some ci | _ -> None

(* ch. 14 (R-14-o): the loop whose round the last step began, when its body has no statement:
   right after while-again its condition is in focus; right after for-step settling has left
   the empty body already. *)
let empty_loop_round cfg =
  match cfg.stack with
  | K_while_test (_, b) :: _ | K_seq (b, 0) :: K_for_body _ :: _ -> Array.length b.Ir.body = 0
  | K_for_body (f, _, _) :: _ -> Array.length f.loop_body.Ir.body = 0
  | _ -> false

(* Each active routine and where it stands, innermost first: a caller stands at its call, the
   statement its callee's activation keeps as the caller's mark. *)
let call_chain_view cfg =
  let rec go (a : activation) here acc =
    let acc = (a.routine, here) :: acc in
    match a.caller with
    | None -> List.rev acc
    | Some c ->
        let at = match a.caller_mark with K_stmt (s, _) :: _ -> s.Ir.sat | _ -> c.routine.at in
        go c at acc
  in
  go cfg.act (focus_region cfg) []

let data_location cfg (slot : Ir.slot) =
  match slot with
  | Global i -> if i >= 0 && i < Array.length cfg.globals then Some cfg.globals.(i) else None
  | Local i ->
      let a = cfg.act in
      if i < 0 || i >= Array.length a.slots then None
      else if i < Array.length a.present && not a.present.(i) then None
      else if Array.length a.slots.(i).box = 0 then None
      else Some a.slots.(i)

let read_data cfg slot = Option.map get (data_location cfg slot)

let write_data cfg slot v =
  match data_location cfg slot with Some l -> set l v; true | None -> false

(* ------------------------------------------------------------------ backward execution (ch. 6) *)

let backward_rule = Backward.backward
let backward cfg = Result.map Rule.name (backward_rule cfg)
let backward_running = Backward.running

let backward_rule_names = List.map Rule.name (List.filter Rule.backward Rule.all)

let global_slot cfg name =
  let n = String.lowercase_ascii name in
  let found = ref None in
  Array.iteri (fun i (g : Ir.global) ->
      if !found = None && String.lowercase_ascii g.g_name = n then found := Some (Ir.Global i)) cfg.program.globals;
  !found

(* ------------------------------------------------------------------ several tasks (ch. 14) *)

let wake_time cfg = cfg.wake

let waiting_for cfg = match cfg.stack with K_wait ws :: _ | K_poll ws :: _ -> Some ws.wait.what | _ -> None

let share_global cfg i ~with_:(other, j) =
  if i >= 0 && i < Array.length cfg.globals && j >= 0 && j < Array.length other.globals then
    cfg.globals.(i) <- other.globals.(j)

