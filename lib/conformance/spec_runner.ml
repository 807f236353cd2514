open Rapid_syntax

type verdict = Passed | Failed | Skipped
type engine = Machine | Closure
type outcome = { case : Spec_case.t; verdict : verdict; detail : string }

let pass case detail = { case; verdict = Passed; detail }
let fail case detail = { case; verdict = Failed; detail }

let class_directive_name = function
  | Diagnostic.Lexical_error -> "lexical-error"
  | Syntax_error -> "syntax-error"
  | Semantic_error -> "semantic-error"
  | Fatal_static_error -> "fatal-error"
  | File_error -> "file-error"

(* The refusal a case expects, against the first error found. *)
let compare_refusal case expected (d : Diagnostic.t) =
  match expected with
  | Spec_case.Accepted -> fail case ("expected ok, got " ^ Diagnostic.to_string d)
  | Refused { error_class; file; line; col } ->
      let p = Source.start d.region in
      let got = class_directive_name d.error_class in
      let got_file = match Source.file_of d.region with Some f -> Filename.basename (Source.name f) | None -> "" in
      let file_ok = match file with None -> true | Some f -> f = got_file in
      if got = error_class && file_ok && p.line = line && p.col = col then pass case (Diagnostic.to_string d)
      else
        fail case (Printf.sprintf "expected %s, got %s %s:%d:%d (%s)"
                     (Spec_case.expectation_to_string expected) got got_file p.line p.col
                     (Diagnostic.to_string d))

let accepted case expected =
  match expected with
  | Spec_case.Accepted -> pass case "ok"
  | Refused _ ->
      fail case (Printf.sprintf "expected %s, but the case was accepted"
                   (Spec_case.expectation_to_string expected))

(* Format 3: the program runs; its output, exit status and error must be those expected. *)
(* The robot description of [! @robot FILE], or the default robot. *)
let robot_of (run : Spec_case.run) =
  let arm = match run.robot with
    | None -> Ok None
    | Some name -> Result.map Option.some (Rapid_motion_model.Robot_library.load name) in
  (* ! @base-frame X,Y,Z,Q1,Q2,Q3,Q4: the run's robot at that base frame (R-bk-12) *)
  Result.bind arm (fun arm ->
      Result.map (fun frames ->
          match Rapid_run.Run_setup.base_frame_for frames None with
          | None -> arm
          | Some b ->
              let r = Option.value arm ~default:Rapid_motion_model.Robot.irb120 in
              Some { r with Rapid_motion_model.Robot.base_frame = b })
        (Rapid_run.Run_setup.parse_base_frames run.base_frames))

(* ! @base-frame TASK=X,Y,Z,Q1,Q2,Q3,Q4 in a format 4 case: that task's robot of its own (the
   run's arm) at that base frame, as rapid-sem run --task ... --base-frame TASK=... makes it; the
   motion task's robot is the run's (R-bk-12). *)
let task_robots (run : Spec_case.run) robot =
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  let motion = match run.motion_task, run.tasks with Some m, _ -> Some m | None, (n, _) :: _ -> Some n | _ -> None in
  let frames = Result.value (Rapid_run.Run_setup.parse_base_frames run.base_frames) ~default:[] in
  let arm = Option.value robot ~default:Rapid_motion_model.Robot.irb120 in
  let motion_frame = match motion with Some m -> Rapid_run.Run_setup.base_frame_for frames (Some m) | None -> None in
  let robot = match motion_frame with
    | Some b -> Some { arm with Rapid_motion_model.Robot.base_frame = b } | None -> robot in
  let others = List.filter_map (fun (n, _) ->
      if (match motion with Some m -> same m n | None -> false) then None
      else Option.map (fun b -> (n, Rapid_installed.Motion_routines.create
                                     ~robot:{ arm with Rapid_motion_model.Robot.base_frame = b } ()))
          (Rapid_run.Run_setup.base_frame_for frames (Some n))) run.tasks in
  (robot, others)

(* The run's output lines and outcome, by the chosen engine. *)

(* The controller of a run case: its clock, and a mass memory of its own, empty at the start but
   for @home (doc/services.md); [release] closes its services and removes the mass memory. *)
let case_world (run : Spec_case.run) io =
  let world = Rapid_controller.World.create ?statement_time:run.statement_time ?max_time:run.max_time io in
  let sandbox = Rapid_controller.File_sandbox.temporary () in
  Option.iter (Rapid_controller.File_sandbox.seed sandbox ~device:"HOME:") run.home;
  let egm_devices = List.concat_map (fun d -> Result.value (Rapid_controller.Egm_channel.parse_devices d) ~default:[])
      run.egm_devices in
  (* A script that cannot be read is a problem of the case, caught when the case is read. *)
  let operator = Option.bind run.operator (fun f -> Result.to_option (Rapid_controller.Operator_script.of_file f)) in
  let services = Rapid_controller.Services.create ~sandbox ~egm_devices ?operator () in
  Rapid_controller.World.set_services world services;
  (world, fun () -> Rapid_controller.Services.close_all services; Rapid_controller.File_sandbox.remove sandbox)
let execute engine case (run : Spec_case.run) ~io program =
  let limits = { Rapid_runtime.Limits.default with
                 retry_limit = Option.value run.retry_limit ~default:Rapid_runtime.Limits.default.retry_limit } in
  let max_steps = Option.value run.max_steps ~default:10_000_000 in
  let output = ref [] in
  let collect = function Rapid_runtime.Event.Output s -> output := s :: !output | _ -> () in
  let world, release = case_world run io in
  let module E = (val Rapid_run.Run.engine (match engine with Machine -> `Machine | Closure -> `Closure)) in
  match Result.bind (robot_of run) (fun robot ->
      let motion = Rapid_installed.Motion_routines.create ?robot () in
      let host = (Rapid_run.Run.setup ~controller:world ~motion ()).host in
      E.run ~limits ~fuel:max_steps ~stub_unmodelled:case.Spec_case.stub_unmodelled ~all_events:false ~host
        ~on_event:collect program ~entry:run.entry) with
  | Error m -> release (); Error m
  | Ok r -> release (); Ok (List.rev !output, r.outcome)

let rec run_program engine case (run : Spec_case.run) ~io program =
  match Loopback_lock.exclusive case (fun () -> execute engine case run ~io program) with
  | Error m -> fail case ("cannot run: " ^ m)
  | Ok r -> judge case run r

(* The output, exit status and error of a run against those the case expects. *)
and judge case (run : Spec_case.run) (output, outcome) =
      let file_of at = match Source.file_of at with Some f -> Some (Filename.basename (Source.name f)) | None -> None in
      let status, error, error_file =
        match (outcome : Rapid_runtime.Outcome.t) with
        | Ended -> (0, None, None)
        | Stopped { name; at; _ } -> let p = Source.start at in (1, Some (name, p.line, p.col), file_of at)
        | Running | Resource_exhausted _ | Deadlock _ -> (3, None, None)
        | Unsupported { name; at; _ } -> let p = Source.start at in (4, Some (name, p.line, p.col), file_of at)
        | Stuck m -> (125, Some ("stuck: " ^ m, 0, 0), None)
      in
      let problems =
        (if output <> run.outputs then
           [ Printf.sprintf "output %s, expected %s"
               (String.concat " | " (List.map (Printf.sprintf "%S") output))
               (String.concat " | " (List.map (Printf.sprintf "%S") run.outputs)) ]
         else [])
        @ (if status <> run.exit_status then [ Printf.sprintf "exit %d, expected %d" status run.exit_status ] else [])
        @ (match run.error, error with
           | Some e, Some g when e <> g ->
               let (n, l, c) = g and (en, el, ec) = e in
               [ Printf.sprintf "error %s %d:%d, expected %s %d:%d" n l c en el ec ]
           | Some (en, el, ec), None -> [ Printf.sprintf "no error, expected %s %d:%d" en el ec ]
           | None, Some (n, l, c) when run.exit_status = 0 -> [ Printf.sprintf "error %s %d:%d" n l c ]
           | _ -> [])
        @ (match run.error_file, error_file with
           | Some f, Some g when f <> g -> [ Printf.sprintf "error in %s, expected in %s" g f ]
           | _ -> [])
      in
      if problems = [] then pass case (Printf.sprintf "ran: %d lines, exit %d" (List.length output) status)
      else fail case (String.concat "; " problems)

(* The first error of a refused task buffer against the case's expectation; the report must also
   name one of the sections the case tests. *)
let compare_static case expected reports =
  match List.filter (fun (r : Rapid_typing.Report.t) -> r.severity = Error) reports with
  | [] -> fail case "refused without an error"
  | first :: _ -> (
      match compare_refusal case expected (Rapid_typing.Report.to_diagnostic first) with
      | { verdict = Passed; _ } as o
        when not (List.exists (fun s -> List.mem s case.Spec_case.sections) first.sections) ->
          { o with verdict = Failed;
                   detail = Printf.sprintf "right place, but the report cites §%s, and the case tests §%s: %s"
                       (String.concat ", §" first.sections) (String.concat ", §" case.sections) o.detail }
      | o -> o)

(* Format 4: several tasks (@task), run as rapid-sem run --task does, by either engine. *)
let run_tasks engine case expected (run : Spec_case.run) =
  let module TS = Rapid_semantics.Task_set in
  let module CT = Rapid_closure.Closure_tasks in
  let module TL = Rapid_run.Task_load in
  let io =
    match run.io with
    | Some file -> Rapid_controller.Io_config.read_file file | None -> Ok Rapid_controller.Io_config.empty in
  match io, robot_of run with
  | Error m, _ | _, Error m -> fail case m
  | Ok io, Ok robot ->
  let io =
    let modules = List.concat_map (fun (_, files) ->
        let options = { Parse.default_options with robotware = case.robotware } in
        List.filter_map (fun f -> Result.to_option (Parse.parse_file ~options f)) files) run.tasks in
    fst (Rapid_load.Signal_inference.for_run ~allow_unknown:case.allow_unknown
           ~stub_unmodelled:case.stub_unmodelled modules io) in
  let limits = { Rapid_runtime.Limits.default with
                 retry_limit = Option.value run.retry_limit ~default:Rapid_runtime.Limits.default.retry_limit } in
  let max_steps = Option.value run.max_steps ~default:10_000_000 in
  let world, release = case_world run io in
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  let entry_of name = match List.find_opt (fun (t, _) -> same t name) (List.rev run.task_entries) with
    | Some (_, r) -> r | None -> run.entry in
  let specs = List.map (fun (name, files) -> { TL.name; files; entry = entry_of name }) run.tasks in
  let robot, robots = task_robots run robot in
  let motion = Rapid_installed.Motion_routines.create ?robot () in
  let stub_unmodelled = case.Spec_case.stub_unmodelled and allow_unknown = case.allow_unknown in
  let seed = run.schedule and motion_task = run.motion_task in
  (* The run's output and outcome, by the chosen engine, loaded and started as rapid-sem run does (Run). *)
  let result = match engine with
    | Machine ->
        Result.map (fun (ts, _) -> (fun () ->
            let output = ref [] in
            let rec loop () =
              if TS.steps ts < max_steps then
                match TS.step ts with
                | None -> ()
                | Some (_, _, events) ->
                    List.iter (function Rapid_runtime.Event.Output s -> output := s :: !output | _ -> ()) events;
                    loop ()
            in
            loop ();
            (List.rev !output, TS.outcome ts)))
          (Rapid_run.Run.machine_tasks ~limits ~stub_unmodelled ~allow_unknown ~robotware:case.robotware ~io ?seed
             ?motion_task ~robots ~controller:world ~motion specs)
    | Closure ->
        Result.map (fun (ct, _) -> (fun () ->
            let output = ref [] in
            let r = CT.run ~fuel:max_steps ~all_events:false
                ~on_event:(fun _ -> function Rapid_runtime.Event.Output s -> output := s :: !output | _ -> ()) ct in
            (List.rev !output, r.outcome)))
          (Rapid_run.Run.closure_tasks ~limits ~stub_unmodelled ~allow_unknown ~robotware:case.robotware ~io ?seed
             ?motion_task ~robots ~controller:world ~motion specs) in
  let verdict = match result with
    | Error (Load (_, Front_end (d :: _))) -> compare_refusal case expected d
    | Error (Load (_, Front_end [])) -> fail case "refused without a diagnostic"
    | Error (Load (_, Static reports)) -> compare_static case expected reports
    | Error (Load (_, Internal m)) | Error (Refused m) -> fail case m
    | Ok _ when expected <> Spec_case.Accepted -> accepted case expected
    | Ok go -> judge case run (go ())
  in
  release (); verdict

let run_case ?(engine = Machine) (case : Spec_case.t) =
  if not (List.mem case.format Spec_case.known_formats) then
    { case; verdict = Skipped;
      detail = Printf.sprintf "format %s (this runner reads formats %s)" case.format
          (String.concat ", " Spec_case.known_formats) }
  else if case.problems <> [] then fail case (String.concat "; " case.problems)
  else
    let options = { Parse.default_options with strict = case.strict; robotware = case.robotware } in
    let expected = Option.get case.expectation in
    match case.run with
    | Some ({ tasks = _ :: _; _ } as run) -> Loopback_lock.exclusive case (fun () -> run_tasks engine case expected run)
    | _ ->
    let results = List.map (Parse.parse_file ~options) case.files in
    match List.find_map (function Error d -> Some d | Ok _ -> None) results with
    | Some d -> compare_refusal case expected d
    | None when not (Spec_case.checks_semantics case) -> accepted case expected
    | None -> (
        let modules = List.filter_map Result.to_option results in
        let io = match case.run with
          | Some { io = Some file; _ } -> Rapid_controller.Io_config.read_file file
          | _ -> Ok Rapid_controller.Io_config.empty in
        match io with
        | Error m -> fail case m
        | Ok io ->
        let io = fst (Rapid_load.Signal_inference.for_run ~allow_unknown:case.allow_unknown
                        ~stub_unmodelled:case.stub_unmodelled modules io) in
        (* The whole static semantics, the initial values known before the run included. *)
        match Rapid_load.Session.load_modules ~allow_unknown:case.allow_unknown ~io modules with
        | Error (Internal m) -> fail case m
        | Error (Front_end (d :: _)) -> compare_refusal case expected d
        | Error (Front_end []) -> fail case "refused without a diagnostic"
        | Ok loaded -> (
            match case.run, expected with
            | Some run, Spec_case.Accepted -> run_program engine case run ~io loaded.program
            | _ -> accepted case expected)
        | Error (Static reports) -> compare_static case expected reports)

(* The cases below [dir], and what could not be looked at (path, reason). Folders are walked
   once each, by their identity, so that a symbolic link that leads back up is reported instead of
   followed for ever; a [.mod] entry that is not a regular file (a FIFO, a device) is reported
   instead of opened, since opening a FIFO waits for a writer. *)
let collect dir =
  let errors = ref [] in
  let error path message = errors := (path, message) :: !errors in
  let visited = Hashtbl.create 64 in
  let rec walk acc path =
    match Unix.stat path with
    | exception Unix.Unix_error (e, _, _) -> error path (Unix.error_message e); acc
    | st -> (
        match st.st_kind with
        | S_DIR when Filename.check_suffix path ".task" -> path :: acc
        | S_DIR ->
            if Hashtbl.mem visited (st.st_dev, st.st_ino) then begin
              error path "a folder reached twice (a symbolic link loop): not walked again";
              acc
            end
            else begin
              Hashtbl.replace visited (st.st_dev, st.st_ino) ();
              match Sys.readdir path with
              | exception Sys_error m -> error path ("cannot list the folder: " ^ m); acc
              | names ->
                  names |> Array.to_list |> List.sort compare
                  |> List.fold_left (fun acc name -> walk acc (Filename.concat path name)) acc
            end
        | _ when not (Filename.check_suffix path ".mod") -> acc
        | S_REG -> (
            match Unix.access path [ Unix.R_OK ] with
            | () -> path :: acc
            | exception Unix.Unix_error (e, _, _) -> error path (Unix.error_message e); acc)
        | _ -> (
            match Spec_case.readable_file path with
            | Error m -> error path m; acc
            | Ok () -> path :: acc))
  in
  let cases =
    match Unix.lstat dir with
    | exception Unix.Unix_error (e, _, _) -> error dir (Unix.error_message e); []
    | _ -> List.rev (walk [] dir)
  in
  (cases, List.rev !errors)

let find_cases dir = fst (collect dir)

(* Sections sort by their numbers: 2.5 before 2.10 before 10.1. *)
let compare_sections a b =
  let key s = List.map (fun p -> Option.value (int_of_string_opt p) ~default:max_int)
      (String.split_on_char '.' s) in
  compare (key a, a) (key b, b)

let run ?(verbose = false) ?engine out dir =
  let paths, errors = collect dir in
  let outcomes = List.map (fun path -> run_case ?engine (Spec_case.read path)) paths in
  (* What could not be looked at fails the run: a suite that is not all there has not passed. *)
  List.iter (fun (path, m) -> Format.fprintf out "ERROR %s: %s@." path m) errors;
  let by_section = Hashtbl.create 64 in
  List.iter (fun o ->
      let sections = if o.case.sections = [] then [ "(none)" ] else o.case.sections in
      List.iter (fun s ->
          let p, f = Option.value (Hashtbl.find_opt by_section s) ~default:(0, 0) in
          match o.verdict with
          | Passed -> Hashtbl.replace by_section s (p + 1, f)
          | Failed -> Hashtbl.replace by_section s (p, f + 1)
          | Skipped -> ()) sections;
      let label = match o.verdict with Passed -> "PASS" | Failed -> "FAIL" | Skipped -> "SKIP" in
      if verbose || o.verdict <> Passed then
        Format.fprintf out "%s %s: %s@." label o.case.path o.detail)
    outcomes;
  let sections = Hashtbl.fold (fun s _ acc -> s :: acc) by_section [] |> List.sort compare_sections in
  Format.fprintf out "@.%-10s %7s %7s@." "section" "passed" "failed";
  List.iter (fun s ->
      let p, f = Hashtbl.find by_section s in
      Format.fprintf out "%-10s %7d %7d@." s p f) sections;
  let count v = List.length (List.filter (fun o -> o.verdict = v) outcomes) in
  let passed = count Passed and failed = count Failed + List.length errors and skipped = count Skipped in
  if skipped = 0 then Format.fprintf out "@.%d passed, %d failed@." passed failed
  else Format.fprintf out "@.%d passed, %d failed, %d skipped@." passed failed skipped;
  (passed, failed)
