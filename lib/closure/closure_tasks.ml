(* Several tasks by the closure engine (ch. 14). The closure engine recurses on the native stack,
   so a task cannot be suspended between two statements as a machine can: each task runs on a
   thread of its own, and a hand-off (one mutex, one condition) lets exactly one run at a time.
   The scheduler, on the calling thread, gives the turns by Task_set's rules; a task hands the
   turn back where the machine's turn ends, so that both engines make the same events in the
   same order for every schedule. *)

module C = Closure_engine

(* How a task's turn ended. *)
type reply =
  | Boundary                                          (* a statement in focus *)
  | Yielded of { wake : float option; what : string; pure : bool }
  | Finished of (C.result, string) Stdlib.result
  | Crashed of exn                                    (* raised by the caller's on_event *)

type command = Go | Abort

exception Aborted   (* the run ended while the task was still running: its thread unwinds *)

type task = {
  name : string;
  program : Ir.program;
  entry : string;
  before : string list;                    (* its event routines (R-bk-8) *)
  after : string list;
  host : Host.t;
  entry_taken : bool;                      (* its start took its first statement's time *)
  mutable globals : Value.t array;         (* its module data, once initialised *)
  mutable links : (int * int) list;        (* a slot of [globals] and the shared object it is *)
  mutable reply : reply option;
  mutable command : command option;
  mutable idle : bool;                     (* it yielded, and nothing happened since *)
  mutable wake : float option;             (* the time its last yield gave *)
  mutable what : string option;            (* what its last yield waits for *)
  mutable finished : C.result option;
  mutable fuel_used : int;
  mutable thread : Thread.t option;
  wakeup : Condition.t;                    (* its turn comes, or its end *)
}


type t = {
  members : task array;
  shared : Value.t array;                  (* each shared data object's value *)
  order : Task_rules.order;
  cursor : int ref;
  mutable ended : Outcome.t option;        (* a deadlock or the time limit of the whole run *)
  mutable cut : bool;                      (* a task ran out of fuel: the run stopped *)
  mutable aborting : bool;
  mutable ran : bool;
  limits : Limits.t;
  stub_unmodelled : bool option;
  clock : Host.t;
  mutable over : bool;                     (* the run is over: no more turns *)
  mutable crashed : exn option;            (* what a caller's on_event raised *)
  lock : Mutex.t;
  done_ : Condition.t;                     (* the run is over *)
}

type task_result =
  { name : string; task_outcome : Outcome.t; fuel_used : int; module_data : (string * string * Value.t) list }
type result = { outcome : Outcome.t; tasks : task_result list }

(* A thread's stack is the C library's default: the soft limit when there is one (glibc), 2 MB
   on x86-64 when it is unlimited (Native_stack reports 1 GB then); at most 8 MB counted. *)
let thread_budget () =
  let limit = Native_stack.native_stack_bytes () in
  let stack = if limit >= 1024 * 1024 * 1024 then 2 * 1024 * 1024 else min limit (8 * 1024 * 1024) in
  min (Native_stack.budget ()) (stack / Native_stack.bytes_per_nest)

let start ?limits ?stub_unmodelled ?seed (loaded : Task_rules.task list) (links : Task_rules.link list) =
  match loaded with
  | [] -> Error "no task to run"
  | first :: _ ->
      (* Each task's start takes its first statement's time on the one clock, in the order of
         the tasks, as the machine's start settles into it: when the entry routine's data has no
         initial value to compute and its body a statement (doc/semantics.md, "Settling"). *)
      let take_entry (l : Task_rules.task) =
        match Task_rules.entry_routine l.program (Task_rules.first_routine l) with
        | Error _ -> false
        | Ok k ->
            let r = l.program.routines.(k) in
            let quiet = List.for_all (function (_, Ir.Init_default _) -> true | _ -> false) r.local_inits in
            if quiet && Array.length r.body.body > 0 then (l.host.statement (); true) else false in
      let tasks = Array.of_list (List.map (fun (l : Task_rules.task) ->
          let entry_taken = take_entry l in
          { name = l.name; program = l.program; entry = l.entry; before = l.before; after = l.after; host = l.host;
            entry_taken;
            globals = [||]; links = []; reply = None; command = None; idle = false; wake = None; what = None;
            finished = None; fuel_used = 0; thread = None; wakeup = Condition.create () }) loaded) in
      let objects = Hashtbl.create 64 in
      let shared = ref [] in
      let object_of k j =
        match Hashtbl.find_opt objects (k, j) with
        | Some n -> n
        | None ->
            let n = Hashtbl.length objects in
            Hashtbl.replace objects (k, j) n;
            let v = match Task_rules.initial_value tasks.(k).program j with
              | Some v -> Value.copy v | None -> Value.Bool false in
            shared := v :: !shared;
            tasks.(k).links <- (j, n) :: tasks.(k).links;
            n in
      List.iter (fun (l : Task_rules.link) ->
          let n = object_of l.owner l.owner_slot in
          tasks.(l.task).links <- (l.slot, n) :: tasks.(l.task).links) links;
      let limits = Limits.for_tasks (Option.value limits ~default:Limits.default) ~count:(Array.length tasks) in
      Ok { members = tasks; shared = Array.of_list (List.rev !shared); order = Task_rules.order_of_seed seed;
           cursor = ref 0; ended = None; cut = false; aborting = false; ran = false; limits; stub_unmodelled;
           clock = first.host; over = false; crashed = None; lock = Mutex.create (); done_ = Condition.create () }

(* The shared data objects: a task's slots hold the same values as the others' while it runs
   (only one runs at a time); a value written whole is taken over when the turn passes. *)
let publish t task = List.iter (fun (slot, n) -> t.shared.(n) <- task.globals.(slot)) task.links
let take_over t task = List.iter (fun (slot, n) -> task.globals.(slot) <- t.shared.(n)) task.links

let running task = task.finished = None

let same_rules_choose t =
  Task_rules.next_turn t.order ~cursor:t.cursor ~count:(Array.length t.members)
    (fun k -> running t.members.(k) && not t.members.(k).idle)
  |> Option.map (fun k -> t.members.(k))

(* Every running task waits: Task_set's rule. *)
let all_wait t =
  let waits =
    Array.to_list t.members |> List.filter running
    |> List.map (fun (task : task) -> (task.name, task.what, task.wake)) in
  match Task_rules.every_task_waits t.clock waits with
  | Some ended -> t.ended <- Some ended
  | None -> Array.iter (fun task -> task.idle <- false) t.members

let wake_all t = Array.iter (fun task -> task.idle <- false) t.members

(* The scheduler, run by the thread whose turn just ended (under the lock): the turn's end as
   Task_set.step counts it, then the next task's turn, or the end of the run. A turn passes
   straight from one task's thread to the next's. *)
let rec pick t =
  if t.ended <> None || t.cut || t.crashed <> None || not (Array.exists running t.members) then begin
    t.over <- true; Condition.signal t.done_
  end
  else
    match same_rules_choose t with
    | Some next -> next.command <- Some Go; Condition.signal next.wakeup
    | None -> all_wait t; pick t

let turn_ended t task reply =
  (match reply with
   | Boundary -> wake_all t
   | Yielded { wake; what; pure } ->
       if not pure then wake_all t;
       task.idle <- true; task.wake <- wake; task.what <- Some what
   | Finished (Ok r) ->
       wake_all t;
       task.finished <- Some r; task.fuel_used <- r.fuel_used;
       if r.outcome = Outcome.Running then t.cut <- true
   | Finished (Error m) ->
       wake_all t;
       task.finished <- Some { C.outcome = Outcome.Stuck m; fuel_used = 0 }
   | Crashed e -> t.crashed <- Some e; task.finished <- Some { C.outcome = Outcome.Running; fuel_used = 0 });
  pick t

(* On the task's thread (lock held): wait for its turn. *)
let await t task =
  while task.command = None do Condition.wait task.wakeup t.lock done;
  let command = task.command in
  task.command <- None;
  command

(* On the task's thread: the turn passes on until it comes back. *)
let hand_over t task reply =
  if t.aborting then raise Aborted;
  publish t task;
  Mutex.lock t.lock;
  let command =
    match turn_ended t task reply; await t task with
    | command -> Mutex.unlock t.lock; command
    | exception e ->
        (* Not part of the semantics (the hand-off failed): the run ends, and says so. *)
        t.crashed <- Some e; t.over <- true; Condition.signal t.done_; Mutex.unlock t.lock;
        raise Aborted in
  match command with
  | Some Go -> take_over t task
  | _ -> raise Aborted

let body t task ~limits ~fuel ~stub_unmodelled ~all_events ~observe ~on_event () =
  Mutex.lock t.lock;
  let command = await t task in
  Mutex.unlock t.lock;
  let reply =
    if command <> Some Go then Finished (Error "not run")
    else
      let cooperation = {
        C.share = (fun globals -> task.globals <- globals; take_over t task);
        entered = not task.entry_taken;
        turn = (fun () -> hand_over t task Boundary);
        yield = (fun ~wake ~what ~pure -> hand_over t task (Yielded { wake; what; pure }));
        native_budget = thread_budget () } in
      let on_event e = if not t.aborting then on_event task.name e in
      match C.run ~limits ~fuel ?stub_unmodelled ~all_events ~observe ~on_event ~before:task.before
              ~after:task.after ~host:task.host ~cooperation task.program ~entry:task.entry with
      | r -> if task.globals <> [||] then publish t task; Finished r
      | exception e -> Crashed e
  in
  Mutex.lock t.lock;
  (match reply with
   | Finished (Ok r) when t.aborting -> task.fuel_used <- r.fuel_used
   | _ when t.aborting -> ()
   | reply -> turn_ended t task reply);
  Mutex.unlock t.lock

let run ?(fuel = C.default_fuel) ?(all_events = true) ?(observe = false) ?(on_event = fun _ _ -> ()) t =
  let limits = t.limits and stub_unmodelled = t.stub_unmodelled in
  if t.ran then invalid_arg "Closure_tasks.run: the tasks ran already";
  t.ran <- true;
  Array.iter (fun task ->
      task.thread <-
        Some (Thread.create (body t task ~limits ~fuel ~stub_unmodelled ~all_events ~observe ~on_event) ()))
    t.members;
  Mutex.lock t.lock;
  pick t;
  while not t.over do Condition.wait t.done_ t.lock done;
  (* The tasks the run's end caught still running unwind (their events no longer count). *)
  t.aborting <- true;
  Array.iter (fun task -> if running task then (task.command <- Some Abort; Condition.signal task.wakeup)) t.members;
  Mutex.unlock t.lock;
  Array.iter (fun task -> Option.iter Thread.join task.thread) t.members;
  Option.iter raise t.crashed;
  let task_outcome (task : task) =
    match task.finished, t.ended with
    | Some r, _ -> r.C.outcome
    | None, Some (Outcome.Deadlock _) ->
        Outcome.Deadlock (Printf.sprintf "deadlock at %g s: the task waits for %s, \
                                          and no task or event can end the wait"
                      (t.clock.now ()) (Option.value task.what ~default:"a wait"))
    | None, Some o -> o
    | None, None -> Outcome.Running in
  let outcome =
    match t.ended with
    | Some o -> o
    | None -> (
        match Array.to_list t.members |> List.map task_outcome |> List.find_opt (fun o -> o <> Outcome.Ended) with
        | Some o -> o
        | None -> Outcome.Ended) in
  { outcome;
    tasks = Array.to_list (Array.map (fun (task : task) ->
        { name = task.name; task_outcome = task_outcome task;
          fuel_used = task.fuel_used;
          module_data = Array.to_list (Array.mapi (fun i (g : Ir.global) ->
              (g.g_module, g.g_name, if i < Array.length task.globals then task.globals.(i) else Value.Bool false))
              task.program.globals) }) t.members) }

let names t = Array.to_list (Array.map (fun (task : task) -> task.name) t.members)

let clock t = t.clock
