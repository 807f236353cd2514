type program = { name : string; files : string list }

let is_dir p = try Sys.is_directory p with Sys_error _ -> false

let sorted_entries dir = let a = Sys.readdir dir in Array.sort compare a; Array.to_list a

let module_files dir =
  List.filter (fun f -> Filename.check_suffix f ".mod" || Filename.check_suffix f ".sys") (sorted_entries dir)
  |> List.map (Filename.concat dir)

let programs_of_paths paths =
  let rec walk acc path =
    match acc with
    | Error _ -> acc
    | Ok found ->
        if is_dir path then
          if Filename.check_suffix path ".task" then
            (try Ok ({ name = path; files = module_files path } :: found)
             with Sys_error m -> Error m)
          else
            (match sorted_entries path with
             | entries -> List.fold_left (fun acc e -> walk acc (Filename.concat path e)) acc entries
             | exception Sys_error m -> Error m)
        else if Sys.file_exists path then
          if Filename.check_suffix path ".mod" then Ok ({ name = path; files = [ path ] } :: found) else acc
        else Error (path ^ ": no such file or folder")
  in
  (* A path named on the command line is a program whatever its extension. *)
  List.fold_left (fun acc p ->
      match acc with
      | Error _ -> acc
      | Ok found when (not (is_dir p)) && Sys.file_exists p -> Ok ({ name = p; files = [ p ] } :: found)
      | _ -> walk acc p) (Ok []) paths
  |> Result.map List.rev

type verdict = Agree of int | Diverge of Event_diff.divergence | Broken of string

(* The first line of what the command wrote on standard error, which is otherwise ignored: a
   tool that cannot write its stream often says why there. *)
let stderr_note (r : Implementation.result) =
  match String.split_on_char '\n' (String.trim r.stderr) with
  | first :: _ when first <> "" -> Printf.sprintf " (its standard error: %s)" (Event_stream.clip first)
  | _ -> ""

let run_lines who ?timeout ~template ~on_line files =
  match Implementation.run ?timeout ~template ~on_line files with
  | exception (Unix.Unix_error (e, _, _)) -> Error (Printf.sprintf "%s could not be run: %s" who (Unix.error_message e))
  | exception (Sys_error m) -> Error (Printf.sprintf "%s could not be run: %s" who m)
  | r -> (
      match r.refused, r.status, Implementation.death r.status with
      | Some m, _, _ ->
          Error (Printf.sprintf "%s wrote something that is not an event stream: %s%s" who m (stderr_note r))
      | None, `Timed_out, _ -> Error (Printf.sprintf "%s did not finish in time%s" who (stderr_note r))
      | None, _, Some death -> Error (Printf.sprintf "%s was %s%s" who death (stderr_note r))
      | None, _, None -> Ok ())

let run_stream who ?timeout ~template files =
  let stream = Event_stream.reader () in
  Result.map (fun () -> Event_stream.contents stream)
    (run_lines who ?timeout ~template ~on_line:(Event_stream.add_line stream) files)

let compare_streams ?ignore ~(expected : Event_stream.t) ~(actual : Event_stream.t) () =
  (* An implementation of schema rapid-sem/1 is compared on what /1 says (Schema_compat); one
     of /2 on everything. *)
  let v1 = actual.schema = Some "rapid-sem/1" && expected.schema = Some Schema_compat.current in
  if actual.schema <> expected.schema && not v1 then
    Broken (Printf.sprintf "the implementation's first line names the schema %s; expected %s"
              (Event_stream.clip (Option.value actual.schema ~default:"(none)"))
              (String.concat " or " Schema_compat.accepted))
  else
    let expected_events, actual_events =
      if v1 then (Schema_compat.to_v1 expected.events, Schema_compat.v1_actual actual.events)
      else (expected.events, actual.events) in
    match Event_diff.compare ?ignore ~expected:expected_events ~actual:actual_events () with
    | None -> Agree (List.length expected_events)
    | Some d -> Diverge d

(* The implementation's events are compared as they come (Event_check), not kept: its memory is
   bounded by a line whatever it writes (doc/oracle.md, "Bounds"). *)
let check ?ignore ?timeout ~reference ~impl program =
  match run_stream "rapid-sem" ?timeout ~template:reference program.files with
  | Error m -> Broken m
  | Ok expected -> (
      let checker = Event_check.create ?ignore ~expected () in
      match run_lines "the implementation" ?timeout ~template:impl ~on_line:(Event_check.add_line checker)
              program.files with
      | Error m -> Broken m
      | Ok () -> (
          match Event_check.finish checker with
          | Agree n -> Agree n
          | Diverge d -> Diverge d
          | Broken m -> Broken m))

let verdict_report program = function
  | Agree n -> Printf.sprintf "%s: agree (%d events)\n" program.name n
  | Diverge d -> Event_diff.report ~file:program.name d
  | Broken m -> Printf.sprintf "%s: %s\n" program.name m

let self_reference () =
  Unix.putenv "RAPID_SEM" Sys.executable_name;
  Filename.quote Sys.executable_name ^ " run --json {files}"
