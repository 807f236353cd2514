(* The corpus of test/realworld: modules written the way programs for real controllers are
   (ROS driver, CAD paths, socket server, palletiser, ...). Each parses, survives printing, and
   each task buffer of tasks.txt checks with --allow-unknown without a single error: a name of
   the installed system that rapid-sem's environment lacks, or an I/O signal of the controller's
   configuration, may only be a warning (issue: no false semantic errors on real code). *)

open Rapid_syntax

let dir = "realworld"

let tasks () =
  let ic = open_in (Filename.concat dir "tasks.txt") in
  let rec read acc =
    match input_line ic with
    | line when String.length line = 0 || line.[0] = '#' -> read acc
    | line -> (
        match String.index_opt line ':' with
        | Some i ->
            let files = String.sub line (i + 1) (String.length line - i - 1)
                        |> String.split_on_char ' ' |> List.filter (( <> ) "") in
            read ((String.sub line 0 i, files) :: acc)
        | None -> read acc)
    | exception End_of_file -> close_in ic; List.rev acc
  in
  read []

let corpus_files () =
  Sys.readdir dir |> Array.to_list
  |> List.filter (fun f -> Filename.check_suffix f ".mod" || Filename.check_suffix f ".sys")
  |> List.sort compare

let parse file =
  match Parse.parse_file (Filename.concat dir file) with
  | Ok m -> m
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)

let every_file_in_a_task () =
  let listed = List.concat_map snd (tasks ()) in
  List.iter (fun f ->
      if not (List.mem f listed) then Alcotest.failf "%s is in no task of tasks.txt" f) (corpus_files ())

let parses_and_prints () =
  List.iter (fun f ->
      let m = parse f in
      let printed = Printer.module_declaration m in
      match Parse.parse_string ~name:f printed with
      | Ok m' ->
          Alcotest.(check string) (f ^ " round trip") (Ast_dump.module_declaration m)
            (Ast_dump.module_declaration m')
      | Error d -> Alcotest.failf "%s printed does not parse: %s" f (Diagnostic.to_string d))
    (corpus_files ())

let task_checks (name, files) =
  Alcotest.test_case ("check --allow-unknown: " ^ name) `Quick (fun () ->
      let installed = match Rapid_typing.Installed_env.modules () with
        | Ok ms -> ms | Error d -> Alcotest.failf "installed: %s" (Diagnostic.to_string d) in
      let result =
        Rapid_typing.Check.check_task ~options:{ allow_unknown = true } ~installed
          (List.map parse files) in
      match Rapid_typing.Check.errors result with
      | [] -> ()
      | errors ->
          Alcotest.failf "false errors:\n%s"
            (String.concat "\n" (List.map Rapid_typing.Report.to_string errors)))

let suite =
  ( "realworld",
    [ Alcotest.test_case "every file belongs to a task" `Quick every_file_in_a_task;
      Alcotest.test_case "every file parses and round-trips" `Quick parses_and_prints ]
    @ List.map task_checks (tasks ()) )
