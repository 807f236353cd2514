(* rapid-sem debug: a stepping session (doc/debugger.md), driven by commands read from standard
   input or from a script file. *)

open Cmdliner
module D = Rapid_tools.Debugger

let cmd =
  let files, entry, max_steps, allow_unknown, max_depth, retry_limit = Run_args.common_run_args in
  let script = Arg.(value & opt (some string) None & info [ "script" ] ~docv:"FILE"
                      ~doc:"Read the debugger's commands from FILE instead of standard input.") in
  let prompt_text = Arg.(value & opt (some string) None & info [ "prompt" ] ~docv:"TEXT"
                           ~doc:"Write TEXT before each command read, whether standard input is a terminal or not \
                                 (default: $(b,(rapid-sem) ) on a terminal, nothing from a pipe or a script); \
                                 an empty TEXT writes none.") in
  let run files entry max_steps allow_unknown max_depth retry_limit controller (robot, base_frames) script prompt_text =
    let input = match script with
      | None -> Ok stdin
      | Some f -> (try Ok (open_in_bin f) with Sys_error m -> Error m) in
    match input with
    | Error m -> Printf.eprintf "rapid-sem: %s\n" m; 2
    | Ok ic ->
    Cli.guard @@ fun () ->
    let options = Run_args.options ~base_frames ~max_steps ~allow_unknown ~max_depth ~retry_limit ~controller ~robot ()
    in
    (* A controller backup or a .pgf file: its one task's modules, read once here and for the data's names. *)
    match Rapid_run.Run_setup.one_task ~notify:Cli.notify options files ~entry with
    | Error f -> Cli.failure f
    | Ok (options, files, entry, robot, events) ->
    (* R-bk-11: START happens at the first continue, not before the session; each warning once. *)
    let said = Hashtbl.create 4 in
    let notify = function
      | Rapid_run.Run_setup.Backup_warning w as n when not (Hashtbl.mem said w) -> Hashtbl.add said w (); Cli.notify n
      | _ -> () in
    let before = List.filter (fun (e : Rapid_run.Task_load.event_routine) -> e.event <> "START") events.before in
    match Rapid_run.Run_setup.start_machine ?robot ~events:{ events with before } ~notify options files ~entry
    with
    | Error f -> Cli.failure f
    | Ok (cfg, _) ->
    let echo = script <> None in
    let parsed = List.filter_map (fun f -> Result.to_option (Rapid_syntax.Parse.parse_file f)) files in
    let ident (i : Rapid_syntax.Ast.identifier) =
      match i.it with Ident n -> String.lowercase_ascii n | ID_placeholder -> "" in
    (* The names of each routine's data, in declaration order, by module and routine. *)
    let data_names = Hashtbl.create 16 in
    List.iter (fun (m : Rapid_syntax.Ast.module_declaration) ->
        List.iter (fun (r : Rapid_syntax.Ast.routine_declaration) ->
            let named name (body : Rapid_syntax.Ast.routine_body) =
              Hashtbl.replace data_names (ident m.module_name, ident name)
                (List.filter_map (fun (d : Rapid_syntax.Ast.data_declaration) ->
                     match d.it with Data_declaration { name; _ } -> Some (ident name) | _ -> None)
                    body.declarations) in
            match r.it with
            | Procedure_declaration { name; body; _ } | Function_declaration { name; body; _ }
            | Trap_declaration { name; body; _ } -> named name body
            | Routine_comment _ | RDN_placeholder -> ()) m.routine_declarations) parsed;
    let routine_data (r : Rapid_runtime.Ir.routine) =
      Option.value ~default:[]
        (Hashtbl.find_opt data_names (String.lowercase_ascii r.module_name, String.lowercase_ascii r.name)) in
    (* §9.2, §9.4: the modules stepping does not enter, from their attributes. *)
    let hidden = List.concat_map (fun (m : Rapid_syntax.Ast.module_declaration) ->
        if List.exists (fun (a : Rapid_syntax.Ast.module_attribute) ->
            match a.it with NOSTEPIN | NOVIEW -> true | _ -> false) m.attributes
        then [ ident m.module_name ] else []) parsed in
    let type_of = Rapid_tools.Debug_types.type_of parsed in
    let files = List.map (fun f -> if f = "-" then Rapid_syntax.Parse.stdin_name else f) files in
    let note w = notify (Rapid_run.Run_setup.Backup_warning w) in
    let debug =
      Rapid_run.Task_load.runnable ~note ~task:events.task (Rapid_semantics.Machine.program cfg) events.debug in
    let events = List.map (fun e ->
        (e, List.filter_map (fun (r : Rapid_run.Task_load.event_routine) ->
             if r.event = e && List.exists (fun n -> String.lowercase_ascii n = String.lowercase_ascii r.routine) debug
             then Some r.routine else None) events.debug)) [ "START"; "RESTART"; "STEP"; "STOP" ] in
    let session = D.create ~max_steps ~routine_data ~type_of ~files ~events
        ~hidden:(fun m -> List.mem (String.lowercase_ascii m) hidden) ~out:print_endline cfg in
    (* A person typing commands sees when the session waits for the next one; a script or a
       pipe gets the transcript alone (doc/debugger.md). *)
    let prompt = match prompt_text with
      | Some "" -> None
      | Some t -> Some t
      | None -> if script = None && Unix.isatty Unix.stdin then Some "(rapid-sem) " else None in
    let rec loop () =
      Option.iter (fun p -> print_string p; flush stdout) prompt;
      match input_line ic with
      | exception End_of_file -> if prompt <> None then print_newline ()
      | line ->
          let line = String.trim line in
          if echo && line <> "" then print_endline ("(rapid) " ^ line);
          (match D.command session line with `Quit -> () | `Go_on -> loop ())
    in
    loop ();
    flush stdout;
    let cfg = D.config session in
    match Rapid_semantics.Machine.outcome cfg with
    | Rapid_runtime.Outcome.Running -> 0
    | o -> Cli.finish o (Rapid_semantics.Machine.steps cfg) ~max_steps
  in
  let doc = "step through a task as on the FlexPendant: forward, backward (ch. 6), by statement" in
  let man = [
    `S Manpage.s_description;
    `P "Checks and loads the FILEs as $(b,rapid-sem run) does, stops at the first statement of the entry routine, then \
        runs the commands of doc/debugger.md (step [N], next, finish, back, continue, break FILE:LINE, delete [N], \
        print EXPR, set REF := EXPR, where, quit), one a line, from standard input or --script FILE. After each \
        command that moves the program pointer it prints MODULE:LINE and the statement's line.";
    `S Manpage.s_exit_status;
    `P "0 when the session ends (quit, or the end of the commands) with the task still running or ended; otherwise \
        that of $(b,rapid-sem run) for how the task ended.";
  ] in
  Cmd.v (Cmd.info "debug" ~doc ~man)
    Term.(const run $ files $ entry $ max_steps $ allow_unknown $ max_depth $ retry_limit $ Run_args.controller_args
          $ Run_args.robot_and_base_frames $ script $ prompt_text)
