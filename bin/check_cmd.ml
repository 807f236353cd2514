(* rapid-sem check: task buffers against the static semantics (Rapid_load.Buffer_check), the
   diagnostics as text, JSON or SARIF (Check_output). *)

open Cmdliner
open Rapid_syntax

(* One buffer, or one per --task (its name and files). *)
let buffers files tasks =
  if tasks = [] then Ok [ ("", files) ]
  else if files <> [] then Error "rapid-sem: with --task, the files are named in each --task NAME=FILE,..."
  else
    let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
    List.fold_left (fun acc t -> Result.bind acc (fun l ->
        match String.index_opt t '=' with
        | Some i when i > 0 && i < String.length t - 1 ->
            let name = String.sub t 0 i in
            if List.exists (fun (n, _) -> same n name) l then
              Error (Printf.sprintf "rapid-sem: --task %s is given twice: task names are unique" name)
            else Ok (l @ [ (name, String.split_on_char ',' (String.sub t (i + 1) (String.length t - i - 1))) ])
        | _ -> Error (Printf.sprintf "rapid-sem: --task %s: expected NAME=FILE[,FILE...]" t))) (Ok []) tasks

let cmd =
  let files = Arg.(value & pos_all string [] & info [] ~docv:"FILE"
                     ~doc:"RAPID module files: one task buffer (without --task).") in
  let tasks = Arg.(value & opt_all string [] & info [ "task" ] ~docv:"NAME=FILE[,FILE...]"
                     ~doc:"A task buffer of its own (ch. 14): its name and its module files. Repeat for several \
                           tasks, checked each on its own and then together: a system-global persistent has one \
                           type in every task (doc/user-guide.md, \"Several tasks\").") in
  let allow_unknown =
    Arg.(value & flag & info [ "allow-unknown" ]
           ~doc:"Report a name that is neither declared nor installed as a warning, and go on: \
                 real programs call installed routines beyond rapid-sem's environment.")
  in
  let strict =
    Arg.(value & flag & info [ "strict" ] ~doc:"Refuse the dialect extensions of doc/dialect.md.")
  in
  let format =
    Arg.(value & opt (enum [ ("text", Check_output.Text); ("json", Check_output.Json);
                             ("sarif", Check_output.Sarif) ]) Check_output.Text
         & info [ "format" ] ~docv:"FORMAT"
             ~doc:"$(b,text) (standard error, the default), $(b,json) or $(b,sarif) (SARIF 2.1.0), \
                   both on standard output: every diagnostic with its file, region, class, \
                   sections, message and hint (doc/user-guide.md).")
  in
  let run files tasks allow_unknown strict format io robot robotware =
    Cli.guard @@ fun () ->
    (* A controller backup: its tasks, each --task NAME=FILE,... replacing a task's files, and its
       EIO.cfg unless --io names another; a .pgf file: its modules. *)
    match Rapid_run.Backup_setup.input ~robot files with
    | Error m -> prerr_endline m; Cli.exit_static_error
    | Ok input ->
    let files, own, io, several, robotware, units = match input with
      | Files fs -> (fs, [], io, tasks <> [], robotware, [])
      | Cell c ->
          if format = Check_output.Text then List.iter prerr_endline c.warnings;
          let given = List.filter_map (fun t -> match String.index_opt t '=' with
              | Some i -> Some (String.sub t 0 i) | None -> None) tasks in
          let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
          let own = List.filter_map (fun (t : Rapid_load.Backup.task) ->
              if List.exists (same t.name) given then None else Some (t.name, t.files)) c.backup.tasks in
          ([], own, (match io with Some _ -> io | None -> c.backup.eio), true,
           (match robotware with Some _ -> robotware | None -> c.backup.robotware), c.backup.units) in
    let buffers = match own, buffers files tasks with
      | [], b -> b
      | own, Ok [ ("", []) ] -> Ok own
      | own, Ok b -> Ok (own @ b)
      | _, e -> e in
    match buffers, Rapid_run.Run_setup.read_io io, Rapid_run.Run_setup.load_robot robot with
    | Error m, _, _ | _, Error m, _ | _, _, Error m -> prerr_endline m; Cli.exit_static_error
    | Ok [ (_, []) ], _, _ ->
        prerr_endline "rapid-sem: required argument FILE is missing (or give --task NAME=FILE)"; Cli.exit_static_error
    | Ok buffers, Ok io, Ok _ ->
    let io = { io with Rapid_controller.Io_config.mechanical_units = units } in
    (* R-14-taskid: the tasks' predefined taskid variables, as a run of these tasks has them. *)
    let io = if several then { io with task_ids = List.filter (( <> ) "") (List.map fst buffers) } else io in
    let robotware = Option.value robotware ~default:Rapid_syntax.Robotware.default in
    let options = { Parse.default_options with strict; robotware } in
    let parsed = List.map (fun (name, files) -> (name, List.map (Parse.parse_file ~options) files)) buffers in
    let syntax_errors =
      List.concat_map (fun (_, p) -> List.filter_map (function Error d -> Some d | Ok _ -> None) p) parsed in
    let print = Check_output.print ~version:Cli.version format in
    if syntax_errors <> [] then begin
      print (List.map Check_output.of_diagnostic syntax_errors);
      Cli.exit_static_error
    end
    else
      let buffers = List.map (fun (name, p) ->
          { Rapid_load.Buffer_check.name; modules = List.filter_map Result.to_option p }) parsed in
      match Rapid_load.Buffer_check.check ~allow_unknown ~io ~several buffers with
      | Error d ->
          Printf.eprintf "rapid-sem: internal error: the installed environment does not parse: %s\n"
            (Diagnostic.to_string d);
          Cli.exit_internal
      | Ok { reports; unknown_summaries } ->
          print (List.map Check_output.of_report reports);
          (* JSON and SARIF carry the warnings themselves: the summary is for people. *)
          if format = Check_output.Text then
            List.iter (fun (name, s) -> prerr_endline (if name = "" then s else "task " ^ name ^ ": " ^ s))
              unknown_summaries;
          if List.exists (fun (r : Rapid_typing.Report.t) -> r.severity = Error) reports then Cli.exit_static_error
          else Cli.exit_ok
  in
  let doc = "check RAPID modules, as one task buffer, against the static semantics" in
  let man = [
    `S Manpage.s_description;
    `P "Reads each FILE as a module and checks them together as one task buffer (§9.1) \
        against the rules of chapters 2-5 and 9 of the RAPID kernel manual, with the installed \
        environment of types, data and routines that real programs use. Each error is reported \
        on standard error as $(b,FILE:LINE:COL: semantic error: MESSAGE (§x.y)), with a hint \
        on an indented next line where one helps; independent errors are all reported in one \
        run. $(b,--format json) and $(b,--format sarif) write them all to standard output \
        instead. A FILE $(b,-) is standard input.";
    `P "With $(b,--task NAME=FILE,...) (repeated), checks several task buffers instead, as \
        $(b,rapid-sem run --task) loads them: each on its own, then, when none has an error, \
        together: a system-global persistent declared with another type than in an earlier \
        task is an error at the later declaration (chapter 14).";
    `P "A FILE that is a controller backup's folder checks the tasks it configures (SYSPAR/SYS.cfg, \
        BACKINFO/backinfo.txt, RAPID/TASKn) with the signals of its SYSPAR/EIO.cfg; a $(b,.pgf) program file, \
        the modules it lists (doc/user-guide.md, \"Controller backups\").";
    `S Manpage.s_exit_status;
    `P "0 when there is no static error (warnings allowed); 2 when there is one.";
  ] in
  Cmd.v (Cmd.info "check" ~doc ~man)
    Term.(const run $ files $ tasks $ allow_unknown $ strict $ format $ Run_args.io_arg $ Run_args.robot_arg
          $ Run_args.robotware_arg)
