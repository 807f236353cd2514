(* The reduction rules of doc/semantics.md, one match clause each, named by the string the step
   returns. The stack is an immutable list of frames, so that capturing "the statement that
   caused the error" for RETRY and TRYNEXT (§7.1) is keeping a pointer; the few expression
   frames that accumulate values (aggregates, arguments) are mutable, and are never captured:
   RETRY restarts a statement from the beginning. *)

open Rapid_syntax
module V = Value

type loc = { box : V.t array; idx : int }

(* An error in flight: [chain] is the call chain where it occurred, innermost first, which the
   system error handler reports even after the error has been propagated: computed only then,
   so that raising an error costs O(1) at any call depth. [about] is the name the error is
   about (the unknown data object or routine, the function without RETURN). *)
type err = { name : string; number : int; err_at : Source.region; searched : bool;
             chain : string list Lazy.t; about : string option;
             asynchronous : bool  (* §7.4: TRYNEXT executes as RETRY *) }

(* The neutral types of a run (lib/runtime), whose constructors the rules write unqualified. *)
type event = Event.t
type outcome = Outcome.t
type limits = Limits.t

open Event
open Outcome

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
  | K_for_to of Ir.for_loop * V.t                   (* FROM evaluated *)
  | K_for_step of Ir.for_loop * V.t * V.t           (* FROM and TO evaluated *)
  | K_for_body of Ir.for_loop * V.t * V.t           (* TO and STEP: the body runs *)
  | K_test_subject of (Ir.expr array * Ir.block) array * Ir.block
  | K_test_value of V.t * (Ir.expr array * Ir.block) array * Ir.block * int * int
  | K_return_value
  | K_raise_value
  | K_connect_target of int * Ir.place
  | K_fit of Value.shape                (* an aggregate argument takes its parameter's type *)
  | K_late_name of Ir.late_argument array * Source.region
  | K_read
  | K_unary of Arith.unary * Ir.expr               (* the whole expression, for the trace *)
  | K_binary_left of Arith.binary * Ir.expr * Ir.expr   (* the right operand; the whole *)
  | K_binary_right of Arith.binary * V.t * Ir.expr
  | K_and of Ir.expr
  | K_or of Ir.expr
  | K_aggregate of Ir.expr array * V.t array * int * Ir.aggregate_kind
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
  | F_value of V.t
  | F_place of Ir.place
  | F_loc of loc
  | F_stmt of Ir.stmt
  | F_next
  | F_raise of err
  | F_search of err * activation option (* the long-jump search of §7.2 *)
  | F_abandon of after_abandon          (* leave the current activation, running its UNDO *)
  | F_done of outcome

type config = {
  program : Ir.program;
  limits : limits;
  globals : loc array;
  mutable act : activation;
  mutable stack : frame list;
  mutable mark : frame list;            (* the stack at the innermost statement in progress *)
  mutable focus : focus;
  mutable count : int;
  mutable memory : int;                 (* bytes of RAPID data: module data and activations *)
  by_name : (string, int list) Hashtbl.t;  (* routines by lower-case name, for late binding *)
  (* Later issues: the user execution level, the motion queue, other tasks. The trap level is
     the activation's; the interrupt numbers and queue are the world's. *)
  mutable unmarked : bool;              (* the next statement is part of a compact IF (§4.17) *)
  host : Host.t;                        (* the world around the program: its controller and motion *)
  stub_unmodelled : bool;               (* --stub-unmodelled: unmodelled routines are no-ops *)
  stubbed : (string, unit) Hashtbl.t;   (* the routines already reported as stubbed *)
  mutable move_owners : (int * activation) list;  (* recent moves and the activation that ran each *)
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
}

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

(* ------------------------------------------------------------------ start *)

(* Routines by lower-case name, built once: a late-bound call looks its name up in O(1). The
   table is only read, so the runs of one program share it: the last one built is kept, keyed
   by the program's routine array compared physically (a fuzzer runs each program three times). *)
let last_by_name : (Ir.routine array * (string, int list) Hashtbl.t) option ref = ref None

(* The leading routines that a program shares physically with the one before it (the installed
   ones, lowered once and numbered first for every task: Lower), with their table: the routine
   array they were found in, how many, the table. A program that starts with the same routines
   starts from a copy of it. *)
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

let routines_by_name (program : Ir.program) =
  let routines = program.routines in
  let count = Array.length routines in
  match !last_by_name with
  | Some (r, t) when r == routines -> t
  | previous ->
      let t =
        match !shared_by_name with
        | Some (a, n, shared) when n <= count && common_prefix a routines >= n ->
            let t = Hashtbl.copy shared in
            add_routines t routines ~from:n ~until:count;
            t
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
            t in
      last_by_name := Some (routines, t);
      t

(* [settle], defined with the step below: the first configuration is settled too. *)
let settle_ref : (config -> unit) ref = ref (fun _ -> ())

let routine_index_in by_name name =
  match Hashtbl.find_opt by_name (String.lowercase_ascii name) with Some (i :: _) -> Some i | _ -> None

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

let call_depth_exceeded = Limits.call_depth_exceeded

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

let start ?(limits = Limits.default) ?(stub_unmodelled = false) ?(cooperative = false)
    ?(observe = false) ~(host : Host.t) (program : Ir.program) ~entry =
  let program = host.prepare program in
  let by_name = routines_by_name program in
  match routine_index_in by_name entry with
  | None -> Error (Printf.sprintf "no procedure %s without parameters to run" entry)
  | Some i ->
      let routine = program.routines.(i) in
      if routine.kind <> Procedure || Array.length routine.parameters > 0 then
        Error (Printf.sprintf "%s is not a procedure without parameters: it cannot be the entry routine (§9.1)" entry)
      else begin
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
                      | Ok (V.Array es), Ok (V.Num f) when Float.is_integer f && f >= 1. && int_of_float f <= Array.length es ->
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
          stub_unmodelled; stubbed = Hashtbl.create 8; move_owners = []; kept = [];
          backward_depth = -1; charged = false; held = None; cooperative; wake = None;
          observe; entered = false; propagated = false;
        } in
        cfg.stack <- [ K_local_init (act, routine.local_inits); K_seq (routine.body, 0); K_routine_end; K_task_end ];
        (match !too_big with
         | Some g -> cfg.focus <- F_done (memory_exhausted cfg ("the initial value of " ^ g.g_name) g.g_at)
         | None -> !settle_ref cfg);
        Ok cfg
      end

(* ------------------------------------------------------------------ calls *)

(* What an activation costs by the model of Value.bytes, besides its data: a record, its frames
   and one slot per parameter and routine data object. *)
let activation_bytes (r : Ir.routine) = 256 + 16 * r.locals

let enter_routine cfg (cs : call_state) =
  let r = cs.callee in
  let depth = cfg.act.call_depth + 1 in
  if depth > cfg.limits.max_call_depth then begin
    cfg.focus <- F_done (call_depth_exceeded cfg.limits);
    ("call-depth-exceeded", [])
  end
  else if activation_bytes r > cfg.limits.max_memory - cfg.memory - cs.args_memory then begin
    (* The activation itself counts: a very deep recursion stays within the budget too. *)
    cfg.focus <- F_done (memory_exhausted cfg ("the call of " ^ r.name) (region_of_focus_stmt cfg));
    ("memory-exhausted", [])
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
    ("call-enter", Routine_entered r.name
                   :: (if cfg.observe && Array.length r.parameters > 0 then
                         [ Observed (Called { routine = r.name; arguments = List.filter_map (fun x -> x)
                             (List.mapi (fun i (p : Ir.parameter) ->
                                  if i < Array.length cs.args_present && not cs.args_present.(i) then None
                                  else if p.p_switch then Some (p.p_name, None)
                                  else Some (p.p_name, Some (Observation.value (get slots.(i)))))
                                (Array.to_list r.parameters)) }) ]
                       else []))
  end

let return_from cfg value =
  let act = cfg.act in
  match act.caller with
  | None ->
      cfg.focus <- F_done Ended;
      ("return-entry", [ Routine_left act.routine.name; Task_ended ])
  | Some caller when act.routine.kind = Trap ->
      (* ch. 8: after ENDTRAP or RETURN, execution goes on where the interrupt came in. *)
      cfg.act <- caller; cfg.stack <- act.return_to; cfg.mark <- act.caller_mark;
      cfg.focus <- F_next;
      ("trap-end", [ Routine_left act.routine.name; Trap_left { trap = act.routine.name; time = cfg.host.now () } ])
  | Some caller ->
      release cfg act;
      cfg.act <- caller;
      cfg.stack <- act.return_to;
      cfg.mark <- act.caller_mark;
      (match act.routine.kind, value with
       | Function, Some v -> cfg.focus <- F_value v
       | _ -> cfg.focus <- F_next);
      ((match act.routine.kind with Function -> "return-function" | _ -> "return-procedure"),
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
  parameters = Array.map (fun (p : Ir.parameter) -> p.p_name) cs.callee.parameters;
  argument_label = Installed_routine.argument_label cfg.program cs.callee cs.call.arguments;
  book_error = cfg.host.book_error;
  error_number = (fun name -> error_number cfg name);
}

let exec_ref : (config -> Ir.stmt -> string * event list) ref = ref (fun _ _ -> ("", []))

let begin_call_ref : (config -> Ir.call -> string) ref = ref (fun _ _ -> "")

(* The routine a late-bound name denotes (§4.6): "name1:name2" the routine name2 of module
   name1 (a LOCAL one too); a plain name by the scope rules of §5.3 from the calling module: its
   own routines, then the global ones. The routines of a name come from a table built once, so
   the look-up is O(1) in the size of the program. *)
let late_routine cfg name =
  let module_name, routine_name =
    match String.index_opt name ':' with
    | Some i -> (Some (String.sub name 0 i), String.sub name (i + 1) (String.length name - i - 1))
    | None -> (None, name)
  in
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  let here = cfg.act.routine.module_name in
  let candidates =
    Option.value (Hashtbl.find_opt cfg.by_name (String.lowercase_ascii routine_name)) ~default:[] in
  let find pred = List.find_opt (fun i -> pred cfg.program.routines.(i)) candidates in
  match module_name with
  | Some m -> find (fun (r : Ir.routine) -> same r.module_name m)
  | None -> (
      match find (fun (r : Ir.routine) -> same r.module_name here) with
      | Some i -> Some i
      | None -> find (fun (r : Ir.routine) -> not r.local))

let raise_to_user_ref : (config -> call_state -> string * event list) ref = ref (fun _ _ -> ("", []))

let call_primitive cfg (cs : call_state) name =
  if String.length name = 11 && String.lowercase_ascii name = "raisetouser" then !raise_to_user_ref cfg cs else
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
   | Some id -> cfg.move_owners <- (id, cfg.act) :: List.filteri (fun i _ -> i < Limits.move_owners - 1) cfg.move_owners
   | None -> ());
  match outcome.result with
  | History_exhausted m ->
      (* The history --samples or rapid-sem motion keeps, beyond its budget (doc/motion.md). *)
      cfg.focus <- F_done (Outcome.motion_history_exhausted m cs.call.call_at);
      ("motion-history-exhausted", List.rev !events)
  | Wait { wait; first_poll } ->
      (* WaitUntil evaluates its condition again at every poll: the argument's expression. *)
      let cond = match entry with
        | Some entry when wait.poll <> None -> Installed_routine.condition_argument entry cs.callee cs.call.arguments
        | _ -> None in
      let now = cfg.host.now () in
      let next_poll = match first_poll with
        | Some t -> Float.max t (now +. Option.value wait.poll ~default:0.)
        | None -> now +. Option.value wait.poll ~default:0. in
      push cfg (K_wait { wait; cond; next_poll });
      cfg.focus <- F_next;
      ("wait-start", List.rev !events)
  | Returned v ->
      (match cs.callee.kind, v with
       | Function, Some v -> cfg.focus <- F_value v
       | Function, None -> raise_ cfg "ERR_FNCNORET"
       | _ -> cfg.focus <- F_next);
      ("call-primitive", List.rev !events)
  | Failed { error = name; at_move = true } ->
      (* §7.4: a \SyncLastMoveInst error, raised at the move instruction. *)
      cfg.focus <- F_raise { (error cfg name (region_of_focus_stmt cfg)) with asynchronous = true };
      ("async-error-at-move", List.rev !events)
  | Failed { error = name; at_move = false } -> raise_ cfg name; ("call-primitive-error", List.rev !events)
  | Stop_requested -> cfg.focus <- F_done Ended; ("call-primitive-stop", List.rev !events @ [ Task_ended ])
  | Call_by_name target -> (
      (* CallByVar: a late-bound call without arguments (§4.6). *)
      match late_routine cfg target with
      | None ->
          raise_ ~about:target cfg (Late_binding.unknown_procedure_error target);
          ("call-by-var-unknown", List.rev !events)
      | Some i when cfg.program.routines.(i).kind <> Procedure ->
          raise_ ~about:target cfg "ERR_CALLPROC"; ("call-by-var-mismatch", List.rev !events)
      | Some i -> (
          match Late_binding.bind cfg.program.routines.(i) ~kind:(reference_kind cfg) [||] with
          | Error name -> raise_ ~about:target cfg name; ("call-by-var-mismatch", List.rev !events)
          | Ok arguments ->
              let rule = !begin_call_ref cfg { Ir.callee = Routine i; arguments; call_at = cs.call.call_at } in
              ignore rule; ("call-by-var", List.rev !events)))
  | Not_modelled when cfg.stub_unmodelled ->
      (* --stub-unmodelled (doc/rulings.md R-13-i): the call does nothing; a function gives the
         initial value of its type (§2.22); VAR and INOUT arguments keep their values. *)
      let key = String.lowercase_ascii name in
      let first = not (Hashtbl.mem cfg.stubbed key) in
      if first then Hashtbl.replace cfg.stubbed key ();
      (match cs.callee.kind with
       | Function -> cfg.focus <- F_value (V.default_of (Option.value cs.callee.stub_result ~default:V.S_num))
       | Procedure | Trap -> cfg.focus <- F_next);
      ("call-stubbed",
       List.rev !events @ (if first then [ Stubbed { routine = cs.callee.name; at = cs.call.call_at } ] else []))
  | Retry_requested -> (
      (* StartMoveRetry: StartMove, then the RETRY statement's rule; outside an error handler
         there is nothing to retry: StartMove alone (R-7.6-b). *)
      match cfg.act.handling with
      | In_handler _ ->
          let rule, more = !exec_ref cfg { Ir.s = Ir.Retry; sat = cs.call.call_at } in
          (rule, List.rev !events @ more)
      | _ -> cfg.focus <- F_next; ("call-primitive", List.rev !events))
  | Not_modelled ->
      cfg.focus <- F_done (Outcome.not_modelled cs.callee.name cs.call.call_at);
      ("call-not-modelled", List.rev !events)

let begin_call cfg (call : Ir.call) =
  match call.callee with
  | Unknown_routine name -> raise_ ~about:name cfg "ERR_REFUNKPRC"; "call-unknown"
  | Routine i ->
      let callee = cfg.program.routines.(i) in
      let n = Array.length callee.parameters in
      push cfg (K_args { call; callee; args_slots = Array.make n (fresh_loc (V.Bool false));
                         args_present = Array.make n false; args_kinds = Array.make n Ir.Ref_other;
                         args_module_data = Array.make n false; args_memory = 0;
                         primitive_args = Array.make n Argument.Missing; next = 0 });
      cfg.focus <- F_next;
      "call-arguments"

let () = begin_call_ref := begin_call

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
  | Error name -> cfg.stack <- rest; raise_ cfg name; ("argument-alias-refused", [])
  | Ok () ->
      cs.args_slots.(i) <- l;
      cs.args_present.(i) <- true;
      cs.primitive_args.(i) <- Argument.Location (l.box, l.idx, cs.args_kinds.(i));
      cs.next <- i + 1;
      cfg.focus <- F_next;
      ("argument-alias", [])

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
      cfg.focus <- F_done (Stuck "an argument left unsettled"); ("stuck", []) in
    match cs.call.arguments.(i) with
    | By_reference (place, k) ->
        cs.args_kinds.(i) <- reference_kind cfg place k;
        cs.args_module_data.(i) <- denotes_module_data cfg place;
        let l = static_loc cfg place in
        if l != no_loc then bind_alias cfg cs rest l
        else (cfg.focus <- F_place place; ("argument-reference", []))
    | Pass_on (Local j) when j < Array.length cfg.act.present && cfg.act.present.(j) ->
        if duplicate_alternative cfg cs i then begin
          cfg.stack <- rest; raise_ cfg "ERR_ARGDUPCND"; ("argument-pass-on-duplicate", [])
        end
        else unsettled ()
    | Absent | Pass_on _ when V.shape_bytes p.p_default > args_room cfg cs ->
        cfg.stack <- rest;
        cfg.focus <- F_done (memory_exhausted cfg ("the absent parameter " ^ p.p_name) (region_of_focus_stmt cfg));
        ("memory-exhausted", [])
    | Absent | Pass_on _ | Present_switch | By_value _ -> unsettled ()

(* ------------------------------------------------------------------ errors *)

let set_errno cfg n = set cfg.globals.(cfg.program.errno) (V.num (float_of_int n))

(* §7.1: the error handler of the current routine takes control. *)
(* §7.2: a move instruction whose wait an error or a long jump leaves is cancelled, and with it
   the rest of its path (doc/motion.md, M-abandon). *)
let waits_left cfg =
  List.iter (function
      | K_wait ws -> cfg.host.wait_abandoned ws.wait
      | _ -> ()) cfg.stack

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
      ("raise-handle", [ Error_handled { name = e.name; routine = act.routine.name } ])

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
      stop cfg e "raise-in-backward"
  | (In_handler _ | In_undo), _ -> stop cfg e "raise-in-handler"
  | Body, Some _ when not (initialising cfg act) -> handle cfg e
  | Body, _ -> (
      match act.caller with
      | None -> stop cfg e "raise-unhandled"
      | Some _ when act.routine.kind = Trap && e.searched ->
          (* An error that leaves a trap goes to the system error handler: there is no call
             point to raise it at (installed-facts.md section 6, R-8-e). *)
          stop cfg e "raise-in-trap"
      | Some caller ->
          ignore caller;
          (* §7.2: only the routines with an error recovery point are searched. *)
          if e.searched then (cfg.focus <- F_abandon (Go_on_propagate e); ("raise-propagate", []))
          else (cfg.focus <- F_search (e, act.recovery_up); ("longjump-search-start", [])))

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

(* ------------------------------------------------------------------ the step *)

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

(* The statements of a statement list, one by one. *)
let rec exec cfg (s : Ir.stmt) =
  match kept_exit cfg s with Some r -> r | None -> exec_statement cfg s

(* §7.4: the handler of an asynchronous error taken while the program pointer was elsewhere
   (a kept program pointer): RETRY and TRYNEXT go on from where the program pointer was; RAISE,
   RETURN and EXIT first abandon the routines the program pointer is in above the handler's
   (their UNDO handlers run), then act as in any handler. *)
and kept_exit cfg (s : Ir.stmt) =
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
            Some ((if s.s = Retry then "async-retry-resume" else "async-trynext-resume"), [])
        | Exit -> restore (); cfg.focus <- F_abandon Go_on_exit; Some ("async-exit", [])
        | _ when k.pp_act == k.handler ->
            (* The program pointer's own routine: its statement in progress is left as by any
               error (a move instruction's path with it, §7.6 example 3). *)
            restore (); waits_left cfg; None
        | _ ->
            restore ();
            cfg.focus <- F_abandon (Go_on_in_handler (s, k.handler));
            Some ("async-handler-leave", []))
    | Some _, _ -> None

and exec_statement cfg (s : Ir.stmt) =
  (* The simple statement of a compact IF is part of the IF: the IF is the statement that RETRY
     and TRYNEXT refer to (§4.17, §7.1). *)
  let part_of_compact_if = cfg.unmarked in
  cfg.unmarked <- false;
  let mark_here () =
    if not part_of_compact_if then (push cfg (K_stmt (s, cfg.mark)); cfg.mark <- cfg.stack) in
  match s.s with
  | Label -> cfg.focus <- F_next; ("label", [])
  | Placeholder_statement -> mark_here (); raise_ cfg "ERR_EXECPHR"; ("execute-placeholder", [])
  | Assign (p, e) ->
      mark_here ();
      let l = static_loc cfg p in
      if l != no_loc then (push cfg (K_assign_store l); cfg.focus <- F_expr e)
      else (push cfg (K_assign_value e); cfg.focus <- F_place p);
      ("assign", [])
  | Call_procedure c -> mark_here (); (begin_call cfg c, [])
  | Call_late (e, args) ->
      mark_here ();
      push cfg (K_late_name (args, s.sat));
      cfg.focus <- F_expr e;
      ("call-late", [])
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
      ("goto", [])
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
      ((if s.s = Break then "break" else "continue"), [])
  | Return None -> return_from cfg None
  | Return (Some e) -> mark_here (); push cfg K_return_value; cfg.focus <- F_expr e; ("return-value", [])
  | Raise None -> (
      match cfg.act.handling with
      | In_handler (e, _) -> (
          match cfg.act.caller with
          | None -> stop cfg e "raise-again-unhandled"
          | Some _ ->
              cfg.focus <- F_search ({ e with searched = false }, cfg.act.recovery_up);
              ("raise-again", []))
      | _ -> cfg.focus <- F_done (Stuck "RAISE without a number outside an error handler"); ("stuck", []))
  | Raise (Some e) -> mark_here (); push cfg K_raise_value; cfg.focus <- F_expr e; ("raise-number", [])
  | Exit -> cfg.focus <- F_abandon Go_on_exit; ("exit", [])
  | Retry -> (
      let resumed = resume_nostepin cfg in
      let named (rule, events) = ((if resumed && rule = "retry" then "resume-retry" else rule), events) in
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
            cfg.focus <- F_raise { (error cfg "ERR_EXCRTYMAX" s.sat) with searched = true };
            act.handling <- In_handler (e, point);
            ("retry-limit", [])
          end
          else begin
            act.handling <- Body;
            (match statement_point point with
             | K_stmt (st, prev) :: rest ->
                 act.retried <- Some st;
                 cfg.stack <- rest; cfg.mark <- prev; cfg.focus <- F_stmt st
             | K_seq _ :: _ ->
                 (* R-7.2-m: no statement caused the error; the point of response is taken again. *)
                 act.retried <- None;
                 cfg.stack <- point; cfg.mark <- []; cfg.focus <- F_next
             | _ -> cfg.focus <- F_done (Stuck "RETRY without a statement to retry"));
            ("retry", [ Observed (Retried cfg.act.routine.name) ])
          end
      | _ -> cfg.focus <- F_done (Stuck "RETRY outside an error handler"); ("stuck", []))
  | Trynext -> (
      let resumed = resume_nostepin cfg in
      let named (rule, events) = ((if resumed && rule = "trynext" then "resume-trynext" else rule), events) in
      named @@
      match cfg.act.handling with
      | In_handler ({ asynchronous = true; _ }, _) ->
          (* §7.4: "in this case TRYNEXT executes as RETRY", for the system can restart from
             where the error occurred (R-7.4-m). *)
          exec cfg { s with s = Retry }
      | In_handler (_, point) ->
          cfg.act.handling <- Body;
          (match statement_point point with
           | K_stmt (_, prev) :: rest -> cfg.stack <- rest; cfg.mark <- prev; cfg.focus <- F_next
           | K_seq _ :: _ -> cfg.stack <- point; cfg.mark <- []; cfg.focus <- F_next  (* R-7.2-m *)
           | _ -> cfg.focus <- F_done (Stuck "TRYNEXT without a statement"));
          ("trynext", [ Observed (Tried_next cfg.act.routine.name) ])
      | _ -> cfg.focus <- F_done (Stuck "TRYNEXT outside an error handler"); ("stuck", []))
  | Connect (p, trap) -> mark_here (); push cfg (K_connect_target (trap, p)); cfg.focus <- F_place p; ("connect", [])
  | If (c, t, f) -> mark_here (); push cfg (K_if (t, f)); cfg.focus <- F_expr c; ("if", [])
  | Elseif (c, t, f) ->
      (* Marked for the error's place (the ELSEIF); RETRY and TRYNEXT go to its IF. *)
      mark_here (); push cfg (K_if (t, f)); cfg.focus <- F_expr c; ("elseif", [])
  | Compact_if (c, inner) ->
      mark_here (); push cfg (K_compact_if inner); cfg.focus <- F_expr c; ("compact-if", [])
  | While (c, b) -> mark_here (); push cfg (K_while_test (c, b)); cfg.focus <- F_expr c; ("while", [])
  | For f -> mark_here (); push cfg (K_for_from f); cfg.focus <- F_expr f.from_; ("for", [])
  | Test (e, cases, default) ->
      mark_here (); push cfg (K_test_subject (cases, default)); cfg.focus <- F_expr e; ("test", [])

let () = exec_ref := exec

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

(* §4.18: is the loop variable still in its range? *)
let for_in_range v t step =
  match v, t, step with
  | V.Num v, V.Num t, V.Num s -> if s >= 0. then v <= t else v >= t
  | _ -> false

(* The activation of an abandoned routine is popped (§7.2): what made it abandoned goes on in
   the caller. *)
let leave_abandoned cfg after rule rule_entry =
  let act = cfg.act in
  match act.caller with
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
       | Go_on_propagate e -> cfg.focus <- F_raise { e with searched = true }; cfg.propagated <- true
       | Go_on_long_jump (e, target) ->
           if cfg.act == target then cfg.focus <- F_raise { e with searched = true }
           else cfg.focus <- F_abandon after
       | Go_on_in_handler (s, target) ->
           if cfg.act == target then cfg.focus <- F_stmt s else cfg.focus <- F_abandon after);
      (rule, Routine_left act.routine.name
             :: (if act.routine.kind = Trap then [ Trap_left { trap = act.routine.name; time = cfg.host.now () } ] else [])
             @ (match after with
                 | Go_on_propagate e -> [ Observed (Propagated { name = e.name; number = e.number;
                                                                 routine = act.routine.name; caller = caller.routine.name }) ]
                 | _ -> []))

(* A statement has completed: the frame on top continues. *)
let next_frame cfg =
  match cfg.stack with
  | (K_stmt _ | K_seq _) :: _ ->
      cfg.focus <- F_done (Stuck "a configuration left unsettled (a completed statement or the next one of a list)");
      ("stuck", [])
  | K_while_body (c, b) :: rest ->
      cfg.stack <- K_while_test (c, b) :: rest; cfg.focus <- F_expr c; ("while-again", [])
  | K_for_body (f, t, step) :: rest ->
      (* §4.18: the loop variable steps on; TO and STEP were evaluated once. *)
      let slot = cfg.act.slots.(f.variable) in
      let v = match get slot, step with
        | V.Num cur, V.Num d -> V.num (cur +. d) | other, _ -> other in
      set slot v;
      if for_in_range v t step then (cfg.stack <- K_seq (f.loop_body, 0) :: cfg.stack; ("for-step", observed_store cfg slot v))
      else (cfg.stack <- rest; ("for-done", []))
  | K_routine_end :: _ -> (
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
          ("function-no-return", [ Routine_left act.routine.name ])
      | Procedure | Trap -> return_from cfg None)
  | K_handler_end :: _ -> (
      (* §7.1: reaching the end of an error handler calls the system error handler. *)
      match cfg.act.handling with
      | In_handler (e, _) -> stop cfg e "handler-end"
      | _ -> cfg.focus <- F_done (Stuck "end of a handler not in a handler"); ("stuck", []))
  | K_undo_end after :: _ -> leave_abandoned cfg after "undo-done" "undo-done-entry"
  | K_local_init (act, inits) :: rest -> (
      match inits with
      | (_, Init_default shape) :: _ when V.shape_bytes shape > cfg.limits.max_memory - cfg.memory ->
          (* Settling initialises routine data the budget holds (see [settle]). *)
          cfg.focus <- F_done (memory_exhausted cfg ("the routine data of " ^ act.routine.name)
                                 (match act.caller_mark with K_stmt (s, _) :: _ -> s.sat | _ -> act.routine.at));
          ("memory-exhausted", [])
      | (slot, Init_expr e) :: more ->
          act.slots.(slot) <- fresh_loc (V.Bool false);
          cfg.stack <- K_assign_store act.slots.(slot) :: K_local_init (act, more) :: rest;
          cfg.focus <- F_expr e; ("local-initial-value", [])
      | _ ->
          cfg.focus <- F_done (Stuck "routine data left unsettled"); ("stuck", []))
  | K_args cs :: rest -> next_argument cfg cs rest
  | K_backward_end :: rest ->
      cfg.stack <- rest; cfg.backward_depth <- -1; cfg.host.set_backward false;
      ("backward-end", [])
  | K_task_end :: _ -> cfg.focus <- F_done (Stuck "the bottom of the stack reached"); ("stuck", [])
  | f :: _ ->
      cfg.focus <- F_done (Stuck ("a statement completed over the frame " ^ frame_kind f));
      ("stuck", [])
  | [] -> cfg.focus <- F_done (Stuck "empty stack"); ("stuck", [])

(* ch. 8: an interrupt is served at the entry of the next statement, after the last statement
   of a statement list, and during waits; never at trap level, where it stays queued until the trap ends. The trap runs as a routine called
   from the point of interruption, with INTNO set to the interrupt's number (ch. 12). *)
let serve_interrupt cfg =
  if cfg.act.trap_level then None
  else
    let taken = match cfg.held with
      | Some _ as h -> cfg.held <- None; h   (* taken by settling, which stopped here *)
      | None -> cfg.host.take_interrupt () in
    match taken with
    | None -> None
    | Some (number, trap) ->
        let r = cfg.program.routines.(trap) in
        set cfg.globals.(cfg.program.intno) (V.num (float_of_int number));
        let slots = Array.init r.locals (fun _ -> fresh_loc (V.Bool false)) in
        let act = { (activation ~routine:r ~slots ~present:[||] ~kinds:[||] ~module_data:[||] ~caller:(Some cfg.act)
                       ~return_to:cfg.stack ~caller_mark:cfg.mark) with trap_level = true } in
        cfg.act <- act;
        cfg.stack <- [ K_local_init (act, r.local_inits); K_seq (r.body, 0); K_routine_end ];
        cfg.mark <- [];
        cfg.focus <- F_next;
        Some ("interrupt-serve", [ Trap_entered { number; trap = r.name; time = cfg.host.now () };
                                   Routine_entered r.name ])

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
        let owner = match move with Some id -> List.assoc_opt id cfg.move_owners | None -> None in
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
            let rule, events = stop cfg e "async-error-unhandled" in
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
            Some ("async-error", [ raised; Error_handled { name = e.name; routine = h.routine.name } ])

let time_exhausted cfg rule =
  cfg.focus <- F_done (Outcome.time_limit cfg.host.max_time);
  (rule, [])

(* A waiting instruction, one step at a time (doc/controller.md): interrupts come in; the wait
   ends when its condition holds or its deadline passes; otherwise the clock jumps to the next
   thing that can change anything: a timed event, the deadline, the next poll. With none, nothing
   can ever end the wait: a deadlock. *)
let wait_step cfg ws rest =
  match serve_interrupt cfg with
  | Some r -> r
  | None ->
  match serve_async_error cfg with
  | Some r -> r
  | None -> (
      let host = cfg.host in
      let now = host.now () in
      let reached = host.reached in
      let finish timed_out rule =
        cfg.stack <- rest;
        match ws.wait.finish ~timed_out with
        | None -> cfg.focus <- F_next; (rule, [])
        | Some { error = name; at_move = true } ->
            (* §7.4: a \SyncLastMoveInst error at the move instruction the program pointer waits in. *)
            cfg.focus <- F_raise { (error cfg name (region_of_focus_stmt cfg)) with asynchronous = true };
            (rule, [])
        | Some { error = name; at_move = false } -> raise_ cfg name; (rule, [])
      in
      match ws.cond with
      | Some e when reached ws.next_poll ->
          cfg.stack <- K_poll ws :: cfg.stack; cfg.focus <- F_expr e; ("wait-poll", [])
      | _ when ws.cond = None && ws.wait.satisfied () -> finish false "wait-done"
      | _ when (match ws.wait.deadline with Some d -> reached d | None -> false) -> finish true "wait-timeout"
      | _ -> (
          let candidates = List.filter_map Fun.id
              [ ws.wait.deadline; host.next_event (); (if ws.cond = None then None else Some ws.next_poll) ] in
          match List.sort compare candidates with
          | l when cfg.cooperative ->
              (* ch. 14: another task may end the wait; the scheduler moves the clock when every
                 task waits (doc/semantics.md, "Several tasks"). *)
              cfg.wake <- (match l with t :: _ -> Some t | [] -> None); ("wait-yield", [])
          | [] ->
              cfg.focus <- F_done (Deadlock
                                     (Printf.sprintf "deadlock at %g s: the task waits for %s, and nothing can end the wait (no stimulus event left, no interrupt to come)"
                                        now ws.wait.what));
              ("wait-deadlock", [])
          | t :: _ when t > host.max_time -> time_exhausted cfg "wait-time-limit"
          | t :: _ -> host.advance_to t; ("wait-advance", [])))

let next cfg =
  let statement_point = match cfg.stack with
    | K_seq (b, i) :: _ -> i < Array.length b.Ir.body
    | (K_while_body _ | K_for_body _) :: _ -> true
    | _ -> false in
  if statement_point then begin
    (* Each statement entered, and each new round of a loop, takes the statement time; once:
       settling may have charged it already and stopped here (see [settle]). *)
    if cfg.charged then cfg.charged <- false else cfg.host.statement ();
    if cfg.host.now () > cfg.host.max_time then time_exhausted cfg "time-limit"
    else match serve_interrupt cfg with Some r -> r | None -> next_frame cfg
  end
  else match cfg.stack with
    | K_wait ws :: rest -> wait_step cfg ws rest
    | K_seq _ :: _ -> (
        (* ch. 8: "after the last statement of a statement list" is a point of response too. *)
        match serve_interrupt cfg with Some r -> r | None -> next_frame cfg)
    | _ -> next_frame cfg

let start_loop cfg (f : Ir.for_loop) from t step rest =
  set cfg.act.slots.(f.variable) from;
  cfg.focus <- F_next;
  if for_in_range from t step then begin
    cfg.stack <- K_seq (f.loop_body, 0) :: K_for_body (f, t, step) :: rest;
    ("for-enter", observed_store cfg cfg.act.slots.(f.variable) from)
  end
  else (cfg.stack <- rest; ("for-empty", []))

let value_step cfg v =
  match cfg.stack with
  | K_assign_store l :: rest -> (
      match get l with
      | V.Handle h when String.length (V.handle_kind h) > 6 && String.sub (V.handle_kind h) 0 6 = "signal" -> (
          (* §2.16: assigning to an output signal sets it. *)
          cfg.stack <- rest;
          match cfg.host.write_signal (V.Handle h) v with
          | Ok () -> cfg.focus <- F_next; ("store-signal", [])
          | Error "" -> cfg.focus <- F_done (Stuck "a signal assigned a value that is not a num"); ("stuck", [])
          | Error name -> raise_ cfg name; ("store-signal", []))
      | _ -> set l v; cfg.stack <- rest; cfg.focus <- F_next; ("store", observed_store cfg l v))
  | K_poll ws :: K_wait _ :: rest -> (
      match bool_of v with
      | Some true ->
          cfg.stack <- rest;
          (match ws.wait.finish ~timed_out:false with
           | None -> cfg.focus <- F_next
           | Some { error; _ } -> raise_ cfg error);
          ("wait-poll-true", [])
      | _ ->
          ws.next_poll <- ws.next_poll +. Option.value ws.wait.poll ~default:Rapid_observable.Wait.default_poll_rate;
          cfg.stack <- K_wait ws :: rest; cfg.focus <- F_next; ("wait-poll-false", []))
  | K_read :: _ -> cfg.focus <- F_done (Stuck "a value where a place was read"); ("stuck", [])
  | K_unary (op, _) :: rest -> (
      cfg.stack <- rest;
      match Arith.unary op v with
      | Ok r -> cfg.focus <- F_value r; ("unary", [])
      | Error name -> cfg.focus <- F_done (Stuck ("a unary operation failed: " ^ name)); ("stuck", []))
  | K_binary_right (op, a, _) :: rest -> (
      cfg.stack <- rest;
      match Arith.binary op a v with
      | Ok r -> cfg.focus <- F_value r; ("binary", [])
      | Error name -> raise_ cfg name; ("binary-error", []))
  | K_and b :: rest -> (
      cfg.stack <- rest;
      match bool_of v with
      | Some false -> cfg.focus <- F_value v; ("and-short", [])
      | _ -> cfg.focus <- F_expr b; ("and-right", []))
  | K_or b :: rest -> (
      cfg.stack <- rest;
      match bool_of v with
      | Some true -> cfg.focus <- F_value v; ("or-short", [])
      | _ -> cfg.focus <- F_expr b; ("or-right", []))
  | K_aggregate (es, acc, i, kind) :: rest ->
      acc.(i) <- v;
      if i + 1 < Array.length es then begin
        cfg.stack <- K_aggregate (es, acc, i + 1, kind) :: rest; cfg.focus <- F_expr es.(i + 1);
        ("aggregate-next", [])
      end
      else begin
        cfg.stack <- rest;
        cfg.focus <- F_value (match kind with Record_value -> V.Record acc | Array_value -> V.Array acc);
        ("aggregate", [])
      end
  | K_if (t, f) :: rest -> (
      match bool_of v with
      | Some true -> cfg.stack <- K_seq (t, 0) :: rest; cfg.focus <- F_next; ("if-true", [])
      | _ -> cfg.stack <- K_seq (f, 0) :: rest; cfg.focus <- F_next; ("if-false", []))
  | K_compact_if inner :: rest -> (
      cfg.stack <- rest;
      match bool_of v with
      | Some true -> cfg.unmarked <- true; cfg.focus <- F_stmt inner; ("compact-if-true", [])
      | _ -> cfg.focus <- F_next; ("compact-if-false", []))
  | K_while_test (c, b) :: rest -> (
      match bool_of v with
      | Some true -> cfg.stack <- K_seq (b, 0) :: K_while_body (c, b) :: rest; cfg.focus <- F_next; ("while-true", [])
      | _ -> cfg.stack <- rest; cfg.focus <- F_next; ("while-false", []))
  | K_for_to (f, from) :: rest -> (
      match f.step with
      | Some _ -> cfg.focus <- F_done (Stuck "a FOR bound left unsettled"); ("stuck", [])
      | None ->
          (* §4.18: the default step is 1, or -1 when the range decreases. *)
          let step = match from, v with V.Num a, V.Num b when a > b -> V.num (-1.) | _ -> V.num 1. in
          start_loop cfg f from v step rest)
  | K_for_step (f, from, t) :: rest -> start_loop cfg f from t v rest
  | K_test_subject (cases, default) :: rest ->
      if Array.length cases = 0 then (cfg.stack <- K_seq (default, 0) :: rest; cfg.focus <- F_next; ("test-default", []))
      else (cfg.stack <- K_test_value (v, cases, default, 0, 0) :: rest;
            cfg.focus <- F_expr (fst cases.(0)).(0); ("test-subject", []))
  | K_test_value (subject, cases, default, ci, vi) :: rest ->
      (* §4.20: the first test value equal to the test expression selects its list. *)
      if V.equal subject v then (cfg.stack <- K_seq (snd cases.(ci), 0) :: rest; cfg.focus <- F_next; ("test-match", []))
      else begin
        let ci, vi = if vi + 1 < Array.length (fst cases.(ci)) then (ci, vi + 1) else (ci + 1, 0) in
        if ci >= Array.length cases then (cfg.stack <- K_seq (default, 0) :: rest; cfg.focus <- F_next; ("test-default", []))
        else (cfg.stack <- K_test_value (subject, cases, default, ci, vi) :: rest;
              cfg.focus <- F_expr (fst cases.(ci)).(vi); ("test-next", []))
      end
  | K_return_value :: _ -> return_from cfg (Some v)
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
                  let rule, events = stop cfg e "raise-new-unhandled" in
                  (rule, Error_raised { name = e.name; number = e.number; at = e.err_at } :: events)
              | In_handler _, Some _ ->
                  cfg.focus <- F_search (e, cfg.act.recovery_up);
                  ("raise-new", [ Error_raised { name = e.name; number = e.number; at = e.err_at } ])
              | _ -> cfg.focus <- F_raise e; ("raise", []))
          | _ -> raise_ cfg "ERR_ILLRAISE"; ("raise-illegal", []))
      | None -> raise_ cfg "ERR_ILLRAISE"; ("raise-illegal", []))
  | K_late_name (args, at) :: rest -> (
      cfg.stack <- rest;
      match v with
      | V.String name -> (
          let found = late_routine cfg name in
          match found with
          | None -> raise_ ~about:name cfg (Late_binding.unknown_procedure_error name); ("call-late-unknown", [])
          | Some i when cfg.program.routines.(i).kind <> Procedure ->
              (* §4.6: late binding calls procedures only. *)
              raise_ ~about:name cfg "ERR_CALLPROC"; ("call-late-mismatch", [])
          | Some i -> (
              let r = cfg.program.routines.(i) in
              match Late_binding.bind r ~kind:(reference_kind cfg) args with
              | Error error_name -> raise_ ~about:name cfg error_name; ("call-late-mismatch", [])
              | Ok arguments ->
                  (begin_call cfg { Ir.callee = Routine i; arguments; call_at = at }, [])))
      | _ -> raise_ cfg "ERR_CALLPROC"; ("call-late-mismatch", []))
  | K_fit shape :: rest -> (
      cfg.stack <- rest;
      (* §3.10: an aggregate takes its parameter's type, when its members fit it. *)
      match V.conform shape v with
      | Some v -> cfg.focus <- F_value v; ("argument-fit", [])
      | None -> (match rest with K_args _ :: r -> cfg.stack <- r | _ -> ());
          raise_ cfg "ERR_CALLPROC"; ("argument-fit-refused", []))
  (* Settling binds a value argument the budget holds (see [settle]). *)
  | K_args cs :: rest when V.bytes v > args_room cfg cs ->
      cfg.stack <- rest;
      cfg.focus <- F_done (memory_exhausted cfg ("the copy for the parameter " ^ cs.callee.parameters.(cs.next).p_name)
                             (region_of_focus_stmt cfg));
      ("memory-exhausted", [])
  | K_element_index (l, idx, i, at) :: rest -> (
      (* §3.6: an index is an integer within the array's dimension (ERR_OUTOFBND). *)
      match get l, num_of v with
      | V.Array elems, Some f -> (
          match to_int f with
          | Some k when k >= 1 && k <= Array.length elems ->
              let l' = { box = elems; idx = k - 1 } in
              if i + 1 < Array.length idx then begin
                cfg.stack <- K_element_index (l', idx, i + 1, at) :: rest; cfg.focus <- F_expr idx.(i + 1);
                ("index-next", [])
              end
              else (cfg.stack <- rest; cfg.focus <- F_loc l'; ("element", []))
          | Some _ -> cfg.stack <- rest; raise_ cfg "ERR_OUTOFBND"; ("index-out-of-bounds", [])
          | None -> cfg.stack <- rest; raise_ cfg "ERR_NOTINTVAL"; ("index-not-integer", []))
      | _ -> cfg.stack <- rest; cfg.focus <- F_done (Stuck "an index into a value that is not an array"); ("stuck", []))
  | _ -> cfg.focus <- F_done (Stuck "a value with no frame to take it"); ("stuck", [])

let loc_step cfg l =
  match cfg.stack with
  | K_args cs :: rest -> bind_alias cfg cs rest l
  | K_connect_target (trap, target) :: rest -> (
      cfg.stack <- rest;
      (* §4.15: the target "must be (or denote) a module variable (not a routine variable)":
         through a VAR or INOUT parameter, what the parameter denotes (ERR_CNTNOTVAR). A
         connected interrupt number cannot be connected again (ERR_ALRDYCNT); one freed by
         IDelete can (R-8-f). *)
      match get l with
      | _ when reference_kind cfg target Ref_variable = Ref_persistent || not (denotes_module_data cfg target) ->
          raise_ cfg "ERR_CNTNOTVAR"; ("connect-not-variable", [])
      | V.Num n when n <> 0. && Float.is_integer n && cfg.host.connected (int_of_float n) ->
          raise_ cfg "ERR_ALRDYCNT"; ("connect-again", [])
      | _ -> (
          match cfg.host.connect ~trap with
          | Ok n -> set l (V.num (float_of_int n)); cfg.focus <- F_next; ("connect-allocate", observed_store cfg l (get l))
          | Error name -> raise_ cfg name; ("connect-inomax", [])))
  | K_read_signal :: rest -> (
      cfg.stack <- rest;
      (* §2.16: a signal in value context is its value. *)
      match cfg.host.read_signal (get l) with
      | Ok v -> cfg.focus <- F_value v; ("signal-value", [])
      | Error name -> raise_ cfg name; ("signal-not-connected", []))
  | _ -> cfg.focus <- F_done (Stuck "a location with no frame to take it"); ("stuck", [])

(* A place in focus between steps is one settling could not locate (see [settle]). *)
let place_step cfg (p : Ir.place) =
  match p with
  | Whole (Local i) when i < Array.length cfg.act.present && not cfg.act.present.(i) ->
      (* §5.2: the value of an absent optional parameter cannot be used (ERR_NOTPRES). *)
      (match cfg.stack with _ :: rest -> cfg.stack <- rest | [] -> ());
      raise_ cfg "ERR_NOTPRES"; ("place-absent", [])
  | Unresolved name -> raise_ ~about:name cfg "ERR_REFUNKDAT"; ("place-unknown", [])
  | _ -> cfg.focus <- F_done (Stuck "a place left unsettled"); ("stuck", [])

let expr_step cfg (e : Ir.expr) =
  match e.e with
  | Literal _ -> cfg.focus <- F_done (Stuck "a literal left unsettled"); ("stuck", [])
  | Read p ->
      let l = static_loc cfg p in
      if l != no_loc then (cfg.focus <- F_value (get l); ("read", []))
      else (push cfg K_read; cfg.focus <- F_place p; ("read-place", []))
  | Read_signal p -> push cfg K_read_signal; cfg.focus <- F_place p; ("read-signal", [])
  | Unary (op, a) -> push cfg (K_unary (op, e)); cfg.focus <- F_expr a; ("unary-operand", [])
  | Binary (op, a, b) -> push cfg (K_binary_left (op, b, e)); cfg.focus <- F_expr a; ("binary-operands", [])
  | And (a, b) -> push cfg (K_and b); cfg.focus <- F_expr a; ("and", [])
  | Or (a, b) -> push cfg (K_or b); cfg.focus <- F_expr a; ("or", [])
  | Aggregate (es, kind) ->
      push cfg (K_aggregate (es, Array.make (Array.length es) (V.Bool false), 0, kind));
      cfg.focus <- F_expr es.(0); ("aggregate-first", [])
  | Call c -> (
      match c.callee with
      | Unknown_routine name -> raise_ ~about:name cfg "ERR_REFUNKFUN"; ("call-unknown-function", [])
      | Routine _ -> (begin_call cfg c, []))
  | Placeholder ->
      (* In an initial value of routine data no statement is in progress: the placeholder's own
         place (R-7.1-w). *)
      if cfg.mark = [] && initialising cfg cfg.act then cfg.focus <- F_raise (error cfg "ERR_EXECPHR" e.at)
      else raise_ cfg "ERR_EXECPHR";
      ("execute-placeholder", [])
  | Fitted (a, shape) -> push cfg (K_fit shape); cfg.focus <- F_expr a; ("argument-aggregate", [])

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
      ("undo-run", [ Undo_run act.routine.name ])
  | _ -> leave_abandoned cfg after "abandon" "abandon-entry"

(* §7.2: the long jump looks for an error recovery point from the routine where the error
   arrives up the call chain; found, every routine in between is abandoned (UNDO first); not
   found, the error is raised again at the call point, an ordinary propagation. *)
let search_step cfg (e : err) candidate =
  match candidate with
  | Some a when recovery_point cfg a e ->
      cfg.focus <- F_abandon (Go_on_long_jump ({ e with searched = true }, a)); ("longjump-found", [])
  | Some a -> cfg.focus <- F_search (e, a.recovery_up); ("longjump-search", [])
  | None when cfg.act.routine.kind = Trap -> stop cfg e "raise-in-trap"
  | None -> cfg.focus <- F_abandon (Go_on_propagate { e with searched = true }); ("raise-propagate", [])

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
      | None -> raise_ cfg "ERR_ILLRAISE"; ("raise-to-user-illegal", [])
      | Some n -> (
          let e' = { (error_of_number cfg n e.err_at) with searched = true } in
          match user_call act with
          | None -> stop cfg e' "raise-to-user-no-user-level"
          | Some (user, mark) -> (
              let e' = { e' with err_at = region_of_mark user mark; chain = lazy (call_chain user) } in
              match user.routine.error, user.handling with
              | Some h, Body when present "breakoff" ->
                  (* This routine is left without its UNDO handler; those above it run theirs. *)
                  let rule, events = leave_abandoned cfg (Go_on_long_jump (e', user)) "raise-to-user-break-off" "raise-to-user-break-off" in
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
                  ("raise-to-user-continue",
                   [ Error_raised { name = e'.name; number = n; at = e'.err_at };
                     Error_handled { name = e'.name; routine = user.routine.name } ])
              | _ -> stop cfg e' "raise-to-user-unhandled")))
  | _ ->
      (* A call the checker cannot see (late binding): there is no error of a NOSTEPIN routine
         to hand on (R-7.3-n). *)
      cfg.focus <- F_done (Stopped { name = "ERR_ILLRAISE"; number = error_number cfg "ERR_ILLRAISE";
                                     at = cs.call.call_at; chain = call_chain act; about = Some "RaiseToUser" });
      ("raise-to-user-misplaced", [])

let () = raise_to_user_ref := raise_to_user

let step_unguarded cfg =
  match cfg.focus with
  | F_next -> next cfg
  | F_stmt s -> exec cfg s
  | F_expr e -> expr_step cfg e
  | F_value v -> value_step cfg v
  | F_place p -> place_step cfg p
  | F_loc l -> loc_step cfg l
  | F_raise e ->
      (* §7.1: an error raised again at the call point after propagation was said by the
         propagation (schema rapid-sem/2: one error-raised, then error-propagated per level). *)
      let again = cfg.propagated in
      cfg.propagated <- false;
      let rule, events = raise_step cfg e in
      (rule, if again then events else Error_raised { name = e.name; number = e.number; at = e.err_at } :: events)
  | F_search (e, c) -> search_step cfg e c
  | F_abandon after -> abandon_step cfg after
  | F_done _ -> ("done", [])

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
let interrupt_taken cfg =
  (not cfg.act.trap_level)
  && (match cfg.host.take_interrupt () with Some i -> cfg.held <- Some i; true | None -> false)

let rec settle cfg =
  match cfg.focus with
  | F_expr { e = Literal v; _ } -> cfg.focus <- F_value v; settle cfg
  | F_value v -> (
      match cfg.stack with
      | K_binary_left (op, b, at) :: rest ->
          cfg.stack <- K_binary_right (op, v, at) :: rest; cfg.focus <- F_expr b; settle cfg
      | K_args cs :: _ -> if bind_value cfg cs v then (cfg.focus <- F_next; settle cfg)
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
            if cfg.host.now () > cfg.host.max_time || interrupt_taken cfg then cfg.charged <- true
            else (cfg.stack <- K_seq (b, i + 1) :: rest; cfg.focus <- F_stmt (Array.unsafe_get b.body i))
          end
          else if not (interrupt_taken cfg) then (cfg.stack <- rest; settle cfg)
      | K_args cs :: _ -> settle_arguments cfg cs  (* a literal argument is bound there *)
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

let () = settle_ref := settle

(* A value of the wrong type for an operation is excluded by the static semantics: meeting one
   is a bug of rapid-sem, reported as a stuck configuration. *)
let step cfg =
  cfg.count <- cfg.count + 1;
  (* The entry routine is entered with the first step (schema rapid-sem/2). *)
  let entry = if cfg.entered then [] else (cfg.entered <- true; [ Routine_entered cfg.act.routine.name ]) in
  let rule, events =
    try let r = step_unguarded cfg in settle cfg; r with
    | Value.Type_mismatch m -> cfg.focus <- F_done (Stuck ("a value of the wrong type: " ^ m)); ("stuck", [])
    | Invalid_argument m -> cfg.focus <- F_done (Stuck ("invalid argument: " ^ m)); ("stuck", [])
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
  | [] -> (rule, events)
  | moved -> (rule, events @ List.map (fun e -> Motion e) moved)

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

let rule_names = [
  "label"; "execute-placeholder"; "assign";
  "store"; "call-arguments"; "argument-reference"; "argument-alias";
  "argument-alias-refused"; "call-enter";
  "argument-pass-on-duplicate"; "argument-aggregate"; "argument-fit"; "argument-fit-refused";
  "elseif"; "connect-not-variable"; "memory-exhausted";
  "call-primitive"; "call-primitive-error"; "call-primitive-stop"; "call-by-var";
  "call-by-var-unknown"; "call-by-var-mismatch"; "call-not-modelled"; "call-stubbed"; "call-depth-exceeded"; "call-unknown";
  "call-unknown-function"; "call-late"; "call-late-unknown"; "call-late-mismatch";
  "return-procedure"; "return-function"; "return-entry"; "return-value"; "function-no-return";
  "goto"; "break"; "continue"; "if"; "if-true"; "if-false"; "compact-if"; "compact-if-true"; "compact-if-false"; "while"; "while-true"; "while-false";
  "while-again"; "for"; "for-enter"; "for-empty"; "for-step"; "for-done"; "test";
  "test-subject"; "test-next"; "test-match"; "test-default"; "connect"; "connect-allocate";
  "connect-again"; "exit"; "raise-number"; "raise"; "raise-illegal"; "raise-again";
  "raise-again-unhandled"; "raise-new"; "raise-new-unhandled"; "raise-handle"; "raise-in-handler"; "raise-unhandled";
  "raise-propagate"; "longjump-search-start"; "longjump-search"; "longjump-found"; "abandon";
  "abandon-entry"; "undo-run"; "undo-done"; "undo-done-entry"; "retry"; "retry-limit"; "trynext"; "handler-end";
  "read-place"; "read"; "read-signal"; "place-absent"; "place-unknown";
  "index-next"; "element"; "index-out-of-bounds"; "index-not-integer";
  "unary-operand"; "unary"; "binary-operands"; "binary";
  "binary-error"; "and"; "and-short"; "and-right"; "or"; "or-short"; "or-right";
  "aggregate-first"; "aggregate-next"; "aggregate"; "local-initial-value";
  "trap-end"; "interrupt-serve"; "time-limit"; "wait-start"; "wait-done"; "wait-timeout";
  "wait-advance"; "wait-yield"; "wait-poll"; "wait-poll-true"; "wait-poll-false"; "wait-deadlock";
  "wait-time-limit"; "async-error"; "signal-value"; "signal-not-connected"; "store-signal"; "connect-inomax";
  "raise-in-trap"; "connect-not-variable";
  "async-error-unhandled"; "async-retry-resume"; "async-trynext-resume"; "async-exit"; "async-handler-leave";
  "async-error-at-move";
  "raise-to-user-continue"; "raise-to-user-break-off"; "raise-to-user-no-user-level";
  "raise-to-user-unhandled"; "raise-to-user-illegal"; "raise-to-user-misplaced";
  "resume-retry"; "resume-trynext";
  "done"; "stuck";
]

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

let statement_name (s : Ir.stmt) =
  match s.s with
  | Assign _ -> "an assignment" | Call_procedure _ -> "a procedure call" | Call_late _ -> "a late-bound procedure call"
  | Goto _ -> "GOTO" | Break -> "BREAK" | Continue -> "CONTINUE" | Return _ -> "RETURN" | Raise _ -> "RAISE"
  | Exit -> "EXIT" | Retry -> "RETRY" | Trynext -> "TRYNEXT" | Connect _ -> "CONNECT"
  | If _ | Elseif _ -> "IF" | Compact_if _ -> "a compact IF" | For _ -> "FOR" | While _ -> "WHILE"
  | Test _ -> "TEST" | Label -> "a label" | Placeholder_statement -> "<SMT>"

let not_supported why = Stdlib.Error ("backward execution is not supported: " ^ why ^ "; no step taken (§6.1)")

(* One statement backward from the program pointer (§6.1-§6.3): the statement before it in its
   statement list, which must be simple. The program pointer is then at that statement. *)
let backward cfg =
  match cfg.focus, cfg.stack with
  | F_done _, _ -> Stdlib.Error "the task is not running"
  | F_stmt cur, K_seq (b, j) :: rest when j >= 1 && j <= Array.length b.body && b.body.(j - 1) == cur ->
      if cfg.act.handling <> Body then
        (* §6.2: "the instructions of a BACKWARD handler or an error handler cannot be executed
           backward"; UNDO handlers likewise (doc/rulings.md R-6-d). *)
        not_supported "the program pointer is in an error or UNDO handler (§6.2)"
      else if cfg.backward_depth >= 0 then not_supported "backward execution cannot be nested (§6.2)"
      else if j = 1 then not_supported "the program pointer is at the top of a statement list"
      else begin
        let prev = b.body.(j - 2) in
        let moved () = cfg.stack <- K_seq (b, j - 1) :: rest; cfg.focus <- F_stmt prev in
        match prev.s with
        | Label | Assign _ | Connect _ ->
            (* §6.1: comments, labels, assignments and CONNECT are no-operations backward. *)
            moved (); Ok "backward-noop"
        | Call_procedure ({ callee = Routine i; _ } as call) -> (
            let r = cfg.program.routines.(i) in
            match r.backward with
            | None ->
                not_supported (Printf.sprintf "the procedure %s has no BACKWARD handler (§6.2)" r.name)
            | Some handler ->
                (* §6.1: the arguments are evaluated forward and bound to the parameters as in
                   forward execution; the BACKWARD handler runs in place of the body, with the
                   routine's data in its scope (§6.2). *)
                cfg.stack <- K_seq (b, j - 2) :: rest;
                push cfg (K_stmt (prev, cfg.mark)); cfg.mark <- cfg.stack;
                push cfg K_backward_end;
                cfg.backward_depth <- cfg.act.call_depth + 1;
                cfg.host.set_backward true;
                cfg.focus <- F_next;
                let callee = { r with body = handler } in
                let n = Array.length callee.parameters in
                push cfg (K_args { call; callee; args_slots = Array.make n (fresh_loc (V.Bool false));
                                   args_present = Array.make n false; args_kinds = Array.make n Ir.Ref_other;
                                   args_module_data = Array.make n false; args_memory = 0;
                                   primitive_args = Array.make n Argument.Missing; next = 0 });
                settle cfg;
                Ok "backward-call")
        | _ -> not_supported (statement_name prev ^ " cannot be executed backward")
      end
  | _ -> Stdlib.Error "the program pointer is not at a statement"

let backward_running cfg = cfg.backward_depth >= 0

let backward_rule_names = [ "backward-noop"; "backward-call"; "backward-end"; "raise-in-backward" ]

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
