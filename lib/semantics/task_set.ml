(* Several tasks on one clock (ch. 14; doc/semantics.md, "Several tasks"). Each task is a
   machine of its own, cooperative: a wait with nothing to do yields. The scheduler gives turns
   of one statement: a turn runs a task's steps until the next statement is in focus, the task
   yields or ends. When every running task waits, the clock jumps to the earliest time one of
   them gave; with none, nothing can ever end the waits: a deadlock. *)

module M = Machine

type task = { t_name : string; cfg : M.config; mutable idle : bool }

type t = {
  tasks : task array;
  order : Task_rules.order;
  cursor : int ref;                     (* round robin: the next task to look at *)
  mutable current : task option;        (* the task whose turn it is *)
  mutable turn_steps : int;
  mutable ended : M.outcome option;     (* a deadlock or the time limit of the whole run *)
  clock : Host.t;                       (* the first task's: the clock is everyone's *)
  links : Task_rules.link list;         (* the shared data objects *)
  limits : Limits.t;                    (* each task's: its share of the run's memory budget *)
}

let start ?limits ?(stub_unmodelled = false) ?(observe = false) ?seed (tasks : Task_rules.task list)
    (links : Task_rules.link list) =
  let limits = Limits.for_tasks (Option.value limits ~default:Limits.default) ~count:(List.length tasks) in
  let rec start_all acc = function
    | [] -> Ok (List.rev acc)
    | (task : Task_rules.task) :: rest -> (
        match M.start ~limits ~stub_unmodelled ~cooperative:true ~observe ~before:task.before ~after:task.after
                ~host:task.host task.program ~entry:task.entry with
        | Error m -> Error (Printf.sprintf "task %s: %s" task.name m)
        | Ok cfg -> start_all ({ t_name = task.name; cfg; idle = false } :: acc) rest)
  in
  match start_all [] tasks, tasks with
  | Error m, _ -> Error m
  | Ok _, [] -> Error "no task to run"
  | Ok started, first :: _ ->
      let tasks = Array.of_list started in
      List.iter (fun (l : Task_rules.link) ->
          M.share_global tasks.(l.task).cfg l.slot ~with_:(tasks.(l.owner).cfg, l.owner_slot)) links;
      Ok { tasks; order = Task_rules.order_of_seed seed; cursor = ref 0; current = None; turn_steps = 0;
           ended = None; clock = first.host; links; limits }

let running task = M.outcome task.cfg = Outcome.Running
let limits t = t.limits

(* The next task to take a turn, among the running tasks that do not wait in vain. *)
let choose s =
  Task_rules.next_turn s.order ~cursor:s.cursor ~count:(Array.length s.tasks)
    (fun k -> running s.tasks.(k) && not s.tasks.(k).idle)
  |> Option.map (fun k -> s.tasks.(k))

let all_wait s =
  let waits = Array.to_list s.tasks |> List.filter running
              |> List.map (fun t -> (t.t_name, M.waiting_for t.cfg, M.wake_time t.cfg)) in
  match Task_rules.every_task_waits s.clock waits with
  | Some ended -> s.ended <- Some ended
  | None -> Array.iter (fun t -> t.idle <- false) s.tasks

(* The task whose turn it is, chosen now if none is: the clock moves on when every task waits. *)
let rec next s =
  if s.ended <> None then None
  else
    match s.current with
    | Some task -> Some (task.t_name, task.cfg)
    | None ->
        if not (Array.exists running s.tasks) then None
        else (
          match choose s with
          | Some task -> s.current <- Some task; s.turn_steps <- 0; Some (task.t_name, task.cfg)
          | None -> all_wait s; next s)

let step s =
  match next s with
  | None -> None
  | Some _ ->
    match s.current with
    | None -> None
    | Some task ->
        let rule, events = M.step_rule task.cfg in
        s.turn_steps <- s.turn_steps + 1;
        if rule = Rule.Wait_yield then (task.idle <- true; s.current <- None)
        else begin
          Array.iter (fun t -> t.idle <- false) s.tasks;
          (* R-14-o: a new round of a loop without a statement ends the turn too, so that every
             turn ends (a loop waiting for another task with an empty body lets it run). *)
          if not (running task) || M.pointer_statement task.cfg <> None
             || ((rule = Rule.While_again || rule = Rule.For_step) && M.empty_loop_round task.cfg) then
            s.current <- None
        end;
        Some (task.t_name, Rule.name rule, events)

let tasks s = Array.to_list (Array.map (fun t -> (t.t_name, t.cfg)) s.tasks)

let steps s = Array.fold_left (fun n t -> n + M.steps t.cfg) 0 s.tasks

(* The run's outcome: the scheduler's (a deadlock, the time limit), else the first task's, in
   the order of the tasks, that did not end normally, else Ended. *)
let outcome s =
  match s.ended with
  | Some o -> o
  | None -> (
      match Array.to_list s.tasks |> List.map (fun t -> M.outcome t.cfg)
            |> List.find_opt (fun o -> o <> Outcome.Ended) with
      | Some o -> o
      | None -> Outcome.Ended)

let clock s = s.clock

(* A task the scheduler's end of the run caught still running has no end of its own: in a
   deadlock it is deadlocked, waiting for what it waits for; at the time limit of the whole run,
   cut by it. Only the step limit leaves it running (doc/trace-format.md, task-end). *)
let task_outcome s cfg =
  match M.outcome cfg, s.ended with
  | Outcome.Running, Some (Outcome.Deadlock _) ->
      Outcome.Deadlock (Printf.sprintf "deadlock at %g s: the task waits for %s, and no task or event can end the wait"
                    (s.clock.now ()) (Option.value (M.waiting_for cfg) ~default:"a wait"))
  | Outcome.Running, Some o -> o
  | o, _ -> o
