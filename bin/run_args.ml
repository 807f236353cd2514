open Cmdliner
module O = Rapid_run.Run_options

(* A count given on the command line: a whole number from 0 to the largest integer; a negative
   one is refused as a usage error (exit status 2) that says so. *)
let count ~what =
  let parse s =
    match int_of_string_opt (String.trim s) with
    | Some n when n >= 0 -> Ok n
    | Some _ -> Error (`Msg (Printf.sprintf "%s must be 0 or more, not %s" what s))
    | None ->
        Error (`Msg (Printf.sprintf "%s must be a whole number from 0 to %d, not %S" what max_int s))
  in
  Arg.conv (parse, Format.pp_print_int)

let io_arg =
  Arg.(value & opt (some string) None & info [ "io" ] ~docv:"FILE"
         ~doc:"The I/O configuration and the stimulus of the inputs (doc/controller.md): a stimulus file, or a \
               RobotWare EIO.cfg file whose EIO_SIGNAL entries declare the signals.")

(* --epoch YYYY-MM-DDTHH:MM:SS, read as seconds since 1970 (UTC, no leap seconds). A date that
   does not exist (February 30, a year before 0001) is refused rather than carried over. *)
let epoch_conv =
  let days_in_month y m =
    if m = 2 then (if (y mod 4 = 0 && y mod 100 <> 0) || y mod 400 = 0 then 29 else 28)
    else if m = 4 || m = 6 || m = 9 || m = 11 then 30 else 31 in
  let parse s =
    try Scanf.sscanf s "%4u-%2u-%2uT%2u:%2u:%2u%!" (fun y m d hh mm ss ->
        if y < 1 || m < 1 || m > 12 || d < 1 || d > days_in_month y m || hh > 23 || mm > 59 || ss > 59 then
          Error (`Msg "a date and time that does not exist")
        else
          let y' = if m <= 2 then y - 1 else y in
          let era = (if y' >= 0 then y' else y' - 399) / 400 in
          let yoe = y' - (era * 400) in
          let mp = if m > 2 then m - 3 else m + 9 in
          let doy = ((153 * mp) + 2) / 5 + d - 1 in
          let doe = (yoe * 365) + (yoe / 4) - (yoe / 100) + doy in
          let days = (era * 146097) + doe - 719468 in
          Ok (float_of_int ((days * 86400) + (hh * 3600) + (mm * 60) + ss)))
    with _ -> Error (`Msg "expected YYYY-MM-DDTHH:MM:SS") in
  let print ppf t = let y, m, d, hh, mm, ss, _ = Rapid_installed.Io_routines.date_time t in
    Format.fprintf ppf "%04d-%02d-%02dT%02d:%02d:%02d" y m d hh mm ss in
  Arg.conv (parse, print)

(* A number of seconds of virtual time: never NaN (it compares false with every time, so a limit of
   NaN would be no limit and a statement of NaN would stop the clock), never negative, and at most
   [most] (a statement time of 1e308 would take the clock past every time it can represent). *)
let seconds_conv ~most =
  let parse s =
    match float_of_string_opt (String.trim s) with
    | None -> Error (`Msg (Printf.sprintf "%S is not a number of seconds" s))
    | Some v when Float.is_nan v -> Error (`Msg "not a number (nan) is not a time")
    | Some v when v < 0. -> Error (`Msg "a time is not negative")
    | Some v when v > most -> Error (`Msg (Printf.sprintf "at most %g s" most))
    | Some v -> Ok v in
  Arg.conv (parse, fun ppf v -> Format.fprintf ppf "%g" v)

(* The longest statement: a day of virtual time. *)
let most_statement_time = 86400.

(* --fs, --fs-quota, --net, --map-address, --egm-device (doc/services.md), --operator. *)
let services_args =
  let fs = Arg.(value & opt (some string) None & info [ "fs" ] ~docv:"ROOT"
                  ~doc:"The folder that holds the controller's mass memory: HOME:, TEMP:, RAMDISK: and \
                        REMOVABLE: are folders under it, and no RAPID path reaches outside it (default \
                        .rapid-sem/fs under the current folder, made when a program first uses a file).") in
  let quota = Arg.(value & opt (some int) None & info [ "fs-quota" ] ~docv:"BYTES"
                     ~doc:"The bytes a run may write into the files of --fs in all (default 256 MiB, \
                           268435456); a write beyond raises ERR_FILEACC, as a full mass memory does.") in
  let net = Arg.(value & opt_all string [] & info [ "net" ] ~docv:"HOST:PORT,..."
                   ~doc:"Addresses beyond the loopback that sockets may bind or connect to (PORT * for any port). \
                         Without it only 127.0.0.0/8 is reachable.") in
  let map = Arg.(value & opt_all string [] & info [ "map-address" ] ~docv:"FROM=TO,..."
                   ~doc:"Read the RAPID address FROM as TO, e.g. 192.168.125.1=127.0.0.1 (the controller's \
                         service port on the loopback), before the --net check.") in
  let egm = Arg.(value & opt_all string [] & info [ "egm-device" ] ~docv:"NAME=HOST:PORT,..."
                   ~doc:"A UdpUc device of Externally Guided Motion: EGMSetupUC's UCDevice NAME sends to the \
                         sensor at HOST:PORT, a loopback address (doc/services.md).") in
  let operator = Arg.(value & opt (some file) None & info [ "operator" ] ~docv:"FILE"
                        ~doc:"The operator at the FlexPendant: FILE's lines answer the program's dialogues \
                              (TPReadFK, TPReadNum, UIMsgBox, UIMessageBox, UINumEntry, UINumTune, UIAlphaEntry, \
                              UIListView) in the order it asks, one line each, ROUTINE ANSWER; UIClientExist is \
                              TRUE (doc/controller.md, \"The operator\").") in
  Term.(const (fun fs fs_quota net map_address egm_device operator ->
      { O.fs; fs_quota; net; map_address; egm_device; operator })
        $ fs $ quota $ net $ map $ egm $ operator)

let robotware_conv =
  let parse s = match Rapid_syntax.Robotware.of_string s with
    | Some r -> Ok r
    | None -> Error (`Msg (Printf.sprintf "expected 5, 6 or 7 (a RobotWare release), found %S" s)) in
  Arg.conv (parse, fun f r -> Format.pp_print_string f (Rapid_syntax.Robotware.to_string r))

(* R-2.4-rw6. *)
let robotware_arg =
  Arg.(value & opt (some robotware_conv) None & info [ "robotware" ] ~docv:"RELEASE"
         ~doc:"The RobotWare release the modules are written for: 7 (the manual's, the default) or 5 and 6, \
               where BREAK and CONTINUE are names and Break is an instruction (doc/dialect.md). A backup's \
               backinfo.txt gives it when this option does not.")

let controller_args =
  let module W = Rapid_controller.World in
  let statement_time =
    Arg.(value & opt (seconds_conv ~most:most_statement_time) W.default_statement_time
         & info [ "statement-time" ] ~docv:"SECONDS"
             ~doc:"Virtual time each executed statement (and each round of a loop) takes (at most 86400).") in
  let max_time = Arg.(value & opt (seconds_conv ~most:infinity) W.default_max_time & info [ "max-time" ]
                        ~docv:"SECONDS"
                        ~doc:"Stop the run when its virtual time goes beyond SECONDS (exit status 3; inf: never).") in
  let epoch = Arg.(value & opt epoch_conv W.default_epoch & info [ "epoch" ] ~docv:"YYYY-MM-DDTHH:MM:SS"
                     ~doc:"The wall-clock time at virtual time 0, for CDate, CTime and GetTime (default \
                           2024-01-01T00:00:00).") in
  Term.(const (fun io statement_time max_time epoch services robotware ->
      { O.io; statement_time; max_time; epoch; services; robotware; units = [] })
        $ io_arg $ statement_time $ max_time $ epoch $ services_args $ robotware_arg)

let base_frame_arg =
  Arg.(value & opt_all string [] & info [ "base-frame" ] ~docv:"[TASK=]X,Y,Z,Q1,Q2,Q3,Q4"
         ~doc:"Where the cell mounts the robot: its base frame in the world frame, the origin in mm and the \
               orientation as a unit quaternion, as a RAPID pose (doc/rulings.md R-bk-12). Robtargets in wobj0 are in \
               the world frame; CRobT, CPos and CalcRobT answer through the base frame. Without TASK= the run's \
               robot (the one task's, or the motion task's); with TASK=, with several tasks, that task's robot: a \
               backup's motion task, or any task of --task, which then has a robot of its own. Overrides MOC.cfg's \
               base frame.")

let robot_arg =
  Arg.(value & opt (some string) None & info [ "robot" ] ~docv:"FILE|NAME"
         ~doc:"The robot: a description file (doc/motion.md, \"The robot description\"), or else a robot of the \
               library by its name (irb2400-10-1.5), its model (irb7600) or a MOC.cfg robot type \
               (ROB1_2400_1.5_10; doc/motion.md, \"The robot library\"); default the built-in ABB IRB 120.")

let robot_and_base_frames = Term.(const (fun r b -> (r, b)) $ robot_arg $ base_frame_arg)

let samples_arg =
  Arg.(value & opt (some float) None & info [ "samples" ] ~docv:"HZ"
         ~doc:"With JSON output: add a tcp-sample event HZ times per second of virtual time (doc/trace-format.md).")

let common_run_args =
  let default = Rapid_runtime.Limits.default in
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer.") in
  let entry = Arg.(value & opt string "main" & info [ "entry" ] ~docv:"NAME" ~doc:"The entry routine (default \
                                                                                   main).") in
  let max_steps = Arg.(value & opt (count ~what:"--max-steps") 100_000_000 & info [ "max-steps" ] ~docv:"N"
                         ~doc:"Stop after N reduction steps (exit status 3).") in
  let allow_unknown = Arg.(value & flag & info [ "allow-unknown" ]
                             ~doc:"Names neither declared nor installed are warnings; reaching one is an execution \
                                   error.") in
  let max_depth = Arg.(value & opt (count ~what:"--max-call-depth") default.max_call_depth
                       & info [ "max-call-depth" ] ~docv:"N" ~doc:"The deepest call chain (resource exhaustion \
                                                                   beyond).") in
  let retry_limit = Arg.(value & opt (count ~what:"--retry-limit") default.retry_limit
                         & info [ "retry-limit" ] ~docv:"N"
                           ~doc:"\"No Of Retry\": RETRYs of one error before ERR_EXCRTYMAX (§7.1).") in
  let max_memory = Arg.(value & opt (count ~what:"--max-memory") default.max_memory & info [ "max-memory" ]
                          ~docv:"BYTES"
                          ~doc:"The memory budget of RAPID data (default 256 MiB; doc/user-guide.md): data beyond it \
                                ends the run with exit status 3.") in
  let stub = Arg.(value & flag & info [ "stub-unmodelled" ]
                    ~doc:"Run an installed routine whose behaviour rapid-sem does not model as a no-op (a function \
                          returns its type's initial value; VAR and INOUT arguments are left as they are), with one \
                          warning per routine, instead of ending the run with exit status 4.") in
  (files, entry, max_steps, Term.(const (fun a b -> (a, b)) $ allow_unknown $ stub), max_depth,
   Term.(const (fun r m -> (r, m)) $ retry_limit $ max_memory))

let tasks_args =
  let files = Arg.(value & pos_all string [] & info [] ~docv:"FILE"
                     ~doc:"RAPID module files: one task buffer (without --task).") in
  let entry = Arg.(value & opt_all string [] & info [ "entry" ] ~docv:"[TASK=]ROUTINE"
                     ~doc:"The entry routine (default main); with --task, TASK=ROUTINE for each task whose entry is \
                           not main.") in
  let tasks = Arg.(value & opt_all string [] & info [ "task" ] ~docv:"NAME=FILE[,FILE...]"
                     ~doc:"A task of its own (ch. 14): its name and the module files of its task buffer. Repeat for \
                           several tasks, all on one virtual clock (doc/user-guide.md, \"Several tasks\"); the first \
                           is the motion task unless --motion-task names another.") in
  let schedule = Arg.(value & opt (some (count ~what:"--schedule")) None & info [ "schedule" ] ~docv:"SEED"
                        ~doc:"With --task: turns in a pseudo-random order that depends on SEED only (SplitMix64), \
                              instead of round robin.") in
  let motion_task = Arg.(value & opt (some string) None & info [ "motion-task" ] ~docv:"NAME"
                           ~doc:"With --task: the task that has the robot (default the first task).") in
  Term.(const (fun files entries tasks schedule motion_task -> { O.files; entries; tasks; schedule; motion_task })
        $ files $ entry $ tasks $ schedule $ motion_task)

let options ?(base_frames = []) ~max_steps ~allow_unknown:(allow_unknown, stub_unmodelled) ~max_depth
    ~retry_limit:(retry_limit, max_memory) ~controller ~robot () =
  { O.max_steps; allow_unknown; stub_unmodelled; controller; robot; base_frames;
    limits = { max_call_depth = max_depth; retry_limit; max_memory } }
