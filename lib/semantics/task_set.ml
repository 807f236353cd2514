(* Several tasks on one clock (ch. 14; doc/semantics.md, "Several tasks"). Each task is a
   machine of its own, cooperative: a wait with nothing to do yields. The scheduler gives turns
   of one statement: a turn runs a task's steps until the next statement is in focus, the task
   yields or ends. When every running task waits, the clock jumps to the earliest time one of
   them gave; with none, nothing can ever end the waits: a deadlock. *)

open Rapid_syntax
module M = Machine
module W = Rapid_controller.World

type spec = { name : string; files : string list; entry : string }

type task = { t_name : string; cfg : M.config; mutable idle : bool }

type order = Round_robin | Seeded of int64 ref   (* SplitMix64's state *)

let order_of_seed = function Some s -> Seeded (ref (Int64.of_int s)) | None -> Round_robin

type t = {
  tasks : task array;
  order : order;
  cursor : int ref;                     (* round robin: the next task to look at *)
  mutable current : task option;        (* the task whose turn it is *)
  mutable turn_steps : int;
  mutable ended : M.outcome option;     (* a deadlock or the time limit of the whole run *)
  world : W.t;                          (* the first task's: the clock is everyone's *)
  links : (M.config * int * M.config * int) list;  (* the shared data objects (see [shared]) *)
  limits : M.limits;                    (* each task's: its share of the run's memory budget *)
}

type failure =
  | Load of string * Session.failure    (** the task's name and why its buffer was refused *)
  | Refused of string                   (** FILE:LINE:COL: class: message, or a plain message *)

(* SplitMix64 (Steele, Lea, Flood 2014): a small generator of our own, so that the order of a
   seed never depends on the version of OCaml's Random. *)
let splitmix state =
  state := Int64.add !state 0x9E3779B97F4A7C15L;
  let z = !state in
  let z = Int64.mul (Int64.logxor z (Int64.shift_right_logical z 30)) 0xBF58476D1CE4E5B9L in
  let z = Int64.mul (Int64.logxor z (Int64.shift_right_logical z 27)) 0x94D049BB133111EBL in
  Int64.logxor z (Int64.shift_right_logical z 31)

let same a b = String.lowercase_ascii a = String.lowercase_ascii b

(* ch. 14: the system-global persistents of a task buffer, that is PERS declared neither TASK
   nor LOCAL: module, name, type (its name and dimensions), whether it has an initial value. *)
let system_global_pers (modules : Ast.module_declaration list) =
  List.concat_map (fun (m : Ast.module_declaration) ->
      let module_name = match m.module_name.it with Ident s -> s | ID_placeholder -> "" in
      List.filter_map (fun (d : Ast.data_declaration) ->
          match d.it with
          | Data_declaration { scope = Global; storage = Pers; data_type; name = { it = Ident name; _ }; dims; initial_value } ->
              let type_name = match data_type.it with Ident s -> s | ID_placeholder -> "" in
              Some (module_name, name, type_name, List.length dims, initial_value <> None, d.at)
          | _ -> None) m.data_declarations) modules

let global_index (program : Ir.program) ~module_name ~name =
  let found = ref None in
  Array.iteri (fun i (g : Ir.global) ->
      if !found = None && same g.g_module module_name && same g.g_name name then found := Some i)
    program.globals;
  !found

type shared_pers = { owner : M.config; slot : int; type_text : string; mutable has_init : bool; task_name : string }

(* ch. 14: one value for every task declaring the persistent with the same name and type; the
   initial value of the first declaration (in the order of the tasks) that has one, else the
   type's initial value (R-14-b). A different type is refused (R-14-c). *)
let share_persistents ~link (tasks : (string * M.config * Ast.module_declaration list) list) =
  let table = Hashtbl.create 16 in
  let rec go = function
    | [] -> Ok ()
    | (task_name, cfg, modules) :: rest ->
        let program = M.program cfg in
        let rec each = function
          | [] -> go rest
          | (module_name, name, type_name, ndims, has_init, at) :: more -> (
              match global_index program ~module_name ~name with
              | None -> each more
              | Some j -> (
                  (* The type: its name and, for an array, the sizes its value has (a dimension
                     may be written as a constant in one task and a literal in another). *)
                  let rec sizes v n = match v, n with
                    | Value.Array es, n when n > 0 ->
                        Array.length es :: (if Array.length es > 0 then sizes es.(0) (n - 1) else [])
                    | _ -> [] in
                  let type_text = match M.read_data cfg (Ir.Global j) with
                    | Some v when ndims > 0 ->
                        type_name ^ "{" ^ String.concat ", " (List.map string_of_int (sizes v ndims)) ^ "}"
                    | _ -> type_name in
                  let key = String.lowercase_ascii name in
                  match Hashtbl.find_opt table key with
                  | None ->
                      Hashtbl.replace table key { owner = cfg; slot = j; type_text; has_init; task_name };
                      each more
                  | Some p when not (same p.type_text type_text) ->
                      Error (Load (task_name, Session.Front_end [ Diagnostic.make Semantic_error at (Printf.sprintf
                                        "the persistent %s is %s in task %s but %s here: a system-global persistent has one type in every task (ch. 14)"
                                        name p.type_text p.task_name type_text) ]))
                  | Some p ->
                      if has_init && not p.has_init then begin
                        (match M.read_data cfg (Ir.Global j) with
                         | Some v -> ignore (M.write_data p.owner (Ir.Global p.slot) v)
                         | None -> ());
                        p.has_init <- true
                      end;
                      link cfg j (p.owner, p.slot);
                      each more))
        in
        each (system_global_pers modules)
  in
  go tasks

(* ch. 14: an installed data object is one for every task ("所有其他数据对象与其他任务共享值"), except
   ERRNO and INTNO, whose values are each task's (R-14-g). Installed: a global of a module that
   is not one of the task's own. *)
let share_installed ~link (tasks : (string * M.config * Ast.module_declaration list) list) =
  match tasks with
  | [] -> ()
  | (_, first, _) :: rest ->
      let first_program = M.program first in
      List.iter (fun (_, cfg, modules) ->
          let own = List.filter_map (fun (m : Ast.module_declaration) ->
              match m.module_name.it with Ident s -> Some (String.lowercase_ascii s) | ID_placeholder -> None) modules in
          let program = M.program cfg in
          Array.iteri (fun i (g : Ir.global) ->
              if i <> program.errno && i <> program.intno && not (List.mem (String.lowercase_ascii g.g_module) own) then
                match global_index first_program ~module_name:g.g_module ~name:g.g_name with
                | Some j when j <> first_program.errno && j <> first_program.intno -> link cfg i (first, j)
                | _ -> ()) program.globals) rest

let parse_all files =
  let parsed = List.map (Parse.parse_file ~options:Parse.default_options) files in
  match List.filter_map (function Error d -> Some d | Ok _ -> None) parsed with
  | [] -> Ok (List.filter_map Result.to_option parsed)
  | errors -> Error (Session.Front_end errors)

(* A controller runs a bounded number of tasks (R-14-cli3); each task's RAPID data counts in the
   one budget of --max-memory, split evenly so that every task has its share whatever the others
   do and whatever the turns: N tasks never hold more than the budget together. *)
let max_tasks = 20

let task_limits (limits : M.limits) ~count = { limits with max_memory = limits.max_memory / max 1 count }

let start ?limits ?(stub_unmodelled = false) ?(allow_unknown = false) ?(observe = false) ?io ?seed ?motion_task ~world
    ~motion (specs : spec list) =
  let motion_name = match motion_task, specs with
    | Some n, _ -> n | None, s :: _ -> s.name | None, [] -> "" in
  let rec load acc = function
    | [] -> Ok (List.rev acc)
    | (s : spec) :: rest -> (
        match parse_all s.files with
        | Error f -> Error (Load (s.name, f))
        | Ok modules -> (
            match Session.load_modules ~allow_unknown ?io modules with
            | Error f -> Error (Load (s.name, f))
            | Ok loaded -> load ((s, modules, loaded) :: acc) rest))
  in
  let count = List.length specs in
  let limits = task_limits (Option.value limits ~default:M.default_limits) ~count in
  if specs = [] then Error (Refused "no task to run")
  else if count > max_tasks then
    Error (Refused (Printf.sprintf "%d tasks: a run has at most %d tasks, as a controller with Multitasking (ch. 14)"
                      count max_tasks))
  else if not (List.exists (fun (s : spec) -> same s.name motion_name) specs) then
    Error (Refused (Printf.sprintf "the motion task %s is not one of the tasks" motion_name))
  else
  match load [] specs with
  | Error f -> Error f
  | Ok loaded ->
      let rec start_all acc first = function
        | [] -> Ok (List.rev acc)
        | ((s : spec), modules, (l : Session.loaded)) :: rest -> (
            let is_motion = same s.name motion_name in
            let w = if first then (W.name_task world ~name:s.name ~motion:is_motion; world)
              else W.add_task world ~name:s.name ~motion:is_motion in
            let motion = if is_motion then motion else Motion_primitives.create () in
            match M.start ~limits ~world:w ~stub_unmodelled ~motion ~cooperative:true ~observe l.program
                    ~entry:s.entry with
            | Error m -> Error (Refused (Printf.sprintf "task %s: %s" s.name m))
            | Ok cfg -> start_all ((s.name, cfg, modules, l) :: acc) false rest)
      in
      match start_all [] true loaded with
      | Error f -> Error f
      | Ok started -> (
          let triples = List.map (fun (n, c, m, _) -> (n, c, m)) started in
          let links = ref [] in
          let link cfg i (owner, j) = M.share_global cfg i ~with_:(owner, j); links := (cfg, i, owner, j) :: !links in
          share_installed ~link triples;
          match share_persistents ~link triples with
          | Error f -> Error f
          | Ok () ->
              let tasks = Array.of_list (List.map (fun (n, cfg, _, _) -> { t_name = n; cfg; idle = false }) started) in
              let order = order_of_seed seed in
              let warnings = List.concat_map (fun (_, _, _, (l : Session.loaded)) -> l.warnings) started in
              Ok ({ tasks; order; cursor = ref 0; current = None; turn_steps = 0; ended = None; world;
                    links = List.rev !links; limits }, warnings))

let running task = M.outcome task.cfg = M.Running
let limits t = t.limits

(* The scheduler's rule, for both engines' task sets: among the [count] tasks, those [eligible]
   (running, not waiting in vain), the next in round robin from [cursor], or SplitMix64's pick. *)
let next_turn order ~cursor ~count eligible =
  let candidates = List.filter eligible (List.init count Fun.id) in
  match candidates, order with
  | [], _ -> None
  | _, Round_robin ->
      let rec look i = if List.mem (i mod count) candidates then i mod count else look (i + 1) in
      let k = look !cursor in
      cursor := (k + 1) mod count; Some k
  | _, Seeded state ->
      let r = Int64.unsigned_rem (splitmix state) (Int64.of_int (List.length candidates)) in
      Some (List.nth candidates (Int64.to_int r))

(* The next task to take a turn, among the running tasks that do not wait in vain. *)
let choose s =
  next_turn s.order ~cursor:s.cursor ~count:(Array.length s.tasks) (fun k -> running s.tasks.(k) && not s.tasks.(k).idle)
  |> Option.map (fun k -> s.tasks.(k))

(* Every running task waits (ch. 14, one clock): [waits] gives each running task's name, what it
   waits for, and the time its wait gave. The clock moves on to the earliest such time ([None]);
   with none, a deadlock; beyond --max-time, the time limit. For both engines' task sets. *)
let every_task_waits world waits =
  let times = List.filter_map (fun (_, _, wake) -> wake) waits in
  match List.sort compare times with
  | [] ->
      let waiting = List.map (fun (name, what, _) ->
          match what with Some what -> name ^ " for " ^ what | None -> name) waits in
      Some (M.Deadlock (Printf.sprintf
                          "deadlock at %g s: every task waits (%s), and nothing can end the waits (no stimulus event left, no interrupt to come)"
                          (W.now world) (String.concat "; " waiting)))
  | t :: _ when t > W.max_time world ->
      Some (M.Resource_exhausted
              (Printf.sprintf "virtual time beyond %g s (the --max-time limit)" (W.max_time world), None))
  | t :: _ -> W.advance_to world t; None

let all_wait s =
  let waits = Array.to_list s.tasks |> List.filter running
              |> List.map (fun t -> (t.t_name, M.waiting_for t.cfg, M.wake_time t.cfg)) in
  match every_task_waits s.world waits with
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
        let rule, events = M.step task.cfg in
        s.turn_steps <- s.turn_steps + 1;
        if rule = "wait-yield" then (task.idle <- true; s.current <- None)
        else begin
          Array.iter (fun t -> t.idle <- false) s.tasks;
          (* R-14-o: a new round of a loop without a statement ends the turn too, so that every
             turn ends (a loop waiting for another task with an empty body lets it run). *)
          if not (running task) || M.pointer_statement task.cfg <> None
             || ((rule = "while-again" || rule = "for-step") && M.empty_loop_round task.cfg) then
            s.current <- None
        end;
        Some (task.t_name, rule, events)

let tasks s = Array.to_list (Array.map (fun t -> (t.t_name, t.cfg)) s.tasks)

let steps s = Array.fold_left (fun n t -> n + M.steps t.cfg) 0 s.tasks

(* The run's outcome: the scheduler's (a deadlock, the time limit), else the first task's, in
   the order of the tasks, that did not end normally, else Ended. *)
let outcome s =
  match s.ended with
  | Some o -> o
  | None -> (
      match Array.to_list s.tasks |> List.map (fun t -> M.outcome t.cfg)
            |> List.find_opt (fun o -> o <> M.Ended) with
      | Some o -> o
      | None -> M.Ended)

let world s = s.world

let shared s =
  let index cfg =
    let rec go k = if s.tasks.(k).cfg == cfg then k else go (k + 1) in
    go 0 in
  List.map (fun (cfg, i, owner, j) -> (index cfg, i, index owner, j)) s.links

(* A task the scheduler's end of the run caught still running has no end of its own: in a
   deadlock it is deadlocked, waiting for what it waits for; at the time limit of the whole run,
   cut by it. Only the step limit leaves it running (doc/trace-format.md, task-end). *)
let task_outcome s cfg =
  match M.outcome cfg, s.ended with
  | M.Running, Some (M.Deadlock _) ->
      M.Deadlock (Printf.sprintf "deadlock at %g s: the task waits for %s, and no task or event can end the wait"
                    (W.now s.world) (Option.value (M.waiting_for cfg) ~default:"a wait"))
  | M.Running, Some o -> o
  | o, _ -> o
