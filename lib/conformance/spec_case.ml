type expectation =
  | Accepted
  | Refused of { error_class : string; file : string option; line : int; col : int }

type t = {
  path : string;
  files : string list;
  sections : string list;
  expectation : expectation option;
  strict : bool;
  robotware : Rapid_syntax.Robotware.t;
  allow_unknown : bool;
  stub_unmodelled : bool;
  description : string option;
  problems : string list;
  format : string;
  run : run option;
}

and run = {
  entry : string;
  outputs : string list;
  exit_status : int;
  error : (string * int * int) option;
  error_file : string option;
  max_steps : int option;
  retry_limit : int option;
  io : string option;
  statement_time : float option;
  max_time : float option;
  home : string option;
  tasks : (string * string list) list;
  schedule : int option;
  motion_task : string option;
  task_entries : (string * string) list;
  robot : string option;
  egm_devices : string list;
  base_frames : string list;
  operator : string option;
}

let no_run = { entry = "main"; outputs = []; exit_status = 0; error = None; error_file = None;
               max_steps = None; retry_limit = None; io = None; statement_time = None; max_time = None; home = None;
               tasks = []; schedule = None; motion_task = None; task_entries = [];
               robot = None; egm_devices = []; base_frames = []; operator = None }

let known_formats = [ "1"; "2"; "3"; "4" ]
let checks_semantics case = case.format = "2" || case.format = "3" || case.format = "4"

let error_classes = [ "lexical-error"; "syntax-error"; "fatal-error"; "semantic-error" ]

let expectation_to_string = function
  | Accepted -> "ok"
  | Refused { error_class; file = None; line; col } -> Printf.sprintf "%s %d:%d" error_class line col
  | Refused { error_class; file = Some f; line; col } -> Printf.sprintf "%s %s:%d:%d" error_class f line col

(* A directive is a line whose first non-blank characters are '!', optional blanks, '@'. *)
let directive line =
  let n = String.length line in
  let i = ref 0 in
  let skip_blanks () = while !i < n && (line.[!i] = ' ' || line.[!i] = '\t') do incr i done in
  skip_blanks ();
  if !i < n && line.[!i] = '!' then begin
    incr i;
    skip_blanks ();
    if !i < n && line.[!i] = '@' then begin
      let rest = String.trim (String.sub line (!i + 1) (n - !i - 1)) in
      match String.index_opt rest ' ' with
      | None -> Some (rest, "")
      | Some k -> Some (String.sub rest 0 k, String.trim (String.sub rest k (String.length rest - k)))
    end
    else None
  end
  else None

let parse_expect value =
  let position error_class p =
    let bad () = Error (Printf.sprintf "bad position %S in @expect" p) in
    let make file l c =
      match int_of_string_opt l, int_of_string_opt c with
      | Some line, Some col when line > 0 && col > 0 -> Ok (Refused { error_class; file; line; col })
      | _ -> bad ()
    in
    match String.split_on_char ':' p with
    | [ l; c ] -> make None l c
    | [ f; l; c ] when f <> "" -> make (Some f) l c
    | _ -> bad ()
  in
  match String.split_on_char ' ' value |> List.filter (( <> ) "") with
  | [ "ok" ] -> Ok Accepted
  | [ error_class; p ] when List.mem error_class error_classes -> position error_class p
  | _ -> Error (Printf.sprintf "cannot read @expect %S" value)

let is_module_file f = Filename.check_suffix f ".mod" || Filename.check_suffix f ".sys"

(* A file to read, or why it cannot be: opening a FIFO would wait for a writer for ever, and
   reading a device need not end. *)
let readable_file path =
  match (Unix.stat path).st_kind with
  | S_REG -> Ok ()
  | S_DIR -> Error "a folder, not a file"
  | S_FIFO -> Error "a FIFO, not a regular file"
  | S_CHR | S_BLK -> Error "a device, not a regular file"
  | S_SOCK -> Error "a socket, not a regular file"
  | S_LNK -> Error "a symbolic link that leads nowhere"
  | exception Unix.Unix_error (e, _, _) -> Error (Unix.error_message e)

let read path =
  let listing_problem = ref None in
  let files =
    if Sys.file_exists path && Sys.is_directory path then
      match Sys.readdir path with
      | names ->
          names |> Array.to_list |> List.filter is_module_file |> List.sort compare
          |> List.map (Filename.concat path)
      | exception Sys_error m -> listing_problem := Some m; []
    else [ path ]
  in
  let empty = { path; files; sections = []; expectation = None; strict = false;
                robotware = Rapid_syntax.Robotware.default;
                allow_unknown = false;
                stub_unmodelled = false; description = None; problems = []; format = "1"; run = None } in
  let with_run case f = { case with run = Some (f (Option.value case.run ~default:no_run)) } in
  (* [! @output TEXT]: TEXT is everything after "@output" and one space, verbatim. *)
  let output_text line =
    let line = if String.length line > 0 && line.[String.length line - 1] = '\r'
      then String.sub line 0 (String.length line - 1) else line in
    match String.index_opt line '@' with
    | None -> ""
    | Some i ->
        let rest = String.sub line (i + 7) (String.length line - i - 7) in
        if String.length rest > 0 && rest.[0] = ' ' then String.sub rest 1 (String.length rest - 1) else rest
  in
  let add_problem case m = { case with problems = case.problems @ [ m ] } in
  (* Format 4: [! @task NAME] in a file of a .task folder: the task whose buffer it belongs to. *)
  let task_of = ref [] in
  let case = List.fold_left (fun case file ->
      match Result.bind (Result.map_error (fun m -> file ^ ": " ^ m) (readable_file file))
              (fun () -> In_channel_compat.read_lines file) with
      | Error message -> add_problem case message
      | Ok lines ->
          List.fold_left (fun case line ->
              match directive line with
              | None -> case
              | Some ("section", v) when v <> "" -> { case with sections = case.sections @ [ v ] }
              | Some ("expect", v) -> (
                  match parse_expect v, case.expectation with
                  | Ok e, None -> { case with expectation = Some e }
                  | Ok _, Some _ -> add_problem case "more than one @expect"
                  | Error m, _ -> add_problem case m)
              | Some ("options", v) ->
                  List.fold_left (fun case w ->
                      match w with
                      | "strict" -> { case with strict = true }
                      | "robotware-6" -> { case with robotware = Rapid_syntax.Robotware.Rw6 }
                      | "allow-unknown" -> { case with allow_unknown = true }
                      | "stub-unmodelled" -> { case with stub_unmodelled = true }
                      | other -> add_problem case ("unknown option " ^ other))
                    case (String.split_on_char ' ' v |> List.filter (( <> ) ""))
              | Some ("description", v) -> { case with description = Some v }
              | Some ("format", v) -> { case with format = v }
              | Some ("task", v) when v <> "" && not (String.contains v ' ') ->
                  if List.mem_assoc file !task_of then add_problem case (file ^ ": more than one @task")
                  else (task_of := (file, v) :: !task_of; case)
              | Some ("schedule", v) -> (
                  match int_of_string_opt v with
                  | Some n when n >= 0 -> with_run case (fun r -> { r with schedule = Some n })
                  | _ -> add_problem case ("bad @schedule " ^ v))
              | Some ("motion-task", v) when v <> "" -> with_run case (fun r -> { r with motion_task = Some v })
              | Some ("output", _) -> with_run case (fun r -> { r with outputs = r.outputs @ [ output_text line ] })
              | Some ("entry", v) -> (
                  (* Format 4: [@entry TASK=ROUTINE], the entry routine of one task. *)
                  match String.index_opt v '=' with
                  | Some i when i > 0 && i < String.length v - 1 ->
                      with_run case (fun r ->
                          { r with task_entries = r.task_entries
                                                  @ [ (String.sub v 0 i,
                                                       String.sub v (i + 1) (String.length v - i - 1)) ] })
                  | Some _ -> add_problem case ("bad @entry " ^ v)
                  | None -> with_run case (fun r -> { r with entry = v }))
              | Some ("exit", v) -> (
                  match int_of_string_opt v with
                  | Some n -> with_run case (fun r -> { r with exit_status = n })
                  | None -> add_problem case ("bad @exit " ^ v))
              | Some ("error", v) -> (
                  match String.split_on_char ' ' v |> List.filter (( <> ) "") with
                  | [ name; pos ] -> (
                      match List.rev (String.split_on_char ':' pos) with
                      | c :: l :: file when int_of_string_opt l <> None && int_of_string_opt c <> None ->
                          let file = match file with [] -> None | f -> Some (String.concat ":" (List.rev f)) in
                          with_run case (fun r -> { r with error = Some (name, int_of_string l, int_of_string c);
                                                           error_file = file })
                      | _ -> add_problem case ("bad @error " ^ v))
                  | _ -> add_problem case ("bad @error " ^ v))
              | Some ("max-steps", v) -> (
                  match int_of_string_opt v with
                  | Some n -> with_run case (fun r -> { r with max_steps = Some n })
                  | None -> add_problem case ("bad @max-steps " ^ v))
              | Some ("retry-limit", v) -> (
                  match int_of_string_opt v with
                  | Some n -> with_run case (fun r -> { r with retry_limit = Some n })
                  | None -> add_problem case ("bad @retry-limit " ^ v))
              | Some ("io", v) when v <> "" ->
                  (* The stimulus file is named relative to the case's folder. *)
                  let dir = if Sys.file_exists path && Sys.is_directory path then path else Filename.dirname path in
                  with_run case (fun r -> { r with io = Some (Filename.concat dir v) })
              | Some ("robot", v) when v <> "" ->
                  (* The robot description of the run (doc/motion.md), beside the case. *)
                  let dir = if Sys.file_exists path && Sys.is_directory path then path else Filename.dirname path in
                  (* a file beside the case, else a name of the robot library (doc/motion.md) *)
                  let file = Filename.concat dir v in
                  with_run case (fun r -> { r with robot = Some (if Sys.file_exists file then file else v) })
              | Some ("home", v) when v <> "" ->
                  (* The files HOME: holds at the start, a folder beside the case (doc/services.md). *)
                  let dir = if Sys.file_exists path && Sys.is_directory path then path else Filename.dirname path in
                  with_run case (fun r -> { r with home = Some (Filename.concat dir v) })
              | Some ("operator", v) when v <> "" ->
                  (* The FlexPendant operator's script, a file beside the case (--operator, R-13-ui2). *)
                  let dir = if Sys.file_exists path && Sys.is_directory path then path else Filename.dirname path in
                  let file = Filename.concat dir v in
                  (match Rapid_controller.Operator_script.of_file file with
                   | Ok _ -> with_run case (fun r -> { r with operator = Some file })
                   | Error m -> add_problem case ("bad @operator " ^ m))
              | Some ("egm-device", v) when Result.is_ok (Rapid_controller.Egm_channel.parse_devices v) ->
                  (* A UdpUc device of EGM (rapid-sem run --egm-device, doc/services.md). *)
                  with_run case (fun r -> { r with egm_devices = r.egm_devices @ [ v ] })
              | Some ("base-frame", v) when Result.is_ok (Rapid_run.Run_setup.parse_base_frames [ v ]) ->
                  (* where the cell mounts a robot (rapid-sem run --base-frame, doc/rulings.md R-bk-12) *)
                  with_run case (fun r -> { r with base_frames = r.base_frames @ [ v ] })
              | Some (("statement-time" | "max-time") as k, v) -> (
                  match float_of_string_opt v with
                  | Some f when f >= 0. && Float.is_finite f ->
                      with_run case (fun r ->
                          if k = "max-time" then { r with max_time = Some f } else { r with statement_time = Some f })
                  | _ -> add_problem case (Printf.sprintf "bad @%s %s" k v))
              | Some (k, v) -> add_problem case (Printf.sprintf "unknown directive @%s %s" k v))
            case lines) empty files
  in
  let case = match !listing_problem with Some m -> add_problem case m | None -> case in
  (* The tasks in the order their first file comes, each with its files in name order. *)
  let case =
    if !task_of = [] then case
    else if List.exists (fun f -> not (List.mem_assoc f !task_of)) files then
      add_problem case "in a case of several tasks, every file names its task (@task)"
    else if case.format <> "4" then add_problem case "@task is format 4"
    else
      let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
      let tasks = List.fold_left (fun acc f ->
          let t = List.assoc f !task_of in
          if List.exists (fun (n, _) -> same n t) acc then
            List.map (fun (n, fs) -> if same n t then (n, fs @ [ f ]) else (n, fs)) acc
          else acc @ [ (t, [ f ]) ]) [] files in
      with_run case (fun r -> { r with tasks }) in
  let case = match case.run with
    | Some { task_entries = (t, _) :: _; tasks; _ }
      when not (List.exists (fun (n, _) -> String.lowercase_ascii n = String.lowercase_ascii t) tasks) ->
        add_problem case (Printf.sprintf "@entry %s=...: no file names the task %s (@task)" t t)
    | _ -> case in
  let case =
    if files = [] && !listing_problem = None then add_problem case "a .task folder without modules" else case in
  let case = if case.format = "3" && case.run = None then { case with run = Some no_run } else case in
  let case = if case.expectation = None then add_problem case "no @expect directive" else case in
  if case.sections = [] then add_problem case "no @section directive" else case
