open Rapid_syntax
module M = Rapid_semantics.Machine
module TS = Rapid_semantics.Task_set
module TL = Rapid_run.Task_load
module F = Fuzz_run

let several_tasks_closure = ref true

let sources (t : Fuzz_case.task) = List.map (fun m -> (Fuzz_case.module_file m, Program_gen.to_source m)) t.modules

(* Every module parses, and its printed form parses to the same tree. *)
let parse_task t =
  List.fold_left (fun acc (file, source) ->
      Result.bind acc (fun ms ->
          match Parse.parse_string ~name:file source with
          | Error d -> Error (F.Refused (Diagnostic.to_string d))
          | Ok m -> Result.map (fun () -> ms @ [ m ]) (F.round_trip ~name:file m))) (Ok []) (sources t)

let io_of (c : Fuzz_case.t) =
  match Rapid_controller.Io_config.parse ~file:"fuzz.io" c.io_text with
  | Ok io -> Ok io
  | Error m -> Error (F.Refused ("the stimulus: " ^ m))

(* One task: as Fuzz_run.check_program, in the case's world. *)
let check_one ~engines ~max_steps (c : Fuzz_case.t) io program =
  F.with_run_options ~io c.options (fun () -> F.judge_runs ~engines ~max_steps program)

(* Several tasks: Task_set reads its buffers from files, written to a directory of their own. *)
let with_files (c : Fuzz_case.t) f =
  let dir = Filename.temp_file "rapid-fuzz-tasks" "" in
  Sys.remove dir; Sys.mkdir dir 0o700;
  let written = ref [] in
  let remove p = if Sys.is_directory p then Sys.rmdir p else Sys.remove p in
  Fun.protect ~finally:(fun () -> List.iter remove !written; Sys.rmdir dir) @@ fun () ->
  let specs = List.map (fun (t : Fuzz_case.task) ->
      let sub = Filename.concat dir t.task_name in
      Sys.mkdir sub 0o700;
      written := sub :: !written;
      let files = List.map (fun (file, source) ->
          let path = Filename.concat sub file in
          let oc = open_out_bin path in
          output_string oc source; close_out oc;
          written := path :: !written; path) (sources t) in
      { TL.name = t.task_name; files; entry = "main" }) c.tasks in
  f specs

(* The events of several tasks, each prefixed by its task, as two streams each in its order
   (the program's, then the world's), as Fuzz_run observes one task: an engine may report what
   the world did during a step before or after the step's own events. *)
let streams () =
  let program = ref [] and world = ref [] in
  let add name e =
    let text = name ^ ": " ^ F.event_text e in
    if Rapid_runtime.Event.world_event e then world := text :: !world else program := text :: !program in
  (add, fun () -> List.rev_append !program ("-- the world's events --" :: List.rev !world))

let observed events (o : Rapid_runtime.Outcome.t) task_outcomes =
  let outcomes = List.map (fun (name, o) -> name ^ " " ^ F.outcome_text o) task_outcomes in
  let finished = match o with Rapid_runtime.Outcome.Running | Resource_exhausted _ | Deadlock _ -> false | _ -> true in
  let stuck =
    List.exists (fun (_, o) -> match o with Rapid_runtime.Outcome.Stuck _ -> true | _ -> false) task_outcomes in
  let outcome = F.outcome_text o in
  { F.events = events @ outcomes;
    outcome = (if stuck && not (String.length outcome >= 5 && String.sub outcome 0 5 = "stuck")
               then "stuck " ^ String.concat "; " outcomes else outcome);
    finished }

(* Both engines load several tasks as Task_set.start does: its refusals, as the fuzzer reports
   them; each run has a world and a motion of its own. *)
let tasks_refused : TL.failure -> F.failure = function
  | Load (name, f) -> (match F.refused f with F.Refused m -> F.Refused (name ^ ": " ^ m) | e -> e)
  | Refused m -> F.Refused m

let tasks_world (c : Fuzz_case.t) io =
  (Rapid_controller.World.create ?max_time:c.options.max_time io, Rapid_installed.Motion_routines.create ())

(* Loaded and started as rapid-sem run --task does (Run.machine_tasks). *)
let run_tasks ~max_steps (c : Fuzz_case.t) io specs ~seed =
  let world, motion = tasks_world c io in
  match Rapid_run.Run.machine_tasks ~limits:(Fuzz_case.limits c.options) ~stub_unmodelled:c.options.stub_unmodelled
          ~observe:true ?seed ~allow_unknown:c.options.allow_unknown ~io ~controller:world ~motion specs with
  | Error f -> Error (tasks_refused f)
  | Ok (ts, _) ->
      let add, events = streams () in
      let rec loop () =
        if TS.steps ts < max_steps then
          match TS.step ts with
          | None -> ()
          | Some (name, rule, evs) ->
              F.note_rule rule;
              List.iter (add name) evs;
              loop () in
      loop ();
      Ok (observed (events ()) (TS.outcome ts)
            (List.map (fun (name, cfg) -> (name, TS.task_outcome ts cfg)) (TS.tasks ts)))

(* The same tasks by the closure engine (Closure_tasks), in the same kind of world. [fuel] is
   each task's there, the whole run's for the machine: runs cut short are not compared. *)
let run_tasks_closure ~max_steps (c : Fuzz_case.t) io specs ~seed =
  let world, motion = tasks_world c io in
  match Rapid_run.Run.closure_tasks ~limits:(Fuzz_case.limits c.options) ~stub_unmodelled:c.options.stub_unmodelled
          ?seed ~allow_unknown:c.options.allow_unknown ~io ~controller:world ~motion specs with
  | Error f -> Error (tasks_refused f)
  | Ok (ct, _) ->
      let add, events = streams () in
      let r = Rapid_closure.Closure_tasks.run ~fuel:max_steps ~observe:true ~on_event:add ct in
      Ok (observed (events ()) r.outcome
            (List.map (fun (t : Rapid_closure.Closure_tasks.task_result) -> (t.name, t.task_outcome)) r.tasks))

let check_tasks ~max_steps (c : Fuzz_case.t) io =
  with_files c @@ fun specs ->
  (* the case's schedule, and round robin: each run twice *)
  let seeds = List.sort_uniq compare [ c.schedule; None ] in
  let rec each = function
    | [] -> assert false
    | seed :: rest ->
        Result.bind (run_tasks ~max_steps c io specs ~seed) (fun first ->
            if F.is_stuck first then Error (F.Stuck first.outcome)
            else
              Result.bind (run_tasks ~max_steps c io specs ~seed) (fun again ->
                  match F.compare_observed "machine twice" first again with
                  | Some d -> Error (F.Nondeterministic d)
                  | None ->
                      let agree =
                        if not !several_tasks_closure then Ok ()
                        else
                          Result.bind (run_tasks_closure ~max_steps c io specs ~seed) (fun (other : F.observed) ->
                              if not (first.finished && other.finished) then Ok ()
                              else match F.compare_observed "machine / closure (several tasks)" first other with
                                | Some d -> Error (F.Engines_differ d)
                                | None -> Ok ()) in
                      Result.bind agree (fun () ->
                          if rest = [] then Ok first else Result.map (fun _ -> first) (each rest)))) in
  each seeds

let check_case ?(engines = []) ?(max_steps = 200_000) (c : Fuzz_case.t) =
  try
    Result.bind (io_of c) (fun io ->
        let parsed =
          List.fold_left (fun acc t -> Result.bind acc (fun l -> Result.map (fun ms -> l @ [ ms ]) (parse_task t)))
            (Ok []) c.tasks in
        Result.bind parsed (fun parsed ->
            match c.tasks, parsed with
            | [ _ ], [ modules ] -> (
                match F.load_modules ~allow_unknown:c.options.allow_unknown ~io modules with
                | Error f -> Error (F.refused f)
                | Ok loaded -> check_one ~engines ~max_steps c io loaded.program)
            | _ -> check_tasks ~max_steps c io))
  with
  | Stack_overflow -> Error (F.Exception "stack overflow")
  | Out_of_memory -> Error (F.Exception "out of memory")
  | e -> Error (F.Exception (Printexc.to_string e))

let observe ?(max_steps = 200_000) c =
  match check_case ~max_steps c with
  | Ok o -> Ok o
  | Error f -> Error (F.failure_to_string f)
