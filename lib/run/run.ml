module MR = Rapid_installed.Motion_routines

type world = { controller : Rapid_controller.World.t; motion : MR.state; host : Host.t }

let setup ?controller ?motion () =
  let controller = match controller with
    | Some w -> w | None -> Rapid_controller.World.create Rapid_controller.Io_config.empty in
  let motion = match motion with Some m -> m | None -> MR.create () in
  { controller; motion; host = Rapid_installed.World_host.make controller motion }

type result = { outcome : Outcome.t; work : int }

module type ENGINE = sig
  val name : string

  val run :
    ?limits:Limits.t -> ?fuel:int -> ?stub_unmodelled:bool -> ?all_events:bool -> ?observe:bool ->
    ?on_event:(Event.t -> unit) -> ?module_data:((string * string * Value.t) list -> unit) ->
    host:Host.t -> Ir.program -> entry:string -> (result, string) Stdlib.result
end

module Machine = struct
  module M = Rapid_semantics.Machine

  let name = "machine"

  let wanted all_events (e : Event.t) =
    all_events || (match e with Output _ | Erase | Log _ -> true | _ -> false)

  let run ?limits ?(fuel = Rapid_closure.Closure_engine.default_fuel) ?stub_unmodelled ?(all_events = true)
      ?observe ?(on_event = ignore) ?module_data ~host program ~entry =
    match M.start ?limits ?stub_unmodelled ?observe ~host program ~entry with
    | Error m -> Error m
    | Ok cfg ->
        while M.outcome cfg = Running && M.steps cfg < fuel do
          List.iter (fun e -> if wanted all_events e then on_event e) (snd (M.step cfg))
        done;
        Option.iter (fun f -> f (M.module_data cfg)) module_data;
        Ok { outcome = M.outcome cfg; work = M.steps cfg }
end

module Closure = struct
  module C = Rapid_closure.Closure_engine

  let name = "closure"

  let run ?limits ?fuel ?stub_unmodelled ?all_events ?observe ?on_event ?module_data ~host program ~entry =
    Result.map (fun (r : C.result) -> { outcome = r.outcome; work = r.fuel_used })
      (C.run ?limits ?fuel ?stub_unmodelled ?all_events ?observe ?on_event ?module_data ~host program ~entry)
end

let engine = function `Machine -> (module Machine : ENGINE) | `Closure -> (module Closure : ENGINE)

let started start loaded =
  match loaded with
  | Error f -> Error f
  | Ok (l : Task_load.loaded) -> (
      match start (List.map (fun (t : Task_load.task) -> t.rules) l.tasks) l.links with
      | Error m -> Error (Task_load.Refused m)
      | Ok t -> Ok (t, l))

let machine_tasks ?limits ?stub_unmodelled ?allow_unknown ?robotware ?observe ?io ?seed ?motion_task ?robots
    ?connected ?events ~controller ~motion specs =
  started (Rapid_semantics.Task_set.start ?limits ?stub_unmodelled ?observe ?seed)
    (Task_load.load ?allow_unknown ?robotware ?io ?motion_task ?robots ?connected ?events ~world:controller ~motion
       specs)

let closure_tasks ?limits ?stub_unmodelled ?allow_unknown ?robotware ?io ?seed ?motion_task ?robots ?connected ?events
    ~controller ~motion specs =
  started (Rapid_closure.Closure_tasks.start ?limits ?stub_unmodelled ?seed)
    (Task_load.load ?allow_unknown ?robotware ?io ?motion_task ?robots ?connected ?events ~world:controller ~motion
       specs)

let motion_task (l : Task_load.loaded) =
  List.find_opt (fun (t : Task_load.task) -> Rapid_controller.World.motion_task t.world) l.tasks

let task_world (t : Task_load.task) = { controller = t.world; motion = t.motion; host = t.rules.host }
