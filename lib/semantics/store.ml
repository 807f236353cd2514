(* The store and the moves every part of the machine makes on a configuration: locations, the
   errors the rules raise, activations and the memory budget, and what the rules read off values
   (store.mli). *)

open Configuration
open Event
module V = Value

let fresh_loc v = { box = [| v |]; idx = 0 }
let get l = Array.unsafe_get l.box l.idx

(* Schema rapid-sem/2: a store write as RAPID names it, in the current routine; built only when
   the run observes (doc/observable.md). The roots are given as the closure engine gives its own,
   so that Observation.find names a place alike. *)
let observed_store cfg (l : loc) v =
  if not cfg.observe then []
  else
    let slots = cfg.act.slots and globals = cfg.globals in
    let roots = { Observation.n_locals = Array.length slots; local = (fun i -> (slots.(i).box, slots.(i).idx));
                  n_globals = Array.length globals; global_box = (fun g -> globals.(g).box);
                  global_idx = (fun g -> globals.(g).idx) } in
    [ Observed (Stored { place = Observation.place_of cfg.program cfg.act.routine (l.box, l.idx) roots;
                         value = Observation.value v }) ]
let set l v = Array.unsafe_set l.box l.idx (V.copy v)

(* The answer of [static_loc] for a place it cannot locate, compared by identity: an option would
   cost an allocation on every read. *)
let no_loc = { box = [||]; idx = 0 }

let error_number cfg name =
  match List.assoc_opt name cfg.program.error_numbers with Some n -> n | None -> 0

let call_chain act =
  let rec go acc = function None -> List.rev acc | Some a -> go (a.routine.Ir.name :: acc) a.caller in
  go [] (Some act)

let error ?about cfg name at =
  let act = cfg.act in
  { name; number = error_number cfg name; err_at = at; searched = false; chain = lazy (call_chain act); about;
    asynchronous = false }

(* The name the system error handler reports: an ERR_ constant's name, or a user error's
   number. *)
let error_of_number cfg n at =
  let name =
    match List.find_opt (fun (_, m) -> m = n) cfg.program.error_numbers with
    | Some (name, _) -> name
    | None -> string_of_int n
  in
  let act = cfg.act in
  { name; number = n; err_at = at; searched = false; chain = lazy (call_chain act); about = None;
    asynchronous = false }

let region_of_focus_stmt cfg =
  match cfg.mark with K_stmt (s, _) :: _ -> s.Ir.sat | _ -> cfg.act.routine.at

(* R-7.1-w: an error raised while the routine's data are initialised (a placeholder in an
   initial value) is not the routine's: its body has not started, so its error handler has no
   statement to go back to; the error is raised at the call, as an argument's. *)
let initialising cfg (act : activation) =
  List.exists (function K_local_init (a, _) -> a == act | _ -> false) cfg.stack

let raise_ ?about cfg name = cfg.focus <- F_raise (error ?about cfg name (region_of_focus_stmt cfg))

let push cfg f = cfg.stack <- f :: cfg.stack

(* A place without an index expression (a data object, or a component of one) is located in one
   step: its path is part of the program's text, so this costs nothing that grows with the run.
   [no_loc] for an absent optional parameter (§5.2) and for a place with indexes, which take
   steps of their own. *)
let rec static_loc cfg (p : Ir.place) =
  match p with
  | Whole (Global i) -> cfg.globals.(i)
  | Whole (Local i) ->
      if i < Array.length cfg.act.present && not (Array.unsafe_get cfg.act.present i) then no_loc
      else cfg.act.slots.(i)
  | Component (q, k) -> (
      let l = static_loc cfg q in
      if l == no_loc then no_loc
      else match get l with V.Record cs -> { box = cs; idx = k } | _ -> no_loc)
  | Element _ | Unresolved _ -> no_loc

(* ------------------------------------------------------------------ activations and memory *)

let has_recovery_point (a : activation) =
  match a.routine.error with Some { recovery = Some _; _ } -> true | _ -> false

let activation ~routine ~slots ~present ~kinds ~module_data ~caller ~return_to ~caller_mark =
  { routine; slots; present; kinds; module_data; caller; return_to; caller_mark;
    call_depth = (match caller with None -> 1 | Some c -> c.call_depth + 1);
    recovery_up = (match caller with
        | Some c when has_recovery_point c -> Some c
        | Some c -> c.recovery_up
        | None -> None);
    memory = 0; handling = Body; retries = 0; retried = None; resume = None;
    trap_level = (match caller with None -> false | Some c -> c.trap_level) }

let memory_exhausted cfg what at = Limits.memory_exhausted_by cfg.limits what at

(* Charges [bytes] of RAPID data to the activation, or says the budget does not hold them. *)
let charge cfg (act : activation) bytes =
  if bytes > cfg.limits.max_memory - cfg.memory then false
  else (cfg.memory <- cfg.memory + bytes; act.memory <- act.memory + bytes; true)

(* The NOSTEPIN routines an error handler at user level could have gone on in (§7.3) are
   abandoned with it when it ends otherwise (doc/rulings.md R-7.3-p). *)
let rec release cfg (act : activation) =
  cfg.memory <- cfg.memory - act.memory; act.memory <- 0;
  match act.resume with
  | None -> ()
  | Some inner ->
      act.resume <- None;
      let rec up (a : activation) =
        if a != act then begin
          release cfg a;
          match a.caller with Some c -> up c | None -> ()
        end in
      up inner

(* The event routines of a controller backup (doc/rulings.md R-bk-8): the routine at the bottom
   of the stack has ended (its end, RETURN, or ExitCycle in an event routine) and another of the
   task's sequence follows: it begins in a new activation, its routine data initialised; module
   data, interrupts, files and the clock are kept. [None] when it was the last. *)
let next_phase cfg =
  match cfg.phases with
  | [] -> None
  | (routine, at_entry) :: rest ->
      release cfg cfg.act;
      cfg.phases <- rest;
      cfg.at_entry <- at_entry;
      let slots = Array.init routine.Ir.locals (fun _ -> fresh_loc (Value.Bool false)) in
      let act = activation ~routine ~slots ~present:[||] ~kinds:[||] ~module_data:[||] ~caller:None
          ~return_to:[ K_task_end ] ~caller_mark:[] in
      cfg.act <- act;
      cfg.stack <- [ K_local_init (act, routine.local_inits); K_seq (routine.body, 0); K_routine_end; K_task_end ];
      cfg.mark <- [];
      cfg.kept <- [];
      cfg.focus <- F_next;
      Some routine

(* R-bk-11: the last routine of an interposed sequence has ended: the task's control comes back
   as it stood before it. *)
let resume cfg =
  match cfg.resumes with
  | [] -> false
  | r :: rest ->
      release cfg cfg.act;
      cfg.resumes <- rest;
      cfg.act <- r.r_act; cfg.stack <- r.r_stack; cfg.mark <- r.r_mark; cfg.focus <- r.r_focus;
      cfg.unmarked <- r.r_unmarked; cfg.kept <- r.r_kept; cfg.charged <- r.r_charged; cfg.held <- r.r_held;
      cfg.phases <- r.r_phases; cfg.at_entry <- r.r_at_entry;
      true

(* ------------------------------------------------------------------ values the rules read *)

let set_errno cfg n = set cfg.globals.(cfg.program.errno) (V.num (float_of_int n))

let bool_of = function V.Bool b -> Some b | _ -> None

let num_of = function V.Num f | V.Dnum f -> Some f | _ -> None

(* A whole number of any size is an integer (R-3.6: 1E20 as an index is out of bounds, not "not
   an integer"); beyond OCaml's ints it is clamped, which keeps it outside every dimension and
   every range of RAISE. *)
let to_int f =
  if not (Float.is_integer f) then None
  else if f >= 4e18 then Some max_int
  else if f <= -4e18 then Some min_int
  else Some (int_of_float f)

(* The kind of a frame, as the trace and the stuck messages name it. *)
let frame_kind = function
  | K_seq _ -> "seq" | K_stmt _ -> "stmt" | K_compact_if _ -> "compact-if" | K_assign_value _ -> "assign-value"
  | K_assign_store _ -> "assign-store" | K_if _ -> "if" | K_while_test _ -> "while-test"
  | K_while_body _ -> "while-body" | K_for_from _ -> "for-from" | K_for_to _ -> "for-to"
  | K_for_step _ -> "for-step" | K_for_body _ -> "for-body" | K_test_subject _ -> "test"
  | K_test_value _ -> "test-value" | K_return_value -> "return" | K_raise_value -> "raise"
  | K_connect_target _ -> "connect" | K_fit _ -> "fit" | K_late_name _ -> "late-call" | K_read -> "read"
  | K_unary _ -> "unary" | K_binary_left _ -> "binary-left" | K_binary_right _ -> "binary-right"
  | K_and _ -> "and" | K_or _ -> "or" | K_aggregate _ -> "aggregate" | K_component _ -> "component"
  | K_element_base _ | K_element_index _ -> "element" | K_args _ -> "arguments"
  | K_local_init _ -> "local-init" | K_routine_end -> "routine-end"
  | K_handler_end -> "handler-end" | K_undo_end _ -> "undo-end" | K_task_end -> "task-end"
  | K_wait _ -> "wait" | K_poll _ -> "poll" | K_read_signal -> "read-signal"
  | K_backward_end -> "backward-end"
