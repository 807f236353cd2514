module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
module Stream = Rapid_oracle.Event_stream

type result = { case : Spec_case.t; passed : bool; skipped : bool; detail : string }

let mode (case : Spec_case.t) =
  match case.format with "1" -> "parse" | "2" -> "check" | _ -> "run"

let several_tasks (case : Spec_case.t) =
  match case.run with Some { tasks = _ :: _; _ } -> true | _ -> false

let options (case : Spec_case.t) =
  let run = case.run in
  let tasks = several_tasks case in
  List.concat [
    (if case.strict then [ "--strict" ] else []);
    (let module R = Rapid_syntax.Robotware in
     if case.robotware <> R.default then [ "--robotware"; R.to_string case.robotware ] else []);
    (if case.allow_unknown then [ "--allow-unknown" ] else []);
    (if case.stub_unmodelled then [ "--stub-unmodelled" ] else []);
    (match run with Some { io = Some f; _ } -> [ "--io"; Filename.quote f ] | _ -> []);
    (* With several tasks, {tasks} names each task's entry. *)
    (match run with Some { entry; _ } when entry <> "main" && not tasks -> [ "--entry"; entry ] | _ -> []);
    (match run with Some { retry_limit = Some n; _ } -> [ "--retry-limit"; string_of_int n ] | _ -> []);
    (match run with Some { statement_time = Some t; _ } -> [ "--statement-time"; Printf.sprintf "%g" t ] | _ -> []);
    (match run with Some { max_time = Some t; _ } -> [ "--max-time"; Printf.sprintf "%g" t ] | _ -> []);
    (* Without them a case of @max-steps or @robot asks another question than the one it
       states: an endless loop runs to the timeout, a track robot's moves fail. *)
    (match run with Some { max_steps = Some n; _ } -> [ "--max-steps"; string_of_int n ] | _ -> []);
    (match run with Some { robot = Some f; _ } -> [ "--robot"; Filename.quote f ] | _ -> []);
    (match run with Some { operator = Some f; _ } -> [ "--operator"; Filename.quote f ] | _ -> []);
    (match run with Some { egm_devices; _ } -> List.concat_map (fun d -> [ "--egm-device"; d ]) egm_devices | _ -> []);
    (match run with
     | Some { base_frames; _ } -> List.concat_map (fun b -> [ "--base-frame"; Filename.quote b ]) base_frames
     | _ -> []);
  ]

(* Format 4 as rapid-sem run spells several tasks: a task's entry as the case's runner takes it,
   its own @entry TASK=ROUTINE (the last one written), else the case's @entry. *)
let task_options (case : Spec_case.t) =
  match case.run with
  | Some ({ tasks = _ :: _; _ } as run) ->
      let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
      let entry_of name = match List.find_opt (fun (t, _) -> same t name) (List.rev run.task_entries) with
        | Some (_, r) -> r | None -> run.entry in
      List.concat [
        List.concat_map (fun (name, files) -> [ "--task"; Filename.quote (name ^ "=" ^ String.concat "," files) ])
          run.tasks;
        List.concat_map (fun (name, _) ->
            let e = entry_of name in
            if e = "main" then [] else [ "--entry"; Filename.quote (name ^ "=" ^ e) ]) run.tasks;
        (match run.schedule with Some n -> [ "--schedule"; string_of_int n ] | None -> []);
        (match run.motion_task with Some t -> [ "--motion-task"; Filename.quote t ] | None -> []);
      ]
  | _ -> []

let replace_all = Rapid_oracle.Implementation.replace_all

let takes_tasks template =
  let sub = "{tasks}" in
  let n = String.length sub in
  let rec go i = i + n <= String.length template && (String.sub template i n = sub || go (i + 1)) in
  go 0

(* A run's mass memory (doc/services.md): a fresh folder for each run, so that the tool's run of
   a case and rapid-sem's own never see each other's files, with HOME: holding the case's @home
   folder; given to the run as [--fs DIR] in {options}. *)
let with_mass_memory (case : Spec_case.t) f =
  match case.run with
  | None -> f []
  | Some run ->
      let sandbox = Rapid_controller.File_sandbox.temporary () in
      Fun.protect ~finally:(fun () -> Rapid_controller.File_sandbox.remove sandbox) @@ fun () ->
      Option.iter (Rapid_controller.File_sandbox.seed sandbox ~device:"HOME:") run.home;
      f [ "--fs"; Filename.quote (Rapid_controller.File_sandbox.root sandbox) ]

let command ?(fs = []) ~template (case : Spec_case.t) =
  let with_mode = replace_all ~sub:"{mode}" ~by:(mode case)
      (replace_all ~sub:"{options}" ~by:(String.concat " " (options case @ fs))
         (replace_all ~sub:"{tasks}" ~by:(String.concat " " (task_options case)) template)) in
  (* The files of several tasks are in {tasks}: rapid-sem run takes no FILE beside --task. *)
  if several_tasks case then replace_all ~sub:"{file}" ~by:"" (replace_all ~sub:"{files}" ~by:"" with_mode)
  else Rapid_oracle.Implementation.command_line ~template:with_mode ~files:case.files

let field name = function `Assoc f -> List.assoc_opt name f | _ -> None
(* The implementation's strings: compared as they are, clipped where a detail shows them (Stream.clip). *)
let string_field name j = match field name j with Some (`String s) -> Some s | _ -> None
let shown_field name j = Option.map Stream.clip (string_field name j)
let int_field name j = match field name j with Some (`Int n) -> Some n | _ -> None

let place j =
  match field "at" j with
  | Some at -> (
      match int_field "line" at, int_field "col" at with
      | Some l, Some c -> Some (Filename.basename (Option.value (string_field "file" at) ~default:""), l, c)
      | _ -> None)
  | None -> None

let show_place = function Some (f, l, c) -> Printf.sprintf "%s:%d:%d" (Stream.clip f) l c | None -> "(no place)"

(* The exit status of spec/README.md's format 3, from an end object. *)
let status_of outcome =
  match outcome with
  | "ended" -> 0 | "stopped" -> 1 | "refused" -> 2 | "exhausted" | "deadlock" | "running" -> 3
  | "unsupported" -> 4 | _ -> 125

(* An implementation's output lines in a detail: each clipped, and at most the first 20. *)
let shown_outputs lines =
  let shown = List.filteri (fun i _ -> i < 20) lines in
  String.concat " | " (List.map (fun l -> Stream.clip (Printf.sprintf "%S" l)) shown)
  ^ (if List.length lines > 20 then Printf.sprintf " | ... (%d lines)" (List.length lines) else "")

let judge (case : Spec_case.t) (events : Stream.event list) =
  let ends = List.filter (fun e -> Stream.kind e = "end") events in
  match ends with
  | [] -> Error "the implementation wrote no end object"
  | _ :: _ :: _ -> Error "the implementation wrote more than one end object"
  | [ last ] -> (
      let outcome = Option.value (string_field "outcome" last) ~default:"" in
      match case.expectation, case.run with
      | Some (Refused { error_class; file; line; col }), _ ->
          let got_class = Option.value (string_field "class" last) ~default:"" in
          let got = place last in
          let file_ok = match file, got with Some f, Some (g, _, _) -> f = g | None, _ -> true | _ -> false in
          if outcome = "refused" && got_class = error_class && file_ok
             && (match got with Some (_, l, c) -> l = line && c = col | None -> false)
          then Ok ()
          else Error (Printf.sprintf "expected %s at %d:%d; got %s%s" error_class line col (Stream.clip outcome)
                        (if outcome = "refused" then Printf.sprintf " %s at %s" (Stream.clip got_class) (show_place got)
                         else ""))
      | Some Accepted, None ->
          if outcome = "accepted" || outcome = "ended" then Ok ()
          else Error (Printf.sprintf "expected the case to be accepted; got %s %s"
                        (Stream.clip outcome) (Option.value (shown_field "class" last) ~default:""))
      | Some Accepted, Some run ->
          let output = List.filter_map (fun e ->
              if Stream.kind e = "output" then string_field "text" e else None) events in
          let status = status_of outcome in
          let problems =
            (if output <> run.outputs then
               [ Printf.sprintf "output %s, expected %s" (shown_outputs output)
                   (String.concat " | " (List.map (Printf.sprintf "%S") run.outputs)) ] else [])
            @ (if status <> run.exit_status then
                 [ Printf.sprintf "exit %d (%s), expected %d" status (Stream.clip outcome) run.exit_status ] else [])
            @ (match run.error with
               | Some (name, l, c) -> (
                   let got_name = Option.value (string_field "name" last) ~default:"" in
                   match place last with
                   | Some (f, gl, gc) when got_name = name && gl = l && gc = c
                                           && (match run.error_file with Some ef -> ef = f | None -> true) -> []
                   | got ->
                       [ Printf.sprintf "error %s at %s, expected %s %d:%d" (Stream.clip got_name) (show_place got)
                           name l c ])
               | None -> [])
          in
          if problems = [] then Ok () else Error (String.concat "; " problems)
      | None, _ -> Error "the case has no expectation")

(* With a reference (rapid-sem's own run --json), a run case passes only when the events agree
   too: the first divergence is named by its index, as rapid-sem oracle names it. *)
let same_events ?ignore ?timeout ~reference (case : Spec_case.t) (actual : Stream.t) =
  match with_mass_memory case (fun fs ->
      Rapid_oracle.Oracle.run_stream "rapid-sem" ?timeout ~template:(command ~fs ~template:reference case) []) with
  | Error m -> Error m
  | Ok expected -> (
    if several_tasks case then
      match Rapid_oracle.Task_streams.compare ?ignore ~expected ~actual () with
      | Agree _ -> Ok ()
      | Broken m -> Error m
      | Diverge d -> Error (Rapid_oracle.Task_streams.report d)
    else
    match Rapid_oracle.Oracle.compare_streams ?ignore ~expected ~actual () with
    | Agree _ -> Ok ()
    | Broken m -> Error m
    | Diverge d ->
        let show = function Some e -> Stream.show e | None -> "(no more events)" in
        Error (Printf.sprintf "event %d: expected %s, got %s" d.index (show d.expected) (show d.actual)))

let no_tasks_detail = "several tasks (format 4): the template has no {tasks}"

let run_case ?(timeout = 60.) ?reference ?ignore ~template (case : Spec_case.t) =
  if not (List.mem case.format Spec_case.known_formats) then
    { case; passed = false; skipped = true; detail = "format " ^ case.format }
  else if several_tasks case && not (takes_tasks template) then
    (* Opt-in: a template without {tasks} is a tool of one task, not failed on several. *)
    { case; passed = false; skipped = true; detail = no_tasks_detail }
  else if case.problems <> [] then
    { case; passed = false; skipped = false; detail = String.concat "; " case.problems }
  else Loopback_lock.exclusive case @@ fun () ->
    match with_mass_memory case (fun fs ->
        Rapid_oracle.Oracle.run_stream "the implementation" ~timeout ~template:(command ~fs ~template case) []) with
    | Error m -> { case; passed = false; skipped = false; detail = m }
    | Ok s -> (
        match judge case s.events with
        | Ok () -> (
            match reference, case.run with
            | Some reference, Some _ -> (
                match same_events ?ignore ~timeout ~reference case s with
                | Ok () -> { case; passed = true; skipped = false; detail = "" }
                | Error m -> { case; passed = false; skipped = false; detail = m })
            | _ -> { case; passed = true; skipped = false; detail = "" })
        | Error m -> { case; passed = false; skipped = false; detail = m })

let xml_escape = Rapid_runtime.Xml_text.escape

let write path text =
  let oc = open_out_bin path in
  Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text)

(* JUnit XML: one test suite per section (a case under its first section), one test case per
   case, a failure element with the detail. *)
let junit_xml results =
  let sections = Hashtbl.create 32 in
  List.iter (fun r ->
      let s = match r.case.Spec_case.sections with s :: _ -> s | [] -> "(none)" in
      Hashtbl.replace sections s (r :: Option.value (Hashtbl.find_opt sections s) ~default:[])) results;
  let names = List.sort compare (Hashtbl.fold (fun k _ acc -> k :: acc) sections []) in
  let b = Buffer.create 4096 in
  Buffer.add_string b "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  let failed l = List.length (List.filter (fun r -> not r.passed && not r.skipped) l) in
  let skipped l = List.length (List.filter (fun r -> r.skipped) l) in
  Printf.bprintf b "<testsuites name=\"rapid-sem conformance\" tests=\"%d\" failures=\"%d\" skipped=\"%d\">\n"
    (List.length results) (failed results) (skipped results);
  List.iter (fun s ->
      let rs = List.rev (Hashtbl.find sections s) in
      Printf.bprintf b "  <testsuite name=\"§%s\" tests=\"%d\" failures=\"%d\" skipped=\"%d\">\n" (xml_escape s)
        (List.length rs) (failed rs) (skipped rs);
      List.iter (fun r ->
          Printf.bprintf b "    <testcase classname=\"spec.§%s\" name=\"%s\"" (xml_escape s)
            (xml_escape r.case.Spec_case.path);
          if r.passed then Buffer.add_string b "/>\n"
          else if r.skipped then Printf.bprintf b "><skipped message=\"%s\"/></testcase>\n" (xml_escape r.detail)
          else Printf.bprintf b "><failure message=\"%s\"/></testcase>\n" (xml_escape r.detail)) rs;
      Buffer.add_string b "  </testsuite>\n") names;
  Buffer.add_string b "</testsuites>\n";
  Buffer.contents b

let json_report results : Yojson.Safe.t =
  `Assoc [
    ("schema", `String "rapid-sem/conformance/1");
    ("passed", `Int (List.length (List.filter (fun r -> r.passed) results)));
    ("failed", `Int (List.length (List.filter (fun r -> not r.passed && not r.skipped) results)));
    ("skipped", `Int (List.length (List.filter (fun r -> r.skipped) results)));
    ("cases", `List (List.map (fun r ->
         `Assoc [ ("case", `String r.case.Spec_case.path);
                  ("sections", `List (List.map (fun s -> `String s) r.case.sections));
                  ("verdict", `String (if r.passed then "passed" else if r.skipped then "skipped" else "failed"));
                  ("detail", `String r.detail) ]) results)) ]

let run ?(verbose = false) ?timeout ?reference ?ignore ?junit ?json ~template out dir =
  let paths, errors = Spec_runner.collect dir in
  List.iter (fun (path, m) -> Format.fprintf out "ERROR %s: %s@." path m) errors;
  let results = List.map (fun p -> run_case ?timeout ?reference ?ignore ~template (Spec_case.read p)) paths in
  List.iter (fun r ->
      if verbose || not r.passed then
        Format.fprintf out "%s %s%s@." (if r.passed then "PASS" else if r.skipped then "SKIP" else "FAIL")
          r.case.Spec_case.path (if r.detail = "" then "" else ": " ^ r.detail)) results;
  let by_section = Hashtbl.create 64 in
  List.iter (fun r ->
      if not r.skipped then
        List.iter (fun s ->
            let p, f = Option.value (Hashtbl.find_opt by_section s) ~default:(0, 0) in
            Hashtbl.replace by_section s (if r.passed then (p + 1, f) else (p, f + 1)))
          (if r.case.sections = [] then [ "(none)" ] else r.case.sections)) results;
  (* Sections sort by their numbers: 2.5 before 2.10 before 10.1. *)
  let key s = List.map (fun p -> Option.value (int_of_string_opt p) ~default:max_int) (String.split_on_char '.' s) in
  let sections = List.sort (fun a b -> compare (key a, a) (key b, b))
      (Hashtbl.fold (fun s _ acc -> s :: acc) by_section []) in
  Format.fprintf out "@.%-10s %7s %7s@." "section" "passed" "failed";
  List.iter (fun s -> let p, f = Hashtbl.find by_section s in Format.fprintf out "%-10s %7d %7d@." s p f) sections;
  Option.iter (fun path -> write path (junit_xml results)) junit;
  Option.iter (fun path -> write path (Json_text.pretty_to_string (json_report results) ^ "\n")) json;
  let passed = List.length (List.filter (fun r -> r.passed) results) in
  let failed = List.length (List.filter (fun r -> not r.passed && not r.skipped) results) + List.length errors in
  let skipped = List.length (List.filter (fun r -> r.skipped) results) in
  let without_tasks = List.length (List.filter (fun r -> r.skipped && r.detail = no_tasks_detail) results) in
  if without_tasks > 0 then
    Format.fprintf out "@.%d case%s of several tasks skipped: the template has no {tasks} \
                        (doc/oracle.md, \"Several tasks\")@."
      without_tasks (if without_tasks = 1 then "" else "s");
  if skipped = 0 then Format.fprintf out "@.%d passed, %d failed@." passed failed
  else Format.fprintf out "@.%d passed, %d failed, %d skipped@." passed failed skipped;
  (passed, failed)
