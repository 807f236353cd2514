module M = Rapid_semantics.Machine
module TS = Rapid_semantics.Task_set
module CT = Rapid_closure.Closure_tasks

type engine = [ `Machine | `Closure ]

let engine ?requested ~samples () =
  match requested with
  | Some e -> e
  | None -> if samples <> None then `Machine else `Closure

type sink = {
  start : string list option -> unit;
  event : string option -> Event.t -> unit;
  stubbed : Event.t list -> unit;
  samples : string option -> Tcp_samples.sample list -> unit;
  cell : Backup_setup.summary -> unit;
  task_end : string -> Outcome.t -> int -> unit;
  run_end : ?entry_at:Rapid_syntax.Source.region -> Outcome.t -> int -> unit;
  flush : unit -> unit;
}

type ended = { outcome : Outcome.t; work : int }

(* Names compared without a lowered copy of each of the 300 routines' (§2.3). *)
let entry_region (program : Ir.program) entry =
  Array.fold_left (fun found (r : Ir.routine) ->
      match found with
      | Some _ -> found
      | None -> if r.kind = Procedure && Rapid_typing.Types.same_name r.name entry then Some r.at else None)
    None program.routines

let ( let* ) = Result.bind

let usage m = Error (Run_setup.Usage m)

let sampler ~notify hz =
  Tcp_samples.create ~on_capped:(fun () -> notify (Run_setup.Samples_capped Tcp_samples.max_samples)) hz

(* The files --save writes back: a module read from standard input has none. *)
let saved_files files = List.filter (( <> ) "-") files

let write_back dir files data =
  Result.map_error (fun m -> Run_setup.Save_failed m)
    (Result.map ignore (Persistent_save.save_modules ~dir ~files:(saved_files files) data))

(* One task by the closure engine, in the same controller (signals, stimulus, clock, services,
   robot) as the machine's. *)
let closure ~notify sink ~json ~save (o : Run_options.t) files ~entry =
  let* s = Run_setup.single ~notify o files in
  sink.start None;
  (* Each warning of a routine stubbed goes out when the call runs, as the machine's do, so that a
     run that waits on the host afterwards (or is killed there) has said it. *)
  let on_event e = sink.stubbed [ e ]; sink.event None e in
  let data = ref [] in
  let module_data = Option.map (fun _ d -> data := d) save in
  match Rapid_closure.Closure_engine.run ~limits:o.limits ~fuel:o.max_steps ~stub_unmodelled:o.stub_unmodelled
          ~all_events:(json || o.stub_unmodelled) ~observe:json ~on_event ~host:s.world.host ?module_data
          s.loaded.program ~entry with
  | Error reason -> Error (Run_setup.Cannot_start { entry; reason })
  | Ok { outcome; fuel_used } ->
      sink.run_end ?entry_at:(entry_region s.loaded.program entry) outcome fuel_used;
      let* () = match save with
        | None -> Ok ()
        | Some dir -> sink.flush (); write_back dir files !data in
      Ok { outcome; work = fuel_used }

(* One task by the machine; --samples as the clock passes them (JSON only). *)
let machine ~notify sink ~json ~samples ~save (o : Run_options.t) files ~entry =
  Run_setup.machine_gc ();
  let* s = Run_setup.single ~history:(samples <> None && json) ~notify o files in
  sink.start None;
  let* cfg = Run_setup.machine ~observe:json o s ~entry in
  let w = s.world in
  let sampler = match samples with Some hz when json -> Some (sampler ~notify hz) | _ -> None in
  while M.outcome cfg = Running && M.steps cfg < o.max_steps do
    let _, events = M.step cfg in
    sink.stubbed events;
    Option.iter (fun s ->
        sink.samples None (Tcp_samples.until s w.motion (Rapid_controller.World.now w.controller))) sampler;
    List.iter (sink.event None) events
  done;
  Option.iter (fun s -> sink.samples None (Tcp_samples.final s (M.outcome cfg) w)) sampler;
  sink.run_end ?entry_at:(entry_region (M.program cfg) entry) (M.outcome cfg) (M.steps cfg);
  sink.flush ();
  let* () = match save with None -> Ok () | Some dir -> write_back dir files (M.module_data cfg) in
  Ok { outcome = M.outcome cfg; work = M.steps cfg }

(* The warnings of a backup counted with those its loading gave (event routines not run). *)
let with_notes summary (loaded : Task_load.loaded) =
  let runs task (routine, _) = List.exists (fun (t : Task_load.task) ->
      t.rules.name = task && List.exists (fun n -> n = routine) (t.rules.before @ t.rules.after)) loaded.tasks in
  Option.map (fun (s : Backup_setup.summary) ->
      { s with warned = s.warned + List.length loaded.notes;
               tasks = List.map (fun (t : Backup_setup.task_summary) ->
                   { t with event_routines = List.filter (runs t.task) t.event_routines }) s.tasks }) summary

(* Several tasks by the closure engine (Closure_tasks): the same events, in the same order, as
   the machine's; --max-steps is each task's fuel. *)
let closure_tasks ?cell ~notify sink ~json (o : Run_options.t) (t : Run_options.tasks) =
  let* s = Run_setup.several ?cell ~notify o t in
  let* ct, loaded = Run_setup.closure_tasks ~notify o t s in
  sink.start (Some s.names);
  Option.iter sink.cell (with_notes s.summary loaded);
  let on_event name e = sink.stubbed [ e ]; sink.event (Some name) e in
  let r = CT.run ~fuel:o.max_steps ~all_events:(json || o.stub_unmodelled) ~observe:json ~on_event ct in
  let work = List.fold_left (fun n (t : CT.task_result) -> n + t.fuel_used) 0 r.tasks in
  List.iter (fun (t : CT.task_result) -> sink.task_end t.name t.task_outcome t.fuel_used) r.tasks;
  sink.run_end r.outcome work;
  sink.flush ();
  Ok { outcome = r.outcome; work }

(* Several tasks by the machine (Task_set), on one clock, in turns of a statement; --samples
   samples the motion task's robot as the one clock passes them. *)
let machine_tasks ?cell ~notify sink ~json ~samples (o : Run_options.t) (t : Run_options.tasks) =
  let* s = Run_setup.several ?cell ~history:(samples <> None && json) ~notify o t in
  let* ts, loaded = Run_setup.machine_tasks ~observe:json ~notify o t s in
  sink.start (Some s.names);
  Option.iter sink.cell (with_notes s.summary loaded);
  let robot_task = Option.map (fun (t : Task_load.task) ->
      (t.rules.name, List.assoc t.rules.name (TS.tasks ts), Run.task_world t)) (Run.motion_task loaded) in
  let sampler = match samples, robot_task with Some hz, Some _ when json -> Some (sampler ~notify hz) | _ -> None in
  let samples l = Option.iter (fun (name, _, _) -> sink.samples (Some name) l) robot_task in
  let rec loop () =
    if TS.steps ts < o.max_steps then
      match TS.step ts with
      | None -> ()
      | Some (name, _, events) ->
          sink.stubbed events;
          Option.iter (fun s -> Option.iter (fun (_, _, (w : Run.world)) ->
              samples (Tcp_samples.until s w.motion ((TS.clock ts).now ()))) robot_task) sampler;
          List.iter (sink.event (Some name)) events;
          loop ()
  in
  loop ();
  Option.iter (fun s -> Option.iter (fun (_, cfg, w) -> samples (Tcp_samples.final s (M.outcome cfg) w)) robot_task)
    sampler;
  List.iter (fun (name, cfg) -> sink.task_end name (TS.task_outcome ts cfg) (M.steps cfg)) (TS.tasks ts);
  sink.run_end (TS.outcome ts) (TS.steps ts);
  sink.flush ();
  Ok { outcome = TS.outcome ts; work = TS.steps ts }

let only_machine = "rapid-sem: --samples runs on the machine only: use --engine machine"

(* R-bk-3: a backup runs as the tasks it configures; NoOfRetry of SYS_MISC is the retry limit
   unless --retry-limit gives another. *)
let cell_run ~notify sink ~engine ~json ~samples ~save (o : Run_options.t) (t : Run_options.tasks)
    (c : Backup_setup.cell) =
  List.iter (fun w -> notify (Run_setup.Backup_warning w)) c.warnings;
  let o = match c.backup.retry_limit with
    | Some n when o.limits.retry_limit = Limits.default.retry_limit ->
        { o with limits = { o.limits with retry_limit = n } }
    | _ -> o in
  let t = { t with files = [] } in
  if save <> None then usage "rapid-sem: --save runs one task: not with a controller backup"
  else if engine = `Closure && samples <> None then usage only_machine
  else if engine = `Closure then closure_tasks ~cell:c ~notify sink ~json o t
  else
    let* () = Result.map_error (fun m -> Run_setup.Usage m) (Tcp_samples.check samples) in
    machine_tasks ~cell:c ~notify sink ~json ~samples o t

let rec run ~notify sink ~engine ~json ~samples ~save (o : Run_options.t) (t : Run_options.tasks) =
  match (if t.files = [] then Ok (Backup_setup.Files []) else Backup_setup.input ~robot:o.robot t.files) with
  | Error m -> usage m
  | Ok (Cell c) -> cell_run ~notify sink ~engine ~json ~samples ~save o t c
  | Ok (Files files) when files <> t.files -> run ~notify sink ~engine ~json ~samples ~save o { t with files }
  | Ok (Files _) ->
  if t.tasks <> [] then
    if t.files <> [] then usage "rapid-sem: with --task, the files are named in each --task NAME=FILE,..."
    else if save <> None then usage "rapid-sem: --save runs one task: not with --task"
    else if engine = `Closure && samples <> None then usage only_machine
    else if engine = `Closure then closure_tasks ~notify sink ~json o t
    else
      let* () = Result.map_error (fun m -> Run_setup.Usage m) (Tcp_samples.check samples) in
      machine_tasks ~notify sink ~json ~samples o t
  else
    let* () = match save with
      | None -> Ok ()
      | Some dir ->
          Result.map_error (fun m -> Run_setup.Save_failed m)
            (Persistent_save.check ~dir ~files:(saved_files t.files)) in
    if save <> None && List.mem "-" t.files then notify Run_setup.Stdin_not_saved;
    let* entry = Run_setup.entry t in
    if engine = `Closure && samples <> None then usage only_machine
    else if engine = `Closure then closure ~notify sink ~json ~save o t.files ~entry
    else
      let* () = Result.map_error (fun m -> Run_setup.Usage m) (Tcp_samples.check samples) in
      machine ~notify sink ~json ~samples ~save o t.files ~entry
