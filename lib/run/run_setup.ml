module W = Rapid_controller.World
module Io = Rapid_controller.Io_config
module MR = Rapid_installed.Motion_routines
module Robot = Rapid_motion_model.Robot

type notice =
  | Inferred_signal of Io.signal * Rapid_syntax.Source.region
  | Warnings of Rapid_typing.Report.t list * string option
  | Stdin_not_saved
  | Samples_capped of int
  | Backup_warning of string

type failure =
  | Usage of string
  | Refused of Rapid_load.Session.failure
  | Task_refused of string * Rapid_load.Session.failure
  | Tasks_refused of string
  | Cannot_start of { entry : string; reason : string }
  | Save_failed of string

let read_io = function
  | None -> Ok Io.empty
  | Some file -> Io.read_file file

(* The I/O configuration of a run, with its backup's mechanical units (R-bk-13). *)
let run_io (o : Run_options.t) =
  Result.map (fun (io : Io.t) -> { io with mechanical_units = o.controller.units }) (read_io o.controller.io)

let load_robot = function
  | None -> Ok Robot.irb120
  | Some name ->
      (* a file's errors name their place in it; a name the library does not know is an error of
         the command line, said as the command line's others are *)
      let from_file = Sys.file_exists name && not (Sys.is_directory name) in
      Rapid_motion_model.Robot_library.load name
      |> Result.map_error (fun m -> if from_file then m else "rapid-sem: " ^ m)

(* --base-frame [TASK=]X,Y,Z,Q1,Q2,Q3,Q4 (R-bk-12): each read, the task it names (None: the run's
   robot). A TASK= form is one with a name before '=' (a pose has none). *)
let parse_base_frames texts =
  List.fold_right (fun text acc ->
      Result.bind acc (fun l ->
          let task, pose = match String.index_opt text '=' with
            | Some i -> (Some (String.trim (String.sub text 0 i)), String.sub text (i + 1) (String.length text - i - 1))
            | None -> (None, text) in
          match task, Rapid_motion_model.Base_frame.of_text pose with
          | Some "", _ -> Error (Printf.sprintf "rapid-sem: --base-frame %s: expected TASK=X,Y,Z,Q1,Q2,Q3,Q4" text)
          | _, Error m -> Error (Printf.sprintf "rapid-sem: --base-frame %s: %s" text m)
          | _, Ok b -> Ok ((task, b) :: l))) texts (Ok [])

let base_frames (o : Run_options.t) = parse_base_frames o.base_frames

(* The last --base-frame for this task ([None]: the run's robot, without TASK=). *)
let base_frame_for frames task =
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  List.fold_left (fun acc (t, b) -> match t, task with
      | None, None -> Some b
      | Some t, Some n when same t n -> Some b
      | _ -> acc) None frames

let placed robot = function None -> robot | Some b -> { robot with Robot.base_frame = b }

(* A backup's robot (--robot's arm at the cell's base frame, Backup_setup.input), or --robot's,
   at the base frame of --base-frame without TASK= when one is given; one task runs here, so a
   TASK= form is refused. *)
let robot_of ?robot (o : Run_options.t) =
  Result.bind (base_frames o) (fun frames ->
      if List.exists (fun (t, _) -> t <> None) frames then
        Error "rapid-sem: --base-frame TASK=...: this run has one task: --base-frame X,Y,Z,Q1,Q2,Q3,Q4 places its robot"
      else
        let b = base_frame_for frames None in
        match robot with
        | Some r -> Ok (placed r b)
        | None -> Result.map (fun r -> placed r b) (load_robot o.robot))

let install_services (s : Run_options.services) world =
  let module K = Rapid_controller.Sockets in
  let all parse items = List.fold_left (fun acc s -> match acc, parse s with
      | Ok l, Ok x -> Ok (l @ x) | (Error _ as e), _ -> e | _, Error e -> Error e) (Ok []) items in
  match all K.parse_allowed s.net, all K.parse_mapping s.map_address with
  | Error e, _ -> Error ("--net " ^ e)
  | _, Error e -> Error ("--map-address " ^ e)
  | _ when Result.is_error (all Rapid_controller.Egm_channel.parse_devices s.egm_device) ->
      Result.fold ~ok:(fun _ -> Ok ()) ~error:(fun e -> Error ("--egm-device " ^ e))
        (all Rapid_controller.Egm_channel.parse_devices s.egm_device)
  | _ when Option.fold ~none:false ~some:(fun q -> q < 0) s.fs_quota -> Error "--fs-quota: a number of bytes, 0 or more"
  | Ok allowed, Ok mapping ->
      match Option.map Rapid_controller.Operator_script.of_file s.operator with
      | Some (Error m) -> Error ("--operator " ^ m)
      | (None | Some (Ok _)) as operator ->
      let operator = Option.map Result.get_ok operator in
      let root = Option.value s.fs ~default:Rapid_controller.File_sandbox.default_root in
      let egm_devices = Result.value (all Rapid_controller.Egm_channel.parse_devices s.egm_device) ~default:[] in
      W.set_services world
        (Rapid_controller.Services.create ~sandbox:(Rapid_controller.File_sandbox.create root)
           ?max_total_size:s.fs_quota ~sockets:(K.create ~allowed ~mapping ()) ~egm_devices ?operator ());
      Ok ()

let machine_gc () = Gc.set { (Gc.get ()) with space_overhead = 400 }

let entry (t : Run_options.tasks) =
  if t.files = [] then Error (Usage "rapid-sem: required argument FILE is missing (or give --task NAME=FILE)")
  else if t.schedule <> None || t.motion_task <> None then
    Error (Usage "rapid-sem: --schedule and --motion-task go with --task")
  else match List.find_opt (fun e -> String.contains e '=') t.entries with
    | Some e -> Error (Usage (Printf.sprintf "rapid-sem: --entry %s: TASK=ROUTINE goes with --task" e))
    | None -> Ok (match List.rev t.entries with e :: _ -> e | [] -> "main")

(* R-13-aa: under --allow-unknown --stub-unmodelled, the undeclared names a program passes as
   signals become virtual signals at 0. *)
let with_inferred_signals ~notify (o : Run_options.t) files io =
  if not (o.allow_unknown && o.stub_unmodelled) then io
  else
    let robotware = Option.value o.controller.robotware ~default:Rapid_syntax.Robotware.default in
    let options = { Rapid_syntax.Parse.default_options with robotware } in
    let modules = List.filter_map (fun f -> Result.to_option (Rapid_syntax.Parse.parse_file ~options f)) files in
    let io, added =
      Rapid_load.Signal_inference.for_run ~allow_unknown:o.allow_unknown ~stub_unmodelled:o.stub_unmodelled
        modules io in
    List.iter (fun (s, at) -> notify (Inferred_signal (s, at))) added;
    io

(* The world of the options' controller, and the robot's motion. *)
let world (o : Run_options.t) ~history io robot =
  let c = o.controller in
  let controller = W.create ~statement_time:c.statement_time ~max_time:c.max_time ~epoch:c.epoch io in
  let history = if history then Some o.limits.max_memory else None in
  let motion = MR.create ~robot ?history () in
  match install_services c.services controller with
  | Error m -> Error (Usage ("rapid-sem: " ^ m))
  | Ok () -> Ok (controller, motion)

type one_task_events = {
  task : string; before : Task_load.event_routine list; after : Task_load.event_routine list;
  debug : Task_load.event_routine list;
}

let no_events = { task = ""; before = []; after = []; debug = [] }

type single = { loaded : Rapid_load.Session.loaded; world : Run.world }

(* The I/O configuration (with the signals --stub-unmodelled infers from the files) and the robot
   of the options, or the backup's robot when --robot does not name one. *)
let io_and_robot ?robot ~notify (o : Run_options.t) files =
  match run_io o, robot_of ?robot o with
  | Error m, _ | _, Error m -> Error (Usage m)
  | Ok io, Ok robot ->
      let io = with_inferred_signals ~notify o files io in
      if o.controller.statement_time < 0. || o.controller.max_time < 0. then
        Error (Usage "rapid-sem: --statement-time and --max-time are not negative")
      else Ok (io, robot)

let single ?(history = false) ?testing ?robot ~notify (o : Run_options.t) files =
  Result.bind (io_and_robot ?robot ~notify o files) (fun (io, robot) ->
      match Rapid_load.Session.load ?robotware:o.controller.robotware ?testing ~allow_unknown:o.allow_unknown ~io files
      with
      | Error f -> Error (Refused f)
      | Ok loaded ->
          notify (Warnings (loaded.warnings, loaded.unknown_summary));
          Result.map (fun (controller, motion) -> { loaded; world = Run.setup ~controller ~motion () })
            (world o ~history io robot))

let fresh_world ?robot ~notify (o : Run_options.t) files =
  Result.bind (io_and_robot ?robot ~notify o files) (fun (io, robot) ->
      Result.map (fun (controller, motion) -> Run.setup ~controller ~motion ()) (world o ~history:false io robot))

(* What a backup gives the controller unless the options do: its EIO.cfg, its RobotWare release
   (R-2.4-rw6); and its mechanical units (R-bk-13), which no option gives. *)
let cell_controller (o : Run_options.t) (c : Backup_setup.cell) =
  let given a b = match a with Some _ -> a | None -> b in
  { o with controller = { o.controller with io = given o.controller.io c.backup.eio;
                                            robotware = given o.controller.robotware c.backup.robotware;
                                            units = c.backup.units } }

let one_task ~notify (o : Run_options.t) files ~entry =
  match Backup_setup.input ~robot:o.robot files with
  | Error m -> Error (Usage m)
  | Ok (Files files) -> Ok (o, files, entry, None, no_events)
  | Ok (Cell c) -> (
      List.iter (fun w -> notify (Backup_warning w)) c.warnings;
      match List.find_opt (fun (t : Rapid_load.Backup.task) -> t.motion) c.backup.tasks with
      | None -> Error (Usage (c.backup.dir ^ ": the backup has no task to run"))
      | Some t ->
          if List.length c.backup.tasks > 1 then
            notify (Backup_warning (Printf.sprintf "%s: warning: this command runs one task: %s, the motion task, \
                                                    alone (the backup's other tasks are not started)" t.at t.name));
          let o = cell_controller o c in
          Ok (o, t.files, (if entry = "main" then t.entry else entry), List.assoc_opt t.name c.robots,
              { task = t.name; before = t.before; after = t.after; debug = t.debug_events }))

let machine ?(observe = false) ?(events = no_events) ?(notify = ignore) (o : Run_options.t) s ~entry =
  (* R-bk-8: a backup's event routines, those the task buffer has. *)
  let note n = notify (Backup_warning n) in
  let before = Task_load.runnable ~note ~task:events.task s.loaded.program events.before
  and after = Task_load.runnable ~note ~task:events.task s.loaded.program events.after in
  Result.map_error (fun reason -> Cannot_start { entry; reason })
    (Rapid_semantics.Machine.start ~limits:o.limits ~host:s.world.host ~stub_unmodelled:o.stub_unmodelled ~observe
       ~before ~after s.loaded.program ~entry)

let start_machine ?observe ?history ?robot ?events ~notify o files ~entry =
  machine_gc ();
  Result.bind (one_task ~notify o files ~entry) (fun (o, files, entry, cell_robot, cell_events) ->
      let robot = match robot with Some _ -> robot | None -> cell_robot in
      let events = match events with Some e -> e | None -> cell_events in
      Result.bind (single ?history ?robot ~notify o files) (fun s ->
          Result.map (fun cfg -> (cfg, s.world)) (machine ?observe ~events ~notify o s ~entry)))

type several = {
  specs : Task_load.spec list;
  names : string list;
  io : Io.t;
  controller : W.t;
  motion : MR.state;
  robots : (string * MR.state) list;
  connected : (string * string) list;
  motion_task : string option;
  summary : Backup_setup.summary option;
  robotware : Rapid_syntax.Robotware.t option;
  events : (string * (Task_load.event_routine list * Task_load.event_routine list)) list;
}

let several ?(history = false) ?cell ~notify (o : Run_options.t) (t : Run_options.tasks) =
  machine_gc ();
  let o = match cell with Some c -> cell_controller o c | None -> o in
  let split s = (String.sub s 0 (String.index s '='),
                 String.sub s (String.index s '=' + 1) (String.length s - String.index s '=' - 1)) in
  let well_formed s = match String.index_opt s '=' with
    | Some i -> i > 0 && i < String.length s - 1
    | None -> false in
  let parse_task s =
    if well_formed s then
      let name, files = split s in
      Ok (name, List.filter (( <> ) "") (String.split_on_char ',' files))
    else Error (Printf.sprintf "rapid-sem: --task %s: expected NAME=FILE[,FILE...]" s) in
  let parse_entry s =
    if well_formed s then Ok (split s)
    else Error (Printf.sprintf "rapid-sem: --entry %s: with --task, expected NAME=ROUTINE" s) in
  let all f l =
    List.fold_right (fun x acc -> match f x, acc with
        | Ok v, Ok vs -> Ok (v :: vs)
        | Error m, _ | _, Error m -> Error m) l (Ok []) in
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  (* A backup's tasks (R-bk-3), each --task NAME=FILE,... replacing the files of the task NAME
     or adding a task; its EIO.cfg unless --io names another configuration (cell_controller). *)
  let backup_tasks = match cell with
    | None -> []
    | Some (c : Backup_setup.cell) ->
        List.map (fun (b : Rapid_load.Backup.task) -> (b.name, b.files, b.entry)) c.backup.tasks in
  match all parse_task t.tasks, all parse_entry t.entries, run_io o, load_robot o.robot, base_frames o with
  | Error m, _, _, _, _ | _, Error m, _, _, _ | _, _, Error m, _, _ | _, _, _, Error m, _ | _, _, _, _, Error m ->
      Error (Usage m)
  | Ok given, Ok entries, Ok io, Ok robot, Ok frames ->
      let replaced = List.map (fun (n, files, entry) ->
          match List.find_opt (fun (g, _) -> same g n) given with
          | Some (_, f) -> (n, f, entry) | None -> (n, files, entry)) backup_tasks in
      let added = List.filter_map (fun (g, f) ->
          if List.exists (fun (n, _, _) -> same n g) backup_tasks then None else Some (g, f, "main")) given in
      let tasks = List.map (fun (n, f, _) -> (n, f)) (replaced @ added) in
      let entry_of = List.map (fun (n, _, e) -> (n, e)) (replaced @ added) in
      let names = List.map fst tasks in
      let duplicate = List.find_opt (fun n -> List.length (List.filter (same n) names) > 1) names in
      let unknown_entry = List.find_opt (fun (n, _) -> not (List.exists (same n) names)) entries in
      match duplicate, unknown_entry with
      | Some n, _ -> Error (Usage (Printf.sprintf "rapid-sem: --task %s is given twice: task names are unique" n))
      | _, Some (n, _) -> Error (Usage (Printf.sprintf "rapid-sem: --entry %s=...: there is no task %s" n n))
      | None, None ->
          (* R-13-aa: the signals are the controller's, shared by every task. *)
          let io = with_inferred_signals ~notify o (List.concat_map snd tasks) io in
          let entry name =
            match List.find_opt (fun (n, _) -> same n name) (List.rev entries) with
            | Some (_, r) -> r
            | None -> Option.value (List.assoc_opt name entry_of) ~default:"main" in
          let specs = List.map (fun (name, files) -> { Task_load.name; files; entry = entry name }) tasks in
          (* MultiMove (R-bk-4): the first motion task of the backup is the run's; each other has
             its robot too. *)
          let cell_robots = match cell with Some c -> c.robots | None -> [] in
          let motion_task = match t.motion_task, cell_robots with
            | Some m, _ -> Some m | None, (m, _) :: _ -> Some m | None, [] -> None in
          (* the backup's robot of the motion task: --robot's arm when given, at the cell's base frame *)
          let robot = match motion_task with
            | Some m -> Option.value (List.assoc_opt m cell_robots) ~default:robot
            | None -> robot in
          (* R-bk-12: --base-frame without TASK= places the run's robot, TASK= that task's; with --task
             alone, a task other than the motion task gets a robot of its own there. *)
          let is_motion n = match motion_task with Some m -> same n m | None -> false in
          let first_task = match motion_task, names with Some m, _ -> Some m | None, n :: _ -> Some n | _ -> None in
          let robot = placed robot (match base_frame_for frames None, first_task with
              | Some b, _ -> Some b
              | None, Some m -> base_frame_for frames (Some m)
              | None, None -> None) in
          let unknown = List.find_map (fun (tk, _) -> match tk with
              | Some n when not (List.exists (same n) names) ->
                  Some (Printf.sprintf "rapid-sem: --base-frame %s=...: there is no task %s" n n)
              | Some n when cell <> None && not (is_motion n)
                            && not (List.exists (fun (c, _) -> same c n) cell_robots) ->
                  Some (Printf.sprintf "rapid-sem: --base-frame %s=...: the task %s has no robot in the backup" n n)
              | _ -> None) frames in
          let own = List.filter_map (fun n ->
              if is_motion n || first_task = Some n || List.exists (fun (c, _) -> same c n) cell_robots then None
              else Option.map (fun b -> (n, placed robot (Some b))) (base_frame_for frames (Some n))) names in
          let cell_robots = List.map (fun (n, r) -> (n, placed r (base_frame_for frames (Some n)))) cell_robots in
          match unknown with
          | Some m -> Error (Usage m)
          | None ->
          let others = List.filter (fun (n, _) -> match motion_task with Some m -> not (same n m) | None -> true)
              cell_robots @ own in
          let history_budget = if history then Some o.limits.max_memory else None in
          let robots = List.map (fun (n, r) -> (n, MR.create ~robot:r ?history:history_budget ())) others in
          let connected = match cell with Some c -> c.backup.connected | None -> [] in
          let summary = Option.map (fun c -> Backup_setup.summary c ~run:specs ~io) cell in
          let robotware = o.controller.robotware in
          (* R-bk-8: the event routines of the backup's tasks (of a task --task gives other files
             too: those its buffer has run). *)
          let events = match cell with
            | Some c -> List.map (fun (b : Rapid_load.Backup.task) -> (b.name, (b.before, b.after))) c.backup.tasks
            | None -> [] in
          Result.map (fun (controller, motion) ->
              { specs; names; io; controller; motion; robots; connected; motion_task; summary; robotware; events })
            (world o ~history io robot)

let refused : Task_load.failure -> failure = function
  | Load (name, f) -> Task_refused (name, f)
  | Refused m -> Tasks_refused m

let loaded ~notify = function
  | Error f -> Error (refused f)
  | Ok (t, (l : Task_load.loaded)) ->
      List.iter (fun n -> notify (Backup_warning n)) l.notes;
      notify (Warnings (l.warnings, None)); Ok (t, l)

let machine_tasks ?(observe = false) ~notify (o : Run_options.t) (t : Run_options.tasks) s =
  loaded ~notify
    (Run.machine_tasks ~limits:o.limits ~stub_unmodelled:o.stub_unmodelled ~allow_unknown:o.allow_unknown
       ?robotware:s.robotware ~io:s.io
       ~observe ?seed:t.schedule ?motion_task:s.motion_task ~robots:s.robots ~connected:s.connected
       ~events:s.events ~controller:s.controller ~motion:s.motion s.specs)

let closure_tasks ~notify (o : Run_options.t) (t : Run_options.tasks) s =
  loaded ~notify
    (Run.closure_tasks ~limits:o.limits ~stub_unmodelled:o.stub_unmodelled ~allow_unknown:o.allow_unknown
       ?robotware:s.robotware ~io:s.io
       ?seed:t.schedule ?motion_task:s.motion_task ~robots:s.robots ~connected:s.connected
       ~events:s.events ~controller:s.controller ~motion:s.motion s.specs)
