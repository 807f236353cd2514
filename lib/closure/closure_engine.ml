(* The second evaluator: routines compiled to closures; a statement completes by going on or by
   RETURN, and every other transfer of control is an exception. Written from doc/semantics.md and
   the manual; the machine is its differential partner, not its source. Where this file says
   "rule", it names the rule of doc/semantics.md it implements. *)

open Ir
module V = Value
module CC = Closure_controller
module IR = Installed_routine

let default_fuel = 100_000_000

type result = { outcome : Outcome.t; fuel_used : int }

(* Several tasks (Closure_tasks): the run hands the turn over at each statement and wait. *)
type cooperation = {
  share : V.t array -> unit;
  mutable entered : bool;
  turn : unit -> unit;
  yield : wake:float option -> what:string -> pure:bool -> unit;
  native_budget : int;
}

(* An error in flight (ch. 7): its name (ERR_... or the number of a user error), its number
   (ERRNO's value), the statement where it occurred and the call chain there, innermost first. *)
type error = {
  name : string; number : int; at : Rapid_syntax.Source.region;
  about : string option;              (* the unknown name, the procedure, the function (§7.1) *)
  mutable chain : string list Lazy.t option;
      (* filled in by the first activation that catches the error, the one it occurred in; lazy,
         so that a raise costs the same at any depth: only a report reads the chain *)
}

(* What may happen to an activation while one of its statements runs. *)
exception Raised of error              (* an error in this activation (§7.1) *)
exception Leaving of error             (* RAISE; in a handler: the error leaves the routine (§4.11) *)
exception Long_jump of int * error     (* to the error recovery point of this activation (§7.2) *)
exception Break_loop                   (* §4.8 *)
exception Continue_loop                (* §4.9 *)
exception Goto_label of int * int      (* §4.7: the label's statement list and index *)
exception Exit_task                    (* §4.12 *)
exception Observer_failed of exn        (* raised by the caller's on_event *)
exception Retry_signal                 (* §4.13 *)
exception Trynext_signal               (* §4.14 *)
exception Initial_value_failed of string * string  (* the data object, the error: nothing runs *)
exception Halt of Outcome.t            (* the task ends where it is: system error handler, Stop, limits *)
exception Kept_leave of int * error option
exception Continued_leave of int * [ `Return | `Raise of error | `Exit ]
    (* §7.3, R-7.3-p: the user level's handler that RaiseToUser \Continue ran ended otherwise
       than by RETRY or TRYNEXT: the NOSTEPIN routines in between are dropped on the way to the
       user routine (this level), without their UNDO handlers *)
    (* §7.4, R-7.4-m: the handler of an asynchronous error, run while the program pointer was
       kept in a routine the handler's activation (this level) called, ended by RETURN (None) or
       RAISE (the error): the routines in between are abandoned on the way *)

(* What only some activations need: routines with alias or optional parameters, or with an error
   handler. Other activations share one that nothing writes. *)
type extension = {
  boxes : V.t array array;            (* an alias parameter's location: container ... *)
  idx : int array;                    (* ... and index *)
  present : bool array;               (* optional parameters present (§5.2) *)
  bound : reference_kind array;       (* what an alias parameter is bound to *)
  module_data : bool array;           (* whether it denotes module data (CONNECT, §4.15) *)
  mutable retries : int;              (* RETRYs since the retried statement last completed *)
  mutable current : error option;     (* the error its handler is handling, for RAISE; *)
  mutable nums : float array;         (* the flat slots' values (see [flat]); [||] until the routine
                                         data's initialisation or a FOR loop needs them *)
  mutable num_boxes : V.t array;      (* per flat slot, the value it last took from a stored one
                                         (see [flat_store]), when it still holds it *)
}

let shared_extension =
  { boxes = [||]; idx = [||]; present = [||]; bound = [||]; module_data = [||]; retries = 0; current = None;
    nums = [||]; num_boxes = [||] }

(* The activation of a routine: its slots, and for alias parameters where their locations are. *)
type act = {
  routine : routine;
  store : V.t array;                  (* own slots: in parameters, routine data, loop variables *)
  mutable ext : extension;            (* its own once its flat slots are made ([flat_values]) *)
  level : int;                        (* its place in the call chain: 0 is the entry routine *)
  parent : act;                       (* its caller; the entry routine's is a sentinel of level -1 *)
  mutable result : V.t;               (* RETURN's value, on its way to the caller; no_value for none *)
  mutable nest : int;                 (* its share of the native stack (see native_budget) *)
  mutable memory : int;               (* bytes of RAPID data it holds: in arguments, routine
                                         data, itself (the memory budget) *)
}

(* Routine data of type num or dnum, and FOR variables, that the routine only reads as values and
   assigns as wholes (never passed by reference, never located): their values are kept unboxed in
   [nums], so that a store needs neither a box nor the write barrier. Nothing can tell such a slot
   from one in [store]: every read gives the value, and no location of it is ever made. *)
type flat = {
  position : int array;               (* per local slot: its index in [nums], or -1 *)
  dnum : bool array;                  (* per local slot: a dnum's (else a num's) *)
  count : int;
  keeps : bool;                       (* some flat slot is assigned a value read where it is
                                         stored: the activation keeps [num_boxes] *)
}

type compiled = {
  c_init : Rapid_syntax.Source.region -> act -> unit;  (* the call's statement, for the budget *)
  c_body : act -> bool;
  c_handler : (act -> bool) option;
  c_undo : (act -> bool) option;
  c_nest : int;                       (* the depth of its syntax tree, statements and expressions *)
  c_value : (act -> V.t) option;
      (* a function whose body ends in RETURN e, for the direct path: its body giving RETURN's
         value itself, not through [result] (see [valued_body]) *)
  c_guard : (Arith.binary * float * V.t option) option;
      (* with [c_value], when its first statement is [IF slot1 op k RETURN e;], e the first slot
         (None) or a literal: the comparison and k, for a call that can see it holds before the
         activation is built (see [direct_call]) *)
}

type state = {
  program : program;
  globals : V.t array;
  limits : Limits.t;
  emit : Event.t -> unit;
  all_events : bool;                  (* false: only output, erase and log are wanted *)
  observe : bool;                     (* schema rapid-sem/2: stores, arguments, returned values *)
  mutable fuel : int;
  fuel_limit : int;
  mutable depth : int;
  mutable native : int;               (* the nests of the active routines *)
  native_budget : int;
  mutable next_interrupt : int;
  numbers : (string, int) Hashtbl.t Lazy.t;
      (* ERR_ names, upper case: built when an error is first raised by name (a sixtieth of
         an empty run's start otherwise) *)
  mutable compiled : compiled Lazy.t array;
  mutable memory : int;               (* bytes of RAPID data: module data and activations *)
  stub_unmodelled : bool;             (* --stub-unmodelled: unmodelled routines are no-ops *)
  stubbed : (string, unit) Hashtbl.t; (* the routines stubbed so far (one event each) *)
  host : Host.t;                      (* the world around the run: controller and motion *)
  mutable in_trap : bool;             (* a trap runs, or a routine it called: no interrupt is served *)
  mutable interrupts : bool;          (* some CONNECT ran: interrupts may occur *)
  mutable observing : bool;           (* the world may have something to report *)
  mutable quiet : int;                (* statements that may still pass uncharged (see [sync]) *)
  mutable quiet_base : int;           (* [quiet] when the world's clock was last charged *)
  mutable moving : bool;              (* the motion may have something to report *)
  max_time : float;
  move_owners : (int, act) Recent.t;  (* recent moves and the activation that ran each *)
  mutable serve_trap : act -> int -> int -> unit;  (* [serve_trap], tied below *)
  mutable undoing : act list;         (* activations whose UNDO handler runs (§7.6's search) *)
  mutable kept : act list;            (* activations in the handler of a kept asynchronous error *)
  mutable async_errors : error list;  (* recent \SyncLastMoveInst errors: TRYNEXT as RETRY (§7.4) *)
  mutable user_calls : (act * Rapid_syntax.Source.region) list;
      (* §7.3: user-level activations in a call of a NOSTEPIN routine, and that call's statement *)
  mutable resuming : (act * act) list;
      (* §7.3: a user level's handler run by RaiseToUser \Continue, and the NOSTEPIN activation
         its RETRY and TRYNEXT go on in *)
  mutable skip_undo : act list;       (* left by RaiseToUser \BreakOff: no UNDO (R-7.3-q) *)
  mutable next_cycle : bool;          (* ExitCycle: the [Exit_task] that unwinds starts the entry again *)
  cooperation : cooperation option;   (* one of several tasks (Closure_tasks) *)
  flats : (routine * flat) list Rapid_syntax.Source.Table.t;
      (* each routine's flat slots, found when it is first compiled (by its region, then
         physically: regions of different programs may coincide) *)
}

(* ------------------------------------------------------------------ errors *)

let number_of st name =
  match Hashtbl.find_opt (Lazy.force st.numbers) (String.uppercase_ascii name) with
  | Some n -> n
  | None -> ( match int_of_string_opt name with Some n -> n | None -> 0)

(* The call chain from an activation up, innermost first. *)
let chain_of (a : act) =
  let rec go (b : act) acc = if b.level < 0 then List.rev acc else go b.parent (b.routine.name :: acc) in
  go a []

(* The error as it was caught in activation [a]: where it occurred, if nothing caught it before. *)
let caught (a : act) e = (match e.chain with None -> e.chain <- Some (lazy (chain_of a)) | Some _ -> ()); e

let chain e = match e.chain with Some l -> Lazy.force l | None -> []

let emit_raised st e =
  if st.all_events then st.emit (Event.Error_raised { name = e.name; number = e.number; at = e.at })

(* An execution error where [at] is the statement in progress. *)
let fail ?about st ~at name =
  let e = { name; number = number_of st name; at; about; chain = None } in
  emit_raised st e;
  raise (Raised e)

let stopped e = Outcome.Stopped { name = e.name; number = e.number; at = e.at; chain = chain e; about = e.about }

(* §7.3: the user level of an activation of a NOSTEPIN routine: the first routine above it that
   is not one (none across a trap: its caller is no call), with the statement of its call. *)
let user_call st (b : act) =
  let rec go (b : act) =
    if b.routine.kind = Trap then None
    else
      let c = b.parent in
      if c.level < 0 then None
      else if c.routine.nostepin then go c
      else Option.map (fun at -> (c, at)) (List.assq_opt c st.user_calls) in
  if b.routine.nostepin then go b else None

(* R-7.3-o: an error the system error handler reports while NOSTEPIN routines are active is
   reported at the call in user code, with the call chain from there. *)
let at_user_level st (b : act) e =
  match user_call st b with
  | Some (u, at) -> { e with at; chain = Some (lazy (chain_of u)) }
  | None -> e

(* The system error handler stops the task (§7.1) with an error caught in activation [b]. *)
let stop st (b : act) e = Halt (stopped (at_user_level st b (caught b e)))

(* R-7.3-o: an error leaving the last NOSTEPIN routine [c] for its user-level caller is raised
   again at the call ([at]), with the caller's call chain. *)
let relocate st (c : act) e ~at =
  if c.routine.nostepin && c.routine.kind <> Trap && c.parent.level >= 0 && not c.parent.routine.nostepin
  then begin
    let e' = { e with at; chain = Some (lazy (chain_of c.parent)) } in
    (* Still the asynchronous error it was (§7.4: TRYNEXT as RETRY wherever it is handled). *)
    if st.async_errors <> [] && List.memq e st.async_errors then st.async_errors <- e' :: st.async_errors;
    e'
  end
  else e

(* This engine recurses on the native stack (doc/semantics.md): a call beyond its budget ends
   the run before the stack overflows; the machine keeps its continuations on the heap. *)
let native_stack_exhausted level =
  Outcome.Resource_exhausted
    (Printf.sprintf "call depth %d: the native stack is exhausted (resource exhaustion, §1.4; a larger ulimit -s, \
                     or --engine machine)" level, None)

(* ------------------------------------------------------------------ the memory budget *)

(* The budget of RAPID data (§1.4, doc/user-guide.md "Resources"), by the model of Value.bytes:
   beyond it the run ends as a resource exhausted at the place, before anything is built. *)
let memory_exhausted st what at =
  raise (Halt (Limits.memory_exhausted_by st.limits what at))

(* Value.bytes, with the scalars of most arguments (32 bytes each) and strings recognised here. *)
let value_bytes (v : V.t) =
  match v with V.Num _ | V.Dnum _ | V.Bool _ -> 32 | V.String s -> 32 + String.length s | _ -> V.bytes v [@@inline]

(* And a record of three scalars (pos, and the like): 16 + 3 x (8 + 32) bytes by Value.bytes. *)
let value_bytes (v : V.t) =
  match v with
  | V.Record [| (V.Num _ | V.Dnum _ | V.Bool _); (V.Num _ | V.Dnum _ | V.Bool _); (V.Num _ | V.Dnum _ | V.Bool _) |] ->
      136
  | _ -> value_bytes v [@@inline]

(* An activation itself counts, so that a deep recursion stays within the budget too. *)
let activation_bytes (r : routine) = 256 + 16 * r.locals

(* While its arguments are bound the callee's bytes are pending, not yet in [st.memory]. *)
let charge_pending st (c : act) bytes what at =
  if bytes > st.limits.max_memory - st.memory - c.memory then memory_exhausted st what at
  else c.memory <- c.memory + bytes

(* A call's argument copy counted with what the call has pending already: the new pending total,
   or the budget's error naming the copy. *)
let count_copy st ~at what v pending =
  let b = value_bytes v in
  if b > st.limits.max_memory - st.memory - pending then memory_exhausted st what at;
  pending + b [@@inline]

(* Routine data of an active routine. *)
let charge_active st (a : act) bytes what at =
  if bytes > st.limits.max_memory - st.memory then memory_exhausted st what at
  else begin a.memory <- a.memory + bytes; st.memory <- st.memory + bytes end

(* For Value.to_single in the operators below: an integer of at most 24 bits is a single
   already, and finite; it is recognised without the conversion's two calls (below 2^24 in
   magnitude, adding and taking away 1.5 x 2^52 rounds x to an integer, exactly). *)
let is_small_integer x = x <= 16777216. && x >= -16777216. && (x +. 0x1.8p52) -. 0x1.8p52 = x [@@inline]

(* What a procedure gives back: no value. Recognised by identity. *)
let no_value = V.String "(no value)"

let v_true = V.Bool true
let v_false = V.Bool false

(* A deep recursion keeps its chain of activations alive: with the default minor heap
   (256 k words) each minor collection promotes the chain and scans the deep native stack, most
   of a recursion 9,000 deep (bench/peers/depth.mod). The first call deeper than [deep_calls]
   in the process gives the minor heap 2 M words (16 MB), once; a run that stays shallow keeps
   the default, and its small resident set. Nothing a program observes depends on it. *)
let deep_calls = ref 1024

let deeper_heap () =
  deep_calls := max_int;
  let g = Gc.get () in
  if g.minor_heap_size < 2_097_152 then Gc.set { g with minor_heap_size = 2_097_152 }

let deepen level = if level >= !deep_calls then deeper_heap () [@@inline]

(* An activation's end: what it counted is given back ([pop], here to be inlined). *)
let release st (c : act) =
  st.depth <- c.level; st.native <- st.native - c.nest;
  st.memory <- st.memory - c.memory; c.memory <- 0 [@@inline]

(* Assignment and in parameters copy (§4.5, §5.2); only records and arrays have parts to copy. *)
let copy (v : V.t) = match v with V.Record _ | V.Array _ -> V.copy v | _ -> v [@@inline]

let fuel_out () = raise (Halt Outcome.Running)

let tick st =
  let f = st.fuel - 1 in
  st.fuel <- f;
  if f < 0 then fuel_out () [@@inline]

let check st ~at = function Ok v -> v | Error name -> fail st ~at name

(* [binary]'s num result, for the fused forms below: rounded to single (R-2.13-a), an integer
   of at most 24 bits as it is, an infinite result ERR_OVERFLOW (R-3.12-c). *)
let single_float st ~at x =
  if is_small_integer x then x
  else
    let y = Int32.float_of_bits (Int32.bits_of_float x) in
    if Float.is_finite y then y else fail st ~at "ERR_OVERFLOW" [@@inline]

(* Written out rather than as [V.Num (single_float ...)]: the box of the float is then built once
   in each branch, which costs fewer instructions on the calls' path (fib, depth). *)
let single_num st ~at x =
  if is_small_integer x then V.Num x
  else
    let y = Int32.float_of_bits (Int32.bits_of_float x) in
    if Float.is_finite y then V.Num y else fail st ~at "ERR_OVERFLOW" [@@inline]

let double_float st ~at x = if Float.is_finite x then x else fail st ~at "ERR_OVERFLOW" [@@inline]

(* [binary]'s dnum result: the double as it is, an infinite result ERR_OVERFLOW (R-3.12-c). *)
let double_num st ~at x = if Float.is_finite x then V.Dnum x else fail st ~at "ERR_OVERFLOW" [@@inline]

(* string + string (§3.12): a result beyond 80 characters is ERR_STRTOOLNG (§2.13), its length
   known before the copy. Stdlib.(^) written out, which spares its call. *)
let concat st ~at p q =
  let n = String.length p and m = String.length q in
  if n + m > 80 then fail st ~at "ERR_STRTOOLNG"
  else begin
    let b = Bytes.create (n + m) in
    Bytes.unsafe_blit_string p 0 b 0 n;
    Bytes.unsafe_blit_string q 0 b n m;
    V.String (Bytes.unsafe_to_string b)
  end [@@inline]

(* [condition]'s comparison of two nums (§3.12). *)
let compare_nums (op : Arith.binary) (p : float) (q : float) =
  match op with
  | Num_lt -> p < q
  | Num_le -> p <= q
  | Num_gt -> p > q
  | Num_ge -> p >= q
  | Equal -> p = q
  | _ -> not (p = q) [@@inline]

let is_num_comparison = function
  | Arith.Num_lt | Num_le | Num_gt | Num_ge | Equal | Not_equal -> true
  | _ -> false

(* An argument [own + k] or [own - k]: an own slot of the caller and a num literal (the step of
   a recursion), computed in the call's closure, as [binary_literal] computes it. *)
let own_step own (source : Closure_call.source) =
  match source with
  | Closure_call.Value { e = Binary ((Num_add | Num_sub) as op, { e = Read (Whole (Local i)); _ },
                                     { e = Literal (V.Num q as v); _ }); _ } when own i ->
      Some (i, op, v, q)
  | _ -> None

(* An event of a call as the run wants it: all of them, or only what [rapid-sem run] without
   --json shows (output, erase, log). *)
let emit_wanted st (e : Event.t) =
  if st.all_events then st.emit e
  else match e with Output _ | Erase | Log _ -> st.emit e | _ -> ()

let not_modelled = { IR.result = Not_modelled; events = []; new_move = None }

(* ------------------------------------------------------------------ the controller *)

(* What the world and the motion did since last asked, as the machine reports it after each
   step: signal changes, interrupts, moves. *)
let rec observe st = observe_world st; observe_motion st

and observe_world st =
  match st.host.observations () with
  | [] -> ()
  | seen -> if st.all_events then List.iter (fun o -> st.emit (Event.Controller o)) seen

and observe_motion st =
  if st.moving then
    match st.host.motion_events () with
    | [] -> ()
    | moved -> if st.all_events then List.iter (fun m -> st.emit (Event.Motion m)) moved

(* While the world has nothing scheduled and the program has not yet touched it (no stimulus,
   no signal, no controller routine), nothing but the time limit can happen at a statement:
   the statements are then counted here and charged to the world's clock at once, before
   anything looks at it ([sync]). *)
let sync st =
  let uncharged = st.quiet_base - st.quiet in
  if uncharged > 0 then begin st.host.statements uncharged; st.quiet_base <- st.quiet end

let watch st =
  if not st.observing then begin sync st; st.observing <- true; st.quiet <- 0; st.quiet_base <- 0 end

(* ch. 8: the entry of a statement, and each new round of a loop, takes the statement time and
   is a point of response: an interrupt queued is served there (not at trap level), then the
   point is taken again, as the machine's settling enters the statement again after the trap.
   Past --max-time the run ends (time-limit). *)
let rec at_point st a =
  sync st;
  if not (st.host.statement_within ()) then raise (Halt (Outcome.time_limit st.host.max_time));
  if st.observing then begin
    observe st;
    if st.interrupts && not st.in_trap then
      match st.host.take_interrupt () with
      | Some (number, trap) -> observe st; st.serve_trap a number trap; at_point st a
      | None -> ()
  end
  else begin
    let left = st.host.statements_left () in
    st.quiet <- left; st.quiet_base <- left
  end

(* ch. 14: where the machine's turn ends, a statement of a statement list in focus, after its
   point of response; what happened in this task's world meanwhile is reported as the turn
   comes back (the machine reports it after the turn's first step). The entry of the first
   statement is the task's start's: the machine made for it took it (Closure_tasks). *)
let entered st a =
  match st.cooperation with
  | None -> at_point st a
  | Some c when not c.entered -> c.entered <- true
  | Some c -> at_point st a; c.turn (); observe st

(* [quiet] is 0 whenever the world is observed (always with several tasks). *)
let at_statement st a = if st.quiet > 0 then st.quiet <- st.quiet - 1 else entered st a [@@inline]

(* A new round of a loop: a point of response, not a statement (no turn ends there). *)
let at_round st a = if st.quiet > 0 then st.quiet <- st.quiet - 1 else at_point st a [@@inline]

(* With several tasks, where the machine's turn ends without a statement being entered: a new
   round of a loop whose body has no statement (R-14-o), the statement RETRY runs again (in
   focus again, its time not taken again). *)
let pass_turn st = match st.cooperation with Some c -> c.turn (); observe st | None -> ()

(* ch. 8: "after the last statement of a statement list" is a point of response too; it takes no
   time. *)
let rec serve_at_end st a =
  match st.host.take_interrupt () with
  | Some (number, trap) -> observe st; st.serve_trap a number trap; if not st.in_trap then serve_at_end st a
  | None -> ()

let at_end st a = if st.interrupts && not st.in_trap then serve_at_end st a [@@inline]

(* ------------------------------------------------------------------ slots and places *)

let is_alias (p : parameter) = p.p_mode <> Rapid_typing.Tables.Mode_in

(* Schema rapid-sem/2 (Observation): the texts are built only when the run observes them. The
   roots are given as the machine gives its own, so that Observation.find names a place alike. *)
let observe_in st (a : act) ~flat (box, i) =
  let r = a.routine in
  let local k =
    if k = flat then (box, i)
    else if k < Array.length r.parameters && is_alias r.parameters.(k) then
      ((if k < Array.length a.ext.boxes then a.ext.boxes.(k) else [||]),
       (if k < Array.length a.ext.idx then a.ext.idx.(k) else 0))
    else (a.store, k) in
  let globals = st.globals in
  let roots = { Observation.n_locals = r.locals; local; n_globals = Array.length globals;
                global_box = (fun _ -> globals); global_idx = (fun g -> g) } in
  st.emit (Event.Observed (Stored { place = Observation.place_of st.program r (box, i) roots;
                                value = Observation.value box.(i) }))

let observe_store st a location = observe_in st a ~flat:(-1) location

(* A flat slot's store (see [flat]): its value in a box of its own, which the slot's root names. *)
let observe_flat st a slot v = observe_in st a ~flat:slot ([| v |], 0)

(* How a local slot is reached, known when the routine is compiled. *)
type slot_access =
  | Own | Alias | Optional_own | Optional_alias
  | Flat_num of int | Flat_dnum of int  (* a flat slot (see [flat]): its index in [nums] *)

(* How a parameter or an own slot is reached, flat slots aside. *)
let parameter_access (r : routine) i =
  if i < Array.length r.parameters then
    let p = r.parameters.(i) in
    match p.p_optional, is_alias p with
    | false, false -> Own
    | false, true -> Alias
    | true, false -> Optional_own
    | true, true -> Optional_alias
  else Own

(* §4.5: an assignment gives its target a copy of the value. A call of a function whose every
   RETURN names one of its own slots (an in parameter's copy, its routine data) gives a value
   nothing else holds: the callee's activation, which held it, is gone once the call returns
   (its slots are written by copies only, and a function without procedure calls and handlers
   leaves no reference to its activation behind: no move remembers it, §7.4). Assigning such a
   result needs no second copy (bench/README.md, "Fourth round"). *)
let returns_own_value (r : routine) =
  let own j = parameter_access r j = Own in
  let rec stmt (x : stmt) = match x.s with
    | Return (Some { e = Read (Whole (Local j)); _ }) -> own j
    | Assign _ | Label | Break | Continue -> true
    | If (_, b1, b2) | Elseif (_, b1, b2) -> block b1 && block b2
    | Compact_if (_, inner) -> stmt inner
    | For f -> block f.loop_body
    | While (_, b) -> block b
    | Test (_, cases, default) -> Array.for_all (fun (_, b) -> block b) cases && block default
    | Return _ | Call_procedure _ | Call_late _ | Goto _ | Raise _ | Exit | Retry | Trynext | Connect _
    | Placeholder_statement -> false
  and block (b : block) = Array.for_all stmt b.body in
  r.kind = Function && r.primitive = None && r.error = None && r.backward = None && r.undo = None
  && block r.body

(* §5.2: an in parameter is a copy of its argument. When the routine neither writes the
   parameter nor any part of it, nor passes it or a part of it by reference, nor returns it or a
   part of it, and the argument is routine data of the caller (which nothing can change while
   the call runs: the direct path's parameters are all in parameters, so no alias of it reaches
   the callee), the copy could be the argument itself: nothing tells them apart
   (bench/README.md, "Fourth round"). *)
let reads_only_parameter (r : routine) i =
  let rec rooted (p : place) = match p with
    | Whole (Local k) -> k = i
    | Element (p, _) | Component (p, _) -> rooted p
    | Whole (Global _) | Unresolved _ -> false in
  let rec place (p : place) = match p with
    | Element (p, ix) -> place p && Array.for_all expr ix
    | Component (p, _) -> place p
    | Whole _ | Unresolved _ -> true
  and expr (e : expr) = match e.e with
    | Literal _ | Placeholder -> true
    | Read p | Read_signal p -> place p
    | Unary (_, x) | Fitted (x, _) -> expr x
    | Binary (_, x, y) | And (x, y) | Or (x, y) -> expr x && expr y
    | Aggregate (xs, _) -> Array.for_all expr xs
    | Call c -> call c
  and call (c : call) = Array.for_all (function
      | By_value e -> expr e
      | By_reference (p, _) -> not (rooted p) && place p
      | Pass_on (Local k) -> k <> i
      | Pass_on (Global _) | Absent | Present_switch -> true) c.arguments
  and stmt (x : stmt) = match x.s with
    | Assign (p, e) -> not (rooted p) && place p && expr e
    | Call_procedure c -> call c
    | Return (Some { e = Read p; _ }) -> not (rooted p) && place p
    | Return (Some e) | Raise (Some e) -> expr e
    | Connect (p, _) -> not (rooted p) && place p
    | If (c, b1, b2) | Elseif (c, b1, b2) -> expr c && block b1 && block b2
    | Compact_if (c, inner) -> expr c && stmt inner
    | For f -> expr f.from_ && expr f.to_ && Option.fold ~none:true ~some:expr f.step && block f.loop_body
    | While (c, b) -> expr c && block b
    | Test (c, cases, default) ->
        expr c && Array.for_all (fun (vs, b) -> Array.for_all expr vs && block b) cases && block default
    | Call_late _ -> false
    | Goto _ | Break | Continue | Return None | Raise None | Exit | Retry | Trynext | Label
    | Placeholder_statement -> true
  and block (b : block) = Array.for_all stmt b.body in
  let inits = List.for_all (fun (_, init) -> match init with Init_expr e -> expr e | Init_default _ -> true)
      r.local_inits in
  inits && List.for_all block
    (r.body :: List.filter_map (fun b -> b)
       [ r.backward; r.undo; Option.map (fun (h : error_handler) -> h.handler) r.error ])

(* The flat slots of a routine (see [flat]): its routine data of type num or dnum and its FOR
   variables, less every one that some part of the routine names otherwise than by reading its
   value or assigning it as a whole: a reference argument, a late-bound call's argument (which
   may be bound by reference, §4.6), CONNECT's target, a conditional argument, an error number
   of an error recovery point (§7.2), a signal's read, or an indexed or component place. *)
let flat_slots (r : routine) : flat =
  let n = r.locals in
  let candidate = Array.make n 0 in   (* 1: num, 2: dnum *)
  let first = Array.length r.parameters in
  List.iter (fun (slot, init) ->
      if slot >= first && slot < n then
        candidate.(slot) <- (match init with
            | Init_default V.S_num | Init_expr { e = Literal (V.Num _); _ } -> 1
            | Init_default V.S_dnum | Init_expr { e = Literal (V.Dnum _); _ } -> 2
            | _ -> 0)) r.local_inits;
  let refused = Array.make n false in
  let refuse = function Local k when k < n -> refused.(k) <- true | Local _ | Global _ -> () in
  (* the slots a statement assigns a value read from a place ([keeps] below) *)
  let assigned_read = Array.make n false in
  let rec other (p : place) = match p with
    | Whole s -> refuse s
    | Element (p, ix) -> other p; Array.iter expr ix
    | Component (p, _) -> other p
    | Unresolved _ -> ()
  and expr (e : expr) = match e.e with
    | Read (Whole _) | Literal _ | Placeholder -> ()
    | Read p | Read_signal p -> other p
    | Unary (_, x) | Fitted (x, _) -> expr x
    | Binary (_, x, y) | And (x, y) | Or (x, y) -> expr x; expr y
    | Aggregate (xs, _) -> Array.iter expr xs
    | Call c -> call c
  and call (c : call) = Array.iter (function
      | By_value e -> expr e
      | By_reference (p, _) -> other p
      | Pass_on s -> refuse s
      | Absent | Present_switch -> ()) c.arguments
  and late (l : late_argument) =
    (match l.late_value with
     | Late_expr { e = Read p; _ } -> other p
     | Late_expr e -> expr e
     | Late_conditional s -> Option.iter refuse s
     | Late_switch -> ());
    match l.late_type with Late_numeric e -> expr e | Late_typed _ | Late_untyped -> ()
  and stmt (x : stmt) = match x.s with
    | Assign (Whole s, e) ->
        (match s, e.e with Local k, Read _ when k < n -> assigned_read.(k) <- true | _ -> ());
        expr e
    | Assign (p, e) -> other p; expr e
    | Call_procedure c -> call c
    | Call_late (e, args) -> expr e; Array.iter late args
    | Return (Some e) | Raise (Some e) -> expr e
    | Connect (p, _) -> other p
    | If (c, b1, b2) | Elseif (c, b1, b2) -> expr c; block b1; block b2
    | Compact_if (c, inner) -> expr c; stmt inner
    | For f ->
        if f.variable >= first && f.variable < n then candidate.(f.variable) <- 1;
        expr f.from_; expr f.to_; Option.iter expr f.step; block f.loop_body
    | While (c, b) -> expr c; block b
    | Test (c, cases, default) ->
        expr c; Array.iter (fun (vs, b) -> Array.iter expr vs; block b) cases; block default
    | Goto _ | Break | Continue | Return None | Raise None | Exit | Retry | Trynext | Label
    | Placeholder_statement -> ()
  and block (b : block) = Array.iter stmt b.body in
  List.iter (fun (_, init) -> match init with Init_expr e -> expr e | Init_default _ -> ()) r.local_inits;
  List.iter block (r.body :: List.filter_map (fun b -> b) [ r.backward; r.undo ]);
  Option.iter (fun (h : error_handler) ->
      block h.handler;
      Option.iter (List.iter (function Object s -> refuse s | Number _ -> ())) h.recovery) r.error;
  let position = Array.make n (-1) and dnum = Array.make n false and count = ref 0 in
  for k = first to n - 1 do
    if candidate.(k) > 0 && not refused.(k) then begin
      position.(k) <- !count; dnum.(k) <- candidate.(k) = 2; incr count
    end
  done;
  let keeps = ref false in
  for k = first to n - 1 do if position.(k) >= 0 && assigned_read.(k) then keeps := true done;
  let keeps = !keeps in
  { position; dnum; count = !count; keeps }

let flat_of st (r : routine) =
  let known = Option.value ~default:[] (Rapid_syntax.Source.Table.find_opt st.flats r.at) in
  match List.assq_opt r known with
  | Some f -> f
  | None ->
      let f = flat_slots r in
      Rapid_syntax.Source.Table.replace st.flats r.at ((r, f) :: known);
      f

(* How a local slot is reached, known when the routine is compiled. *)
let local_access st (r : routine) i =
  if i < Array.length r.parameters then parameter_access r i
  else
    let f = flat_of st r in
    let k = if i < Array.length f.position then f.position.(i) else -1 in
    if k < 0 then Own else if f.dnum.(i) then Flat_dnum k else Flat_num k

let flat_num st r i = match local_access st r i with Flat_num k -> Some k | _ -> None

(* The flat slots' array of an activation, made when first needed. *)
let flat_values st (a : act) =
  if Array.length a.ext.nums = 0 then begin
    let f = flat_of st a.routine in
    let nums = Array.make f.count 0. and num_boxes = if f.keeps then Array.make f.count no_value else [||] in
    if a.ext == shared_extension then a.ext <- { shared_extension with nums; num_boxes }
    else begin a.ext.nums <- nums; a.ext.num_boxes <- num_boxes end
  end;
  a.ext.nums

(* §3.6: an index is an integer value within the declared dimension. *)
let index st ~at (v : V.t) n =
  match v with
  | V.Num x | V.Dnum x ->
      (* an integer within the bounds, the common case, with one conversion and no call *)
      let k = int_of_float x in
      if float_of_int k = x && k >= 1 && k <= n then k - 1
      else if not (Float.is_integer x) then fail st ~at "ERR_NOTINTVAL"
      else if x < 1. || x > float_of_int n then fail ~about:(Outcome.index_outside x n) st ~at "ERR_OUTOFBND"
      else int_of_float x - 1
  | _ -> V.type_mismatch "index"

(* Value.components, inlined here: the parts of a record or an array. *)
let parts (v : V.t) = match v with V.Record e | V.Array e -> e | _ -> V.components v [@@inline]

(* [index] of a num given as a float (an index expression computed without its box). *)
let index_float st ~at x n =
  let k = int_of_float x in
  if float_of_int k = x && k >= 1 && k <= n then k - 1 else index st ~at (V.Num x) n [@@inline]

(* [index] of [j + k] (an own slot's num p and a literal q): an integer sum within the bounds
   and of at most 24 bits is a single as it is, so the element's; any other goes through the
   general expression, which rounds the sum to single first (R-2.13-a). *)
let index_sum st ~at general (a : 'a) p q n =
  let x = p +. q in
  let k = int_of_float x in
  if float_of_int k = x && k >= 1 && k <= n && k <= 16777216 then k - 1 else index st ~at (general a) n [@@inline]

(* Whether module data [g] is an array of nums, dnums, bools or strings (every element has the
   first's type): an element stored there is never a signal, and a value of those types is its
   own copy. *)
let scalar_elements st g =
  match st.globals.(g) with
  | V.Array e when Array.length e > 0 -> (
      match e.(0) with V.Num _ | V.Dnum _ | V.Bool _ | V.String _ -> true | _ -> false)
  | _ -> false

(* Whether parameter [i] of [r] is a num, a dnum, a bool or a string: no signal is bound to it,
   and a value of those types is its own copy. *)
let scalar_parameter (r : routine) i =
  i < Array.length r.parameters
  && (match r.parameters.(i).p_type with
      | Some { base = Num | Dnum | Bool | String; dims = Scalar } -> true
      | _ -> false)

(* A whole place read and written where it is: module data, or an own slot of the activation. *)
let plain_whole st (r : routine) = function
  | Global _ -> true
  | Local i -> local_access st r i = Own

(* An activation's arrays, allocated in place for the common sizes: Array.make is a call to the
   runtime, the largest part of a call with alias parameters. One function per element type,
   so that each literal is built without the runtime's test for floats. *)
let small_store n : V.t array =
  match n with
  | 1 -> [| v_false |] | 2 -> [| v_false; v_false |] | 3 -> [| v_false; v_false; v_false |]
  | 4 -> [| v_false; v_false; v_false; v_false |] | 5 -> [| v_false; v_false; v_false; v_false; v_false |]
  | 6 -> [| v_false; v_false; v_false; v_false; v_false; v_false |]
  | _ -> Array.make n v_false

let small_boxes n : V.t array array =
  match n with
  | 1 -> [| [||] |] | 2 -> [| [||]; [||] |] | 3 -> [| [||]; [||]; [||] |] | 4 -> [| [||]; [||]; [||]; [||] |]
  | _ -> Array.make n [||]

let small_ints n : int array =
  match n with 1 -> [| 0 |] | 2 -> [| 0; 0 |] | 3 -> [| 0; 0; 0 |] | 4 -> [| 0; 0; 0; 0 |] | _ -> Array.make n 0

let small_present n : bool array =
  match n with
  | 1 -> [| true |] | 2 -> [| true; true |] | 3 -> [| true; true; true |] | 4 -> [| true; true; true; true |]
  | _ -> Array.make n true

let small_bools n : bool array =
  match n with
  | 1 -> [| false |] | 2 -> [| false; false |] | 3 -> [| false; false; false |]
  | 4 -> [| false; false; false; false |]
  | _ -> Array.make n false

let small_kinds n : reference_kind array =
  match n with
  | 1 -> [| Ref_other |] | 2 -> [| Ref_other; Ref_other |] | 3 -> [| Ref_other; Ref_other; Ref_other |]
  | 4 -> [| Ref_other; Ref_other; Ref_other; Ref_other |]
  | _ -> Array.make n Ref_other

let small_arguments n : Argument.t array =
  match n with
  | 1 -> [| Argument.Missing |] | 2 -> [| Argument.Missing; Argument.Missing |]
  | 3 -> [| Argument.Missing; Argument.Missing; Argument.Missing |]
  | _ -> Array.make n Argument.Missing

(* The root slot of a place, for the binding of alias arguments. *)
let rec root = function
  | Whole s -> Some s
  | Element (p, _) | Component (p, _) -> root p
  | Unresolved _ -> None

let rec read st (r : routine) ~at (p : place) : act -> V.t =
  match p with
  | Whole (Global i) -> let g = st.globals in fun _ -> g.(i)
  | Whole (Local i) -> (
      match local_access st r i with
      | Own -> fun a -> a.store.(i)
      | Flat_num k when not (flat_of st r).keeps -> fun a -> V.Num a.ext.nums.(k)
      | Flat_dnum k when not (flat_of st r).keeps -> fun a -> V.Dnum a.ext.nums.(k)
      | Flat_num k -> fun a ->
          let e = a.ext in
          let x = Array.unsafe_get e.nums k in
          (match Array.unsafe_get e.num_boxes k with V.Num y as b when x = y && x <> 0. -> b | _ -> V.Num x)
      | Flat_dnum k -> fun a ->
          let e = a.ext in
          let x = Array.unsafe_get e.nums k in
          (match Array.unsafe_get e.num_boxes k with V.Dnum y as b when x = y && x <> 0. -> b | _ -> V.Dnum x)
      | Alias -> fun a -> a.ext.boxes.(i).(a.ext.idx.(i))
      | Optional_own -> fun a -> if a.ext.present.(i) then a.store.(i) else fail st ~at "ERR_NOTPRES"
      | Optional_alias ->
          fun a -> if a.ext.present.(i) then a.ext.boxes.(i).(a.ext.idx.(i)) else fail st ~at "ERR_NOTPRES")
  | Element (Whole (Global g), [| ix |]) when flat_index st r ~at ix <> None ->
      (* module data's array, its index a flat slot or one and a literal ([flat_index]) *)
      let k, q, general = Option.get (flat_index st r ~at ix) and globals = st.globals in
      fun a ->
        let elements = parts globals.(g) in
        Array.unsafe_get elements (index_sum st ~at general a a.ext.nums.(k) q (Array.length elements))
  | Element (Whole w, [| ix |]) when plain_whole st r w ->
      (* One index into module data or an own slot: located as [locate] does (the index first,
         then its bounds), without building the location. *)
      let container = read st r ~at (Whole w) in
      (match index_at st r ~at ix, w with
       | Some _, Global g -> (
           (* module data's array, its index computed in the same closure ([index_at]'s two forms) *)
           let globals = st.globals in
           match ix.e with
           | Read (Whole (Local i)) when local_access st r i = Own ->
               fun a ->
                 let elements = parts globals.(g) in
                 let n = Array.length elements in
                 (match a.store.(i) with
                  | V.Num x -> elements.(index_float st ~at x n)
                  | v -> elements.(index st ~at v n))
           | Binary (op, { e = Read (Whole (Local i)); _ }, { e = Literal (V.Num q); _ })
             when local_access st r i = Own ->
               let general = expr st r ~at ix in
               let q = if op = Arith.Num_sub then -. q else q in
               fun a ->
                 let elements = parts globals.(g) in
                 let n = Array.length elements in
                 (match a.store.(i) with
                  | V.Num p -> Array.unsafe_get elements (index_sum st ~at general a p q n)
                  | _ -> elements.(index st ~at (general a) n))
           | _ ->
               let j = Option.get (index_at st r ~at ix) in
               fun a -> let elements = parts globals.(g) in elements.(j a (Array.length elements)))
       | Some j, _ ->
           fun a -> let elements = parts (container a) in elements.(j a (Array.length elements))
       | None, _ ->
           let ix = expr st r ~at ix in
           fun a ->
             let v = ix a in
             let elements = parts (container a) in
             elements.(index st ~at v (Array.length elements)))
  | Component (Whole (Local i), k) when local_access st r i = Own ->
      (* a component of an own slot's record (p.x), the record read in the same closure *)
      fun a -> (parts a.store.(i)).(k)
  | Component (q, k) ->
      (* A component of a record, read where it is: [locate]'s component rule without building
         the location (the record's place is read as [locate] finds it). *)
      let container = read st r ~at q in
      fun a -> (parts (container a)).(k)
  | Element _ | Unresolved _ ->
      let l = locate st r ~at p in
      fun a -> let box, i = l a in box.(i)

(* A place's location (rules place-global, place-local, place-absent, place-component,
   place-element, index-out-of-bounds, index-not-integer, place-unknown). *)
and locate st (r : routine) ~at (p : place) : act -> V.t array * int =
  match p with
  | Whole (Global i) -> let g = st.globals in fun _ -> (g, i)
  | Whole (Local i) -> (
      match local_access st r i with
      | Own -> fun a -> (a.store, i)
      | Flat_num _ | Flat_dnum _ ->
          (* [flat_slots] keeps every slot some place locates out of [nums]: never reached *)
          fun _ -> raise (Halt (Outcome.Stuck "a flat slot located"))
      | Alias -> fun a -> (a.ext.boxes.(i), a.ext.idx.(i))
      | Optional_own -> fun a -> if a.ext.present.(i) then (a.store, i) else fail st ~at "ERR_NOTPRES"
      | Optional_alias ->
          fun a -> if a.ext.present.(i) then (a.ext.boxes.(i), a.ext.idx.(i)) else fail st ~at "ERR_NOTPRES")
  | Component (q, k) ->
      let l = locate st r ~at q in
      fun a -> let box, i = l a in (parts box.(i), k)
  | Element (q, indexes) ->
      let l = locate st r ~at q in
      let indexes = Array.map (expr st r ~at) indexes in
      fun a ->
        let box, i = l a in
        let values = Array.map (fun e -> e a) indexes in
        let n = Array.length values in
        let rec down (container : V.t) k =
          let elements = parts container in
          let j = index st ~at values.(k) (Array.length elements) in
          if k = n - 1 then (elements, j) else down elements.(j) (k + 1)
        in
        down box.(i) 0
  | Unresolved name -> fun _ -> fail ~about:name st ~at "ERR_REFUNKDAT"

(* ------------------------------------------------------------------ expressions *)

(* An index expression that is an own slot, or an own slot and a num literal added or taken
   away (a{j}, a{j + 1}), as [index] finds the position in a dimension of n: the sum rounded to
   single as [binary_literal] rounds it (R-2.13-a; infinite: ERR_OVERFLOW), without building
   the num. Any other value goes through the expression's closure, then [index]. Neither form
   can change the container, so the container may be read first. *)
and index_at st (r : routine) ~at (ix : Ir.expr) : (act -> int -> int) option =
  match ix.e with
  | Read (Whole (Local i)) when local_access st r i = Own ->
      Some (fun a n -> match a.store.(i) with V.Num x -> index_float st ~at x n | v -> index st ~at v n)
  | _ when flat_index st r ~at ix <> None ->
      let k, q, general = Option.get (flat_index st r ~at ix) in
      Some (fun a n -> index_sum st ~at general a a.ext.nums.(k) q n)
  | Binary ((Num_add | Num_sub) as op, { e = Read (Whole (Local i)); _ }, { e = Literal (V.Num q); _ })
    when local_access st r i = Own ->
      let general = expr st r ~at ix in
      let q = if op = Arith.Num_sub then -. q else q in
      Some (fun a n ->
          match a.store.(i) with
          | V.Num p -> index_sum st ~at general a p q n
          | _ -> index st ~at (general a) n)
  | _ -> None

(* [at] is the statement evaluating the expression: where its errors occur (spec/README.md). *)
and expr st (r : routine) ~at (e : Ir.expr) : act -> V.t =
  match e.e with
  | Literal v -> fun _ -> v
  | Read p -> read st r ~at p
  | Read_signal p ->
      (* §2.16: a signal in value context is its value (signal-value, signal-not-connected). *)
      let f = read st r ~at p in
      fun a -> let v = f a in watch st; check st ~at (st.host.read_signal v)
  | Unary ((Num_neg | Num_plus | Dnum_neg | Dnum_plus | Not) as op, { e = Literal v; _ })
    when (match Arith.unary op v with Ok _ -> true | Error _ | exception _ -> false) ->
      (* -k on a scalar literal: its value, computed once (the same rule, §3.12) *)
      let w = match Arith.unary op v with Ok w -> w | Error _ -> v in
      fun _ -> w
  | Unary (op, x) ->
      let x = expr st r ~at x in
      fun a -> check st ~at (Arith.unary op (x a))
  | Binary ((Num_add | Num_sub) as op, { e = Read (Whole (Local i)); _ }, { e = Literal (V.Num q as v); _ })
    when local_access st r i = Alias ->
      (* x +- k on an alias parameter, read where it is bound without a call *)
      let slow u = check st ~at (Arith.binary op u v) in
      let q = if op = Num_sub then -. q else q in
      fun a -> (match a.ext.boxes.(i).(a.ext.idx.(i)) with V.Num p -> single_num st ~at (p +. q) | u -> slow u)
  | Binary ((Num_add | Num_sub) as op, x, { e = Literal (V.Num q); _ }) when is_str_length st r x ->
      (* StrLen(s) +- k: the length not built as a num (as [binary_literal]) *)
      let len = Option.get (str_length st r ~at x) and q = if op = Num_sub then -. q else q in
      fun a -> single_num st ~at (float_of_int (len a) +. q)
  | Binary (op, x, { e = Literal (V.Num q as v); _ }) ->
      let own = match x.e with Read (Whole (Local i)) when local_access st r i = Own -> Some i | _ -> None in
      binary_literal ?own st ~at op (expr st r ~at x) v q
  | Binary ((Dnum_add | Dnum_sub as op), { e = Read (Whole (Local i)); _ }, { e = Literal (V.Dnum q as v); _ })
    when local_access st r i = Own ->
      (* x +- k on an own dnum slot, read without a call (as [binary]'s dnum rows) *)
      let slow u = check st ~at (Arith.binary op u v) in
      if op = Dnum_add then fun a -> (match a.store.(i) with V.Dnum p -> double_num st ~at (p +. q) | u -> slow u)
      else fun a -> (match a.store.(i) with V.Dnum p -> double_num st ~at (p -. q) | u -> slow u)
  | Binary ((Num_add | Num_sub | Num_mul | Dnum_add | Dnum_sub | Dnum_mul) as op,
            { e = Read (Whole (Local i)); _ }, { e = Read (Whole (Local j)); _ })
    when local_access st r i = Own && local_access st r j = Own ->
      (* two own slots (s + i): read without a call each, as [binary]'s rows compute them *)
      let slow u v = check st ~at (Arith.binary op u v) in
      (match op with
       | Num_add -> fun a -> (match a.store.(i), a.store.(j) with
           | V.Num p, V.Num q -> single_num st ~at (p +. q) | u, v -> slow u v)
       | Num_sub -> fun a -> (match a.store.(i), a.store.(j) with
           | V.Num p, V.Num q -> single_num st ~at (p -. q) | u, v -> slow u v)
       | Num_mul -> fun a -> (match a.store.(i), a.store.(j) with
           | V.Num p, V.Num q -> single_num st ~at (p *. q) | u, v -> slow u v)
       | Dnum_add -> fun a -> (match a.store.(i), a.store.(j) with
           | V.Dnum p, V.Dnum q -> double_num st ~at (p +. q) | u, v -> slow u v)
       | Dnum_sub -> fun a -> (match a.store.(i), a.store.(j) with
           | V.Dnum p, V.Dnum q -> double_num st ~at (p -. q) | u, v -> slow u v)
       | _ -> fun a -> (match a.store.(i), a.store.(j) with
           | V.Dnum p, V.Dnum q -> double_num st ~at (p *. q) | u, v -> slow u v))
  | Binary ((Num_add | Num_sub | Num_mul) as op, x, y)
    when (match own_operand st r x, own_operand st r y with
        | Some (_, k), Some (_, l) -> k >= 0 || l >= 0 | _ -> false) ->
      (* own slots and components of own slots' records (p.x + dx, an Offs-like computation):
         each read in the same closure, the left first, as [binary]'s rows compute them *)
      let slow u v = check st ~at (Arith.binary op u v) in
      let i, k = Option.get (own_operand st r x) and j, l = Option.get (own_operand st r y) in
      let arith p q = match op with Num_add -> p +. q | Num_sub -> p -. q | _ -> p *. q [@@inline] in
      let compute u v = match u, v with
        | V.Num p, V.Num q -> single_num st ~at (arith p q) | _ -> slow u v [@@inline] in
      if k >= 0 && l >= 0 then fun a -> compute (parts a.store.(i)).(k) (parts a.store.(j)).(l)
      else if k >= 0 then fun a -> compute (parts a.store.(i)).(k) a.store.(j)
      else fun a -> compute a.store.(i) (parts a.store.(j)).(l)
  | Binary (op, x, y) -> binary st ~at op (expr st r ~at x) (expr st r ~at y)
  | And (x, y) ->
      let x = expr st r ~at x and y = expr st r ~at y in
      fun a -> if V.bool_value (x a) then y a else V.Bool false
  | Or (x, y) ->
      let x = expr st r ~at x and y = expr st r ~at y in
      fun a -> if V.bool_value (x a) then V.Bool true else y a
  | Aggregate (members, kind) ->
      let members = Array.map (expr st r ~at) members in
      let n = Array.length members in
      fun a ->
        let vs = Array.make n (V.Bool false) in
        for k = 0 to n - 1 do vs.(k) <- members.(k) a done;
        (match kind with Record_value -> V.Record vs | Array_value -> V.Array vs)
  | Call _ when is_str_length st r e ->
      let len = Option.get (str_length st r ~at e) in fun a -> V.Num (float_of_int (len a))
  | Call c -> (
      let f = call st r ~at ~function_call:true c in
      match c.callee with
      | Routine k when st.program.routines.(k).primitive = None
                       && st.program.routines.(k).kind = Function -> f  (* a RAPID function gives a value *)
      | Routine k when values_entry st st.program.routines.(k) c.arguments <> None -> f  (* and a computing one *)
      | _ -> fun a -> let v = f a in if v == no_value then V.type_mismatch "a function without value" else v)
  | Placeholder -> fun _ -> fail st ~at "ERR_EXECPHR"
  | Fitted (x, shape) ->
      (* §3.10: an aggregate argument of a late-bound call takes its parameter's type when its
         members fit it; otherwise the arguments do not fit the procedure. *)
      let x = expr st r ~at x in
      fun a -> match V.conform shape (x a) with Some v -> v | None -> fail st ~at "ERR_CALLPROC"

(* An operand read where it is without a call: an own slot (its index and -1) or a component
   of an own slot's record (the slot and the component). *)
and own_operand st (r : routine) (e : Ir.expr) =
  match e.e with
  | Read (Whole (Local i)) when local_access st r i = Own -> Some (i, -1)
  | Read (Component (Whole (Local i), k)) when local_access st r i = Own -> Some (i, k)
  | _ -> None

(* The operators of §3.12 by their row in Arith. The rows on two nums (the bulk of real
   programs) are computed here without building a result: the same rule as Arith's (one
   operation in double precision rounded once to single, R-2.13-a; an infinite result is
   ERR_OVERFLOW, R-3.12-c; division by zero ERR_DIVZERO); every other operand goes to Arith.
   The left operand is evaluated before the right (§3.1). *)
and binary st ~at (op : Arith.binary) x y : act -> V.t =
  let slow u v = check st ~at (Arith.binary op u v) in
  match op with
  | Num_add -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> single_num st ~at (p +. q) | _ -> slow u v)
  | Num_sub -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> single_num st ~at (p -. q) | _ -> slow u v)
  | Num_mul -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> single_num st ~at (p *. q) | _ -> slow u v)
  | Num_div -> fun a -> let u = x a in let v = y a in
      (match u, v with
       | V.Num p, V.Num q when q <> 0. -> single_num st ~at (p /. q)
       | _ -> slow u v)
  | Num_lt -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> if p < q then v_true else v_false | _ -> slow u v)
  | Num_le -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> if p <= q then v_true else v_false | _ -> slow u v)
  | Num_gt -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> if p > q then v_true else v_false | _ -> slow u v)
  | Num_ge -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> if p >= q then v_true else v_false | _ -> slow u v)
  | Equal -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> if p = q then v_true else v_false | _ -> slow u v)
  | Not_equal -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Num p, V.Num q -> if p = q then v_false else v_true | _ -> slow u v)
  (* The rows on two dnums: Arith's rule (one operation in double precision; an infinite result
     is ERR_OVERFLOW, R-3.12-c; division by zero ERR_DIVZERO) without building a result. *)
  | Dnum_add -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q -> double_num st ~at (p +. q) | _ -> slow u v)
  | Dnum_sub -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q -> double_num st ~at (p -. q) | _ -> slow u v)
  | Dnum_mul -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q -> double_num st ~at (p *. q) | _ -> slow u v)
  | Dnum_div -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q when q <> 0. -> double_num st ~at (p /. q) | _ -> slow u v)
  | Dnum_lt -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q -> if p < q then v_true else v_false | _ -> slow u v)
  | Dnum_le -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q -> if p <= q then v_true else v_false | _ -> slow u v)
  | Dnum_gt -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q -> if p > q then v_true else v_false | _ -> slow u v)
  | Dnum_ge -> fun a -> let u = x a in let v = y a in
      (match u, v with V.Dnum p, V.Dnum q -> if p >= q then v_true else v_false | _ -> slow u v)
  (* string + string: Arith's row (a result beyond 80 characters is ERR_STRTOOLNG, §3.12), its
     length known before the copy *)
  | String_concat -> fun a -> let u = x a in let v = y a in
      (match u, v with
       | V.String p, V.String q -> concat st ~at p q
       | _ -> slow u v)
  | _ -> fun a -> let u = x a in let v = y a in slow u v

(* The same with a num literal on the right, which then costs no call. *)
and binary_literal ?own st ~at (op : Arith.binary) x v q : act -> V.t =
  let slow u = check st ~at (Arith.binary op u v) in
  match op, own with
  (* An own slot on the left is read without a call. *)
  | Num_add, Some i -> fun a -> (match a.store.(i) with V.Num p -> single_num st ~at (p +. q) | u -> slow u)
  | Num_sub, Some i -> fun a -> (match a.store.(i) with V.Num p -> single_num st ~at (p -. q) | u -> slow u)
  | _ ->
  match op with
  | Num_add -> fun a -> (match x a with V.Num p -> single_num st ~at (p +. q) | u -> slow u)
  | Num_sub -> fun a -> (match x a with V.Num p -> single_num st ~at (p -. q) | u -> slow u)
  | Num_mul -> fun a -> (match x a with V.Num p -> single_num st ~at (p *. q) | u -> slow u)
  | _ -> binary st ~at op x (fun _ -> v)

(* An operand of a flat slot's store or of a comparison (see [flat]), read where it is: a flat
   slot, or a num or dnum literal. Closures give floats boxed, so these are read in the closure of
   the store or the comparison itself; and StrLen's number, which [str_length] gives unboxed. *)
and flat_operand st (r : routine) ~at (e : Ir.expr) =
  match e.e with
  | Literal (V.Num q | V.Dnum q) -> `Const q
  | Read (Whole (Local i)) -> (match local_access st r i with Flat_num k | Flat_dnum k -> `Slot k | _ -> `Other)
  | Call _ -> (match str_length st r ~at e with Some f -> `Length f | None -> `Other)
  | _ -> `Other

(* x op y into the flat slot k, x a flat slot and y one or a literal: as [binary] computes it (a
   num rounded to single, R-2.13-a; an infinite result ERR_OVERFLOW, R-3.12-c). One case per
   operator and precision: choosing the rounding when the store runs costs the dnum loop 3 %. *)
and flat_arith st ~at (op : Arith.binary) k x y : (act -> bool) option =
  match op, x, y with
  | Num_add, `Slot i, `Slot j -> Some (fun a ->
      let n = a.ext.nums in n.(k) <- single_float st ~at (n.(i) +. n.(j)); true)
  | Num_add, `Slot i, `Const q -> Some (fun a -> let n = a.ext.nums in n.(k) <- single_float st ~at (n.(i) +. q); true)
  | Num_sub, `Slot i, `Slot j -> Some (fun a ->
      let n = a.ext.nums in n.(k) <- single_float st ~at (n.(i) -. n.(j)); true)
  | Num_sub, `Slot i, `Const q -> Some (fun a -> let n = a.ext.nums in n.(k) <- single_float st ~at (n.(i) -. q); true)
  | Num_mul, `Slot i, `Slot j -> Some (fun a ->
      let n = a.ext.nums in n.(k) <- single_float st ~at (n.(i) *. n.(j)); true)
  | Num_mul, `Slot i, `Const q -> Some (fun a -> let n = a.ext.nums in n.(k) <- single_float st ~at (n.(i) *. q); true)
  | Dnum_add, `Slot i, `Slot j -> Some (fun a ->
      let n = a.ext.nums in n.(k) <- double_float st ~at (n.(i) +. n.(j)); true)
  | Dnum_add, `Slot i, `Const q -> Some (fun a -> let n = a.ext.nums in n.(k) <- double_float st ~at (n.(i) +. q); true)
  | Dnum_sub, `Slot i, `Slot j -> Some (fun a ->
      let n = a.ext.nums in n.(k) <- double_float st ~at (n.(i) -. n.(j)); true)
  | Dnum_sub, `Slot i, `Const q -> Some (fun a -> let n = a.ext.nums in n.(k) <- double_float st ~at (n.(i) -. q); true)
  | Dnum_mul, `Slot i, `Slot j -> Some (fun a ->
      let n = a.ext.nums in n.(k) <- double_float st ~at (n.(i) *. n.(j)); true)
  | Dnum_mul, `Slot i, `Const q -> Some (fun a -> let n = a.ext.nums in n.(k) <- double_float st ~at (n.(i) *. q); true)
  (* the slot read before the length is computed (the left operand first, §3.1) *)
  | Num_add, `Slot i, `Length f -> Some (fun a ->
      let n = a.ext.nums in let p = n.(i) in n.(k) <- single_float st ~at (p +. float_of_int (f a)); true)
  | Num_sub, `Slot i, `Length f -> Some (fun a ->
      let n = a.ext.nums in let p = n.(i) in n.(k) <- single_float st ~at (p -. float_of_int (f a)); true)
  | Num_add, `Length f, `Const q ->
      Some (fun a -> a.ext.nums.(k) <- single_float st ~at (float_of_int (f a) +. q); true)
  | Num_sub, `Length f, `Const q ->
      Some (fun a -> a.ext.nums.(k) <- single_float st ~at (float_of_int (f a) -. q); true)
  | _ -> None

(* The store of a flat slot k: the value of e computed where [flat_arith] can, or else by its
   closure; the assignment's closure itself (it goes on: true). *)
and flat_store st (r : routine) ~at k (e : Ir.expr) : act -> bool =
  let general () =
    let f = expr st r ~at e in
    match e.e with
    | Read _ when (flat_of st r).keeps ->
        (* A value read from where it is stored (an element, a field, module data) is kept with
           the slot: the slot's value read as a whole value (as an argument, or stored back, as
           a swap does) is then that one, not a new one, nor one the collector must move. The
           cache is never stale: a read gives it only while the slot holds the same number
           (zero, whose sign the test cannot see, is always made anew). *)
        fun a ->
          let v = f a in
          (match v with
           | V.Num x | V.Dnum x -> a.ext.nums.(k) <- x; Array.unsafe_set a.ext.num_boxes k v
           | v -> a.ext.nums.(k) <- V.num_value v);
          true
    | _ -> fun a -> a.ext.nums.(k) <- (match f a with V.Num x | V.Dnum x -> x | v -> V.num_value v); true in
  match e.e with
  | Binary (op, x, y) -> (
      match flat_arith st ~at op k (flat_operand st r ~at x) (flat_operand st r ~at y) with
      | Some f -> f
      | None -> general ())
  | _ ->
      match flat_operand st r ~at e with
      | `Slot j -> fun a -> let n = a.ext.nums in n.(k) <- n.(j); true
      | `Const q -> fun a -> a.ext.nums.(k) <- q; true
      | `Length f -> fun a -> a.ext.nums.(k) <- float_of_int (f a); true
      | `Other -> general ()

(* An index that is a flat num slot, or one and a num literal added or taken away (a{j},
   a{j + 1}): the slot, the literal (0 for none) and the index's closure, for [index_sum], which
   finds an integer sum within the bounds without building the num and takes any other through
   the closure (an index of 0 added is the slot's value itself). *)
and flat_index st (r : routine) ~at (ix : Ir.expr) =
  match ix.e with
  | Read (Whole (Local i)) -> Option.map (fun k -> (k, 0., expr st r ~at ix)) (flat_num st r i)
  | Binary ((Num_add | Num_sub) as op, { e = Read (Whole (Local i)); _ }, { e = Literal (V.Num q); _ }) ->
      let q = if op = Arith.Num_sub then -. q else q in
      Option.map (fun k -> (k, q, expr st r ~at ix)) (flat_num st r i)
  | _ -> None

(* An element of module data's array indexed as [flat_index] finds: the array and the index. *)
and flat_element st (r : routine) ~at (e : Ir.expr) =
  match e.e with
  | Read (Element (Whole (Global g), [| ix |])) ->
      Option.map (fun (k, q, general) -> (g, k, q, general)) (flat_index st r ~at ix)
  | _ -> None

(* x op y of a flat slot and a flat slot or a literal (either side), compared (§3.12). *)
and flat_compare st (r : routine) ~at (op : Arith.binary) x y : (act -> bool) option =
  let flip = function
    | Arith.Num_lt -> Arith.Num_gt | Num_gt -> Num_lt | Num_le -> Num_ge | Num_ge -> Num_le
    | Dnum_lt -> Dnum_gt | Dnum_gt -> Dnum_lt | Dnum_le -> Dnum_ge | Dnum_ge -> Dnum_le | o -> o in
  let op, x, y = match flat_operand st r ~at x, flat_operand st r ~at y with
    | (`Const _ as c), ((`Slot _ | `Length _) as v) -> (flip op, v, c)
    | u, v -> (op, u, v) in
  match op, x, y with
  | (Num_lt | Dnum_lt), `Slot i, `Slot j -> Some (fun a -> let n = a.ext.nums in n.(i) < n.(j))
  | (Num_lt | Dnum_lt), `Slot i, `Const q -> Some (fun a -> a.ext.nums.(i) < q)
  | (Num_le | Dnum_le), `Slot i, `Slot j -> Some (fun a -> let n = a.ext.nums in n.(i) <= n.(j))
  | (Num_le | Dnum_le), `Slot i, `Const q -> Some (fun a -> a.ext.nums.(i) <= q)
  | (Num_gt | Dnum_gt), `Slot i, `Slot j -> Some (fun a -> let n = a.ext.nums in n.(i) > n.(j))
  | (Num_gt | Dnum_gt), `Slot i, `Const q -> Some (fun a -> a.ext.nums.(i) > q)
  | (Num_ge | Dnum_ge), `Slot i, `Slot j -> Some (fun a -> let n = a.ext.nums in n.(i) >= n.(j))
  | (Num_ge | Dnum_ge), `Slot i, `Const q -> Some (fun a -> a.ext.nums.(i) >= q)
  | Num_lt, `Length f, `Const q -> Some (fun a -> float_of_int (f a) < q)
  | Num_le, `Length f, `Const q -> Some (fun a -> float_of_int (f a) <= q)
  | Num_gt, `Length f, `Const q -> Some (fun a -> float_of_int (f a) > q)
  | Num_ge, `Length f, `Const q -> Some (fun a -> float_of_int (f a) >= q)
  | Equal, `Length f, `Const q -> Some (fun a -> float_of_int (f a) = q)
  | Not_equal, `Length f, `Const q -> Some (fun a -> not (float_of_int (f a) = q))
  | _ -> None

(* A condition (IF, WHILE, compact IF) as a truth value, without building a bool value for
   the comparisons of two nums, NOT, AND and OR. *)
and condition st (r : routine) ~at (e : Ir.expr) : act -> bool =
  let compare op x (y : Ir.expr) =
    match op, flat_element st r ~at x, flat_element st r ~at y with
    | (Arith.Num_lt | Num_le | Num_gt | Num_ge), Some (g1, k1, q1, gen1), Some (g2, k2, q2, gen2) ->
        (* two elements of module data's arrays, each indexed by a flat slot or a flat slot and
           a literal ([index_sum]), read in the comparison's closure, the left one first *)
        let globals = st.globals in
        let slow u v = V.bool_value (check st ~at (Arith.binary op u v)) in
        Some (match op with
            | Arith.Num_lt -> fun a ->
                let e1 = parts globals.(g1) in
                let u = Array.unsafe_get e1 (index_sum st ~at gen1 a a.ext.nums.(k1) q1 (Array.length e1)) in
                let e2 = parts globals.(g2) in
                let v = Array.unsafe_get e2 (index_sum st ~at gen2 a a.ext.nums.(k2) q2 (Array.length e2)) in
                (match u, v with V.Num p, V.Num q -> p < q | _ -> slow u v)
            | Num_le -> fun a ->
                let e1 = parts globals.(g1) in
                let u = Array.unsafe_get e1 (index_sum st ~at gen1 a a.ext.nums.(k1) q1 (Array.length e1)) in
                let e2 = parts globals.(g2) in
                let v = Array.unsafe_get e2 (index_sum st ~at gen2 a a.ext.nums.(k2) q2 (Array.length e2)) in
                (match u, v with V.Num p, V.Num q -> p <= q | _ -> slow u v)
            | Num_gt -> fun a ->
                let e1 = parts globals.(g1) in
                let u = Array.unsafe_get e1 (index_sum st ~at gen1 a a.ext.nums.(k1) q1 (Array.length e1)) in
                let e2 = parts globals.(g2) in
                let v = Array.unsafe_get e2 (index_sum st ~at gen2 a a.ext.nums.(k2) q2 (Array.length e2)) in
                (match u, v with V.Num p, V.Num q -> p > q | _ -> slow u v)
            | _ -> fun a ->
                let e1 = parts globals.(g1) in
                let u = Array.unsafe_get e1 (index_sum st ~at gen1 a a.ext.nums.(k1) q1 (Array.length e1)) in
                let e2 = parts globals.(g2) in
                let v = Array.unsafe_get e2 (index_sum st ~at gen2 a a.ext.nums.(k2) q2 (Array.length e2)) in
                (match u, v with V.Num p, V.Num q -> p >= q | _ -> slow u v))
    | _ ->
    match flat_compare st r ~at op x y with
    | Some _ as flat -> flat
    | None ->
    match op, y.e with
    | (Arith.Num_lt | Num_le | Num_gt | Num_ge | Equal | Not_equal), Literal (V.Num q as v) ->
        (* A num literal on the right: compared without a call. *)
        let own = match x.e with Read (Whole (Local i)) when local_access st r i = Own -> Some i | _ -> None in
        let x = match own with
          | Some i -> fun a -> a.store.(i)
          | None -> expr st r ~at x in
        let slow u = V.bool_value (check st ~at (Arith.binary op u v)) in
        Some (match op, own with
            | Num_lt, Some i -> fun a -> (match a.store.(i) with V.Num p -> p < q | u -> slow u)
            | Num_gt, Some i -> fun a -> (match a.store.(i) with V.Num p -> p > q | u -> slow u)
            | Equal, Some i -> fun a -> (match a.store.(i) with V.Num p -> p = q | u -> slow u)
            | _ ->
            match op with
            | Num_lt -> fun a -> (match x a with V.Num p -> p < q | u -> slow u)
            | Num_le -> fun a -> (match x a with V.Num p -> p <= q | u -> slow u)
            | Num_gt -> fun a -> (match x a with V.Num p -> p > q | u -> slow u)
            | Num_ge -> fun a -> (match x a with V.Num p -> p >= q | u -> slow u)
            | Equal -> fun a -> (match x a with V.Num p -> p = q | u -> slow u)
            | _ -> fun a -> (match x a with V.Num p -> not (p = q) | u -> slow u))
    | (Arith.Dnum_lt | Dnum_le | Dnum_gt | Dnum_ge), Literal (V.Dnum q as v) ->
        (* A dnum literal on the right: compared without a call. *)
        let x0 = x in
        let x = match x.e with
          | Read (Whole (Local i)) when local_access st r i = Own -> fun a -> a.store.(i)
          | _ -> expr st r ~at x in
        let slow u = V.bool_value (check st ~at (Arith.binary op u v)) in
        let own = match x0.e with Read (Whole (Local i)) when local_access st r i = Own -> Some i | _ -> None in
        Some (match op, own with
            (* an own slot on the left, read without a call *)
            | Dnum_lt, Some i -> fun a -> (match a.store.(i) with V.Dnum p -> p < q | u -> slow u)
            | Dnum_gt, Some i -> fun a -> (match a.store.(i) with V.Dnum p -> p > q | u -> slow u)
            | _ ->
            match op with
            | Dnum_lt -> fun a -> (match x a with V.Dnum p -> p < q | u -> slow u)
            | Dnum_le -> fun a -> (match x a with V.Dnum p -> p <= q | u -> slow u)
            | Dnum_gt -> fun a -> (match x a with V.Dnum p -> p > q | u -> slow u)
            | _ -> fun a -> (match x a with V.Dnum p -> p >= q | u -> slow u))
    | _ ->
    let x = expr st r ~at x and y = expr st r ~at y in
    let slow u v = V.bool_value (check st ~at (Arith.binary op u v)) in
    match op with
    | Arith.Num_lt -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Num p, V.Num q -> p < q | _ -> slow u v)
    | Num_le -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Num p, V.Num q -> p <= q | _ -> slow u v)
    | Num_gt -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Num p, V.Num q -> p > q | _ -> slow u v)
    | Num_ge -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Num p, V.Num q -> p >= q | _ -> slow u v)
    | Equal -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Num p, V.Num q -> p = q | _ -> slow u v)
    | Not_equal -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Num p, V.Num q -> not (p = q) | _ -> slow u v)
    | Dnum_lt -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Dnum p, V.Dnum q -> p < q | _ -> slow u v)
    | Dnum_le -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Dnum p, V.Dnum q -> p <= q | _ -> slow u v)
    | Dnum_gt -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Dnum p, V.Dnum q -> p > q | _ -> slow u v)
    | Dnum_ge -> Some (fun a -> let u = x a in let v = y a in
                        match u, v with V.Dnum p, V.Dnum q -> p >= q | _ -> slow u v)
    | _ -> None
  in
  let general () = let f = expr st r ~at e in fun a -> V.bool_value (f a) in
  match e.e with
  | Literal (V.Bool b) -> fun _ -> b
  | Binary (op, x, y) -> (match compare op x y with Some f -> f | None -> general ())
  | And (x, y) -> let x = condition st r ~at x and y = condition st r ~at y in fun a -> x a && y a
  | Or (x, y) -> let x = condition st r ~at x and y = condition st r ~at y in fun a -> x a || y a
  | Unary (Arith.Not, x) -> let x = condition st r ~at x in fun a -> not (x a)
  | _ -> general ()

(* ------------------------------------------------------------------ calls *)

(* How the caller's slot [s] passes on to a conditional argument (§3.11): present or not. *)
and slot_present (r : routine) s : act -> bool =
  match s with
  | Global _ -> fun _ -> false
  | Local i when i >= Array.length r.parameters -> fun _ -> false
  | Local i -> (
      match parameter_access r i with
      | Optional_own | Optional_alias -> fun a -> a.ext.present.(i)
      | Own | Alias | Flat_num _ | Flat_dnum _ -> fun _ -> true)

(* Whether an alias argument denotes module data, seen through the parameters it goes through
   (§4.15: CONNECT's target). *)
and denotes_module_data (r : routine) (p : place) : act -> bool =
  match root p with
  | Some (Global _) -> fun _ -> true
  | Some (Local i) when i < Array.length r.parameters && is_alias r.parameters.(i) -> fun a -> a.ext.module_data.(i)
  | _ -> fun _ -> false

(* What the root of an alias argument is bound to: an alias parameter passes on its own
   binding; anything else is what the lowering says it denotes. *)
and effective_kind (r : routine) (p : place) (kind : reference_kind) : act -> reference_kind =
  match root p with
  | Some (Local i) when i < Array.length r.parameters && is_alias r.parameters.(i) -> fun a -> a.ext.bound.(i)
  | _ -> fun _ -> kind

(* One argument bound to one parameter of a RAPID routine (rules argument-value,
   argument-bound, argument-reference, argument-alias, argument-alias-refused, argument-absent,
   argument-switch, argument-pass-on-present, argument-pass-on-absent). *)
and binder st (caller : routine) ~at (callee : routine) c_arguments i (arg : argument) : act -> act -> unit =
  let p = callee.parameters.(i) in
  (* §5.2: an in parameter is a copy of its argument, counted in the memory budget. *)
  let what = "the copy for the parameter " ^ p.p_name in
  let by_value f =
    match is_alias p, p.p_optional with
    | false, false -> fun a (c : act) ->
        let v = f a in charge_pending st c (value_bytes v) what at; c.store.(i) <- copy v
    | _ ->
        fun a (c : act) ->
          let v = f a in
          charge_pending st c (value_bytes v) what at;
          let v = copy v in
          c.store.(i) <- v;
          if is_alias p then begin
            c.ext.boxes.(i) <- c.store; c.ext.idx.(i) <- i; c.ext.bound.(i) <- Ref_other;
            c.ext.module_data.(i) <- false end;
          if p.p_optional then c.ext.present.(i) <- true
  in
  (* An absent parameter still has storage of its type (§5.2). *)
  let absent (c : act) =
    charge_pending st c (V.shape_bytes p.p_default) ("the absent parameter " ^ p.p_name) at;
    c.ext.present.(i) <- false; c.store.(i) <- V.default_of p.p_default
  in
  let by_reference place kind =
    if not (is_alias p) then by_value (read st caller ~at place)
    else
      let kind_const = kind in
      let l = locate st caller ~at place in
      let kind = effective_kind caller place kind in
      let module_data = denotes_module_data caller place in
      (* §5.2, the execution-error cells of the access table: an INOUT parameter passes on
         what it is bound to, which must suit the callee's mode. *)
      let refused =
        match root place with
        | Some (Local s) when s < Array.length caller.parameters
                              && caller.parameters.(s).p_mode = Rapid_typing.Tables.Mode_inout -> (
            match p.p_mode with
            | Mode_var -> fun (a : act) -> if a.ext.bound.(s) = Ref_persistent then Some "ERR_ARGNOTVAR" else None
            | Mode_pers -> fun a -> if a.ext.bound.(s) = Ref_variable then Some "ERR_ARGNOTPER" else None
            | _ -> fun _ -> None)
        | _ -> fun _ -> None
      in
      (* For a place whose root is not an alias parameter, what it is bound to and whether it
         denotes module data are known here (as [effective_kind], [denotes_module_data]). *)
      let through_alias = match root place with
        | Some (Local s) -> s < Array.length caller.parameters && is_alias caller.parameters.(s)
        | _ -> false in
      let known_data = match root place with Some (Global _) -> true | _ -> false in
      match place with
      | Whole (Global g) when not through_alias && not p.p_optional ->
          (* module data: its location is known; [refused] is for a caller's INOUT parameter *)
          let globals = st.globals in
          fun _ (c : act) ->
            c.ext.boxes.(i) <- globals; c.ext.idx.(i) <- g; c.ext.bound.(i) <- kind_const;
            c.ext.module_data.(i) <- known_data
      | Whole (Local s) when local_access st caller s = Own && not through_alias && not p.p_optional ->
          (* an own slot of the caller (not a parameter bound elsewhere): [refused] is None *)
          fun a (c : act) ->
            c.ext.boxes.(i) <- a.store; c.ext.idx.(i) <- s; c.ext.bound.(i) <- kind_const;
            c.ext.module_data.(i) <- known_data
      | Whole (Global g) ->
          let globals = st.globals in
          fun a (c : act) ->
            c.ext.boxes.(i) <- globals; c.ext.idx.(i) <- g; c.ext.bound.(i) <- kind a;
            c.ext.module_data.(i) <- module_data a;
            if p.p_optional then c.ext.present.(i) <- true
      | Whole (Local s) when local_access st caller s = Own ->
          fun a (c : act) ->
            c.ext.boxes.(i) <- a.store; c.ext.idx.(i) <- s; c.ext.bound.(i) <- kind a;
            c.ext.module_data.(i) <- module_data a;
            if p.p_optional then c.ext.present.(i) <- true
      | _ ->
      fun a (c : act) ->
        let box, j = l a in
        (match refused a with Some name -> fail st ~at name | None -> ());
        c.ext.boxes.(i) <- box; c.ext.idx.(i) <- j; c.ext.bound.(i) <- kind a;
        c.ext.module_data.(i) <- module_data a;
        if p.p_optional then c.ext.present.(i) <- true
  in
  match arg with
  | Absent -> fun _ c -> absent c
  | Present_switch -> fun _ c -> c.ext.present.(i) <- true
  | By_value e -> by_value (expr st caller ~at e)
  | By_reference (place, kind) -> by_reference place kind
  | Pass_on s ->
      let present = slot_present caller s in
      let pass =
        if p.p_switch then fun _ c -> c.ext.present.(i) <- true
        else by_reference (Whole s) Ref_variable
      in
      (* §3.11, §5.2: of the alternatives of one optional parameter at most one is present;
         a second made present by a conditional argument is ERR_ARGDUPCND (ch. 12). *)
      let others = ref [] in
      Array.iteri (fun j (q : parameter) ->
          if j <> i && p.p_group >= 0 && q.p_group = p.p_group && j < Array.length c_arguments then
            others := (match c_arguments.(j) with
                | Present_switch | By_value _ | By_reference _ -> fun _ -> true
                | Pass_on s' -> slot_present caller s'
                | Absent -> fun _ -> false) :: !others) callee.parameters;
      let others = !others in
      fun a c ->
        if present a then begin
          if List.exists (fun f -> f a) others then fail st ~at "ERR_ARGDUPCND";
          pass a c
        end
        else absent c

(* An argument of an installed routine with a body in OCaml (Primitive). *)
and primitive_argument st (caller : routine) ~at (callee : routine) i (arg : argument)
  : act -> Argument.t =
  let p = callee.parameters.(i) in
  match arg with
  | Absent -> fun _ -> Argument.Missing
  | Present_switch -> fun _ -> Argument.Switch
  | By_value e -> let f = expr st caller ~at e in fun a -> Argument.Value (f a)
  | By_reference (place, kind) ->
      if is_alias p then begin
        (* §5.2, the execution-error cells of the access table, for an installed routine's
           parameter as for a RAPID one's: an INOUT parameter bound to a persistent passed on
           to a VAR parameter (ITimer's interrupt), or to a variable passed on to a PERS one. *)
        let l = primitive_location st caller ~at place kind and bound = effective_kind caller place kind in
        match p.p_mode with
        | Mode_var -> fun a -> if bound a = Ref_persistent then fail st ~at "ERR_ARGNOTVAR" else l a
        | Mode_pers when Late_binding.unresolved place -> l   (* ERR_REFUNKDAT (R-5.2-unknown1) *)
        | Mode_pers -> fun a -> (match bound a with
            | Ref_variable | Ref_other -> fail st ~at "ERR_ARGNOTPER" | _ -> l a)
        | _ -> l
      end
      else let f = read st caller ~at place in fun a -> Argument.Value (f a)
  | Pass_on s ->
      let present = slot_present caller s in
      let pass =
        if p.p_switch then fun _ -> Argument.Switch
        else if is_alias p then primitive_location st caller ~at (Whole s) Ref_variable
        else let f = read st caller ~at (Whole s) in fun a -> Argument.Value (f a)
      in
      fun a -> if present a then pass a else Argument.Missing

and primitive_location st caller ~at place kind : act -> Argument.t =
  let l = locate st caller ~at place and kind = effective_kind caller place kind in
  fun a -> let box, j = l a in Argument.Location (box, j, kind a)

(* A call of routine [k] with its arguments bound (rules call-arguments, call-enter,
   call-primitive, call-primitive-error, call-primitive-stop, call-not-modelled, call-unknown,
   call-unknown-function). *)
and call st (caller : routine) ~at ~function_call (c : Ir.call) : act -> V.t =
  match c.callee with
  | Unknown_routine about ->
      let name = if function_call then "ERR_REFUNKFUN" else "ERR_REFUNKPRC" in
      fun _ -> fail ~about st ~at name
  | Routine k -> call_routine st caller ~at ~call_at:c.call_at k c.arguments

and call_routine st (caller : routine) ~at ~call_at k (arguments : argument array) : act -> V.t =
  let callee = st.program.routines.(k) in
  match callee.primitive with
  | Some name when Rapid_typing.Types.same_name name "raisetouser" ->
      raise_to_user st caller ~at ~call_at callee arguments
  | _ when callee.nostepin && not caller.nostepin ->
      user_level_call st ~at (call_routine_core st caller ~at ~call_at k arguments)
  | _ -> call_routine_core st caller ~at ~call_at k arguments

(* §7.3: a call from user code into a NOSTEPIN routine: the statement is remembered, for what
   is reported at the user level (R-7.3-o). *)
and user_level_call st ~at (f : act -> V.t) : act -> V.t =
  fun a ->
    st.user_calls <- (a, at) :: st.user_calls;
    let restore () = match st.user_calls with (b, _) :: rest when b == a -> st.user_calls <- rest
                                             | l -> st.user_calls <- List.filter (fun (b, _) -> b != a) l in
    match f a with
    | v -> restore (); v
    | exception x -> restore (); raise x

(* RaiseToUser (§7.3, R-7.3-m..q; rules raise-to-user-continue, raise-to-user-break-off,
   raise-to-user-no-user-level, raise-to-user-unhandled, raise-to-user-illegal,
   raise-to-user-misplaced): in the error handler of a NOSTEPIN routine, the error in hand (or
   \ErrorNumber's) goes to the error handler of the user level. \BreakOff: this routine is left
   without its UNDO handler, the NOSTEPIN routines above it run theirs, and the error jumps to
   the user routine, raised at its call. \Continue (\Resume): the user's handler runs at once,
   the NOSTEPIN routines kept; its RETRY and TRYNEXT go on in this routine as its own would; any
   other end leaves the user routine, the NOSTEPIN routines dropped without UNDO. No user level,
   or one without a free error handler: the system error handler. *)
and raise_to_user st (caller : routine) ~at ~call_at (callee : routine) arguments : act -> V.t =
  let args = Array.mapi (primitive_argument st caller ~at callee) arguments in
  let index name =
    let found = ref None in
    Array.iteri (fun i (p : parameter) ->
        if String.lowercase_ascii p.p_name = name && i < Array.length args then found := Some i) callee.parameters;
    !found in
  let errornumber = index "errornumber" and breakoff = index "breakoff" in
  fun a ->
    let arg = function Some i -> args.(i) a | None -> Argument.Missing in
    match a.ext.current with
    | Some e when a.routine.nostepin && a.routine.kind <> Trap -> (
        let number = match arg errornumber with
          | Argument.Missing -> Some e.number
          | Value (V.Num x) when Float.is_integer x ->
              let n = int_of_float x in
              if (n >= 1 && n <= 90) || st.host.booked n
                 || List.exists (fun (_, m) -> m = n) st.program.error_numbers then Some n else None
          | _ -> None in
        match number with
        | None -> fail st ~at "ERR_ILLRAISE"
        | Some n -> (
            let name = match List.find_opt (fun (_, m) -> m = n) st.program.error_numbers with
              | Some (name, _) -> name | None -> string_of_int n in
            let e' = caught a { name; number = n; at = e.at; about = None; chain = None } in
            match user_call st a with
            | None -> raise (stop st a e')
            | Some (user, user_at) -> (
                let e' = { e' with at = user_at; chain = Some (lazy (chain_of user)) } in
                let free = user.routine.error <> None && user.ext.current = None
                           && not (List.memq user st.undoing) in
                if not free then raise (stop st a e')
                else if arg breakoff <> Argument.Missing then begin
                  st.skip_undo <- a :: st.skip_undo;
                  raise (Long_jump (user.level, e'))
                end
                else begin
                  emit_raised st e';
                  let rec index i = if st.program.routines.(i) == user.routine then i else index (i + 1) in
                  let handler = Option.get (Lazy.force st.compiled.(index 0)).c_handler in
                  st.resuming <- (user, a) :: st.resuming;
                  let finish () = st.resuming <- List.filter (fun (u, _) -> u != user) st.resuming in
                  match run_handler st handler user e' with
                  | `Retry -> finish (); raise_notrace Retry_signal
                  | `Trynext -> finish (); raise_notrace Trynext_signal
                  | `Return -> finish (); raise (Continued_leave (user.level, `Return))
                  | exception Leaving x -> finish (); raise (Continued_leave (user.level, `Raise x))
                  | exception Exit_task -> finish (); raise (Continued_leave (user.level, `Exit))
                  | exception x -> finish (); raise x
                end)))
    | _ ->
        (* A call the checker cannot see (late binding): no error of a NOSTEPIN routine to hand
           on (R-7.3-n). *)
        raise (Halt (Outcome.Stopped { name = "ERR_ILLRAISE"; number = number_of st "ERR_ILLRAISE"; at = call_at;
                                 chain = chain_of a; about = Some "RaiseToUser" }))

(* The entry of an installed function that only computes, when its call is made on the
   arguments' values ([values_call]): its answer is a value, never [no_value]. *)
and values_entry st (callee : routine) (arguments : argument array) =
  match callee.primitive with
  | Some name when Array.for_all (function By_value _ -> true | _ -> false) arguments
                   && Array.for_all (fun p -> not (is_alias p)) callee.parameters -> (
      match st.host.routine name with
      | Some ({ IR.values = Some _; reach = Values; _ } as entry) -> Some entry
      | _ -> None)
  | _ -> None

(* A call of StrLen (ch. 11) that [values_call] would make, the library's function
   (Installed_routine.Length): its number as a float, without the call nor the num built. Its
   argument's copy counted in the memory budget as [values_call] counts it; an own slot read in
   the closure itself. *)
and str_length_call st (caller : routine) (e : Ir.expr) =
  match e.e with
  | Call { callee = Routine k; arguments = [| By_value x |] as arguments; _ } -> (
      let callee = st.program.routines.(k) in
      match callee.primitive, values_entry st callee arguments with
      | Some name, Some { IR.fixed = Some (IR.Length g); _ }
        when not (Rapid_typing.Types.same_name name "raisetouser") && not (callee.nostepin && not caller.nostepin) ->
          Some (callee, x, g)
      | _ -> None)
  | _ -> None

and is_str_length st caller e = str_length_call st caller e <> None

(* The length as an int: a closure's float result would be a new box at each call. *)
and str_length st (caller : routine) ~at (e : Ir.expr) : (act -> int) option =
  match str_length_call st caller e with
  | None -> None
  | Some (callee, (x : Ir.expr), g) ->
      let what = "the copy for the parameter " ^ callee.parameters.(0).p_name in
      let limits = st.limits in
      let slow v =
        if value_bytes v > limits.max_memory - st.memory then memory_exhausted st what at;
        match g v with Ok v -> int_of_float (V.num_value v) | Error name -> fail st ~at name in
      let length p =
        let n = String.length p in
        if 32 + n > limits.max_memory - st.memory then memory_exhausted st what at;
        n [@@inline] in
      Some (match x.e with
          | Read (Whole (Local i)) when local_access st caller i = Own ->
              fun a -> (match a.store.(i) with V.String p -> length p | v -> slow v)
          | _ -> let f = expr st caller ~at x in fun a -> (match f a with V.String p -> length p | v -> slow v))

and call_routine_core st (caller : routine) ~at ~call_at k (arguments : argument array) : act -> V.t =
  let callee = st.program.routines.(k) in
  match callee.primitive, values_entry st callee arguments with
  | Some _, Some { IR.values = Some f; fixed; _ } -> values_call st caller ~at callee f fixed arguments
  | Some name, _ ->
      let args = Array.mapi (primitive_argument st caller ~at callee) arguments in
      (* The memory budget counts an installed routine's in arguments and absent parameters as
         a RAPID routine's, while its arguments are bound. *)
      (* The bytes at each call; what they are for, only when they do not fit. *)
      let absent = Installed_routine.default_bytes callee in
      (* an in parameter's copy whose bytes are the same for every value: counted so *)
      let fixed = Installed_routine.copy_bytes callee in
      let cost i (v : Argument.t) = match Array.unsafe_get arguments i, v with
        | By_value _, Argument.Value x -> let b = Array.unsafe_get fixed i in if b >= 0 then b else V.bytes x
        | Absent, _ | Pass_on _, Argument.Missing -> absent.(i)
        | _ -> 0 in
      let what i (v : Argument.t) =
        let p = callee.parameters.(i) in
        match arguments.(i), v with
        | By_value _, Argument.Value _ -> "the copy for the parameter " ^ p.p_name
        | Absent, _ | Pass_on _, Argument.Missing -> "the absent parameter " ^ p.p_name
        | _ -> "" in
      let n = Array.length args in
      let entry = st.host.routine name in
      let reach = match entry with Some e -> e.reach | None -> IR.Values in
      (* Every installed routine finds its arguments by parameter name, and the motion names its
         targets (as the machine's call-primitive). *)
      let site : IR.context = {
        parameters = Installed_routine.parameter_names callee;
        argument_label = IR.argument_label st.program callee arguments;
        book_error = st.host.book_error;
        error_number = number_of st } in
      (* WaitUntil evaluates its condition again at every poll: the argument's expression. *)
      let condition = match entry with
        | None -> None
        | Some e ->
            Option.map (fun c -> let f = expr st caller ~at c in fun a -> match f a with V.Bool b -> b | _ -> false)
              (IR.condition_argument e callee arguments) in
      let invoke values =
        match entry with
        | None -> not_modelled
        | Some e ->
            if reach <> Values then begin watch st; if reach = Moves then st.moving <- true end;
            e.call site values in
      fun a ->
        let pending = ref 0 in
        let values = small_arguments n in
        for i = 0 to n - 1 do
          let v = args.(i) a in
          let bytes = cost i v in
          if bytes > st.limits.max_memory - st.memory - !pending then memory_exhausted st (what i v) at;
          pending := !pending + bytes;
          values.(i) <- v
        done;
        let before = if st.observe then Observation.references values else [] in
        let o = invoke values in
        (* Schema rapid-sem/2: the writes through its reference arguments, after its own events. *)
        let stores () = if st.observe then List.iter (observe_store st a) (Observation.changed before) in
        if reach <> Values then begin
          (* A move remembers the routine that ran it: its asynchronous errors go there (§7.4). *)
          (match o.new_move with
           | Some id -> Recent.add st.move_owners id a
           | None -> ());
          (* The machine's order within a step: the world, the routine's own events, the motion. *)
          List.iter (function Event.Controller _ as e -> if st.all_events then st.emit e | _ -> ()) o.events;
          observe_world st;
          List.iter (function Event.Controller _ -> () | e -> emit_wanted st e) o.events;
          stores ();
          observe_motion st
        end
        else begin
          List.iter (emit_wanted st) o.events;
          stores ()
        end;
        primitive_outcome st caller a ~at ~call_at ~condition callee name o.result
  | None, _ when Closure_call.direct callee arguments <> None ->
      direct_call st caller ~at ~r_index:k callee (Option.get (Closure_call.direct callee arguments))
  | None, _ ->
      let binders = Array.mapi (binder st caller ~at callee arguments) arguments in
      let n = Array.length binders in
      let shape = activation_shape callee in
      let is_function = callee.kind = Function in
      let code = ref None in
      let has_init = callee.local_inits <> [] in
      (* A plain in parameter (not optional): the argument's value is stored in its slot
         without a binder of its own. *)
      let plain i = match arguments.(i) with
        | By_value e when not (is_alias callee.parameters.(i)) && not callee.parameters.(i).p_optional ->
            Some (expr st caller ~at e)
        | _ -> None in
      (* Up to four arguments, each a value for an in parameter or, for an alias parameter,
         module data or an own slot of the caller (not optional): bound as the binders bind
         them, the extension's arrays built at once; what an argument is bound to, its index
         and whether it is module data are the same at every call of this site, so those
         arrays are made once (nothing writes them after the binding). *)
      let simple = Array.mapi (fun i (arg : argument) ->
          let p = callee.parameters.(i) in
          if p.p_optional then None
          else match arg, is_alias p with
            | By_value e, false -> Some (`Value (expr st caller ~at e, "the copy for the parameter " ^ p.p_name))
            | By_reference (Whole (Global g), kind), true -> Some (`Global (g, kind))
            | By_reference (Whole (Local s), kind), true
              when local_access st caller s = Own && not (s < Array.length caller.parameters
                                                       && is_alias caller.parameters.(s)) ->
                Some (`Own (s, kind))
            | _ -> None) arguments in
      let (_, aliases, optional, size, _) = shape in
      if n >= 1 && n <= 4 && aliases && not optional && Array.for_all Option.is_some simple then begin
        let d = Array.map Option.get simple in
        let idx = Array.map (function `Global (g, _) -> g | `Own (s, _) -> s | `Value _ -> 0) d in
        let bound = Array.map (function `Global (_, k) | `Own (_, k) -> k | `Value _ -> Ref_other) d in
        let module_data = Array.map (function `Global _ -> true | _ -> false) d in
        let values = List.filter_map (fun i -> match d.(i) with `Value (f, w) -> Some (i, f, w) | _ -> None)
            (List.init n Fun.id) |> Array.of_list in
        let nv = Array.length values in
        let globals = st.globals in
        (* each argument's container: the caller's slots (1), module data (0), none (2) *)
        let kinds = Array.map (function `Global _ -> 0 | `Own _ -> 1 | `Value _ -> 2) d in
        let box (a : act) k = if k = 1 then a.store else if k = 0 then globals else [||] [@@inline] in
        let box_constant kinds m = if m < n && kinds.(m) = 0 then globals else [||] in
        let boxes_of = match kinds with
          | [| k0 |] -> fun a -> [| box a k0 |]
          | [| k0; k1 |] -> fun a -> [| box a k0; box a k1 |]
          | [| k0; k1; k2 |] -> fun a -> [| box a k0; box a k1; box a k2 |]
          | _ -> let k0 = kinds.(0) and k1 = kinds.(1) and k2 = kinds.(2) and k3 = kinds.(3) in
              fun a -> [| box a k0; box a k1; box a k2; box a k3 |] in
        let general a =
          let ext = { boxes = boxes_of a; idx; present = [||]; bound; module_data; retries = 0; current = None;
                     nums = [||]; num_boxes = [||] } in
          let c = { routine = callee; store = small_store size; ext; level = a.level + 1; parent = a;
                    result = no_value; nest = 0; memory = 0 } in
          for m = 0 to nv - 1 do
            let i, f, what = values.(m) in
            let v = f a in
            charge_pending st c (value_bytes v) what at;
            c.store.(i) <- copy v
          done;
          enter st callee c ~code ~r_index:k ~at ~is_function ~has_init in
        let act_bytes = activation_bytes callee and limits = st.limits in
        let events = st.all_events and observe = st.observe in
        let entered_event = Event.Routine_entered callee.name and left_event = Event.Routine_left callee.name in
        match values with
        | [| (0, f, what) |] when size <= 6 ->
            (* one value, for the first parameter: the slots built with its copy in place (no
               write barrier); the copy is made before it is counted, which nothing can see *)
            let g0 = box_constant kinds 0 and g1 = box_constant kinds 1 and g2 = box_constant kinds 2
            and g3 = box_constant kinds 3 in
            let own0 = kinds.(0) = 1 and own1 = n > 1 && kinds.(1) = 1 and own2 = n > 2 && kinds.(2) = 1
            and own3 = n > 3 && kinds.(3) = 1 in
            fun a ->
              let v = f a in
              let s = a.store in
              let b0 = if own0 then s else g0 and b1 = if own1 then s else g1 in
              let b2 = if own2 then s else g2 and b3 = if own3 then s else g3 in
              let boxes = match n with
                | 1 -> [| b0 |] | 2 -> [| b0; b1 |] | 3 -> [| b0; b1; b2 |] | _ -> [| b0; b1; b2; b3 |] in
              let ext = { boxes; idx; present = [||]; bound; module_data; retries = 0; current = None; nums = [||];
                         num_boxes = [||] } in
              let w = copy v in
              let store = match size with
                | 1 -> [| w |] | 2 -> [| w; v_false |] | 3 -> [| w; v_false; v_false |]
                | 4 -> [| w; v_false; v_false; v_false |] | 5 -> [| w; v_false; v_false; v_false; v_false |]
                | _ -> [| w; v_false; v_false; v_false; v_false; v_false |] in
              let level = a.level + 1 in
              let c = { routine = callee; store; ext; level; parent = a; result = no_value; nest = 0; memory = 0 } in
              let bytes = value_bytes v in
              begin match !code with
              | Some code when not observe && level < limits.max_call_depth
                               && bytes + act_bytes <= limits.max_memory - st.memory
                               && st.fuel > 0 && st.native + code.c_nest <= st.native_budget ->
                  (* no budget runs out: [charge_pending]'s, [enter]'s and [entered]'s work at once,
                     as they do it when every test passes *)
                  st.fuel <- st.fuel - 1;
                  let nest = code.c_nest and memory = bytes + act_bytes in
                  c.nest <- nest; c.memory <- memory;
                  st.native <- st.native + nest; st.memory <- st.memory + memory;
                  st.depth <- level + 1; deepen level;
                  if events then st.emit entered_event;
                  (match if has_init then code.c_init at c; code.c_body c with
                   | true ->
                       release st c;
                       if events then st.emit left_event;
                       if is_function then fail ~about:callee.name st ~at "ERR_FNCNORET" else no_value
                   | false -> release st c; if events then st.emit left_event; c.result
                   | exception left -> left_entered st code c ~at left)
              | _ ->
                  charge_pending st c bytes what at;
                  enter st callee c ~code ~r_index:k ~at ~is_function ~has_init
              end
        | _ -> general
      end
      else
      (* The common numbers of arguments without a loop over the binders. *)
      match binders, (if n = 1 then plain 0 else None) with
      | [| _ |], Some f ->
          let what = "the copy for the parameter " ^ callee.parameters.(0).p_name in
          fun a ->
          let v = f a in
          let c = new_act shape callee a in
          charge_pending st c (value_bytes v) what at;
          c.store.(0) <- copy v;
          enter st callee c ~code ~r_index:k ~at ~is_function ~has_init
      | _ ->
      match binders with
      | [||] -> fun a -> enter st callee (new_act shape callee a) ~code ~r_index:k ~at ~is_function ~has_init
      | [| b0 |] -> fun a ->
          let c = new_act shape callee a in
          b0 a c;
          enter st callee c ~code ~r_index:k ~at ~is_function ~has_init
      | [| b0; b1 |] -> fun a ->
          let c = new_act shape callee a in
          b0 a c; b1 a c;
          enter st callee c ~code ~r_index:k ~at ~is_function ~has_init
      | [| b0; b1; b2 |] -> fun a ->
          let c = new_act shape callee a in
          b0 a c; b1 a c; b2 a c;
          enter st callee c ~code ~r_index:k ~at ~is_function ~has_init
      | [| b0; b1; b2; b3 |] -> fun a ->
          let c = new_act shape callee a in
          b0 a c; b1 a c; b2 a c; b3 a c;
          enter st callee c ~code ~r_index:k ~at ~is_function ~has_init
      | _ ->
          fun a ->
            let c = new_act shape callee a in
            for i = 0 to n - 1 do binders.(i) a c done;
            enter st callee c ~code ~r_index:k ~at ~is_function ~has_init

(* A call of an installed function that only computes (IR.values: the library's functions,
   rule call-primitive) with every argument a value: its copies counted in the memory budget
   as [call_routine_core]'s general path counts them, in order, then the function on the
   values; an error it gives occurs at the statement (call-primitive-error). *)
and values_call st (caller : routine) ~at (callee : routine) f fixed (arguments : argument array) : act -> V.t =
  let args = Array.map (function By_value e -> expr st caller ~at e | _ -> assert false) arguments in
  let whats = Array.map (fun (p : parameter) -> "the copy for the parameter " ^ p.p_name) callee.parameters in
  let limits = st.limits in
  let result = function Ok v -> v | Error name -> fail st ~at name [@@inline] in
  let n = Array.length args in
  match args, fixed with
  (* By the number of arguments: the same copies counted in the same order, no array. *)
  | [| f0 |], Some (IR.One g | IR.Length g) -> let w0 = whats.(0) in fun a ->
      let v0 = f0 a in
      if value_bytes v0 > limits.max_memory - st.memory then memory_exhausted st w0 at;
      result (g v0)
  | [| f0; f1 |], Some (IR.Two g) -> let w0 = whats.(0) and w1 = whats.(1) in fun a ->
      let v0 = f0 a in
      let pending = count_copy st ~at w0 v0 0 in
      let v1 = f1 a in
      ignore (count_copy st ~at w1 v1 pending);
      result (g v0 v1)
  | [| f0; f1; f2 |], Some (IR.Three g) -> let w0 = whats.(0) and w1 = whats.(1) and w2 = whats.(2) in fun a ->
      let v0 = f0 a in
      let pending = count_copy st ~at w0 v0 0 in
      let v1 = f1 a in
      let pending = count_copy st ~at w1 v1 pending in
      let v2 = f2 a in
      ignore (count_copy st ~at w2 v2 pending);
      result (g v0 v1 v2)
  | [| f0 |], _ -> let w0 = whats.(0) in fun a ->
      let v0 = f0 a in
      if value_bytes v0 > limits.max_memory - st.memory then memory_exhausted st w0 at;
      result (f [| Some v0 |])
  | _, _ -> fun a ->
      let values = Array.make n None in
      let pending = ref 0 in
      for i = 0 to n - 1 do
        let v = args.(i) a in
        pending := count_copy st ~at whats.(i) v !pending;
        values.(i) <- Some v
      done;
      result (f values)

(* A call that needs no binder (Closure_call.direct): every argument a copy (§5.2) of a value,
   the callee without an error handler or UNDO, so its activation shares the empty extension.
   The call's fixed work (the copies counted in the memory budget, the call depth, the
   activation's bytes, its unit of fuel, its share of the native stack) is done here in one
   place, in the order [enter] does it, so that a budget runs out at the same point. *)
and direct_call st (caller : routine) ~at ~r_index (callee : routine) (sources : Closure_call.source array)
  : act -> V.t =
  let args = Array.map (function
      | Closure_call.Value e -> expr st caller ~at e
      | Closure_call.Read p -> read st caller ~at p) sources in
  (* the arguments that are the caller's routine data and that the callee only reads *)
  let shared = Array.mapi (fun i (source : Closure_call.source) ->
      match source with
      | Closure_call.Value { e = Read (Whole (Local j)); _ } | Closure_call.Read (Whole (Local j)) ->
          local_access st caller j = Own && reads_only_parameter callee i
      | _ -> false) sources in
  let copy_arg i v = if Array.unsafe_get shared i then v else copy v [@@inline] in
  let whats = Array.map (fun (p : parameter) -> "the copy for the parameter " ^ p.p_name) callee.parameters in
  (* The bytes of all the copies, when each is known before the call: every value of its
     parameter's type has the same bytes (Installed_routine.copy_bytes: no string, not
     conformant), and its argument can neither fail nor change what the budget counts (a
     literal, a negated one, a whole slot of module data or of the caller's own): then the copies
     fit or not all at once, and the per-copy tests, in order, would all pass when the sum fits. *)
  let fixed_copies =
    let harmless (source : Closure_call.source) = match source with
      | Value { e = Literal _ | Unary (Num_neg, { e = Literal (V.Num _); _ }); _ } -> true
      | Value { e = Read (Whole (Global _)); _ } | Read (Whole (Global _)) -> true
      | Value { e = Read (Whole (Local j)); _ } | Read (Whole (Local j)) ->
          (match local_access st caller j with Own | Flat_num _ | Flat_dnum _ -> true | _ -> false)
      | _ -> false in
    let bytes = IR.copy_bytes callee in
    if Array.length bytes = Array.length sources
       && Array.for_all2 (fun b source -> b >= 0 && harmless source) bytes sources
    then Some (Array.fold_left ( + ) 0 bytes)
    else None in
  let n = Array.length args in
  let size = if callee.locals < 1 then 1 else callee.locals in
  let act_bytes = activation_bytes callee in
  let code = ref None in
  let is_function = callee.kind = Function in
  let has_init = callee.local_inits <> [] in
  let limits = st.limits in
  let call_of = "the call of " ^ callee.name in
  let start (a : act) store pending =
    let level = a.level + 1 in
    if level >= limits.max_call_depth then
      raise (Halt (Limits.call_depth_exceeded limits));
    if act_bytes > limits.max_memory - st.memory - pending then memory_exhausted st call_of at;
    tick st;
    let code = match !code with Some c -> c | None -> let c = Lazy.force st.compiled.(r_index) in code := Some c; c in
    let nest = code.c_nest in
    if st.native + nest > st.native_budget then
      raise (Halt (native_stack_exhausted level));
    let memory = pending + act_bytes in
    let c = { routine = callee; store; ext = shared_extension; level; parent = a; result = no_value; nest; memory } in
    st.native <- st.native + nest;
    st.memory <- st.memory + memory;
    st.depth <- level + 1; deepen level;
    entered st callee c ~code ~at ~is_function ~has_init
  in
  (* A run that observes nothing (schema rapid-sem/2) needs of [entered] only the routine's
     entry and exit, built once here: when every budget has room, the call is made here with
     one test each; otherwise [start] takes it, to stop at the budget that runs out first. *)
  let entered_event = Event.Routine_entered callee.name and left_event = Event.Routine_left callee.name in
  let events = st.all_events and observe = st.observe in
  (* A valued body's call, once its code is known ([fast]), with the budgets' bounds computed
     once: [quick]'s tests, in a form that needs fewer loads. *)
  let max_depth = limits.max_call_depth and room = limits.max_memory - act_bytes
  and native_budget = st.native_budget in
  let fast = ref None in
  let leaf = ref None in   (* the callee's [c_guard], when [fast] is known *)
  let valued (a : act) store pending code body =
    let level = a.level + 1 and nest = code.c_nest in
    if level < max_depth && st.memory + pending <= room && st.fuel > 0 && st.native + nest <= native_budget
    then begin
      st.fuel <- st.fuel - 1;
      let memory = pending + act_bytes in
      let c = { routine = callee; store; ext = shared_extension; level; parent = a; result = no_value; nest; memory } in
      st.native <- st.native + nest;
      st.memory <- st.memory + memory;
      st.depth <- level + 1; deepen level;
      if events then st.emit entered_event;
      match if has_init then code.c_init at c; body c with
      | v -> release st c; if events then st.emit left_event; v
      | exception left -> left_by st code c left
    end
    else start a store pending
  in
  let quick (a : act) store pending =
      match !fast with
      | Some (code, body) -> valued a store pending code body
      | None ->
      match !code with
      | Some code when not observe ->
          let level = a.level + 1 and nest = code.c_nest in
          if level < limits.max_call_depth && act_bytes <= limits.max_memory - st.memory - pending
             && st.fuel > 0 && st.native + nest <= st.native_budget then begin
            st.fuel <- st.fuel - 1;
            let memory = pending + act_bytes in
            let c =
              { routine = callee; store; ext = shared_extension; level; parent = a; result = no_value; nest; memory } in
            st.native <- st.native + nest;
            st.memory <- st.memory + memory;
            st.depth <- level + 1; deepen level;
            if events then st.emit entered_event;
            match code.c_value with
            | Some body -> (
                fast := Some (code, body);
                leaf := (if has_init then None else code.c_guard);
                match if has_init then code.c_init at c; body c with
                | v -> release st c; if events then st.emit left_event; v
                | exception left -> left_by st code c left)
            | _ ->
            match if has_init then code.c_init at c; code.c_body c with
            | true ->
                release st c;
                if events then st.emit left_event;
                if is_function then fail ~about:callee.name st ~at "ERR_FNCNORET" else no_value
            | false -> release st c; if events then st.emit left_event; c.result
            | exception left -> left_by st code c left
          end
          else start a store pending
      | _ -> start a store pending
  in
  match args with
  | [||] -> fun a -> quick a (small_store size) 0
  | [| _ |] when size = 1 && own_step (fun i -> local_access st caller i = Own) sources.(0) <> None ->
      let i, op, v, q = Option.get (own_step (fun i -> local_access st caller i = Own) sources.(0)) in
      let w0 = whats.(0) in
      let slow u = check st ~at (Arith.binary op u v) in
      let sub = op = Arith.Num_sub in
      let stepped a v =
        if 32 > limits.max_memory - st.memory then memory_exhausted st w0 at;
        quick a [| v |] 32 in
      let other a u =
        let v = slow u in
        let b = value_bytes v in
        if b > limits.max_memory - st.memory then memory_exhausted st w0 at;
        quick a [| copy_arg 0 v |] b in
      (* Once the callee's code is known ([fast]), its calls go through a closure made for it,
         with the step, the leading guard's comparison and its value chosen once: the same
         work as [general] does for it, in the same order, without its tests of what is known. *)
      let impl = ref (fun (_ : act) -> no_value) in
      let step = if sub then -. q else q in
      let specialised code body =
        let nest = code.c_nest and memory = 32 + act_bytes in
        let enter a v level =
          st.fuel <- st.fuel - 1;
          let c = { routine = callee; store = [| v |]; ext = shared_extension; level; parent = a;
                    result = no_value; nest; memory } in
          st.native <- st.native + nest;
          st.memory <- st.memory + memory;
          st.depth <- level + 1; deepen level;
          if events then st.emit entered_event;
          match if has_init then code.c_init at c; body c with
          | v -> release st c; if events then st.emit left_event; v
          | exception left -> left_by st code c left [@@inline] in
        let fits level = level < max_depth && st.memory + 32 <= room && st.fuel > 0 && st.native + nest <= native_budget
        [@@inline] in
        let returns a level w v =
          (* as [general]'s leading guard: the callee's first statement returns *)
          st.fuel <- st.fuel - 1;
          if events then st.emit entered_event;
          tick st; at_statement st a;
          st.depth <- level;
          if events then st.emit left_event;
          (match w with None -> v | Some w -> w) [@@inline] in
        match !leaf with
        | Some (Arith.Num_lt, k, w) -> fun a -> (
            match a.store.(i) with
            | V.Num p ->
                let x = single_float st ~at (p +. step) in
                let v = V.Num x in
                let level = a.level + 1 in
                if fits level then
                  if x < k && st.fuel > 1 && st.quiet > 0 then returns a level w v else enter a v level
                else stepped a v
            | u -> other a u)
        | Some (Equal, k, w) -> fun a -> (
            match a.store.(i) with
            | V.Num p ->
                let x = single_float st ~at (p +. step) in
                let v = V.Num x in
                let level = a.level + 1 in
                if fits level then
                  if x = k && st.fuel > 1 && st.quiet > 0 then returns a level w v else enter a v level
                else stepped a v
            | u -> other a u)
        | Some (op, k, w) -> fun a -> (
            match a.store.(i) with
            | V.Num p ->
                let x = single_float st ~at (p +. step) in
                let v = V.Num x in
                let level = a.level + 1 in
                if fits level then
                  if compare_nums op x k && st.fuel > 1 && st.quiet > 0 then returns a level w v
                  else enter a v level
                else stepped a v
            | u -> other a u)
        | None -> fun a ->
            match a.store.(i) with
            | V.Num p ->
                let v = single_num st ~at (p +. step) in
                let level = a.level + 1 in
                if fits level then enter a v level else stepped a v
            | u -> other a u in
      let general a = (
        match a.store.(i) with
        | V.Num p -> (
            (* a num: 32 bytes (value_bytes), its copy itself *)
            let v = single_num st ~at (if sub then p -. q else p +. q) in
            match !fast with
            | Some (code, body) ->
                (* [valued] here, the copy's bytes tested with the activation's: when any test
                   fails, [stepped] makes them one by one, as the general path *)
                let level = a.level + 1 and nest = code.c_nest in
                if level < max_depth && st.memory + 32 <= room && st.fuel > 0 && st.native + nest <= native_budget
                then begin
                  match !leaf, v with
                  | Some (op, k, w), V.Num x
                    when (if op == Arith.Num_lt then x < k else compare_nums op x k) && st.fuel > 1 && st.quiet > 0 ->
                      (* The callee's first statement returns (§4.17, §4.10): its unit of fuel and
                         the call's, its entry (no point of response falls due, ch. 8: [quiet]),
                         its value; what the activation would have counted is given back as it
                         returns, so it is not built. *)
                      st.fuel <- st.fuel - 1;
                      if events then st.emit entered_event;
                      tick st; at_statement st a;
                      st.depth <- level;
                      if events then st.emit left_event;
                      (match w with None -> v | Some w -> w)
                  | _ ->
                  st.fuel <- st.fuel - 1;
                  let memory = 32 + act_bytes in
                  let c = { routine = callee; store = [| v |]; ext = shared_extension; level; parent = a;
                            result = no_value; nest; memory } in
                  st.native <- st.native + nest;
                  st.memory <- st.memory + memory;
                  st.depth <- level + 1; deepen level;
                  if events then st.emit entered_event;
                  match if has_init then code.c_init at c; body c with
                  | v -> release st c; if events then st.emit left_event; v
                  | exception left -> left_by st code c left
                end
                else stepped a v
            | None -> stepped a v)
        | u -> other a u) in
      impl := (fun a ->
          match !fast with
          | Some (code, body) -> let f = specialised code body in impl := f; f a
          | None -> general a);
      fun a -> !impl a
  | [| f0 |] -> let w0 = whats.(0) in fun a ->
      let v = f0 a in
      let b = value_bytes v in
      if b > limits.max_memory - st.memory then memory_exhausted st w0 at;
      let store = small_store size in
      store.(0) <- copy_arg 0 v;
      quick a store b
  | [| f0; f1; f2; f3 |] when size <= 6 ->
      (* four arguments, each counted as it is made (the loop below), the slots built at once
         (no write barrier for each copy) *)
      let w0 = whats.(0) and w1 = whats.(1) and w2 = whats.(2) and w3 = whats.(3) in
      let counted a =
        let v0 = f0 a in let p = count_copy st ~at w0 v0 0 in let v0 = copy_arg 0 v0 in
        let v1 = f1 a in let p = count_copy st ~at w1 v1 p in let v1 = copy_arg 1 v1 in
        let v2 = f2 a in let p = count_copy st ~at w2 v2 p in let v2 = copy_arg 2 v2 in
        let v3 = f3 a in let p = count_copy st ~at w3 v3 p in let v3 = copy_arg 3 v3 in
        let store = match size with
          | 4 -> [| v0; v1; v2; v3 |] | 5 -> [| v0; v1; v2; v3; v_false |]
          | _ -> [| v0; v1; v2; v3; v_false; v_false |] in
        quick a store p in
      (match fixed_copies with
       | None -> counted
       | Some total ->
           (* the copies' bytes known (see [fixed_copies]): when all of them fit, no copy's test
              can fail, and they are made without one; else [counted] finds the first that does
              not fit *)
           fun a ->
             if total > limits.max_memory - st.memory then counted a
             else
               let v0 = copy_arg 0 (f0 a) in let v1 = copy_arg 1 (f1 a) in
               let v2 = copy_arg 2 (f2 a) in let v3 = copy_arg 3 (f3 a) in
               let store = match size with
                 | 4 -> [| v0; v1; v2; v3 |] | 5 -> [| v0; v1; v2; v3; v_false |]
                 | _ -> [| v0; v1; v2; v3; v_false; v_false |] in
               quick a store total)
  | _ -> fun a ->
      let store = small_store size in
      let pending = ref 0 in
      for i = 0 to n - 1 do
        let v = args.(i) a in
        pending := count_copy st ~at whats.(i) v !pending;
        store.(i) <- copy_arg i v
      done;
      quick a store !pending

and primitive_outcome st (caller : routine) caller_act ~at ~call_at ~condition (callee : routine) name
  : IR.result -> V.t = function
  | Returned (Some v) -> v
  | Returned None -> (match callee.kind with Function -> fail st ~at "ERR_FNCNORET" | _ -> no_value)
  | Failed { error; at_move = true } -> async_at_move st ~at error
  | Failed { error; at_move = false } -> fail st ~at error
  | Call_by_name target -> (
      (* CallByVar (rules call-by-var, call-by-var-unknown, call-by-var-mismatch). *)
      late_target st caller ~at ~call_at target [||] caller_act)
  | Stop_requested -> if st.all_events then st.emit Event.Task_ended; raise (Halt Outcome.Ended)
  | Exit_cycle_requested ->
      (* R-13-exitcycle1 (rule call-primitive-exit-cycle): every routine is abandoned as by EXIT;
         the entry routine catches it and starts again (cycle-restart). *)
      st.next_cycle <- true; raise Exit_task
  | Not_modelled when st.stub_unmodelled ->
      (* --stub-unmodelled (doc/rulings.md R-13-i): the call does nothing; a function gives the
         initial value of its type (§2.22). *)
      let key = String.lowercase_ascii name in
      if not (Hashtbl.mem st.stubbed key) then begin
        Hashtbl.replace st.stubbed key ();
        if st.all_events then st.emit (Event.Stubbed { routine = callee.name; at = call_at })
      end;
      (match callee.kind with
       | Function -> IR.stub_value callee
       | Procedure | Trap -> no_value)
  | Not_modelled -> raise (Halt (Outcome.not_modelled callee.name call_at))
  | Unanswered reason -> raise (Halt (Outcome.unanswered callee.name reason call_at))
  | Wait { wait = wt; first_poll } -> wait st caller_act ~at wt ~first_poll ~condition; no_value
  | History_exhausted m -> raise (Halt (Outcome.motion_history_exhausted m call_at))
  | Assertion_failed message ->
      (* rapid-sem test (R-test-b): the task stops at the call, as Stop does: no handler, no UNDO. *)
      raise (Halt (Outcome.Stopped { name = "ERR_ASSERT"; number = number_of st "ERR_ASSERT"; at = call_at;
                                     chain = chain_of caller_act; about = Some message }))
  | Retry_requested ->
      (* StartMoveRetry: StartMove, then the RETRY statement's rule; outside an error handler
         StartMove alone (R-7.6-b). *)
      if caller_act.ext.current = None then no_value
      else if caller_act.ext.retries >= st.limits.retry_limit then
        fail ~about:(Outcome.retries_beyond st.limits.retry_limit) st ~at:call_at "ERR_EXCRTYMAX"
      else begin caller_act.ext.retries <- caller_act.ext.retries + 1; raise_notrace Retry_signal end

(* A waiting instruction (doc/controller.md): interrupts are served while it waits, and an
   asynchronous error of the motion is raised at it (§7.4, §7.6). A wait that an error or a long
   jump leaves is abandoned: a move instruction's move is cancelled (M-abandon). *)
and wait st (a : act) ~at (wt : Rapid_observable.Wait.t) ~first_poll ~condition =
  let condition = if wt.poll = None then None else Option.map (fun f () -> f a) condition in
  let serve () =
    if st.in_trap then false
    else
      match (if st.interrupts then st.host.take_interrupt () else None) with
      | Some (number, trap) -> observe st; st.serve_trap a number trap; true
      | None -> (
          match st.host.motion_error () with
          | None -> false
          | Some { error; move; handled } -> kept_async_error st a ~at error move handled)
  in
  let yield = Option.map (fun c -> c.yield) st.cooperation in
  let spend () = tick st in
  match CC.wait ?yield st.host wt ~first_poll ~condition ~serve ~observe:(fun () -> observe st) ~spend with
  | Finished None -> ()
  | Finished (Some { error; at_move = true }) -> ignore (async_at_move st ~at error)
  | Finished (Some { error; at_move = false }) -> fail st ~at error
  | Halted o -> raise (Halt o)
  | exception ((Raised _ | Leaving _ | Long_jump _ | Exit_task | Kept_leave _) as left) ->
      st.host.wait_abandoned wt;
      raise left

(* §7.4 (\SyncLastMoveInst): the error raised at the move instruction, as any error there, but
   remembered as asynchronous: TRYNEXT in its handler executes as RETRY (R-7.4-m). *)
and async_at_move : 'a. state -> at:Rapid_syntax.Source.region -> string -> 'a = fun st ~at name ->
  let e = { name; number = number_of st name; at; about = None; chain = None } in
  st.async_errors <- e :: List.filteri (fun i _ -> i < 15) st.async_errors;
  emit_raised st e;
  raise (Raised e)

(* §7.4 (\SyncOrgMoveInst), §7.6 (collisions), rules async-error, async-error-unhandled: the
   error is raised at the statement the program pointer [a] waits in. Its handler is looked for
   in §7.6's order (R-7.6-m): the routine whose move instruction made the path and up from it
   (when that call has ended, a \SyncOrgMoveInst error starts at its nearest caller still in the
   chain; a collision goes on to step 3), then the program pointer's routine and up; an
   activation already in its error or UNDO handler does not take it. None: the system error
   handler (step 5), at once, without UNDO handlers. Found: its handler runs while the program
   pointer stays where it is (R-7.4-m); RETRY and TRYNEXT resume the wait ([true]: the wait
   goes on, rules async-retry-resume, async-trynext-resume); RETURN and RAISE leave by
   [Kept_leave] (async-handler-leave), EXIT by [Exit_task] (async-exit): the routines in
   between are abandoned with their UNDO handlers on the way. *)
and kept_async_error st (a : act) ~at name move handled =
  let e = caught a { name; number = number_of st name; at; about = None; chain = None } in
  (* Handled elsewhere than in the kept handler (propagated, carried by a long jump), TRYNEXT
     executes as RETRY, as for any asynchronous error (R-7.4-m). *)
  st.async_errors <- e :: List.filteri (fun i _ -> i < 15) st.async_errors;
  emit_raised st e;
  let rec in_chain (x : act) (b : act) = b.level >= 0 && (b == x || in_chain x b.parent) in
  let rec up acc (b : act) = if b.level < 0 then List.rev acc else up (b :: acc) b.parent in
  let rec live (b : act) = if b.level < 0 then [] else if in_chain b a then up [] b else live b.parent in
  let owner = match move with Some id -> Recent.find_opt st.move_owners id | None -> None in
  let from_motion = match owner with
    | Some o when in_chain o a -> up [] o
    | Some o when name <> "ERR_COLL_STOP" -> live o.parent
    | _ -> [] in
  let takes (b : act) =
    b.routine.error <> None && b.ext.current = None && not (List.memq b st.undoing) in
  match (if handled then List.find_opt takes (from_motion @ up [] a) else None) with
  | None -> raise (stop st a e)
  | Some h ->
      let rec index i = if st.program.routines.(i) == h.routine then i else index (i + 1) in
      let handler = Option.get (Lazy.force st.compiled.(index 0)).c_handler in
      st.kept <- h :: st.kept;
      let finish () = st.kept <- List.filter (fun k -> k != h) st.kept in
      match run_handler st handler h e with
      | `Retry | `Trynext -> finish (); true
      | `Return -> finish (); raise (Kept_leave (h.level, None))
      | exception Leaving e' -> finish (); raise (Kept_leave (h.level, Some e'))
      | exception left -> finish (); raise left

(* §4.6, §5.3: the procedure a late-bound name denotes from the calling module, bound to its
   arguments (rules call-late, call-late-unknown, call-late-mismatch). *)
and late_target st (caller : routine) ~at ~call_at name (args : late_argument array) : act -> V.t =
  let same = Rapid_typing.Types.same_name in
  let routines = st.program.routines in
  let candidates =
    match String.index_opt name ':' with
    | Some i ->
        let m = String.sub name 0 i and n = String.sub name (i + 1) (String.length name - i - 1) in
        List.filter (fun k -> same routines.(k).module_name m && same routines.(k).name n)
          (List.init (Array.length routines) Fun.id)
    | None ->
        let all = List.filter (fun k -> same routines.(k).name name) (List.init (Array.length routines) Fun.id) in
        let own = List.filter (fun k -> same routines.(k).module_name caller.module_name) all in
        let visible = List.filter (fun k -> not routines.(k).local) all in
        own @ visible
  in
  let about = name in
  match candidates with
  | [] -> let error = Late_binding.unknown_procedure_error name in fun _ -> fail ~about st ~at error
  | k :: _ ->
      let r = routines.(k) in
      if r.kind <> Procedure then fun _ -> fail ~about st ~at "ERR_CALLPROC"
      else
        (* The arguments are checked as a direct call's (§4.6). A data reference through an alias
           parameter of the caller denotes what the parameter is bound to (§5.2), known only
           when the call runs: such a call is bound at each call, any other once. *)
        let through_alias (la : late_argument) =
          match la.late_value with
          | Late_expr { e = Read p | Read_signal p; _ } -> (
              match root p with
              | Some (Local i) -> i < Array.length caller.parameters && is_alias caller.parameters.(i)
              | _ -> false)
          | _ -> false in
        let bound kind =
          match Late_binding.bind r ~kind args with
          | Error error -> fun _ -> fail ~about st ~at error
          | Ok arguments -> call_routine st caller ~at ~call_at k arguments in
        if Array.exists through_alias args then
          fun a ->
            let kind p k =
              match root p with
              | Some (Local i) when i < Array.length caller.parameters && is_alias caller.parameters.(i) ->
                  a.ext.bound.(i)
              | _ -> k in
            bound kind a
        else bound (fun _ k -> k)

(* A new activation: fresh routine data (§2.21). *)
and activation_shape (r : routine) =
  let n = Array.length r.parameters in
  let aliases = Array.exists is_alias r.parameters in
  let optional = Array.exists (fun (p : parameter) -> p.p_optional) r.parameters in
  (n, aliases, optional, (if r.locals < 1 then 1 else r.locals),
   aliases || optional || r.error <> None)

and new_act (n, aliases, optional, size, own_extension) (r : routine) (parent : act) =
  { routine = r;
    store = small_store size;
    ext = (if own_extension then
             { boxes = (if aliases then small_boxes n else [||]);
               idx = (if aliases then small_ints n else [||]);
               present = (if optional then small_present n else [||]);
               bound = (if aliases then small_kinds n else [||]);
               module_data = (if aliases then small_bools n else [||]);
               retries = 0; current = None; nums = [||]; num_boxes = [||] }
           else shared_extension);
    level = parent.level + 1; parent; result = no_value; nest = 0; memory = 0 }

and pop st (c : act) =
  st.depth <- c.level; st.native <- st.native - c.nest;
  st.memory <- st.memory - c.memory; c.memory <- 0

(* A RAPID routine runs (rules call-enter, locals-initialised, return-procedure,
   return-function, function-no-return, call-depth-exceeded). *)
and enter st (r : routine) (c : act) ~code ~r_index ~at ~is_function ~has_init : V.t =
  if c.level >= st.limits.max_call_depth then
    raise (Halt (Limits.call_depth_exceeded st.limits));
  let bytes = activation_bytes r in
  if bytes > st.limits.max_memory - st.memory - c.memory then memory_exhausted st ("the call of " ^ r.name) at;
  tick st;
  let code = match !code with Some c -> c | None -> let c = Lazy.force st.compiled.(r_index) in code := Some c; c in
  (* Each activation costs the native stack in proportion to the nesting of its routine: beyond
     the budget the run ends as the call-depth limit ends it, before the stack overflows. *)
  if st.native + code.c_nest > st.native_budget then
    raise (Halt (native_stack_exhausted c.level));
  c.nest <- code.c_nest;
  st.native <- st.native + code.c_nest;
  c.memory <- c.memory + bytes;
  st.memory <- st.memory + c.memory;
  st.depth <- c.level + 1; deepen c.level;
  entered st r c ~code ~at ~is_function ~has_init

(* The activation is counted: it runs. *)
and entered st (r : routine) (c : act) ~code ~at ~is_function ~has_init : V.t =
  if st.all_events then st.emit (Event.Routine_entered r.name);
  if st.observe && Array.length r.parameters > 0 then
    st.emit (Event.Observed (Called { routine = r.name; arguments = List.filter_map (fun x -> x)
        (List.mapi (fun i (p : parameter) ->
             if p.p_optional && i < Array.length c.ext.present && not c.ext.present.(i) then None
             else if p.p_switch then Some (p.p_name, None)
             else Some (p.p_name, Some (Observation.value
                                          (if is_alias p then c.ext.boxes.(i).(c.ext.idx.(i)) else c.store.(i)))))
           (Array.to_list r.parameters)) }));
  match if has_init then code.c_init at c; code.c_body c with
  | true ->
      pop st c;
      if st.all_events then st.emit (Event.Routine_left r.name);
      (* R-5.5: a function that reaches its end raises ERR_FNCNORET at its call point. *)
      if is_function then fail ~about:r.name st ~at "ERR_FNCNORET" else no_value
  | false ->
      pop st c;
      if st.observe && is_function then
        st.emit (Event.Observed (Returned { routine = r.name; value = Observation.value c.result }));
      if st.all_events then st.emit (Event.Routine_left r.name); c.result
  | exception left -> left_entered st code c ~at left

(* What [entered] does when an exception leaves the routine's body, its call being at [at]. *)
and left_entered st code (c : act) ~at left =
  match left with
  | Raised e | Leaving e -> leave_with_error ~call:at st code c (caught c e)
  | Long_jump (j, e) when j = c.level ->
      (* An asynchronous error carried to the routine of its move, which has no error handler
         (§7.6): it is raised there, and propagated to the call point without a new search. *)
      emit_raised st e; abandon st code c; emit_raised st e; raise (Raised e)
  | Long_jump (j, e) -> abandon st code c; raise (Long_jump (j, relocate st c e ~at))
  | Exit_task -> abandon st code c; raise Exit_task
  | Kept_leave _ -> abandon st code c; raise left
  | Continued_leave _ -> pop st c; raise left
  | _ -> raise left

(* What [entered] does when an exception leaves the routine's body. *)
and left_by st code (c : act) left =
  match left with
  | Raised e | Leaving e -> leave_with_error st code c (caught c e)
  | Long_jump (j, e) when j = c.level -> emit_raised st e; abandon st code c; emit_raised st e; raise (Raised e)
  | Long_jump _ | Exit_task -> abandon st code c; raise left
  | _ -> raise left

(* A routine left by a propagated error, a long jump or EXIT runs its UNDO handler, then its
   activation is popped (rules abandon, undo-run, undo-done). An error in the UNDO handler goes
   to the system error handler (raise-in-handler). *)
and abandon st code (c : act) =
  let skip = st.skip_undo <> [] && List.memq c st.skip_undo in
  if skip then st.skip_undo <- List.filter (fun x -> x != c) st.skip_undo;
  (match code.c_undo with
   | Some _ when skip -> ()
   | None -> ()
   | Some undo -> (
       if st.all_events then st.emit (Event.Undo_run c.routine.name);
       st.undoing <- c :: st.undoing;
       match undo c with
       | _ -> st.undoing <- List.tl st.undoing
       | exception (Raised e | Leaving e | Long_jump (_, e)) -> raise (stop st c e)));
  pop st c;
  if st.all_events then begin
    st.emit (Event.Routine_left c.routine.name);
    if c.routine.kind = Trap then st.emit (Event.Trap_left { trap = c.routine.name; time = st.host.now () })
  end

(* ch. 8 (interrupt-serve, trap-end): the trap of an interrupt runs as a routine called from the
   point of interruption, with INTNO set to the interrupt's number; at its end execution goes on
   there. No interrupt is served while it runs. An error that leaves it is carried by a long
   jump to an error recovery point of the routines it interrupted (§7.2), or, there being none,
   goes to the system error handler: there is no call point to raise it at (R-8-e). *)
and serve_trap st (a : act) number k =
  let r = st.program.routines.(k) in
  st.globals.(st.program.intno) <- V.num (float_of_int number);
  if st.all_events then begin
    st.emit (Event.Trap_entered { number; trap = r.name; time = st.host.now () });
    st.emit (Event.Routine_entered r.name)
  end;
  let code = Lazy.force st.compiled.(k) in
  let c = new_act (activation_shape r) r a in
  c.nest <- code.c_nest;
  st.native <- st.native + code.c_nest;
  st.depth <- c.level + 1; deepen c.level;
  st.in_trap <- true;
  let resume () = st.in_trap <- false; st.depth <- a.level + 1 in
  match code.c_init r.at c; code.c_body c with
  | _ ->
      pop st c;
      resume ();
      if st.all_events then begin
        st.emit (Event.Routine_left r.name);
        st.emit (Event.Trap_left { trap = r.name; time = st.host.now () })
      end
  | exception (Raised e | Leaving e) -> (
      let e = caught c e in
      match recovery_search st c.parent e with
      | None -> raise (Halt (stopped e))
      | Some j -> abandon st code c; resume (); raise (Long_jump (j, e)))
  | exception ((Long_jump _ | Exit_task) as left) -> abandon st code c; resume (); raise left

and recovery_search st (b : act) e =
  if b.level < 0 then None else if recovers st b e.number then Some b.level else recovery_search st b.parent e

(* An error leaves routine [c] (R-7.1, R-7.2-a: rules longjump-search-start, longjump-search,
   longjump-found, raise-propagate): after the routine is abandoned, the call chain is searched
   from the caller up for an error recovery point naming the error; found, the error jumps there;
   not found, it is raised again at the call point. *)
and leave_with_error ?call st code (c : act) e =
  abandon st code c;
  let e = match call with Some at -> relocate st c e ~at | None -> e in
  let rec search (b : act) =
    if b.level < 0 then None
    else if recovers st b e.number then Some b.level
    else search b.parent
  in
  match search c.parent with
  | Some j -> raise (Long_jump (j, e))
  | None ->
      (* Schema rapid-sem/2: raised again at the call point, said as a propagation (§7.1). *)
      if st.all_events then
        st.emit (Event.Observed (Propagated { name = e.name; number = e.number; routine = c.routine.name;
                                          caller = c.parent.routine.name }));
      raise (Raised e)

(* §7.2: an error recovery point, ERROR (n, ...), names the error or LONG_JMP_ALL_ERR. *)
and recovers st (a : act) number =
  match a.routine.error with
  | Some { recovery = Some numbers; all_errors; _ } ->
      all_errors
      || List.exists (function
          | Number n -> n = number
          | Object (Global g) -> ( match st.globals.(g) with V.Num x -> x = float_of_int number | _ -> false)
          | Object (Local s) -> (
              match a.store.(s) with V.Num x -> x = float_of_int number | _ -> false)) numbers
  | _ -> false

(* ------------------------------------------------------------------ the error handler *)

(* The error handler takes an error (rule raise-handle): ERRNO is set and the handler runs. It
   ends by RETRY (retry), TRYNEXT (trynext), RETURN, RAISE (the error leaves the routine), or
   by reaching its end, which calls the system error handler (handler-end). An error inside it
   goes to the system error handler (raise-in-handler). *)
and run_handler st handler (a : act) e : [ `Retry | `Trynext | `Return ] =
  if st.all_events then st.emit (Event.Error_handled { name = e.name; routine = a.routine.name });
  st.globals.(st.program.errno) <- V.num (float_of_int e.number);
  let previous = a.ext.current in
  a.ext.current <- Some e;
  match handler a with
  | true -> raise (stop st a e)
  | false -> `Return
  | exception Retry_signal -> a.ext.current <- previous; `Retry
  | exception Trynext_signal -> a.ext.current <- previous; `Trynext
  | exception Raised e' -> raise (stop st a e')
  | exception Long_jump (j, e') when j >= a.level ->
      (* A long jump to this activation while it runs its handler arrives there, and is an
         error in the handler. *)
      emit_raised st e';
      raise (stop st a e')

(* A statement of a routine with an error handler: an error in it, or in a routine it calls
   that reaches it, is handled here, this being the innermost statement in progress (§7.1, "the
   statement that caused the error"). RETRY runs it again; TRYNEXT goes on after it. *)
and guarded st handler (core : act -> bool) : act -> bool =
  fun a ->
    let rec attempt retried =
      match core a with
      | goes_on -> if retried then a.ext.retries <- 0; goes_on
      | exception Raised e -> handle (caught a e)
      | exception Long_jump (j, e) when j = a.level -> emit_raised st e; handle e
      | exception Kept_leave (j, left) when j = a.level -> (
          (* R-7.4-m: the kept handler's RETURN or RAISE, now that the routines the program
             pointer was in are abandoned, acts here as in any handler. *)
          match left with None -> false | Some e -> raise (Leaving e))
      | exception Continued_leave (j, left) when j = a.level -> (
          match left with `Return -> false | `Raise e -> raise (Leaving e) | `Exit -> raise Exit_task)
    and handle e =
      match run_handler st handler a e with
      | `Retry -> if st.all_events then st.emit (Event.Observed (Retried a.routine.name)); pass_turn st; attempt true
      | `Trynext -> if st.all_events then st.emit (Event.Observed (Tried_next a.routine.name)); true
      | `Return -> false
    in
    attempt false

(* ------------------------------------------------------------------ statements *)

(* [handler]: the routine's error handler when the statement is in the routine's body. *)
(* A statement runs to its completion: [true] when execution goes on after it, [false] when it
   executed RETURN (the value, if any, is in the activation) and the routine returns. *)
and stmt st (r : routine) ~handler ~gotos (s : Ir.stmt) : act -> bool =
  let core = stmt_core st r ~handler ~gotos s in
  match handler, s.s with
  | Some _, Elseif _ -> core  (* §4.16, R-4.16: the IF it belongs to is the statement in progress *)
  | Some h, _ -> guarded st h core
  | None, _ -> core

and stmt_core ?at st (r : routine) ~handler ~gotos (s : Ir.stmt) : act -> bool =
  let at = Option.value at ~default:s.sat in
  let block b = block st r ~handler ~gotos b in
  let truth e = condition st r ~at e in
  let number e = let f = expr st r ~at e in fun a -> V.num_value (f a) in
  match s.s with
  | Assign (place, e) -> (
      (* Rules assign, assign-target, store: the target is located before the value. *)
      (* §2.16: assigning to an output signal sets it (store-signal). Module data and routine
         data whose declared type is not a signal's are stored without looking. *)
      let value = expr st r ~at e in
      let signal_shape = function V.S_handle k -> CC.is_signal (V.default_of (V.S_handle k)) | _ -> false in
      let own_signal i =
        if i < Array.length r.parameters then signal_shape r.parameters.(i).p_default
        else match List.assoc_opt i r.local_inits with
          | Some (Init_default sh) -> signal_shape sh
          | _ -> false (* an initial value, a FOR variable: never a signal's *) in
      let store_signal box i v =
        watch st;
        match st.host.write_signal box.(i) v with
        | Ok () -> ()
        | Error "" -> raise (Halt (Outcome.Stuck "a signal assigned a value that is not a num"))
        | Error name -> fail st ~at name in
      match place with
      | Whole (Local i) when (match local_access st r i with Flat_num _ | Flat_dnum _ -> true | _ -> false) ->
          (* a flat slot (see [flat]): the value computed unboxed, stored in place *)
          let k, box = match local_access st r i with
            | Flat_dnum k -> (k, fun x -> V.Dnum x)
            | Flat_num k -> (k, fun x -> V.Num x)
            | _ -> (-1, fun x -> V.Num x) in
          let f = flat_store st r ~at k e in
          if st.observe then fun a -> ignore (f a); observe_flat st a i (box a.ext.nums.(k)); true
          else f
      | _ when st.observe ->
          let l = locate st r ~at place in
          fun a ->
            let box, i = l a in
            let v = value a in
            if CC.is_signal box.(i) then store_signal box i v
            else (box.(i) <- copy v; observe_store st a (box, i));
            true
      | Whole (Global i) when not (CC.is_signal st.globals.(i)) ->
          let g = st.globals in fun a -> g.(i) <- copy (value a); true
      | Whole (Local i) when local_access st r i = Own && not (own_signal i)
                             && (match e.e with
                                 | Binary ((Num_add | Num_sub | Dnum_add | Dnum_sub),
                                           { e = Read (Whole (Local j)); _ }, _) -> j = i
                                 | _ -> false) ->
          (* x := x +- y on an own slot (a counter, a sum): its value read before y is evaluated
             (the left operand first, §3.1), the sum as [binary] computes it (a num rounded to
             single, R-2.13-a; an infinite result ERR_OVERFLOW, R-3.12-c), stored in place *)
          let op, y = match e.e with Binary (op, _, y) -> (op, y) | _ -> assert false in
          let slow u v = check st ~at (Arith.binary op u v) in
          (match op, y.e with
           | (Num_add | Num_sub), Literal (V.Num q as k) ->
               let q = if op = Arith.Num_sub then -. q else q in
               fun a ->
                 (a.store.(i) <- match a.store.(i) with V.Num p -> single_num st ~at (p +. q) | u -> slow u k);
                 true
           | Dnum_add, Literal (V.Dnum q as k) ->
               fun a ->
                 (a.store.(i) <- match a.store.(i) with V.Dnum p -> double_num st ~at (p +. q) | u -> slow u k);
                 true
           | Dnum_sub, Literal (V.Dnum q as k) ->
               fun a ->
                 (a.store.(i) <- match a.store.(i) with V.Dnum p -> double_num st ~at (p -. q) | u -> slow u k);
                 true
           | (Num_add | Num_sub), _ ->
               let y = expr st r ~at y and sub = op = Arith.Num_sub in
               fun a ->
                 let u = a.store.(i) in
                 let w = y a in
                 (a.store.(i) <- match u, w with
                     | V.Num p, V.Num q -> single_num st ~at (if sub then p -. q else p +. q)
                     | _ -> slow u w);
                 true
           | _ ->
               let y = expr st r ~at y and sub = op = Arith.Dnum_sub in
               fun a ->
                 let u = a.store.(i) in
                 let w = y a in
                 (a.store.(i) <- match u, w with
                     | V.Dnum p, V.Dnum q -> double_num st ~at (if sub then p -. q else p +. q)
                     | _ -> slow u w);
                 true)
      | Whole (Local i) when local_access st r i = Own && not (own_signal i)
                             && (match e.e with
                                 | Call { callee = Routine k; _ } -> returns_own_value st.program.routines.(k)
                                 | _ -> false) ->
          fun a -> a.store.(i) <- value a; true
      | Whole (Local i) when local_access st r i = Own && not (own_signal i) ->
          fun a -> a.store.(i) <- copy (value a); true
      | Whole (Local i) when local_access st r i = Alias
                             && (match e.e with
                                 | Binary ((Num_add | Num_sub), { e = Read (Whole (Local j)); _ }, _) -> j = i
                                 | _ -> false) ->
          (* x := x +- y on an alias parameter (an INOUT counter): located once where it is
             bound, its value read there before y is evaluated (the left operand first, §3.1),
             the sum as [binary] computes it, then stored as below *)
          let op, y = match e.e with Binary (op, _, y) -> (op, y) | _ -> assert false in
          let slow u v = check st ~at (Arith.binary op u v) in
          let negate = op = Arith.Num_sub in
          let store box j v =
            match box.(j) with
            | V.Handle _ as old when CC.is_signal old -> store_signal box j v
            | _ -> box.(j) <- v [@@inline] in
          (match y.e with
           | Literal (V.Num q as k) ->
               let q = if negate then -. q else q in
               fun a ->
                 let box = a.ext.boxes.(i) and j = a.ext.idx.(i) in
                 (* a num where it is bound: no signal, stored where it was read *)
                 (match box.(j) with
                  | V.Num p -> Array.unsafe_set box j (single_num st ~at (p +. q))
                  | u -> store box j (slow u k));
                 true
           | _ ->
               let y = expr st r ~at y in
               fun a ->
                 let box = a.ext.boxes.(i) and j = a.ext.idx.(i) in
                 let u = box.(j) in
                 let w = y a in
                 (match u, w with
                  | V.Num p, V.Num q ->
                      (* the parameter's type is num (its value was one): its place holds no signal *)
                      Array.unsafe_set box j (single_num st ~at (if negate then p -. q else p +. q))
                  | _ -> store box j (slow u w));
                 true)
      | Whole (Local i) when local_access st r i = Alias && scalar_parameter r i ->
          (* an alias parameter of type num, dnum, bool or string: where it is bound, located
             before the value; no signal is bound there, and the value is its own copy *)
          fun a ->
            let box = a.ext.boxes.(i) and j = a.ext.idx.(i) in
            let v = value a in
            box.(j) <- v;
            true
      | Whole (Local i) when local_access st r i = Alias ->
          (* an alias parameter: where it is bound, located before the value (as below) *)
          fun a ->
            let box = a.ext.boxes.(i) and j = a.ext.idx.(i) in
            let v = value a in
            (match box.(j) with
             | V.Handle _ as old when CC.is_signal old -> store_signal box j v
             | _ -> box.(j) <- copy v);
            true
      | Component (q, k) ->
          (* As the general case below, the record located (its components) before the value,
             without building the location; an own slot's record read in the same closure. *)
          let container = match q with
            | Whole (Local i) when local_access st r i = Own -> None
            | _ -> Some (read st r ~at q) in
          let i = match q with Whole (Local i) -> i | _ -> -1 in
          (* A component that holds a num, dnum, bool or string holds no signal, and a value of
             its type is its own copy: stored where it was read. *)
          let store comps v =
            match comps.(k) with
            | V.Num _ | V.Dnum _ | V.Bool _ | V.String _ -> Array.unsafe_set comps k v
            | V.Handle _ as old when CC.is_signal old -> store_signal comps k v
            | _ -> comps.(k) <- copy v [@@inline] in
          (match container with
           | None -> fun a -> let comps = parts a.store.(i) in store comps (value a); true
           | Some c -> fun a -> let comps = parts (c a) in store comps (value a); true)
      | Element (Whole (Global g), [| ix |]) when flat_index st r ~at ix <> None ->
          (* module data's array, its index a flat slot or one and a literal ([flat_index]):
             the element located before the value, as below *)
          let k, q, general = Option.get (flat_index st r ~at ix) and globals = st.globals in
          if scalar_elements st g then
            (* its elements numbers, booleans or strings: none is a signal, each its own copy *)
            fun a ->
              let elements = parts globals.(g) in
              let j = index_sum st ~at general a a.ext.nums.(k) q (Array.length elements) in
              Array.unsafe_set elements j (value a);
              true
          else
          fun a ->
            let elements = parts globals.(g) in
            let j = index_sum st ~at general a a.ext.nums.(k) q (Array.length elements) in
            let v = value a in
            (match elements.(j) with
             | V.Handle _ as old when CC.is_signal old -> store_signal elements j v
             | _ -> elements.(j) <- copy v);
            true
      | Element (Whole w, [| ix |]) when plain_whole st r w ->
          (* As the general case below, the element located (index, bounds) before the value,
             without building the location. *)
          let container = read st r ~at (Whole w) in
          (match index_at st r ~at ix, w, ix.e with
           | Some _, Global g, Read (Whole (Local i)) when local_access st r i = Own ->
               (* module data's array, its index computed in the same closure *)
               let globals = st.globals in
               fun a ->
                 let elements = parts globals.(g) in
                 let n = Array.length elements in
                 let j = match a.store.(i) with V.Num x -> index_float st ~at x n | v -> index st ~at v n in
                 let v = value a in
                 (match elements.(j) with
                  | V.Handle _ as old when CC.is_signal old -> store_signal elements j v
                  | _ -> elements.(j) <- copy v);
                 true
           | Some _, Global g, Binary (op, { e = Read (Whole (Local i)); _ }, { e = Literal (V.Num q); _ })
             when local_access st r i = Own ->
               let general = expr st r ~at ix in
               let q = if op = Arith.Num_sub then -. q else q in
               let globals = st.globals in
               fun a ->
                 let elements = parts globals.(g) in
                 let n = Array.length elements in
                 let j = match a.store.(i) with
                   | V.Num p -> index_sum st ~at general a p q n
                   | _ -> index st ~at (general a) n in
                 let v = value a in
                 (match elements.(j) with
                  | V.Handle _ as old when CC.is_signal old -> store_signal elements j v
                  | _ -> elements.(j) <- copy v);
                 true
           | Some j, _, _ ->
               fun a ->
                 let elements = parts (container a) in
                 let j = j a (Array.length elements) in
                 let v = value a in
                 (match elements.(j) with
                  | V.Handle _ as old when CC.is_signal old -> store_signal elements j v
                  | _ -> elements.(j) <- copy v);
                 true
           | None, _, _ ->
               let ix = expr st r ~at ix in
               fun a ->
                 let iv = ix a in
                 let elements = parts (container a) in
                 let j = index st ~at iv (Array.length elements) in
                 let v = value a in
                 if CC.is_signal elements.(j) then store_signal elements j v else elements.(j) <- copy v;
                 true)
      | _ ->
          let l = locate st r ~at place in
          fun a ->
            let box, i = l a in
            let v = value a in
            if CC.is_signal box.(i) then store_signal box i v else box.(i) <- copy v;
            true)
  | Call_procedure c -> let f = call st r ~at ~function_call:false c in fun a -> ignore (f a); true
  | Call_late (name, args) ->
      let name = expr st r ~at name in
      let cache = Hashtbl.create 1 in
      fun a ->
        let n = V.string_value (name a) in
        let f = match Hashtbl.find_opt cache n with
          | Some f -> f
          | None -> let f = late_target st r ~at ~call_at:at n args in Hashtbl.replace cache n f; f in
        ignore (f a); true
  | Goto (b, i) -> fun _ -> raise_notrace (Goto_label (b, i))
  | Break -> fun _ -> raise_notrace Break_loop
  | Continue -> fun _ -> raise_notrace Continue_loop
  | Return None -> fun _ -> false
  | Return (Some e) -> let f = expr st r ~at e in fun a -> a.result <- f a; false
  | Raise None -> (
      (* raise-again: the error being handled leaves the routine. *)
      fun a -> match a.ext.current with Some e -> raise (Leaving e) | None -> fail st ~at "ERR_ILLRAISE")
  | Raise (Some e) ->
      (* Rules raise-number, raise, raise-illegal (§4.11, R-4.11, R-4.11-b). *)
      let f = number e in
      fun a ->
        let x = f a in
        let booked = Float.is_integer x && st.host.booked (int_of_float x) in
        if Float.is_integer x && ((x >= 1. && x <= 90.) || booked) then
          let n = int_of_float x in
          let e = { name = string_of_int n; number = n; at; about = None; chain = None } in
          emit_raised st e;
          (* R-4.11-handler1 (doc/dialect.md): in an error handler the new error leaves the
             routine, as RAISE; makes the error in hand leave it (rule raise-new). *)
          if Option.is_some a.ext.current then raise (Leaving e) else raise (Raised e)
        else
          fail ~about:(Raise_number.refusal st.program ~in_handler:(Option.is_some a.ext.current) x) st ~at
            "ERR_ILLRAISE"
  | Exit -> fun _ -> raise Exit_task
  | Retry ->
      (* R-7.2-b: beyond the limit RETRY raises ERR_EXCRTYMAX, in the handler, at the RETRY
         itself (in a compact IF too, where other errors are the IF's). *)
      fun a ->
        (* R-7.4-m: resuming a kept program pointer executes no statement again: not counted. *)
        if st.kept <> [] && List.memq a st.kept then raise_notrace Retry_signal
        else if st.resuming <> [] && List.mem_assq a st.resuming then begin
          (* R-7.3-p: the NOSTEPIN routine's own RETRY, counted there (rule resume-retry). *)
          let inner = List.assq a st.resuming in
          if inner.ext.retries >= st.limits.retry_limit then begin
            let e = { name = "ERR_EXCRTYMAX"; number = number_of st "ERR_EXCRTYMAX"; at = s.sat;
                      about = Some (Outcome.retries_beyond st.limits.retry_limit);
                      chain = None } in
            emit_raised st e;
            raise (stop st inner e)
          end
          else begin inner.ext.retries <- inner.ext.retries + 1; raise_notrace Retry_signal end
        end
        else if a.ext.retries >= st.limits.retry_limit then
          fail ~about:(Outcome.retries_beyond st.limits.retry_limit) st ~at:s.sat "ERR_EXCRTYMAX"
        else begin a.ext.retries <- a.ext.retries + 1; raise_notrace Retry_signal end
  | Trynext ->
      fun a -> (
        match a.ext.current with
        | Some e when st.async_errors <> [] && not (List.memq a st.kept) && List.memq e st.async_errors ->
            (* §7.4: "TRYNEXT executes as RETRY" for an asynchronous error (R-7.4-m). *)
            if a.ext.retries >= st.limits.retry_limit then
              fail ~about:(Outcome.retries_beyond st.limits.retry_limit) st ~at:s.sat "ERR_EXCRTYMAX"
            else begin a.ext.retries <- a.ext.retries + 1; raise_notrace Retry_signal end
        | _ -> raise_notrace Trynext_signal)
  | Connect (place, trap) ->
      (* §4.15: the target "must be (or denote) a module variable (not a routine variable)",
         through parameters too (ERR_CNTNOTVAR); it gets a new interrupt number; one still
         connected is ERR_ALRDYCNT (R-8-f); beyond the controller's numbers, ERR_INOMAX. The
         interrupts themselves are the machine's (the trap never runs here). *)
      let l = locate st r ~at place in
      let kind = effective_kind r place Ref_variable and module_data = denotes_module_data r place in
      fun a ->
        let box, i = l a in
        if kind a = Ref_persistent || not (module_data a) then fail st ~at "ERR_CNTNOTVAR";
        (match box.(i) with
         | V.Num n when n <> 0. && Float.is_integer n && st.host.connected (int_of_float n) ->
             fail st ~at "ERR_ALRDYCNT"
         | _ -> ());
        (match st.host.connect ~trap with
         | Ok n ->
             box.(i) <- V.num (float_of_int n); watch st; st.interrupts <- true;
             if st.observe then observe_store st a (box, i)
         | Error name -> fail st ~at name);
        true
  | If (c, t, e) | Elseif (c, t, e) ->
      let c = truth c and t = block t and e = block e in
      fun a -> if c a then t a else e a
  | Compact_if (c, { s = Return (Some e); _ }) ->
      (* IF c RETURN e; in one closure. *)
      let c = truth c and f = expr st r ~at e in
      fun a -> if c a then begin a.result <- f a; false end else true
  | Compact_if (c, s) ->
      (* §4.17: the statement is part of the compact IF, which is the statement in progress. *)
      let c = truth c and s = stmt_core ~at st r ~handler ~gotos s in
      fun a -> if c a then s a else true
  | While (c, b) ->
      let c = truth c and body = block b in
      let empty = Array.length b.body = 0 in
      fun a ->
        let continue = ref true and goes_on = ref true in
        while !continue do
          tick st;
          if c a then (match body a with
              | true -> at_round st a; if empty then pass_turn st  (* a new round (while-again) *)
              | false -> continue := false; goes_on := false
              | exception Continue_loop -> ()
              | exception Break_loop -> continue := false)
          else continue := false
        done;
        !goes_on
  | For { variable; from_; to_; step; loop_body } ->
      (* §4.18: FROM, TO and STEP once; the default step is 1, or -1 when FROM > TO. *)
      let from_ = number from_ and to_ = number to_ in
      let step = Option.map number step in
      let body = block loop_body in
      let empty = Array.length loop_body.body = 0 in
      let flat = match local_access st r variable with Flat_num k -> k | _ -> -1 in
      fun a ->
        let nums = if flat >= 0 then flat_values st a else a.ext.nums in
        let lo = from_ a in
        let hi = to_ a in
        let step = match step with Some f -> f a | None -> if lo > hi then -1. else 1. in
        let small x = Float.is_integer x && Float.abs x < 8388608. [@@inline] in
        if small lo && small hi && small step && not (lo = 0. && 1. /. lo < 0.) && not st.observe then begin
          (* FROM, TO and STEP integers below 2^23 in magnitude (and FROM not -0): every value
             of the variable, and each sum, is an integer of at most 24 bits, which a num holds
             exactly (the sum needs no rounding): the rounds counted on an int *)
          let hi = int_of_float hi and s = int_of_float step in
          let i = ref (int_of_float lo) and continue = ref true and goes_on = ref true and round = ref false in
          while !continue && (if s >= 0 then !i <= hi else !i >= hi) do
            tick st;
            if flat >= 0 then nums.(flat) <- float_of_int !i else a.store.(variable) <- V.Num (float_of_int !i);
            (match body a with
             | true -> if empty then (if !round then pass_turn st else round := true); at_round st a
             | false -> continue := false; goes_on := false
             | exception Continue_loop -> at_round st a
             | exception Break_loop -> continue := false);
            if !continue then i := !i + s
          done;
          !goes_on
        end
        else
        let v = ref lo and continue = ref true and goes_on = ref true and round = ref false in
        while !continue && (if step >= 0. then !v <= hi else !v >= hi) do
          tick st;
          if flat >= 0 then begin
            nums.(flat) <- !v;
            if st.observe then observe_flat st a variable (V.Num !v)
          end
          else begin
            a.store.(variable) <- V.Num !v;
            if st.observe then observe_store st a (a.store, variable)
          end;
          (match body a with
           | true ->
               (* R-14-o: the turn ends after the variable stepped and the empty body passed
                  (for-step), before the next round's point of response. *)
               if empty then (if !round then pass_turn st else round := true);
               at_round st a  (* a new round (for-step, for-done) *)
           | false -> continue := false; goes_on := false
           | exception Continue_loop -> at_round st a
           | exception Break_loop -> continue := false);
          (* num + num (Arith's rule: rounded to single, R-2.13-a; infinite: ERR_OVERFLOW) *)
          if !continue then begin
            let next = !v +. step in
            v := if is_small_integer next then next
              else
                let y = Int32.float_of_bits (Int32.bits_of_float next) in
                if Float.is_finite y then y else fail st ~at "ERR_OVERFLOW"
          end
        done;
        !goes_on
  | Test (subject, cases, default) ->
      let subject = expr st r ~at subject in
      let cases = Array.map (fun (values, b) -> (Array.map (expr st r ~at) values, block b)) cases in
      let default = block default in
      let n = Array.length cases in
      (* The CASE values evaluated in order until one equals the subject (§4.20); in loops,
         local functions here would be closures allocated at every execution *)
      fun a ->
        let v = subject a in
        let k = ref 0 and chosen = ref (-1) in
        while !chosen < 0 && !k < n do
          let values = fst cases.(!k) in
          let m = Array.length values and j = ref 0 in
          while !chosen < 0 && !j < m do
            if V.equal v (values.(!j) a) then chosen := !k else incr j
          done;
          incr k
        done;
        if !chosen < 0 then default a else (snd cases.(!chosen)) a
  | Label -> fun _ -> true
  | Placeholder_statement -> fun _ -> fail st ~at "ERR_EXECPHR"

(* A statement list, one unit of fuel for each statement started; it stops at a RETURN. A list
   holding a GOTO's label continues there (rule goto). *)
and block ?top st (r : routine) ~handler ~gotos (b : Ir.block) : act -> bool =
  let body = Array.map (stmt st r ~handler ~gotos) b.body in
  let n = Array.length body in
  let jumps = Hashtbl.mem gotos b.id in
  let id = b.id in
  match top with
  | None ->
      (* Each statement entered and the end of the list are points of response (ch. 8). *)
      let rec from a k =
        if k >= n then (at_end st a; true)
        else (tick st; at_statement st a; body.(k) a && from a (k + 1)) in
      if n = 0 then fun a -> at_end st a; true
      else if n = 1 && not jumps then
        (let s0 = body.(0) in fun a -> tick st; at_statement st a; s0 a && (at_end st a; true))
      else if n = 2 && not jumps then
        (let s0 = body.(0) and s1 = body.(1) in
         fun a -> tick st; at_statement st a; s0 a && (tick st; at_statement st a; s1 a) && (at_end st a; true))
      else if n = 3 && not jumps then
        (let s0 = body.(0) and s1 = body.(1) and s2 = body.(2) in
         fun a ->
           tick st; at_statement st a; s0 a && (tick st; at_statement st a; s1 a)
           && (tick st; at_statement st a; s2 a) && (at_end st a; true))
      else if jumps then
        fun a ->
          let rec go i = match from a i with v -> v | exception Goto_label (l, j) when l = id -> go j in
          go 0
      else fun a -> from a 0
  | Some h ->
      (* The body of a routine with an error handler: a long jump that arrives between two of
         its statements (from a trap served there) is handled there (doc/rulings.md R-7.2-m). *)
      let rec from a k =
        if k >= n then between st h a at_end
        else (tick st; between st h a at_statement && body.(k) a && from a (k + 1)) in
      if jumps then
        fun a ->
          let rec go i = match from a i with v -> v | exception Goto_label (l, j) when l = id -> go j in
          go 0
      else fun a -> from a 0

(* R-7.2-m: an error that a long jump brings to a routine between two statements of its body,
   no statement of it being in progress, is handled by its error handler; RETRY and TRYNEXT
   both go on from where the program pointer was (the point of response is taken again), RETURN
   returns. *)
and between st h (a : act) point =
  match point st a with
  | () -> true
  | exception Long_jump (j, e) when j = a.level -> (
      emit_raised st e;
      match run_handler st h a e with
      | `Retry -> if st.all_events then st.emit (Event.Observed (Retried a.routine.name)); between st h a point
      | `Trynext -> if st.all_events then st.emit (Event.Observed (Tried_next a.routine.name)); between st h a point
      | `Return -> false)

(* ------------------------------------------------------------------ routines *)

let rec goto_targets acc (b : block) = Array.iter (goto_stmt acc) b.body
and goto_stmt acc (s : stmt) =
  match s.s with
  | Goto (b, _) -> Hashtbl.replace acc b ()
  | If (_, t, e) | Elseif (_, t, e) -> goto_targets acc t; goto_targets acc e
  | Compact_if (_, s) -> goto_stmt acc s
  | For f -> goto_targets acc f.loop_body
  | While (_, b) -> goto_targets acc b
  | Test (_, cases, d) -> Array.iter (fun (_, b) -> goto_targets acc b) cases; goto_targets acc d
  | _ -> ()

(* A valued body of exactly two statements, [IF own op k RETURN e1; RETURN x op' y;], e1 an own
   slot or a literal and op' one of +, -, * of two operands neither a num literal (the end of a
   recursion, then its step): both statements in one closure, the comparison as [condition]
   makes it (§4.17, §3.12) and the operator as [binary] computes it (§3.12, R-2.13-a; the left
   operand first, §3.1), RETURN's value the function's (§4.10). Each statement is entered as
   [block] enters it; the run is [valued_body]'s general form's, step for step. *)
let guarded_return st (r : routine) (b : Ir.block) : (act -> V.t) option =
  let own i = local_access st r i = Own in
  match b.body with
  | [| { s = Compact_if ({ e = Binary (op, { e = Read (Whole (Local i)); _ }, { e = Literal (V.Num q as v); _ }); _ },
                         { s = Return (Some e1); _ }); sat = at1; _ };
       { s = Return (Some { e = Binary ((Num_add | Num_sub | Num_mul) as op', x, y); _ }); sat = at2; _ } |]
    when is_num_comparison op && own i
         && (match e1.e with Read (Whole (Local j)) -> own j | Literal _ -> true | _ -> false)
         && (match y.e with Literal (V.Num _) -> false | _ -> true) ->
      (* the first statement's value: an own slot ([j]), or else the literal [w] *)
      let j, w = match e1.e with Read (Whole (Local j)) -> (j, no_value) | Literal w -> (-1, w) | _ -> assert false in
      let slow_if u = V.bool_value (check st ~at:at1 (Arith.binary op u v)) in
      let slow u' v' = check st ~at:at2 (Arith.binary op' u' v') in
      let x = expr st r ~at:at2 x and y = expr st r ~at:at2 y in
      let add = op' = Arith.Num_add and sub = op' = Arith.Num_sub in
      (* the second statement, entered *)
      let second a =
        tick st; at_statement st a;
        let u' = x a in
        let v' = y a in
        match u', v' with
        | V.Num p, V.Num q' -> single_num st ~at:at2 (if add then p +. q' else if sub then p -. q' else p *. q')
        | _ -> slow u' v' in
      begin match op with
      | Num_lt ->
          (* the usual end of a recursion, its comparison a branch of its own *)
          Some (fun a ->
              tick st; at_statement st a;
              match a.store.(i) with
              | V.Num p ->
                  if p < q then (if j >= 0 then a.store.(j) else w)
                  else begin
                    tick st; at_statement st a;
                    let u' = x a in
                    let v' = y a in
                    match u', v' with
                    | V.Num p, V.Num q' ->
                        single_num st ~at:at2 (if add then p +. q' else if sub then p -. q' else p *. q')
                    | _ -> slow u' v'
                  end
              | u -> if slow_if u then (if j >= 0 then a.store.(j) else w) else second a)
      | _ ->
          Some (fun a ->
              tick st; at_statement st a;
              if (match a.store.(i) with V.Num p -> compare_nums op p q | u -> slow_if u)
              then (if j >= 0 then a.store.(j) else w)
              else second a)
      end
  | _ -> None

(* The body of a function for the direct path (no handler, no UNDO, no label in its statement
   list), when its last statement is RETURN e: it gives RETURN's value as its result, so that
   the value is neither stored in the activation nor tested for. Each statement is entered as
   [block] enters it (a unit of fuel, a point of response); the list's end is never reached. *)
let valued_body st (r : routine) ~gotos : (act -> V.t) option =
  let b = r.body in
  let n = Array.length b.body in
  let ends_in_return = n > 0 && (match b.body.(n - 1).s with Return (Some _) -> true | _ -> false) in
  if r.kind <> Function || r.error <> None || r.undo <> None || Hashtbl.mem gotos b.id || not ends_in_return
  then None
  else
    match guarded_return st r b with
    | Some f -> Some f
    | None ->
    let rec from k : act -> V.t =
      let s = b.body.(k) in
      match s.s with
      | Return (Some e) ->
          let f = expr st r ~at:s.sat e in
          fun a -> tick st; at_statement st a; f a
      | Compact_if ({ e = Binary (op, { e = Read (Whole (Local i)); _ }, { e = Literal (V.Num q as v); _ }); _ },
                    { s = Return (Some e); _ })
        when is_num_comparison op && local_access st r i = Own -> (
          (* IF own < k RETURN e; (the end of a recursion): the comparison in the statement's
             closure, as [condition] makes it, and an own slot returned in place *)
          let at = s.sat and rest = from (k + 1) in
          let slow u = V.bool_value (check st ~at (Arith.binary op u v)) in
          match e.e with
          | Read (Whole (Local j)) when local_access st r j = Own ->
              fun a -> tick st; at_statement st a;
                if (match a.store.(i) with V.Num p -> compare_nums op p q | u -> slow u) then a.store.(j)
                else rest a
          | _ ->
              let f = expr st r ~at e in
              fun a -> tick st; at_statement st a;
                if (match a.store.(i) with V.Num p -> compare_nums op p q | u -> slow u) then f a
                else rest a)
      | Compact_if (c, { s = Return (Some e); _ }) ->
          let c = condition st r ~at:s.sat c and f = expr st r ~at:s.sat e and rest = from (k + 1) in
          fun a -> tick st; at_statement st a; if c a then f a else rest a
      | _ ->
          let g = stmt st r ~handler:None ~gotos s and rest = from (k + 1) in
          fun a -> tick st; at_statement st a; if g a then rest a else a.result
    in
    Some (from 0)

(* [c_guard]: a body that [valued_body] compiles, of a routine with one slot and no routine
   data, whose first statement is [IF slot1 op k RETURN e;], e the slot or a literal. *)
let leading_guard (r : routine) ~gotos =
  let b = r.body in
  let n = Array.length b.body in
  if r.kind <> Function || r.error <> None || r.undo <> None || Hashtbl.mem gotos b.id || n < 2
     || r.locals > 1 || Array.length r.parameters <> 1 || r.local_inits <> []
     || parameter_access r 0 <> Own
     || (match b.body.(n - 1).s with Return (Some _) -> false | _ -> true) then None
  else
    match b.body.(0).s with
    | Compact_if ({ e = Binary (op, { e = Read (Whole (Local 0)); _ }, { e = Literal (V.Num q); _ }); _ },
                  { s = Return (Some e); _ }) when is_num_comparison op -> (
        match e.e with
        | Read (Whole (Local 0)) -> Some (op, q, None)
        | Literal w -> Some (op, q, Some w)
        | _ -> None)
    | _ -> None

(* §2.21: routine data gets its initial value at each call. When the routine's first statement
   assigns the whole of it from an expression that does not name it, and no handler (ERROR, UNDO,
   BACKWARD) can run before that statement completes, nothing reads the initial value: the
   assignment replaces it before anything could (an error in the expression leaves the routine,
   and the slot with it). The memory budget still counts it. *)
let first_assigned (r : routine) slot =
  let rec names_place (p : place) = match p with
    | Whole (Local k) -> k = slot
    | Whole (Global _) | Unresolved _ -> false
    | Element (p, ix) -> names_place p || Array.exists names ix
    | Component (p, _) -> names_place p
  and names (e : expr) = match e.e with
    | Literal _ | Placeholder -> false
    | Read p | Read_signal p -> names_place p
    | Unary (_, x) | Fitted (x, _) -> names x
    | Binary (_, x, y) | And (x, y) | Or (x, y) -> names x || names y
    | Aggregate (xs, _) -> Array.exists names xs
    | Call c -> Array.exists (function
        | By_value e -> names e
        | By_reference (p, _) -> names_place p
        | Pass_on (Local k) -> k = slot
        | Pass_on (Global _) | Absent | Present_switch -> false) c.arguments in
  (* a signal's data is not replaced by an assignment but written through (§2.16): its value,
     the unconnected signal, is what the assignment finds *)
  let rec plain (sh : V.shape) = match sh with
    | S_handle _ -> false
    | S_num | S_dnum | S_bool | S_string -> true
    | S_record cs -> Array.for_all plain cs
    | S_array (_, c) -> plain c in
  r.error = None && r.undo = None && r.backward = None
  && Array.length r.body.body > 0
  && (match r.body.body.(0).s with Assign (Whole (Local k), e) -> k = slot && not (names e) | _ -> false)
  && (match List.assoc_opt slot r.local_inits with Some (Init_default sh) -> plain sh | _ -> false)

let compile_routine st k =
  let r = st.program.routines.(k) in
  let gotos = Hashtbl.create 4 in
  goto_targets gotos r.body;
  Option.iter (fun (h : error_handler) -> goto_targets gotos h.handler) r.error;
  Option.iter (goto_targets gotos) r.undo;
  let c_handler = Option.map (fun (h : error_handler) -> block st r ~handler:None ~gotos h.handler) r.error in
  let c_body = block ?top:c_handler st r ~handler:c_handler ~gotos r.body in
  let c_undo = Option.map (block st r ~handler:None ~gotos) r.undo in
  let inits = List.map (fun (slot, init) ->
      match init, local_access st r slot with
      | Init_default shape, (Flat_num k | Flat_dnum k) ->
          let bytes = V.shape_bytes shape and what = "the routine data of " ^ r.name in
          fun at (a : act) -> charge_active st a bytes what at; (flat_values st a).(k) <- 0.
      | Init_expr e, ((Flat_num k | Flat_dnum k) as access) ->
          let f = flat_store st r ~at:e.at k e in
          let box x = match access with Flat_dnum _ -> V.Dnum x | _ -> V.Num x in
          fun _ a ->
            ignore (flat_values st a); ignore (f a);
            if st.observe then observe_flat st a slot (box a.ext.nums.(k))
      | Init_default shape, _ when first_assigned r slot ->
          let bytes = V.shape_bytes shape and what = "the routine data of " ^ r.name in
          fun at (a : act) -> charge_active st a bytes what at
      | Init_default shape, _ ->
          (* Routine data counts in the memory budget while its routine is active: refused by
             the budget, it is never built. *)
          let bytes = V.shape_bytes shape and what = "the routine data of " ^ r.name in
          fun at (a : act) ->
            charge_active st a bytes what at;
            a.store.(slot) <- V.default_of shape
      | Init_expr e, _ ->
          let f = expr st r ~at:e.at e in
          fun _ a ->
            a.store.(slot) <- V.copy (f a); if st.observe then observe_store st a (a.store, slot)) r.local_inits in
  let c_init = match inits with
    | [] -> fun _ _ -> ()
    | [ f ] -> f
    | [ f; g ] -> fun at a -> f at a; g at a
    | _ -> fun at a -> List.iter (fun f -> f at a) inits in
  { c_init; c_body; c_handler; c_undo; c_nest = Native_stack.routine_nest r;
    c_value = valued_body st r ~gotos;
    c_guard = leading_guard r ~gotos }

(* The ERR_ names by upper-case name, only read: the table of the last list (the installed
   environment's, the same list physically for every program) is kept. *)
let last_numbers : ((string * int) list * (string, int) Hashtbl.t) option ref = ref None

let error_number_table error_numbers =
  match !last_numbers with
  | Some (l, t) when l == error_numbers -> t
  | _ ->
      let numbers = Hashtbl.create (2 * List.length error_numbers) in
      (* the names are upper case already, but for a user's: no copy of those *)
      let upper n = if String.exists (fun c -> c >= 'a' && c <= 'z') n then String.uppercase_ascii n else n in
      List.iter (fun (n, v) -> Hashtbl.replace numbers (upper n) v) error_numbers;
      last_numbers := Some (error_numbers, numbers);
      numbers

let not_compiled : compiled Lazy.t = lazy (invalid_arg "Closure_engine: a routine not compiled")

(* [Array.make n x] without its minor collection: for more than 256 elements and a young [x]
   (not_compiled, allocated at initialisation, is young until the first one) caml_make_vect
   empties the minor heap first, promoting all that start-up built (1.2 M instructions of an
   empty main); Array.concat copies the small arrays into the major heap without it. *)
let make_filled n x =
  if n <= 256 then Array.make n x
  else Array.concat (List.init ((n + 255) / 256) (fun i -> Array.make (min 256 (n - (256 * i))) x))

let initial_state ?(limits = Limits.default) ?(fuel = default_fuel) ?(stub_unmodelled = false) ?(observe = false)
    ?cooperation ~all_events ~emit ~(host : Host.t) (program : program) =
  let numbers = lazy (error_number_table program.error_numbers) in
  let st = {
    program; globals = Array.make (Array.length program.globals) (V.Bool false); limits; emit; all_events;
    observe = observe && all_events;
    fuel; fuel_limit = fuel; depth = 0; native = 0;
    native_budget = (match cooperation with Some (c : cooperation) -> c.native_budget | None -> Native_stack.budget ());
    next_interrupt = 0; numbers; compiled = [||];
    memory = 0; stub_unmodelled; stubbed = Hashtbl.create 8;
    host; in_trap = false; interrupts = false;
    (* A stimulus, or collisions, make the world report without the program asking. *)
    observing = host.next_event () <> None || host.collisions || cooperation <> None;
    quiet = 0; quiet_base = 0;
    moving = host.collisions;
    max_time = host.max_time; move_owners = Recent.create Limits.move_owners;
    serve_trap = (fun _ _ _ -> ());
    undoing = []; kept = []; async_errors = []; user_calls = []; resuming = []; skip_undo = [];
    next_cycle = false; cooperation; flats = Rapid_syntax.Source.Table.create 16 } in
  (* Filled in place: Array.init of hundreds of fresh lazy values forces a minor collection. *)
  st.compiled <- make_filled (Array.length program.routines) not_compiled;
  (* A routine's closures live as long as the run: compiled at the collector's building pace
     (Build_pace), as Session.load builds the program they come from. *)
  Array.iteri (fun k _ -> st.compiled.(k) <- lazy (Build_pace.building (fun () -> compile_routine st k)))
    program.routines;
  st.serve_trap <- serve_trap st;
  st

let outcome_of_exception st = function
  | Halt o -> o
  | Stack_overflow ->
      Outcome.Resource_exhausted
        (Printf.sprintf "the native stack is exhausted at call depth %d (resource exhaustion, §1.4)" st.depth, None)
  | Out_of_memory -> Outcome.Resource_exhausted ("out of memory (resource exhaustion, §1.4)", None)
  | V.Type_mismatch what -> Outcome.Stuck ("a value of the wrong type: " ^ what)
  | e -> Outcome.Stuck (Printexc.to_string e)

(* The routines a task runs one after the other (doc/rulings.md R-bk-8): the event routines
   [before], the entry routine, the event routines [after], as the machine's [sequence] finds
   them: each a procedure without parameters (the program's entry points). *)
let sequence (program : program) ~before ~entry ~after =
  let module T = Rapid_runtime.Task_rules in
  let find ~is_entry name =
    let lower = String.lowercase_ascii name in
    match List.find_opt (fun (n, _) -> String.lowercase_ascii n = lower) program.entry_points with
    | Some (_, k) -> Ok (k, is_entry)
    | None -> Error (if is_entry then T.no_entry program name else T.not_an_event_routine program name) in
  T.sequence ~find ~before ~entry ~after

let rec run ?limits ?fuel ?stub_unmodelled ?(all_events = true) ?observe ?(on_event = ignore) ?(before = [])
    ?(after = []) ~host ?cooperation ?module_data (program : program) ~entry =
  try
    run_entry ?limits ?fuel ?stub_unmodelled ~all_events ?observe ?cooperation ?module_data ~on_event ~host program
      ~before ~entry ~after
  with Initial_value_failed (g, name) -> Error (Printf.sprintf "the initial value of %s: %s" g name)

and run_entry ?limits ?fuel ?stub_unmodelled ~all_events ?observe ?cooperation ?module_data ~on_event
    ~(host : Host.t) (program : program) ~before ~entry ~after =
  (* The installed data that depend on the robot (vmax), as the machine has them. *)
  let program = host.prepare program in
  match sequence program ~before ~entry ~after with
  | Error m -> Error m
  | Ok [] -> Error (Rapid_runtime.Task_rules.no_entry program entry)
  | Ok ((k, first_is_entry) :: phases) ->
      (* What the caller's [on_event] raises (a closed standard output) is the caller's, not the
         program's: it leaves the run as it came, instead of ending it as Stuck. *)
      let on_event e = try on_event e with ex -> raise (Observer_failed ex) in
      let st =
        initial_state ?limits ?fuel ?stub_unmodelled ?observe ?cooperation ~all_events ~emit:on_event ~host program in
      let r = program.routines.(k) in
      let outcome =
        try
          (* §2.21: module data is initialised when its module is loaded. *)
          let rec sentinel = { routine = r; store = [||]; ext = shared_extension; level = -1;
                               parent = sentinel; result = no_value; nest = 0; memory = 0 } in
          let dummy = new_act (activation_shape r) r sentinel in
          (* Module data first takes its type's initial value, within the memory budget; then
             the initial values the static semantics left as expressions (a placeholder, an
             unknown name) are evaluated, and fail as they would at run time. *)
          Array.iteri (fun i (g : global) ->
              match g.g_init with
              | Init_default shape ->
                  let bytes = V.shape_bytes shape in
                  if bytes > st.limits.max_memory - st.memory then
                    memory_exhausted st ("the initial value of " ^ g.g_name) g.g_at;
                  st.memory <- st.memory + bytes;
                  st.globals.(i) <- V.default_of shape
              | Init_expr _ -> ()) program.globals;
          Array.iteri (fun i (g : global) ->
              match g.g_init with
              | Init_expr e -> (
                  match expr st r ~at:e.at e dummy with
                  | v -> st.memory <- st.memory + V.bytes v; st.globals.(i) <- V.copy v
                  | exception Raised err -> raise (Initial_value_failed (g.g_name, err.name)))
              | Init_default _ -> ()) program.globals;
          Option.iter (fun c -> c.share st.globals) cooperation;
          (* Rules return-entry, raise-unhandled, raise-again-unhandled, exit; cycle-restart: the
             entry routine runs again, in a new activation, after ExitCycle (R-13-exitcycle1).
             The routines of the task's sequence (R-bk-8) follow one another, each in a new
             activation, when one ends by its end, RETURN, or ExitCycle in an event routine. *)
          if all_events then on_event (Event.Routine_entered r.name);
          let rec cycle (k, at_entry) phases =
            let r = program.routines.(k) in
            let code = Lazy.force st.compiled.(k) in
            let a = new_act (activation_shape r) r sentinel in
            a.nest <- code.c_nest;
            st.native <- code.c_nest;
            st.depth <- 1;
            let next () =
              match phases with
              | [] ->
                  if all_events then begin on_event (Event.Routine_left r.name); on_event Event.Task_ended end;
                  Outcome.Ended
              | ((k', _) as phase) :: phases ->
                  pop st a;
                  st.in_trap <- false; st.kept <- []; st.undoing <- []; st.resuming <- []; st.skip_undo <- [];
                  st.user_calls <- [];
                  if all_events then begin
                    on_event (Event.Routine_left r.name);
                    on_event (Event.Routine_entered program.routines.(k').name)
                  end;
                  cycle phase phases in
            match code.c_init r.at a; code.c_body a with
            | _ -> next ()
            | exception (Raised e | Leaving e | Long_jump (_, e)) -> stopped (caught a e)
            | exception Exit_task ->
                (match code.c_undo with
                 | Some undo ->
                     if all_events then on_event (Event.Undo_run r.name);
                     (match undo a with
                      | _ -> ()
                      | exception (Raised e | Leaving e | Long_jump (_, e)) -> raise (Halt (stopped (caught a e))))
                 | None -> ());
                if st.next_cycle && not at_entry then begin st.next_cycle <- false; next () end
                else if st.next_cycle then begin
                  st.next_cycle <- false;
                  pop st a;
                  st.in_trap <- false; st.kept <- []; st.undoing <- []; st.resuming <- []; st.skip_undo <- [];
                  st.user_calls <- [];
                  tick st;
                  if all_events then begin
                    on_event (Event.Routine_left r.name); on_event (Event.Routine_entered r.name)
                  end;
                  cycle (k, at_entry) phases
                end
                else begin
                  if all_events then on_event Event.Task_ended;
                  Outcome.Ended
                end in
          cycle (k, first_is_entry) phases
        with
        | Initial_value_failed (g, name) -> raise (Initial_value_failed (g, name))
        | Observer_failed ex -> raise ex
        | e -> outcome_of_exception st e
      in
      (* What the world and the motion did last; at the end of the task, what the robot still
         does (as the machine's last step). *)
      (try
         sync st;
         observe_world st;
         observe_motion st;
         if outcome = Outcome.Ended && all_events then
           List.iter (fun m -> on_event (Event.Motion m)) (st.host.motion_finish ())
       with _ -> ());
      (* --save (Persistent_save): the module data as the run left it. *)
      Option.iter (fun f ->
          f (Array.to_list (Array.mapi (fun i (g : global) -> (g.g_module, g.g_name, st.globals.(i))) program.globals)))
        module_data;
      Ok { outcome; fuel_used = max 0 (min st.fuel_limit (st.fuel_limit - st.fuel)) }

let events ?limits ?fuel ?stub_unmodelled ?all_events ?observe ~host program ~entry =
  let acc = ref [] in
  match
    run ?limits ?fuel ?stub_unmodelled ?all_events ?observe ~host ~on_event:(fun e -> acc := e :: !acc) program ~entry
  with
  | Error m -> Error m
  | Ok r -> Ok (List.rev !acc, r)
