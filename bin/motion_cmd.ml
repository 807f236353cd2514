(* rapid-sem motion: a run by the machine, and what the robot did drawn (doc/motion.md,
   doc/user-guide.md). *)

open Cmdliner
module M = Rapid_semantics.Machine
module MP = Rapid_installed.Motion_routines
module MM = Rapid_motion_model

(* ------------------------------------------------------------------ rapid-sem motion *)

let write_file path text =
  try
    let oc = open_out_bin path in
    Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text); Ok ()
  with Sys_error m -> Error m

(* The program's side of the timeline: its waits (from the rule that starts a wait to the one
   that ends it), traps, signal changes. A wait is a waiting instruction's (WaitTime, WaitDI,
   WaitUntil, RMQReadWait, ...): a move instruction's program pointer waiting for its stop
   point is the moves row's, not a wait of the program. *)
let waiting_instruction cfg =
  match M.current_statement cfg with
  | Some { s = Call_procedure { callee = Routine i; _ }; _ } ->
      let name = (M.program cfg).routines.(i).name in
      let lower = String.lowercase_ascii name in
      let rec has k = k + 4 <= String.length lower && (String.sub lower k 4 = "wait" || has (k + 1)) in
      if has 0 then Some name else None
  | _ -> None

let collect (w : Rapid_run.Run.world) =
  let marks = ref [] and waits = ref [] and traps = ref [] in
  let now () = Rapid_controller.World.now w.controller in
  let observe cfg rule events =
    let open MM.Path_output in
    (match rule with
     | "wait-start" ->
         let what = Option.map (fun name ->
             match M.waiting_for cfg with Some what -> name ^ ": " ^ what | None -> name) (waiting_instruction cfg) in
         waits := (now (), what) :: !waits
     | "wait-done" | "wait-timeout" | "wait-poll-true" -> (
         (* a trap's wait within the wait of the routine it interrupted: the innermost ends *)
         match !waits with
         | (t0, what) :: rest ->
             Option.iter (fun m_label ->
                 marks := { lane = Waits; m_from = t0; m_to = now (); m_label } :: !marks) what;
             waits := rest
         | [] -> ())
     | _ -> ());
    List.iter (function
        | Rapid_runtime.Event.Trap_entered { trap; time; _ } -> traps := (trap, time) :: !traps
        | Rapid_runtime.Event.Trap_left { trap; time } -> (
            match !traps with
            | (name, t0) :: rest when name = trap ->
                traps := rest; marks := { lane = Traps; m_from = t0; m_to = time; m_label = trap } :: !marks
            | _ -> ())
        | Rapid_runtime.Event.Controller (Signal_changed { time; signal; value }) ->
            let m_label = Printf.sprintf "%s=%g" signal value in
            marks := { lane = Signals; m_from = time; m_to = time; m_label } :: !marks
        | _ -> ()) events
  in
  (observe, fun () -> List.rev !marks)

let cmd =
  let files, entry, max_steps, allow_unknown, max_depth, retry_limit = Run_args.common_run_args in
  let out name doc = Arg.(value & opt (some string) None & info [ name ] ~docv:"FILE" ~doc) in
  let svg = out "svg" "Write the TCP path (top and side views) as SVG to FILE." in
  let timeline = out "timeline" "Write the timeline (moves, corner paths, TCP speed, the program's waits, traps and \
                                 signal changes) as SVG to FILE." in
  let csv = out "csv" "Write TCP and axis samples as CSV to FILE (t,x,y,z,q1,q2,q3,q4,j1..j6)." in
  let step_ = Arg.(value & opt float 0.01 & info [ "csv-step" ] ~docv:"SECONDS"
                     ~doc:"The CSV's sampling step (default 0.01 s).") in
  let run files entry max_steps allow_unknown max_depth retry_limit controller (robot, base_frames) svg timeline csv
      csv_step =
    if not (csv_step > 0. && csv_step <= 1000.) then (prerr_endline "rapid-sem: --csv-step takes a step above 0 and at \
                                                                     most 1000 s"; 2)
    else
    Cli.guard @@ fun () ->
    let options = Run_args.options ~base_frames ~max_steps ~allow_unknown ~max_depth ~retry_limit ~controller ~robot ()
    in
    match Rapid_run.Run_setup.start_machine ~history:true ~notify:Cli.notify options files ~entry with
    | Error f -> Cli.failure f
    | Ok (cfg, w) ->
    let observe, marks = collect w in
    let rec loop () =
      if M.outcome cfg = Rapid_runtime.Outcome.Running && M.steps cfg < max_steps then begin
        let rule, events = M.step cfg in
        observe cfg rule events;
        List.iter (function Rapid_runtime.Event.Output s -> print_endline s | _ -> ()) events;
        loop ()
      end in
    loop ();
    let p = MP.planner w.motion in
    (* the cell: the program's files and the robot that moved (doc/motion.md, "Output") *)
    let robot = MM.Kinematics.robot (MM.Planner.kinematics p) in
    let title = String.concat " " (List.map Filename.basename files) ^ ", " ^ robot.MM.Robot.name in
    let written = List.filter_map (fun (target, text) ->
        match target with
        | None -> None
        | Some path -> (
            match write_file path (Lazy.force text) with
            | Ok () -> Some (Ok path)
            | Error m -> Some (Error m)))
        [ (svg, lazy (MM.Path_output.path_svg ~title p));
          (timeline, lazy (MM.Path_output.timeline_svg ~title ~program:(marks ()) p));
          (csv, lazy (MM.Path_output.csv ~step:csv_step p)) ] in
    List.iter (function
        | Ok path -> Printf.eprintf "rapid-sem: wrote %s\n" path
        | Error m -> Printf.eprintf "rapid-sem: cannot write: %s\n" m) written;
    let status = Cli.finish (M.outcome cfg) (M.steps cfg) ~max_steps in
    if status = 0 && List.exists Result.is_error written then 2 else status
  in
  let doc = "run a task and draw its motion: the TCP path, the timeline, samples" in
  let man = [
    `S Manpage.s_description;
    `P "Runs the task as $(b,rapid-sem run --engine machine) does (its output on standard output), then writes what \
        the robot did: $(b,--svg) the TCP path in the world frame (top view x-y, side view x-z), $(b,--timeline) \
        the moves, corner paths and TCP speed against virtual time with the program's waits, traps and signal \
        changes below, $(b,--csv) samples of the TCP pose, the axis angles and the external axes (doc/motion.md, \
        \"Output\"). Each file written is named on standard error.";
    `S Manpage.s_exit_status; `P "As $(b,rapid-sem run); 2 also when a file cannot be written.";
  ] in
  Cmd.v (Cmd.info "motion" ~doc ~man)
    Term.(const run $ files $ entry $ max_steps $ allow_unknown $ max_depth $ retry_limit $ Run_args.controller_args
          $ Run_args.robot_and_base_frames $ svg $ timeline $ csv $ step_)
