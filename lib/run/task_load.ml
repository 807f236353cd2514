(* Several tasks loaded for one run (ch. 14; doc/semantics.md, "Several tasks"): each task
   buffer read, checked and lowered as one task's; the worlds of the tasks share the clock, the
   signals and the services; the data objects they share found, and the initial values those
   take. Neutral: both engines' task sets start from what this gives. *)

open Rapid_syntax
module Session = Rapid_load.Session
module W = Rapid_controller.World

type spec = { name : string; files : string list; entry : string }

type failure =
  | Load of string * Session.failure
  | Refused of string

type task = {
  rules : Task_rules.task;
  world : Rapid_controller.World.t;
  motion : Rapid_installed.Motion_routines.state;
}

type loaded = {
  tasks : task list; links : Task_rules.link list; warnings : Rapid_typing.Report.t list; notes : string list;
}

type event_routine = Rapid_load.Backup.event_routine

let same a b = String.lowercase_ascii a = String.lowercase_ascii b

(* R-bk-9: ABB allows no motion instruction in a STOP or QSTOP event routine. The first move
   instruction the routine calls, directly or through the task's routines, with where. *)
let move_instructions =
  [ "MoveL"; "MoveJ"; "MoveC"; "MoveAbsJ"; "MoveExtJ"; "SearchL"; "SearchC"; "SearchExtJ"; "TriggL"; "TriggJ";
    "TriggC"; "MoveLDO"; "MoveJDO"; "MoveCDO"; "MoveLSync"; "MoveJSync"; "MoveCSync"; "MoveLAO"; "MoveJAO";
    "MoveCAO"; "MoveLGO"; "MoveJGO"; "MoveCGO" ]

let first_move (program : Ir.program) start =
  let seen = Hashtbl.create 16 in
  let rec routine i =
    if Hashtbl.mem seen i then None
    else begin
      Hashtbl.replace seen i ();
      let r = program.routines.(i) in
      if r.primitive <> None then None
      else
        let blocks = r.body :: List.filter_map Fun.id [ Option.map (fun (h : Ir.error_handler) -> h.handler) r.error;
                                                       r.undo ] in
        List.find_map block blocks
    end
  and block (b : Ir.block) = Array.to_list b.body |> List.find_map stmt
  and stmt (s : Ir.stmt) =
    match s.s with
    | Call_procedure { callee = Routine i; call_at; _ } ->
        let callee = program.routines.(i) in
        if List.exists (same callee.name) move_instructions && callee.primitive <> None then
          Some (callee.name, call_at)
        else routine i
    | If (_, a, b) | Elseif (_, a, b) -> (match block a with Some m -> Some m | None -> block b)
    | Compact_if (_, s) -> stmt s
    | For f -> block f.loop_body
    | While (_, b) -> block b
    | Test (_, cases, default) ->
        (match Array.to_list cases |> List.find_map (fun (_, b) -> block b) with
         | Some m -> Some m
         | None -> block default)
    | _ -> None in
  routine start

(* R-bk-8: the event routines of a task that its buffer has as procedures without parameters;
   each other one is a note, FILE:LINE of its CAB_EXEC_HOOKS instance, and not run. *)
let runnable ~note ~task (program : Ir.program) (routines : event_routine list) =
  List.filter_map (fun (e : event_routine) ->
      match Task_rules.entry_routine program e.routine with
      | Ok i ->
          (if e.event = "STOP" || e.event = "QSTOP" then
             match first_move program i with
             | Some (name, at) ->
                 note (Printf.sprintf "%s: warning: the %s event routine %s of task %s moves the robot (%s at %s): \
                                       ABB allows no motion instruction in STOP and QSTOP event routines; it runs as \
                                       written" e.hook_at e.event e.routine task name (Source.to_string at))
             | None -> ());
          Some e.routine
      | Error _ ->
          let what = if Array.exists (fun (r : Ir.routine) -> same r.name e.routine) program.routines
            then "is not a procedure without parameters" else "is not in the task" in
          note (Printf.sprintf "%s: warning: the event routine %s (%s) %s %s: not run" e.hook_at e.routine e.event what
                  task);
          None) routines

(* ch. 14: the system-global persistents of a task buffer, that is PERS declared neither TASK
   nor LOCAL: module, name, type (its name and dimensions), whether it has an initial value. *)
let system_global_pers (modules : Ast.module_declaration list) =
  List.concat_map (fun (m : Ast.module_declaration) ->
      let module_name = match m.module_name.it with Ident s -> s | ID_placeholder -> "" in
      List.filter_map (fun (d : Ast.data_declaration) ->
          match d.it with
          | Data_declaration { scope = Global; storage = Pers; data_type; name = { it = Ident name; _ }; dims;
                               initial_value } ->
              let type_name = match data_type.it with Ident s -> s | ID_placeholder -> "" in
              Some (module_name, name, type_name, List.length dims, initial_value <> None, d.at)
          | _ -> None) m.data_declarations) modules

(* The first global of [program] declared in [module_name] with [name] (case-insensitive),
   through a table made once per program: a task's 400 and more installed globals were each
   looked up by a scan of the first task's, lowering both names at every step. *)
let key module_name name = String.lowercase_ascii module_name ^ "\000" ^ String.lowercase_ascii name

let global_table (program : Ir.program) =
  let table = Hashtbl.create (2 * Array.length program.globals) in
  Array.iteri (fun i (g : Ir.global) ->
      let k = key g.g_module g.g_name in
      if not (Hashtbl.mem table k) then Hashtbl.replace table k i) program.globals;
  table

let global_index table ~module_name ~name = Hashtbl.find_opt table (key module_name name)

type shared_pers = { owner : int; slot : int; type_text : string; mutable has_init : bool; task_name : string }

(* ch. 14: one value for every task declaring the persistent with the same name and type; the
   initial value of the first declaration (in the order of the tasks) that has one, else the
   type's initial value (R-14-b). A different type is refused (R-14-c). *)
let share_persistents ~link (programs : Ir.program array) (tasks : (int * string * Ast.module_declaration list) list) =
  let table = Hashtbl.create 16 in
  let rec go = function
    | [] -> Ok ()
    | (k, task_name, modules) :: rest ->
        let program = programs.(k) in
        let globals_by_name = lazy (global_table program) in
        let rec each = function
          | [] -> go rest
          | (module_name, name, type_name, ndims, has_init, at) :: more -> (
              match global_index (Lazy.force globals_by_name) ~module_name ~name with
              | None -> each more
              | Some j -> (
                  (* The type: its name and, for an array, the sizes its value has (a dimension
                     may be written as a constant in one task and a literal in another). *)
                  let rec sizes v n = match v, n with
                    | Value.Array es, n when n > 0 ->
                        Array.length es :: (if Array.length es > 0 then sizes es.(0) (n - 1) else [])
                    | _ -> [] in
                  let type_text = match Task_rules.initial_value program j with
                    | Some v when ndims > 0 ->
                        type_name ^ "{" ^ String.concat ", " (List.map string_of_int (sizes v ndims)) ^ "}"
                    | _ -> type_name in
                  let key = String.lowercase_ascii name in
                  match Hashtbl.find_opt table key with
                  | None ->
                      Hashtbl.replace table key { owner = k; slot = j; type_text; has_init; task_name };
                      each more
                  | Some p when not (same p.type_text type_text) ->
                      Error (Load (task_name, Session.Front_end [ Diagnostic.make Semantic_error at (Printf.sprintf
                                        "the persistent %s is %s in task %s but %s here: a system-global persistent \
                                         has one type in every task (ch. 14)"
                                        name p.type_text p.task_name type_text) ]))
                  | Some p ->
                      if has_init && not p.has_init then begin
                        (* The owner takes this task's initial value (a literal expression, §3.3). *)
                        let owner = programs.(p.owner) in
                        let globals = Array.copy owner.globals in
                        globals.(p.slot) <- { globals.(p.slot) with g_init = program.globals.(j).g_init };
                        programs.(p.owner) <- { owner with globals };
                        p.has_init <- true
                      end;
                      link k j (p.owner, p.slot);
                      each more))
        in
        each (system_global_pers modules)
  in
  go tasks

(* ch. 14: an installed data object is one for every task ("所有其他数据对象与其他任务共享值"), except
   ERRNO and INTNO, whose values are each task's (R-14-g). Installed: a global of a module that
   is not one of the task's own. *)
let share_installed ~link (programs : Ir.program array) (tasks : (int * string * Ast.module_declaration list) list) =
  match tasks with
  | [] -> ()
  | (first, _, _) :: rest ->
      let first_program = programs.(first) in
      let first_table = global_table first_program in
      List.iter (fun (k, _, modules) ->
          let own = List.filter_map (fun (m : Ast.module_declaration) ->
              match m.module_name.it with
              | Ident s -> Some (String.lowercase_ascii s)
              | ID_placeholder -> None) modules in
          let program = programs.(k) in
          Array.iteri (fun i (g : Ir.global) ->
              if i <> program.errno && i <> program.intno && not (List.mem (String.lowercase_ascii g.g_module) own) then
                match global_index first_table ~module_name:g.g_module ~name:g.g_name with
                | Some j when j <> first_program.errno && j <> first_program.intno -> link k i (first, j)
                | _ -> ()) program.globals) rest

let parse_all ~robotware files =
  let options = { Parse.default_options with robotware } in
  let parsed = List.map (Parse.parse_file ~options) files in
  match List.filter_map (function Error d -> Some d | Ok _ -> None) parsed with
  | [] -> Ok (List.filter_map Result.to_option parsed)
  | errors -> Error (Session.Front_end errors)

let same = Rapid_typing.Types.same_name

let load ?(allow_unknown = false) ?(robotware = Rapid_syntax.Robotware.default) ?io ?motion_task ?(robots = [])
    ?(connected = []) ?(events = []) ~world ~motion (specs : spec list) =
  let notes = ref [] in
  let note n = notes := n :: !notes in
  (* R-14-taskid: every task has each program task's predefined taskid variable. *)
  let io = Some { (Option.value io ~default:Rapid_controller.Io_config.empty) with
                  task_ids = List.map (fun (s : spec) -> s.name) specs } in
  let motion_name = match motion_task, specs with
    | Some n, _ -> n | None, s :: _ -> s.name | None, [] -> "" in
  let rec load acc = function
    | [] -> Ok (List.rev acc)
    | (s : spec) :: rest -> (
        match parse_all ~robotware s.files with
        | Error f -> Error (Load (s.name, f))
        | Ok modules -> (
            match Session.load_modules ~allow_unknown ?io modules with
            | Error f -> Error (Load (s.name, f))
            | Ok loaded -> load ((s, modules, loaded) :: acc) rest))
  in
  let count = List.length specs in
  if specs = [] then Error (Refused "no task to run")
  else if count > Task_rules.max_tasks then
    Error (Refused (Printf.sprintf "%d tasks: a run has at most %d tasks, as a controller with Multitasking (ch. 14)"
                      count Task_rules.max_tasks))
  else if not (List.exists (fun (s : spec) -> same s.name motion_name) specs) then
    Error (Refused (Printf.sprintf "the motion task %s is not one of the tasks" motion_name))
  else
  match load [] specs with
  | Error f -> Error f
  | Ok loaded -> (
      match List.find_map (fun ((s : spec), _, (l : Session.loaded)) ->
          match Task_rules.entry_routine l.program s.entry with
          | Error m -> Some (Printf.sprintf "task %s: %s" s.name m)
          | Ok _ -> None) loaded with
      | Some m -> Error (Refused m)
      | None ->
          let programs = Array.of_list (List.map (fun (_, _, (l : Session.loaded)) -> l.program) loaded) in
          let indexed = List.mapi (fun k ((s : spec), modules, _) -> (k, s.name, modules)) loaded in
          let links = ref [] in
          let link task slot (owner, owner_slot) = links := { Task_rules.task; slot; owner; owner_slot } :: !links in
          share_installed ~link programs indexed;
          match share_persistents ~link programs indexed with
          | Error f -> Error f
          | Ok () ->
              let tasks = List.mapi (fun k ((s : spec), _, _) ->
                  (* MultiMove (R-bk-4): besides the run's motion task, each task of [robots]
                     has a robot of its own. *)
                  let own = List.find_opt (fun (n, _) -> same n s.name) robots in
                  let is_motion = same s.name motion_name || own <> None in
                  let w = if k = 0 then (W.name_task world ~name:s.name ~motion:is_motion; world)
                    else W.add_task world ~name:s.name ~motion:is_motion in
                  let motion = if same s.name motion_name then motion
                    else match own with Some (_, m) -> m | None -> Rapid_installed.Motion_routines.create () in
                  let host = Rapid_installed.World_host.make w motion in
                  let before, after = match List.find_opt (fun (n, _) -> same n s.name) events with
                    | Some (_, (b, a)) ->
                        (runnable ~note ~task:s.name programs.(k) b, runnable ~note ~task:s.name programs.(k) a)
                    | None -> ([], []) in
                  { rules = { Task_rules.name = s.name; program = programs.(k); entry = s.entry; host; before; after };
                    world = w; motion }) loaded in
              (* R-14-pos1: the position functions of a task without a robot reach the motion
                 task's by its name, and read it by default (its mechanical unit group's). *)
              let robots = List.filter_map (fun (t : task) ->
                  if W.motion_task t.world then Some (W.task_name t.world, t.motion) else None) tasks in
              (* R-bk-4: the motion task of its mechanical unit group first: the one read by default. *)
              List.iter (fun (t : task) ->
                  if not (W.motion_task t.world) then
                    let name = W.task_name t.world in
                    let first = match List.find_opt (fun (n, _) -> same n name) connected with
                      | Some (_, m) -> List.filter (fun (n, _) -> same n m) robots | None -> [] in
                    Rapid_installed.Motion_routines.connect_robots t.motion
                      (first @ List.filter (fun r -> not (List.memq r first)) robots))
                tasks;
              let warnings = List.concat_map (fun (_, _, (l : Session.loaded)) -> l.warnings) loaded in
              Ok { tasks; links = List.rev !links; warnings; notes = List.rev !notes })
