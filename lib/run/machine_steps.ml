module M = Rapid_semantics.Machine
module TS = Rapid_semantics.Task_set

type t = {
  next : unit -> (string option * M.config) option;
  step : unit -> string * Event.t list;
  outcome : unit -> Outcome.t;
  steps : unit -> int;
  robot : (M.config * Run.world) option;
  entry_at : Rapid_syntax.Source.region option;
}

let single max_steps cfg w entry = {
  next = (fun () -> if M.outcome cfg = Running && M.steps cfg < max_steps then Some (None, cfg) else None);
  step = (fun () -> M.step cfg);
  outcome = (fun () -> M.outcome cfg);
  steps = (fun () -> M.steps cfg);
  robot = Some (cfg, w);
  entry_at = Run_drive.entry_region (M.program cfg) entry;
}

let several max_steps ts (loaded : Task_load.loaded) = {
  next = (fun () -> if TS.steps ts < max_steps then Option.map (fun (n, c) -> (Some n, c)) (TS.next ts) else None);
  step = (fun () -> match TS.step ts with Some (_, rule, events) -> (rule, events) | None -> ("", []));
  outcome = (fun () -> TS.outcome ts);
  steps = (fun () -> TS.steps ts);
  robot = Option.map (fun (t : Task_load.task) -> (List.assoc t.rules.name (TS.tasks ts), Run.task_world t))
      (Run.motion_task loaded);
  entry_at = None;
}

let rec start ?history ~notify (o : Run_options.t) (t : Run_options.tasks) =
  match (if t.files = [] then Ok (Backup_setup.Files []) else Backup_setup.input ~robot:o.robot t.files) with
  | Error m -> Error (Run_setup.Usage m)
  | Ok (Files files) when files <> t.files -> start ?history ~notify o { t with files }
  | Ok (Cell cell) ->
      (* A backup: its tasks, as run takes them (R-bk-3). *)
      List.iter (fun w -> notify (Run_setup.Backup_warning w)) cell.warnings;
      let t = { t with files = [] } in
      Result.bind (Run_setup.several ?history ~cell ~notify o t) (fun s ->
          Result.map (fun (ts, loaded) -> several o.max_steps ts loaded) (Run_setup.machine_tasks ~notify o t s))
  | Ok (Files _) ->
  if t.tasks <> [] then
    Result.bind (Run_setup.several ?history ~notify o t) (fun s ->
        Result.map (fun (ts, loaded) -> several o.max_steps ts loaded) (Run_setup.machine_tasks ~notify o t s))
  else
    Result.bind (Run_setup.entry t) (fun entry ->
        Result.map (fun (cfg, w) -> single o.max_steps cfg w entry)
          (Run_setup.start_machine ?history ~notify o t.files ~entry))

let next t = t.next ()
let step t = t.step ()
let outcome t = t.outcome ()
let steps t = t.steps ()
let robot t = t.robot
let entry_at t = t.entry_at
