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

(* The installed environment holds every installed name the corpus uses: what stays unknown
   under --allow-unknown is only the I/O signals of the controllers' configurations, which the
   corpus names by their type's prefix (README.md: di signaldi, do signaldo, ...). *)
let is_signal_name name =
  String.length name > 2
  && List.mem (String.sub name 0 2) [ "di"; "do"; "gi"; "go"; "ai"; "ao" ]
  && Char.uppercase_ascii name.[2] = name.[2] && Char.lowercase_ascii name.[2] <> name.[2]

let installed () =
  match Rapid_typing.Installed_env.modules () with
  | Ok ms -> ms | Error d -> Alcotest.failf "installed: %s" (Diagnostic.to_string d)

let only_signals_unknown (name, files) =
  Alcotest.test_case ("only I/O signals unknown: " ^ name) `Quick (fun () ->
      let result =
        Rapid_typing.Check.check_task ~options:{ allow_unknown = true } ~installed:(installed ())
          (List.map parse files) in
      let others = List.filter (fun (u : Rapid_typing.Check.unknown_name) ->
          not (u.what = "data object" && is_signal_name u.name)) result.unknown in
      if others <> [] then
        Alcotest.failf "names the installed environment lacks: %s"
          (String.concat ", " (List.map (fun (u : Rapid_typing.Check.unknown_name) ->
               Printf.sprintf "%s %s (%s)" u.what u.name (Source.to_string u.first)) others)))

(* The polishing cell run as it is and with --stub-unmodelled. As it is, the run ends at the
   first installed routine rapid-sem does not model (ConfL), at that call. Stubbed, the moves
   and settings run as no-ops and the run goes on to the first feature that is genuinely
   missing: SetDO of doPolisherOn, an I/O signal of the controller's configuration, which is
   unknown here and raises ERR_REFUNKDAT when reached. *)
let run_polishing ~stub_unmodelled =
  let module M = Rapid_semantics.Machine in
  match Rapid_load.Session.load_modules ~allow_unknown:true [ parse "CadPolishCover.mod" ] with
  | Error _ -> Alcotest.fail "the polishing cell does not load"
  | Ok loaded -> (
      match M.start ~host:(Rapid_run.Run.setup ()).host ~stub_unmodelled loaded.program ~entry:"main" with
      | Error m -> Alcotest.fail m
      | Ok cfg ->
          let stubbed = ref [] in
          while M.outcome cfg = Running && M.steps cfg < 1_000_000 do
            List.iter (function Rapid_runtime.Event.Stubbed { routine; _ } -> stubbed := routine :: !stubbed | _ -> ())
              (snd (M.step cfg))
          done;
          (M.outcome cfg, List.rev !stubbed))

let place at =
  let p = Source.start at in
  ((match Source.file_of at with Some f -> Filename.basename (Source.name f) | None -> ""), p.line, p.col)

(* The moves and settings of the polishing cell run now (ConfL, SingArea, MoveL with the motion
   model), with or without --stub-unmodelled: the run goes on to the first feature that is
   genuinely missing, SetDO of doPolisherOn, an I/O signal of the controller's configuration that
   is unknown here (no --io file) and raises ERR_REFUNKDAT when reached. *)
let polishing_runs_to_the_unknown_signal ~stub_unmodelled () =
  match run_polishing ~stub_unmodelled with
  | Stopped { name; at; _ }, stubbed ->
      Alcotest.(check string) "error" "ERR_REFUNKDAT" name;
      Alcotest.(check (triple string int int)) "place" ("CadPolishCover.mod", 329, 9) (place at);
      Alcotest.(check (list string)) "nothing stubbed: all is modelled up to there" [] stubbed
  | _ -> Alcotest.fail "expected the run to stop at the unknown signal doPolisherOn"

let suite =
  ( "realworld",
    [ Alcotest.test_case "every file belongs to a task" `Quick every_file_in_a_task;
      Alcotest.test_case "every file parses and round-trips" `Quick parses_and_prints ]
    @ List.map task_checks (tasks ())
    @ List.map only_signals_unknown (tasks ())
    @ [ Alcotest.test_case "polishing cell: runs to the first unknown signal" `Quick
          (polishing_runs_to_the_unknown_signal ~stub_unmodelled:false);
        Alcotest.test_case "polishing cell: --stub-unmodelled changes nothing there" `Quick
          (polishing_runs_to_the_unknown_signal ~stub_unmodelled:true) ] )
