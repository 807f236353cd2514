(* The world of one run. Time is an integer count of microseconds; timed events are kept in a
   list sorted by time and then by the order they were scheduled in, so that equal times
   happen in a reproducible order. *)

type observation = Rapid_observable.Controller_observation.t = 
  | Signal_changed of { time : float; signal : string; value : float }
  | Interrupt_occurred of { time : float; number : int }
  | Interrupt_discarded of { time : float; number : int; reason : string }

let default_statement_time = 0.0001
let default_max_time = 3600.
let default_epoch = 1704067200.   (* 2024-01-01 00:00:00 UTC, a Monday *)
let default_poll_rate = Rapid_observable.Wait.default_poll_rate
let min_poll_rate = 0.04
let min_timer_single = 0.01
let min_timer_cyclic = 0.1
let max_interrupts = 100
let queue_capacity = 30

(* A time beyond 10^12 s (about 31700 years, far past any --max-time) is "never": the count
   stops at 10^18 µs, which sums of two such times still hold, instead of overflowing the
   integer (a num goes up to 3.4E38 seconds). *)
let never_us = 1_000_000_000_000_000_000
let seconds s =
  if Float.is_nan s || s >= 1e12 then never_us
  else if s <= -1e12 then - never_us
  else int_of_float (Float.round (s *. 1e6))
let to_seconds us = float_of_int us /. 1e6

type signal = { s_name : string; s_kind : Io_config.signal_type; mutable value : float }

type trigger = old:float -> now:float -> bool

type error_datum = { domain : int; id : int; error_type : int; strings : string list }

type source =
  | No_source
  | Timer of { period : int; single : bool }
  | Signal_edge of { signal : int; trigger : trigger; single : bool }
  | Watch of { changed : unit -> bool; single : bool }
  | Error_log of { domain : int; id : int option; error_type : int }
  | Rmq_message of { datatype : string }      (* IRMQMessage: a message of this data type *)

type interrupt = {
  trap : int;
  mutable source : source;
  mutable generation : int;           (* a new order cancels the pending timer events of the old *)
  mutable sleeping : bool;
  mutable safe : bool;                (* ordered with \SingleSafe: ISleep refuses it (R-8-w) *)
}

type clock = { mutable since : int option; mutable total : int }

(* The RAPID Message Queue (ABB's RMQ, doc/controller.md): what a message carries is the
   installed routines' value, which this library does not know. *)
type rmq_data = ..

type rmq_message = { sender : int; datatype : string; dims : int list; user_def : int; data : rmq_data }

type rmq_mode = Rmq_unset | Rmq_interrupt | Rmq_synchronous

type rmq = {
  messages : rmq_message Queue.t;
  mutable mode : rmq_mode;
  mutable awaiting : (int * string) option;
  mutable answer : rmq_message option;
}

type wait = Rapid_observable.Wait.t = {
  what : string;
  satisfied : unit -> bool;
  deadline : float option;
  finish : timed_out:bool -> Rapid_observable.Wait.raised option;
  poll : float option;
}

(* ch. 14: the tasks of a run share the clock, the timed events, the signals and the services;
   each task has its own interrupts, queue, clocks and observations. [c] is the shared part. *)
type action =
  | Set_signal of int * float
  | Timer_due of t * int * int        (* the task's world, number, generation *)
  | Wake                              (* nothing happens: a wait looks again (wake_at) *)
  | Call of (unit -> unit)            (* a model beside the controller acts (at) *)

and shared = {
  mutable now : int;
  mutable events : (int * int * action) list;  (* time, sequence, action: sorted *)
  mutable sequence : int;
  mutable members : t list;                    (* the tasks, in order of their numbers *)
  syncs : (string, int) Hashtbl.t;             (* WaitSyncTask: (sync point, task) -> arrivals *)
  sync_moves : (string, string list) Hashtbl.t; (* SyncMoveOn: task -> the task list it synchronises with *)
  rmqs : (int, rmq) Hashtbl.t;                 (* each task's RAPID Message Queue, by its number *)
  rmq_kept : (int, rmq_message) Hashtbl.t;     (* the messages rmqmessage variables hold *)
  mutable rmq_last : int;                      (* the identity of the last message kept *)
  mutable executed : int;                      (* statements executed, by any task *)
  host_waits : (int, unit) Hashtbl.t;          (* the tasks, by number, in a wait on the host *)
  mutable all_waiting : (string list * int) option;
      (* the running tasks when they last all waited, and [executed] then (R-13-sockwait2) *)
}

and t = {
  c : shared;
  mutable task_name : string;
  task_number : int;
  mutable motion_task : bool;
  statement_time : int;
  max_time : float;
  epoch : float;
  signals : signal array;             (* identity i is signals.(i - 1) *)
  interrupts : (int, interrupt) Hashtbl.t;
  mutable watching : bool;             (* some IPers was ordered: look at persistents *)
  queue : (int * error_datum option) Queue.t;
  mutable disabled : bool;
  mutable served_datum : error_datum option;    (* of the interrupt served last (GetTrapData) *)
  mutable data : error_datum list;              (* trapdata objects, newest first *)
  clocks : (int, clock) Hashtbl.t;
  mutable observations : observation list;      (* newest first *)
  collisions : float list;                      (* of the stimulus, for the motion model *)
  system_inputs : Io_config.system_input list;  (* of the configuration (SYSSIG_IN) *)
  mutable services : Services.t option;         (* files, sockets, text resources: made on first use *)
}

let schedule w time action =
  w.c.sequence <- w.c.sequence + 1;
  let entry = (time, w.c.sequence, action) in
  let rec insert = function
    | [] -> [ entry ]
    | ((t, s, _) as e) :: rest -> if (t, s) > (time, w.c.sequence) then entry :: e :: rest else e :: insert rest
  in
  w.c.events <- insert w.c.events

let observe w o = w.observations <- o :: w.observations

let create ?(statement_time = default_statement_time) ?(max_time = default_max_time)
    ?(epoch = default_epoch) (config : Io_config.t) =
  let signals = Array.of_list (List.map (fun (s : Io_config.signal) ->
      { s_name = s.name; s_kind = s.kind; value = s.initial }) config.signals) in
  let c = { now = 0; events = []; sequence = 0; members = []; syncs = Hashtbl.create 4;
            sync_moves = Hashtbl.create 2; rmqs = Hashtbl.create 2; rmq_kept = Hashtbl.create 8; rmq_last = 0;
            executed = 0; host_waits = Hashtbl.create 2; all_waiting = None } in
  let w = { c; task_name = "T_ROB1"; task_number = 1; motion_task = true;
            statement_time = max 0 (seconds statement_time); max_time; epoch; signals;
            interrupts = Hashtbl.create 8; watching = false;
            queue = Queue.create (); disabled = false; served_datum = None; data = []; clocks = Hashtbl.create 4;
            observations = []; collisions = config.collisions; system_inputs = config.system_inputs;
            services = None } in
  c.members <- [ w ];
  (* The stimulus is in order of time already (Io_config): its events are the list as it is. *)
  let ids = Hashtbl.create 16 in
  Array.iteri (fun i s -> Hashtbl.replace ids (String.lowercase_ascii s.s_name) (i + 1)) signals;
  c.events <- List.filter_map (fun (st : Io_config.stimulus) ->
      match Hashtbl.find_opt ids (String.lowercase_ascii st.signal) with
      | Some id -> c.sequence <- c.sequence + 1; Some (seconds st.time, c.sequence, Set_signal (id, st.value))
      | None -> None) config.stimuli;
  w

let now w = to_seconds w.c.now
let collisions w = w.collisions

let set_services w s = w.services <- Some s
let services w =
  match w.services with
  | Some s -> s
  | None -> let s = Services.create () in w.services <- Some s; s
let max_time w = w.max_time
let epoch w = w.epoch

(* ---------------------------------------------------------------- interrupts *)

(* An interrupt occurs: queued for its trap, unless it sleeps (ISleep: "discarded without any
   trap execution") or the queue is full (R-8-c). *)
let occur ?datum w number =
  match Hashtbl.find_opt w.interrupts number with
  | None -> ()
  | Some i ->
      let time = now w in
      if i.sleeping then observe w (Interrupt_discarded { time; number; reason = "sleeping (ISleep)" })
      else if Queue.length w.queue >= queue_capacity then
        observe w (Interrupt_discarded { time; number; reason = "the interrupt queue is full" })
      else (Queue.add (number, datum) w.queue; observe w (Interrupt_occurred { time; number }))

let signal_changed_in w id old value =
  Hashtbl.fold (fun n i acc -> (n, i) :: acc) w.interrupts []
  |> List.sort (fun (a, _) (b, _) -> compare a b)
  |> List.iter (fun (n, i) ->
      match i.source with
      | Signal_edge { signal; trigger; single } when signal = id && trigger ~old ~now:value ->
          if single then i.source <- No_source;
          occur w n
      | _ -> ())

(* A signal is the system's: every task's interrupts on it see the change (ch. 14). *)
let signal_changed w id old value = List.iter (fun m -> signal_changed_in m id old value) w.c.members

(* ---------------------------------------------------------------- signals *)

let signal_of w id = if id >= 1 && id <= Array.length w.signals then Some w.signals.(id - 1) else None
let signals w = Array.to_list (Array.mapi (fun i s -> (s.s_name, s.s_kind, i + 1)) w.signals)
let find_signal w name =
  let rec go i = if i >= Array.length w.signals then None
    else if String.lowercase_ascii w.signals.(i).s_name = String.lowercase_ascii name then Some (i + 1)
    else go (i + 1) in
  go 0

let signal_name w id = match signal_of w id with Some s -> s.s_name | None -> "?"
let signal_kind w id = Option.map (fun s -> s.s_kind) (signal_of w id)
let read w id = match signal_of w id with Some s -> s.value | None -> 0.

(* A system input (Io_config.system_input) acts while its digital input is 1. *)
let system_input_active w ~action =
  List.exists (fun (si : Io_config.system_input) ->
      String.lowercase_ascii si.action = String.lowercase_ascii action
      && (match find_signal w si.input with Some id -> read w id <> 0. | None -> false)) w.system_inputs

let write w id value =
  match signal_of w id with
  | Some s when s.value <> value ->
      let old = s.value in
      s.value <- value;
      observe w (Signal_changed { time = now w; signal = s.s_name; value });
      signal_changed w id old value
  | _ -> ()

let write_later w id value ~delay = schedule w (w.c.now + max 0 (seconds delay)) (Set_signal (id, value))

(* ---------------------------------------------------------------- time *)

let perform w = function
  | Set_signal (id, v) -> write w id v
  | Timer_due (w, n, generation) -> (
      match Hashtbl.find_opt w.interrupts n with
      | Some ({ source = Timer { period; single }; _ } as i) when i.generation = generation ->
          if single then i.source <- No_source
          else schedule w (w.c.now + period) (Timer_due (w, n, generation));
          occur w n
      | _ -> ())
  | Wake -> ()
  | Call f -> f ()

let advance_us w target =
  let rec go () =
    match w.c.events with
    | (t, _, a) :: rest when t <= target ->
        w.c.events <- rest;
        if t > w.c.now then w.c.now <- t;
        perform w a; go ()
    | _ -> ()
  in
  go ();
  if target > w.c.now then w.c.now <- target

let advance_to w time = advance_us w (seconds time)
let statement w = w.c.executed <- w.c.executed + 1; advance_us w (w.c.now + w.statement_time)

let statement_within w =
  w.c.executed <- w.c.executed + 1;
  let target = w.c.now + w.statement_time in
  (match w.c.events with
   | (t, _, _) :: _ when t <= target -> advance_us w target
   | _ -> w.c.now <- target);
  not (to_seconds w.c.now > w.max_time)

let statements w k =
  if k > 0 then begin w.c.executed <- w.c.executed + k; advance_us w (w.c.now + k * w.statement_time) end

let statements_left w =
  let d = w.statement_time in
  let within k = not (to_seconds (w.c.now + k * d) > w.max_time) in
  if d = 0 then (if within 0 then max_int else 0)
  else
    let guess = (w.max_time *. 1e6 -. float_of_int w.c.now) /. float_of_int d in
    if not (guess < 1e15) then 1 lsl 48
    else begin
      let k = ref (max 0 (int_of_float guess)) in
      while within (!k + 1) do incr k done;
      while !k > 0 && not (within !k) do decr k done;
      if within !k then !k else 0
    end
let next_event w = match w.c.events with (t, _, _) :: _ -> Some (to_seconds t) | [] -> None

let next_change w =
  (* A model's own event (a trigger on the path, [at]) changes a signal or makes an interrupt. *)
  List.find_map (function
      | (t, _, (Set_signal _ | Timer_due _ | Call _)) -> Some (to_seconds t) | _, _, Wake -> None) w.c.events

(* A wait whose end another model computes (the robot's ready time, doc/motion.md) has the
   clock stop there. *)
let wake_at w time =
  if Float.is_finite time && time < 1e12 && seconds time > w.c.now then schedule w (seconds time) Wake

(* A trigger on the robot's path (TriggIO, TriggInt) acts at the time the motion model computes,
   among the events due then in the order they were scheduled. *)
let at w time f =
  if Float.is_finite time && time < 1e12 then schedule w (max w.c.now (seconds time)) (Call f)

(* ---------------------------------------------------------------- ordering interrupts *)

(* Generations are unique in the run, so that a timer event of a deleted interrupt never matches
   a later interrupt that got the same number. *)
let fresh_generation w = w.c.sequence <- w.c.sequence + 1; w.c.sequence

let connect w ~trap =
  if Hashtbl.length w.interrupts >= max_interrupts then Error "ERR_INOMAX"
  else begin
    (* The lowest number not in use: numbers are freed by IDelete. *)
    let rec free n = if Hashtbl.mem w.interrupts n then free (n + 1) else n in
    let n = free 1 in
    Hashtbl.replace w.interrupts n { trap; source = No_source; generation = 0; sleeping = false; safe = false };
    Ok n
  end

let connected w n = Hashtbl.mem w.interrupts n
let interrupt w n = occur w n
(* The occurrences still queued go with the number: dropped now, so that a later CONNECT that
   gets the same number never serves them with its trap (R-8-x). *)
let delete w n =
  if Hashtbl.mem w.interrupts n then begin
    Hashtbl.remove w.interrupts n;
    let kept = Queue.create () in
    Queue.iter (fun ((m, _) as q) ->
        if m = n then observe w (Interrupt_discarded { time = now w; number = n; reason = "deleted (IDelete)" })
        else Queue.add q kept) w.queue;
    Queue.clear w.queue;
    Queue.transfer kept w.queue
  end

let with_interrupt w n f =
  match Hashtbl.find_opt w.interrupts n with Some i -> f i | None -> Error "ERR_UNKINO"

(* ch. 8: "通常,定义程序(比如,ISignalDI)将激活中断" — an order activates the interrupt, even one
   that ISleep deactivated (R-8-w). *)
(* A shorter time is the minimum ABB gives ITimer (doc/rulings.md R-8-waits1): a cyclic timer
   fires at most ten times a virtual second, so that the firings of a run are bounded by
   --max-time. *)
let order_timer w n ~period ~single =
  with_interrupt w n (fun i ->
      let p = seconds (Float.max period (if single then min_timer_single else min_timer_cyclic)) in
      i.generation <- fresh_generation w;
      i.sleeping <- false;
      i.source <- Timer { period = p; single };
      schedule w (w.c.now + p) (Timer_due (w, n, i.generation));
      Ok ())

let order_signal w n ~signal ~trigger ~single =
  with_interrupt w n (fun i ->
      i.generation <- fresh_generation w;
      i.sleeping <- false;
      i.source <- Signal_edge { signal; trigger; single };
      Ok ())

let order_watch w n ~changed ~single =
  with_interrupt w n (fun i ->
      i.generation <- fresh_generation w;
      i.sleeping <- false;
      i.source <- Watch { changed; single };
      w.watching <- true;
      Ok ())

let order_error w n ~domain ~id ~error_type =
  with_interrupt w n (fun i ->
      i.generation <- fresh_generation w;
      i.sleeping <- false;
      i.source <- Error_log { domain; id; error_type };
      Ok ())

(* IError: COMMON_ERR (0) is every domain, an absent ErrorId every number, TYPE_ALL (0) every
   type. *)
let post_error w (d : error_datum) =
  Hashtbl.fold (fun n i acc -> (n, i) :: acc) w.interrupts []
  |> List.sort (fun (a, _) (b, _) -> compare a b)
  |> List.iter (fun (n, i) ->
      match i.source with
      | Error_log { domain; id; error_type }
        when (domain = 0 || domain = d.domain) && (id = None || id = Some d.id)
             && (error_type = 0 || error_type = d.error_type) ->
          occur ~datum:d w n
      | _ -> ())

(* IPers: a persistent changed since the last look. Looked at wherever an interrupt may be
   served. *)
let look_at_watches w =
  if w.watching then
  Hashtbl.fold (fun n i acc -> (n, i) :: acc) w.interrupts []
  |> List.sort (fun (a, _) (b, _) -> compare a b)
  |> List.iter (fun (n, i) ->
      match i.source with
      | Watch { changed; single } when changed () ->
          if single then i.source <- No_source;
          occur w n
      | _ -> ())

let set_safe w n ~safe = match Hashtbl.find_opt w.interrupts n with Some i -> i.safe <- safe | None -> ()

(* ch. 12, ERR_INOISSAFE: "如果尝试暂时停用安全中断,则采用ISleep" — a safe interrupt cannot be
   deactivated for a while (R-8-w). *)
let sleep w n = with_interrupt w n (fun i -> if i.safe then Error "ERR_INOISSAFE" else (i.sleeping <- true; Ok ()))
let watch w n = with_interrupt w n (fun i -> i.sleeping <- false; Ok ())
let disable w = w.disabled <- true
let enable w = w.disabled <- false
let enabled w = not w.disabled

let rec take_queued w =
  if w.disabled || Queue.is_empty w.queue then None
  else
    let n, datum = Queue.pop w.queue in
    match Hashtbl.find_opt w.interrupts n with
    | Some i -> w.served_datum <- datum; Some (n, i.trap)
    | None -> take_queued w

let take w = look_at_watches w; take_queued w

let trap_data w =
  match w.served_datum with
  | None -> 0
  | Some d -> w.data <- d :: w.data; List.length w.data

let error_datum w k =
  let n = List.length w.data in
  if k >= 1 && k <= n then Some (List.nth w.data (n - k)) else None

(* ---------------------------------------------------------------- clocks *)

let new_clock w =
  let id = Hashtbl.length w.clocks + 1 in
  Hashtbl.replace w.clocks id { since = None; total = 0 };
  id

let clock w id =
  match Hashtbl.find_opt w.clocks id with
  | Some c -> c
  | None -> let c = { since = None; total = 0 } in Hashtbl.replace w.clocks id c; c

let elapsed w c = c.total + (match c.since with Some s -> w.c.now - s | None -> 0)

(* ClkReset stops the clock and sets it to 0 (ABB's ClkReset: "if a clock is running it will be
   stopped and then reset"). *)
let clock_reset w id = let c = clock w id in c.total <- 0; c.since <- None
let clock_start w id = let c = clock w id in if c.since = None then c.since <- Some w.c.now
let clock_stop w id = let c = clock w id in c.total <- elapsed w c; c.since <- None
let clock_read w id = to_seconds (elapsed w (clock w id))

let drain w =
  match w.observations with
  | [] -> []
  | l -> w.observations <- []; List.rev l

(* ---------------------------------------------------------------- tasks (ch. 14) *)

let task_name w = w.task_name
let task_number w = w.task_number
let motion_task w = w.motion_task
let task_names w = List.map (fun m -> m.task_name) w.c.members

let add_task w ~name ~motion =
  let t = { w with task_name = name; task_number = List.length w.c.members + 1; motion_task = motion;
                   interrupts = Hashtbl.create 8; watching = false; queue = Queue.create (); disabled = false;
                   served_datum = None; data = []; clocks = Hashtbl.create 4; observations = [];
                   services = Some (services w) } in
  w.c.members <- w.c.members @ [ t ];
  t

let name_task w ~name ~motion = w.task_name <- name; w.motion_task <- motion

(* R-13-sockwait2: the scheduler says when every running task waits; a wait on the host (a
   socket's) says when it begins and ends. Nothing but the host can then end any wait while no
   statement has run since and every task that waited then still waits on the host. *)
let every_task_waits w names = w.c.all_waiting <- Some (names, w.c.executed)
let host_wait_begin w = Hashtbl.replace w.c.host_waits w.task_number ()
let host_wait_end w = Hashtbl.remove w.c.host_waits w.task_number

let only_host_waits w =
  match w.c.members with
  | [ _ ] -> true
  | members -> (
      match w.c.all_waiting with
      | Some (names, executed) when executed = w.c.executed ->
          List.for_all (fun name ->
              List.exists (fun m -> String.lowercase_ascii m.task_name = String.lowercase_ascii name
                                    && Hashtbl.mem w.c.host_waits m.task_number) members) names
      | _ -> false)

let host_waiters w = Hashtbl.length w.c.host_waits

let sync_key point task = String.lowercase_ascii point ^ "\x00" ^ String.lowercase_ascii task

let sync_arrive w point =
  let k = sync_key point w.task_name in
  let n = 1 + Option.value (Hashtbl.find_opt w.c.syncs k) ~default:0 in
  Hashtbl.replace w.c.syncs k n; n

let sync_arrivals w point ~task = Option.value (Hashtbl.find_opt w.c.syncs (sync_key point task)) ~default:0

(* R-14-m: a task is in synchronized movement from its SyncMoveOn until SyncMoveOff or
   SyncMoveUndo; the list is the one its SyncMoveOn named, which its SyncMoveOff meets. *)
let sync_move w = Hashtbl.find_opt w.c.sync_moves (String.lowercase_ascii w.task_name)

let set_sync_move w tasks =
  let k = String.lowercase_ascii w.task_name in
  match tasks with
  | Some l -> Hashtbl.replace w.c.sync_moves k l
  | None -> Hashtbl.remove w.c.sync_moves k

(* ---------------------------------------------------------------- RAPID Message Queue *)

(* ABB's defaults of the task's system parameters RMQ Max No Of Messages and RMQ Max Message Size
   (doc/rulings.md R-14-rmq1). *)
let rmq_max_messages = 5
let rmq_max_size = 400
let rmq_kept_limit = 1000

let rmq w =
  match Hashtbl.find_opt w.c.rmqs w.task_number with
  | Some q -> q
  | None ->
      let q = { messages = Queue.create (); mode = Rmq_unset; awaiting = None; answer = None } in
      Hashtbl.replace w.c.rmqs w.task_number q;
      q

(* A task's slot is its number, its slot name RMQ_ and its name (ABB's RMQFindSlot examples:
   "RMQ_T_ROB2"); names compare without letter case, as task names. *)
let rmq_slot_name w slot =
  List.find_map (fun m -> if m.task_number = slot then Some ("RMQ_" ^ m.task_name) else None) w.c.members

let same_text a b = String.lowercase_ascii a = String.lowercase_ascii b

let rmq_slot w name =
  List.find_map (fun m -> if same_text ("RMQ_" ^ m.task_name) name then Some m.task_number else None) w.c.members

let order_rmq w n ~datatype =
  with_interrupt w n (fun i ->
      i.generation <- fresh_generation w;
      i.sleeping <- false;
      i.source <- Rmq_message { datatype };
      Ok ())

(* A message arrives (R-14-rmq2): the answer a waiting RMQSendWait of the receiver expects goes
   to it; in interrupt mode a message of a data type some IRMQMessage ordered is queued and the
   interrupt of the lowest such number occurs (a message whose interrupt is discarded, sleeping
   or finding the interrupt queue full, is discarded with it), any other is discarded; in
   synchronous mode, and before the task has chosen a mode, every message is queued. A queue
   already holding rmq_max_messages refuses the message: ERR_RMQ_FULL for the sender. *)
let rmq_send w ~slot (m : rmq_message) =
  match List.find_opt (fun r -> r.task_number = slot) w.c.members with
  | None -> Error "ERR_RMQ_INVALID"
  | Some r -> (
      let q = rmq r in
      let full () = Queue.length q.messages >= rmq_max_messages in
      match q.awaiting with
      | Some (from, datatype) when from = m.sender && same_text datatype m.datatype && q.answer = None ->
          q.answer <- Some m;
          Ok ()
      | _ when q.mode <> Rmq_interrupt ->
          if full () then Error "ERR_RMQ_FULL" else (Queue.add m q.messages; Ok ())
      | _ -> (
          let lowest = Hashtbl.fold (fun n i found ->
              match i.source with
              | Rmq_message { datatype } when same_text datatype m.datatype ->
                  (match found with Some k when k < n -> found | _ -> Some n)
              | _ -> found) r.interrupts None in
          match lowest with
          | None -> Ok ()
          | Some _ when full () -> Error "ERR_RMQ_FULL"
          | Some n ->
              let i = Hashtbl.find r.interrupts n in
              if (not i.sleeping) && Queue.length r.queue < queue_capacity then Queue.add m q.messages;
              occur r n;
              Ok ()))

(* A message an rmqmessage variable holds, under a new identity: the one the variable held before
   is forgotten, so that a variable taking message after message holds one; of the others the
   last rmq_kept_limit given out are kept, the oldest forgotten first (R-14-rmq3). *)
let rmq_keep w ?into m =
  let c = w.c in
  Option.iter (Hashtbl.remove c.rmq_kept) into;
  c.rmq_last <- c.rmq_last + 1;
  Hashtbl.replace c.rmq_kept c.rmq_last m;
  Hashtbl.remove c.rmq_kept (c.rmq_last - rmq_kept_limit);
  c.rmq_last

let rmq_kept w k = Hashtbl.find_opt w.c.rmq_kept k
