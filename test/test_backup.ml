(* Controller backups (lib/load/cfg_file.ml, lib/load/backup.ml, lib/run/backup_setup.ml): the
   cfg format as the backups gathered in doc/real-programs.md write it, a backup's tasks and
   robots read as R-bk-1 to R-bk-7 say, and hostile inputs that must never crash. The runs of
   whole backups are golden tests (test/golden/backup-*.cmd). *)

module Cfg = Rapid_load.Cfg_file
module Backup = Rapid_load.Backup

let ( // ) = Filename.concat

let parse text = Cfg.parse ~file:"t.cfg" text

let cfg_ok text = match parse text with Ok c -> c | Error m -> Alcotest.fail m

let attributes (c : Cfg.t) section =
  match Cfg.section c section with
  | None -> Alcotest.fail ("no section " ^ section)
  | Some s -> List.map (fun (i : Cfg.instance) ->
      List.map (fun (a : Cfg.attribute) ->
          (a.key, match a.value with Cfg.Flag -> "<flag>" | Text v -> v)) i.attributes) s.instances

let pairs = Alcotest.(list (list (pair string string)))

let format () =
  let c = cfg_ok "SYS:CFG_1.0:5:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask \n\n\
                  \      -Name \"T_ui\" -Type \"STATIC\" -Entry \"Main\"\\\r\n      -TrustLevel \"None\"\n#\n\
                  MMC_MC1 = MMC_PALETTE:\n      -name \"x\" -text_id 30,82 -low -5.5 -mode  -x\n#\n" in
  Alcotest.(check string) "domain" "SYS" c.domain;
  Alcotest.check pairs "two instances, a flag, a continued line"
    [ [ ("Name", "T_ROB1"); ("Type", "NORMAL"); ("MotionTask", "<flag>") ];
      [ ("Name", "T_ui"); ("Type", "STATIC"); ("Entry", "Main"); ("TrustLevel", "None") ] ]
    (attributes c "CAB_TASKS");
  Alcotest.check pairs "NAME = TYPE: header; a list, a negative number, flags"
    [ [ ("name", "x"); ("text_id", "30,82"); ("low", "-5.5"); ("mode", "<flag>"); ("x", "<flag>") ] ]
    (attributes c "MMC_MC1");
  (* Instances written one after the other, without a blank line between them. *)
  let c = cfg_ok "MOC:CFG_1.0:6:0::\nARM:\n      -name \"a\" -upper_joint_bound 1\n      -name \"b\"\n#\n" in
  Alcotest.check pairs "an instance per line" [ [ ("name", "a"); ("upper_joint_bound", "1") ]; [ ("name", "b") ] ]
    (attributes c "ARM")

(* Malformed files: each a clear FILE:LINE:COL error of the cfg class, never an exception. *)
let malformed () =
  List.iter (fun (text, where) ->
      match parse text with
      | Ok _ -> Alcotest.failf "accepted: %S" text
      | Error m ->
          let prefix = "t.cfg:" ^ where ^ ": cfg error: " in
          if not (String.length m > String.length prefix && String.sub m 0 (String.length prefix) = prefix) then
            Alcotest.failf "%S: %s (expected %s...)" text m prefix)
    [ ("", "1:1"); ("not a header\n", "1:1");
      ("SYS:CFG_1.0:5:0::\n      -Name \"x\"\n", "2:1");
      ("SYS:CFG_1.0:5:0::\nCAB_TASKS:\n      -Name \"x\n", "3:13");
      ("SYS:CFG_1.0:5:0::\nCAB_TASKS:\n      \"x\" -Name\n", "3:7");
      ("SYS:CFG_1.0:5:0::\nCAB_TASKS:\n  garbage here\n", "3:3");
      ("SYS:CFG_1.0:5:0::\nCAB_TASKS:\n      -Name \"x\" \\", "3:1") ]

(* Random bytes and cut files: the reader and the backup never raise. *)
let hostile () =
  let rs = Random.State.make [| 17 |] in
  let base = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\\\n \
              -Entry \"main\"\n#\nMECHANICAL_UNIT_GROUP:\n      -Name \"rob1\" -Robot \"ROB_1\"\n#\n" in
  for _ = 1 to 2000 do
    let n = String.length base in
    let b = Bytes.of_string base in
    for _ = 1 to 1 + Random.State.int rs 4 do
      Bytes.set b (Random.State.int rs n) (Char.chr (Random.State.int rs 256))
    done;
    let cut = Bytes.sub_string b 0 (Random.State.int rs (n + 1)) in
    match parse cut with
    | Ok _ | Error _ -> ()
    | exception e -> Alcotest.failf "%S: %s" cut (Printexc.to_string e)
  done

(* A line of 200,000 attributes, and 100,000 instances: no stack overflow. *)
let long_lines () =
  let flags = String.concat " " (List.init 200_000 (fun _ -> "-a")) in
  (match parse ("SYS:CFG_1.0:6:0::\nX:\n " ^ flags ^ "\n") with
   | Ok c -> Alcotest.(check int) "attributes" 200_000 (List.length (List.hd (attributes c "X")))
   | Error m -> Alcotest.fail m);
  let many = String.concat "" (List.init 100_000 (fun k -> Printf.sprintf " -Name \"t%d\"\n" k)) in
  match parse ("SYS:CFG_1.0:6:0::\nCAB_TASKS:\n" ^ many) with
  | Ok c -> Alcotest.(check int) "instances" 100_000 (List.length (attributes c "CAB_TASKS"))
  | Error m -> Alcotest.fail m

let write path text =
  let rec mkdir d = if not (Sys.file_exists d) then (mkdir (Filename.dirname d); Sys.mkdir d 0o755) in
  mkdir (Filename.dirname path);
  let oc = open_out_bin path in
  output_string oc text; close_out oc

let temp_backup files =
  let dir = Filename.temp_file "rapid-sem-backup" "" in
  Sys.remove dir; Sys.mkdir dir 0o755;
  List.iter (fun (p, t) -> write (dir // p) t) files;
  dir

let main_mod name = Printf.sprintf "MODULE %s\n  PROC main()\n  ENDPROC\nENDMODULE\n" name

(* R-bk-13: MOC.cfg's mechanical units are mecunit data of the backup's tasks: a gantry's unit named
   in a call checks, as ROB_1 does; without the backup it is unknown. *)
let mechanical_units () =
  let module_text = "MODULE A\n  PROC main()\n    ActUnit Gantry11;\n    DeactUnit ROB_1;\n  ENDPROC\nENDMODULE\n" in
  let dir = temp_backup [
      ("SYSPAR/MOC.cfg", "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT:\n      -name \"ROB_1\" -use_robot \"ROB_1\"\n\n\
                         \      -name \"Gantry11\" -use_robot \"Gantry11\"\n\n      -name \"9bad\"\n#\n");
      ("RAPID/TASK1/PROGMOD/A.mod", module_text) ] in
  match Backup.read dir with
  | Error m -> Alcotest.fail m
  | Ok b ->
      Alcotest.(check (list string)) "the units" [ "ROB_1"; "Gantry11"; "9bad" ] b.units;
      let files = (List.hd b.tasks).files in
      let io = { Rapid_controller.Io_config.empty with mechanical_units = b.units } in
      (match Rapid_load.Session.load ~io files with
       | Ok _ -> ()
       | Error _ -> Alcotest.fail "Gantry11 is a mecunit of the backup");
      (match Rapid_load.Session.load files with
       | Error (Static _) -> ()
       | _ -> Alcotest.fail "without the backup, Gantry11 is unknown");
      (* A name that is no identifier (9bad) declares nothing, and ROB_1 is installed once. *)
      match Rapid_load.Session.installed ~io () with
      | Error _ -> Alcotest.fail "the installed environment with the units does not parse"
      | Ok modules ->
          let last = List.nth modules (List.length modules - 1) in
          let text = Rapid_syntax.Printer.module_declaration last in
          let has part = let n = String.length part in
            let rec at i = i + n <= String.length text && (String.sub text i n = part || at (i + 1)) in at 0 in
          Alcotest.(check (list bool)) "declared: Gantry11, not ROB_1, not 9bad" [ true; false; false ]
            [ has "mecunit Gantry11"; has "mecunit ROB_1"; has "9bad" ]

(* R-bk-14: without SYS.cfg, a folder of system modules alone is not started; with SYS.cfg
   configuring it, it is a task (its missing entry routine is then the run's error). *)
let no_program () =
  let files = [ ("RAPID/TASK1/PROGMOD/A.mod", main_mod "A");
                ("RAPID/TASK2/SYSMOD/user.sys", "MODULE user (SYSMODULE)\nENDMODULE\n") ] in
  let names dir = match Backup.read dir with
    | Error m -> Alcotest.fail m
    | Ok b -> (List.map (fun (t : Backup.task) -> t.name) b.tasks, b.warnings) in
  let tasks, warnings = names (temp_backup files) in
  Alcotest.(check (list string)) "TASK2 not started" [ "TASK1" ] tasks;
  Alcotest.(check bool) "a warning says so" true
    (List.exists (fun w -> let part = "the task TASK2 has no program module" in
                   let n = String.length part in
                   let rec at i = i + n <= String.length w && (String.sub w i n = part || at (i + 1)) in at 0) warnings);
  let sys = ("SYSPAR/SYS.cfg", "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n      -Name \"TASK1\" -MotionTask\n\n\
                                \      -Name \"TASK2\"\n#\n") in
  let tasks, _ = names (temp_backup (sys :: files)) in
  Alcotest.(check (list string)) "configured by SYS.cfg: a task" [ "TASK1"; "TASK2" ] tasks

(* R-bk-15: a robot's -base_frame_coordinated naming a track (MECHANICAL_UNIT -use_single_0, the
   SINGLE's joint, the arm of that joint) gives the track and its travel; a gantry's unit does not,
   and is warned as not modelled. test/golden/backup-track runs a robot on such a track. *)
let tracks () =
  let moc = "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT:\n      -name \"T1\" -use_single_0 \"T1\"\n\n\
             \      -name \"G1\" -use_robot \"G1\"\n#\nROBOT:\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\\\n\
             \      -base_frame_coordinated \"T1\"\n\n      -name \"ROB_2\" -use_robot_type \"ROB2_120_0.58_3\"\\\n\
             \      -base_frame_coordinated \"G1\"\n\n      -name \"G1\" -use_robot_type \"G1_X_Y_Z_NOTCP\"\n#\n\
             SINGLE:\n      -name \"T1\" -use_joint \"t1\" -base_frame_orient_u0 0.707107 -base_frame_orient_u3 0.707107\n#\n\
             ARM:\n      -name \"a\" -use_arm_type \"t1\" -upper_joint_bound 3.9 -lower_joint_bound -0.1\n#\n" in
  let dir = temp_backup [ ("SYSPAR/MOC.cfg", moc); ("RAPID/TASK1/PROGMOD/A.mod", main_mod "A") ] in
  match Backup.read dir with
  | Error m -> Alcotest.fail m
  | Ok b ->
      (match Option.bind (List.assoc_opt "TASK1" b.robots) (fun (r : Backup.robot) -> r.track) with
       | Some t ->
           Alcotest.(check string) "the unit" "T1" t.track_unit;
           Alcotest.(check (pair (float 1e-9) (float 1e-9))) "the travel, m" (-0.1, 3.9) t.travel
       | None -> Alcotest.fail "ROB_1 rides the track T1");
      let warned part = List.exists (fun w ->
          let n = String.length part in
          let rec at i = i + n <= String.length w && (String.sub w i n = part || at (i + 1)) in at 0) b.warnings in
      Alcotest.(check (list bool)) "the gantry warned, the track not" [ true; false ]
        [ warned "moved by the mechanical unit G1"; warned "the mechanical unit T1 (an external axis)" ]

(* R-2.4-rw6: the release of backinfo.txt's "RobotWare Version:", and what reading a module as
   RobotWare 6 changes: BREAK and CONTINUE are names there, reserved words by the manual's (7). *)
let robotware () =
  let module R = Rapid_syntax.Robotware in
  let release = Alcotest.testable (fun f r -> Format.pp_print_string f (R.to_string r)) ( = ) in
  List.iter (fun (text, expected) -> Alcotest.(check (option release)) text expected (R.of_string text))
    [ ("6.13.02.00", Some R.Rw6); ("5.15.9100.10", Some R.Rw6); ("7.12", Some R.Rw7); ("7", Some R.Rw7);
      ("6", Some R.Rw6); ("8.0", None); ("", None); ("six", None) ];
  let info version = Printf.sprintf "#\n>>SYSTEM_ID:\n1\n\n>>PRODUCTS_ID:\n%s\n\n>>TASK1: (T_ROB1,P,)\n\
                                     PROGMOD/A.mod @ a.mod\n" version in
  let module_text = "MODULE A\n  VAR bool continue := TRUE;\n  PROC main()\n    Break;\n  ENDPROC\nENDMODULE\n" in
  let read version =
    let dir = temp_backup [ ("BACKINFO/backinfo.txt", info version); ("RAPID/TASK1/PROGMOD/A.mod", module_text) ] in
    match Backup.read dir with Error m -> Alcotest.fail m | Ok b -> b in
  Alcotest.(check (option release)) "RobotWare 6" (Some R.Rw6) (read "RobotWare Version: 6.13.02.00").robotware;
  Alcotest.(check (option release)) "RobotWare 7" (Some R.Rw7) (read "RobotWare Version: 7.12.0").robotware;
  Alcotest.(check (option release)) "no version" None (read "").robotware;
  let files = (List.hd (read "RobotWare Version: 6.13.02.00").tasks).files in
  (match Rapid_load.Session.load ~robotware:R.Rw6 files with
   | Ok _ -> ()
   | Error _ -> Alcotest.fail "a RobotWare 6 module naming a variable continue is refused as RobotWare 6");
  match Rapid_load.Session.load files with
  | Error (Front_end [ d ]) ->
      Alcotest.(check bool) "refused at CONTINUE" true
        (let m = Rapid_syntax.Diagnostic.to_string d in
         let part = "found CONTINUE" in
         let n = String.length part in
         let rec at i = i + n <= String.length m && (String.sub m i n = part || at (i + 1)) in at 0)
  | _ -> Alcotest.fail "as RobotWare 7, CONTINUE is a reserved word"

(* Without SYS.cfg and backinfo.txt: the folders' tasks, SYSMOD's modules before PROGMOD's, the
   first task with the robot (R-bk-1 to R-bk-3). *)
let bare_folders () =
  let dir = temp_backup [ ("RAPID/TASK2/PROGMOD/B.mod", main_mod "B"); ("RAPID/TASK1/PROGMOD/Z.mod", main_mod "Z");
                          ("RAPID/TASK1/SYSMOD/a.sys", "MODULE a(SYSMODULE)\nENDMODULE\n") ] in
  match Backup.read dir with
  | Error m -> Alcotest.fail m
  | Ok b ->
      Alcotest.(check (list string)) "names" [ "TASK1"; "TASK2" ] (List.map (fun (t : Backup.task) -> t.name) b.tasks);
      Alcotest.(check (list string)) "TASK1's files"
        [ dir // "RAPID" // "TASK1" // "SYSMOD" // "a.sys"; dir // "RAPID" // "TASK1" // "PROGMOD" // "Z.mod" ]
        (List.hd b.tasks).files;
      Alcotest.(check (list bool)) "the first has the robot" [ true; false ]
        (List.map (fun (t : Backup.task) -> t.motion) b.tasks);
      Alcotest.(check (list (pair string string))) "the other reads it" [ ("TASK2", "TASK1") ] b.connected

(* backinfo.txt's names and order (Windows separators too), SYS.cfg's types and entries, a task
   of an option left out, an encrypted module left out with a warning. *)
let configured () =
  let dir = temp_backup [
      ("BACKINFO/backinfo.txt", ">>TASK1: (T_ROB1,P,)\nPROGMOD\\Z.mod @ z.mod\nSYSMOD\\k.sys @ k.sys\nPROGMOD\\Enc.mod @ enc.mod\n\n\
                                 >>TASK2: (SC_CBC,,)\n\n>>TASK3: (T_BG,,)\nPROGMOD/B.mod @ b.mod\n>>TASK4: (t_bg,,)\n>>EOF:\n");
      ("SYSPAR/SYS.cfg", "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n\
                          \ -Name \"T_BG\" -Entry \"loop\"\n#\n");
      ("RAPID/TASK1/PROGMOD/Z.mod", main_mod "Z"); ("RAPID/TASK1/SYSMOD/k.sys", "MODULE k(SYSMODULE)\nENDMODULE\n");
      ("RAPID/TASK1/PROGMOD/Enc.mod", "\xfc\x30\x1d\xe1\x0a\x01\x80");
      ("RAPID/TASK2/SYSMOD/user.sys", "MODULE user(SYSMODULE)\nENDMODULE\n");
      ("RAPID/TASK3/PROGMOD/B.mod", main_mod "B"); ("RAPID/TASK4/PROGMOD/C.mod", main_mod "C") ] in
  match Backup.read dir with
  | Error m -> Alcotest.fail m
  | Ok b ->
      Alcotest.(check (list string)) "tasks" [ "T_ROB1"; "T_BG" ] (List.map (fun (t : Backup.task) -> t.name) b.tasks);
      Alcotest.(check (list string)) "backinfo's order"
        [ dir // "RAPID" // "TASK1" // "PROGMOD" // "Z.mod"; dir // "RAPID" // "TASK1" // "SYSMOD" // "k.sys" ]
        (List.hd b.tasks).files;
      let bg = List.nth b.tasks 1 in
      Alcotest.(check string) "-Entry" "loop" bg.entry;
      Alcotest.(check string) "no -Type: SEMISTATIC" "SEMISTATIC" (Backup.kind_name bg.kind);
      let warned part = List.exists (fun w ->
          let n = String.length part in
          let rec at i = i + n <= String.length w && (String.sub w i n = part || at (i + 1)) in at 0) b.warnings in
      Alcotest.(check bool) "the option's task is a warning" true (warned "SC_CBC");
      Alcotest.(check bool) "the encrypted module is a warning" true (warned "Enc.mod:1: warning: an encrypted module");
      Alcotest.(check bool) "a second folder of one name is a warning" true (warned "a second folder")

(* Errors of a backup: FILE:LINE:COL, never an exception. *)
let refused () =
  List.iter (fun (files, expected) ->
      let dir = temp_backup files in
      match Backup.read dir with
      | Ok _ -> Alcotest.failf "accepted: %s" expected
      | Error m ->
          let expected = dir // expected in
          if not (String.length m >= String.length expected && String.sub m 0 (String.length expected) = expected) then
            Alcotest.failf "%s (expected %s)" m expected)
    [ ([ ("SYSPAR/SYS.cfg", "SYS:CFG_1.0:6:0::\nCAB_TASKS:\n -Name \"A\"\n -Name \"a\"\n");
         ("RAPID/TASK1/PROGMOD/A.mod", main_mod "A") ], "SYSPAR/SYS.cfg:4:1: cfg error: the task a is configured twice");
      ([ ("SYSPAR/SYS.cfg", "SYS:CFG_1.0:6:0::\nCAB_TASKS:\n -Name \"A\" -Type \"FAST\"\n");
         ("RAPID/TASK1/PROGMOD/A.mod", main_mod "A") ], "SYSPAR/SYS.cfg:3:12: cfg error: task A: -Type");
      ([ ("SYSPAR/MOC.cfg", "MOC:CFG_1.0:6:0::\nROBOT:\n -name \"R\" -use_joint_0 \"j\"\nARM:\n \
                             -name \"j\" -upper_joint_bound x -lower_joint_bound 0\n");
         ("RAPID/TASK1/PROGMOD/A.mod", main_mod "A") ], "SYSPAR/MOC.cfg:5:12: cfg error: -upper_joint_bound x");
      ([ ("BACKINFO/backinfo.txt", ">>TASK: broken\n") ], "BACKINFO/backinfo.txt:1:1: backup error");
      ([ ("SYSPAR/EIO.cfg", "EIO:CFG_1.0:6:1::\n") ], "RAPID:1:1: backup error: no task to run") ]

(* R-bk-5: the arm's bounds (radians) narrow the description's range, never widen it. *)
let narrowed () =
  let r = Rapid_motion_model.Robot.irb120 in
  let b axis lower upper = { Backup.axis; lower; upper; bound_at = "MOC.cfg:1" } in
  let n, warnings = Rapid_run.Backup_setup.narrow r [ b 1 (-. Float.pi /. 2.) (Float.pi /. 2.); b 2 (-10.) 10. ] in
  Alcotest.(check (float 1e-9)) "axis 1 min" (-90.) n.axes.(0).min;
  Alcotest.(check (float 1e-9)) "axis 1 max" 90. n.axes.(0).max;
  Alcotest.(check (float 1e-9)) "axis 2 not widened" r.axes.(1).max n.axes.(1).max;
  Alcotest.(check int) "no warning" 0 (List.length warnings);
  let _, warnings = Rapid_run.Backup_setup.narrow r [ b 1 4. 5. ] in
  Alcotest.(check int) "bounds outside the range: kept, with a warning" 1 (List.length warnings)

(* R-bk-12: a ROBOT's base frame: metres to mm, the quaternion u0 .. u3 (u0 1 when not given),
   -base_frame_coordinated a warning; values that are not numbers, a quaternion that is not a unit
   one and an origin beyond the bound are warnings at their FILE:LINE with the world frame's value,
   never an error or an exception. *)
let base_frames () =
  let moc robots = [ ("SYSPAR/MOC.cfg", "MOC:CFG_1.0:6:0::\n#\nROBOT:\n" ^ robots ^ "#\n");
                     ("RAPID/TASK1/PROGMOD/A.mod", main_mod "A") ] in
  let read robots = let dir = temp_backup (moc robots) in
    match Backup.read dir with Ok b -> (dir, b) | Error m -> Alcotest.fail m in
  let contains w part =
    let n = String.length part in
    let rec at i = i + n <= String.length w && (String.sub w i n = part || at (i + 1)) in at 0 in
  let pose (r : Backup.robot) = fst (Rapid_run.Backup_setup.base_frame r) in
  let f = Alcotest.float 1e-9 in
  (* a tilted robot (a real cell's: u0 0, u1 -0.707107, u2 0.707107, u3 not given) *)
  let dir, b = read "      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\\\n\
                    \      -base_frame_pos_z 0.8 -base_frame_orient_u0 0 -base_frame_orient_u1 -0.707107\\\n\
                    \      -base_frame_orient_u2 0.707107\n" in
  let r = List.assoc "TASK1" b.robots in
  let p = pose r in
  Alcotest.(check f) "z in mm" 800. p.trans.z;
  Alcotest.(check f) "x not given: 0" 0. p.trans.x;
  Alcotest.(check f) "q1" 0. p.rot.q1;
  Alcotest.(check (float 1e-6)) "q2 normalised" (-. sqrt 0.5) p.rot.q2;
  Alcotest.(check (float 1e-6)) "q3 normalised" (sqrt 0.5) p.rot.q3;
  Alcotest.(check f) "u3 not given: 0" 0. p.rot.q4;
  Alcotest.(check string) "where it is" (dir // "SYSPAR" // "MOC.cfg" ^ ":5") r.base_frame.base_at;
  Alcotest.(check bool) "no warning of a base frame" false
    (List.exists (fun w -> contains w "base frame") b.warnings);
  (* the robot of the run stands there: the library's IRB 120 placed at it *)
  (match Rapid_run.Backup_setup.input ~robot:None [ dir ] with
   | Ok (Cell c) ->
       let placed = List.assoc "TASK1" c.robots in
       Alcotest.(check f) "the run's robot at z 800" 800. placed.base_frame.trans.z;
       Alcotest.(check string) "the library's arm" "ABB IRB 120-3/0.58" placed.name
   | Ok (Files _) -> Alcotest.fail "not a backup"
   | Error m -> Alcotest.fail m);
  (* --robot's arm is placed at the cell's base frame too *)
  (match Rapid_run.Backup_setup.input ~robot:(Some "irb2400-10-1.5") [ dir ] with
   | Ok (Cell c) -> Alcotest.(check f) "--robot at z 800" 800. (List.assoc "TASK1" c.robots).base_frame.trans.z
   | Ok (Files _) -> Alcotest.fail "not a backup"
   | Error m -> Alcotest.fail m);
  (* nothing given: the world frame *)
  let _, b = read "      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n" in
  Alcotest.(check bool) "no base frame: the world's" true
    (Rapid_motion_model.Base_frame.is_world (pose (List.assoc "TASK1" b.robots)));
  (* bad values: warnings at their lines, defaults taken *)
  let dir, b = read "      -name \"ROB_1\" -base_frame_pos_x abc\\\n\
                    \      -base_frame_pos_y nan -base_frame_orient_u0 -base_frame_pos_z 1E400\\\n\
                    \      -base_frame_orient_u3 0x10 -base_frame_pos_w 1 -base_frame_coordinated \"TRACK_1\"\n" in
  let r = List.assoc "TASK1" b.robots in
  let moc = dir // "SYSPAR" // "MOC.cfg" in
  List.iter (fun (line, part) ->
      if not (List.exists (fun w -> contains w (Printf.sprintf "%s:%d: warning: robot ROB_1: %s" moc line part))
                b.warnings) then Alcotest.failf "no warning %d: %s in %s" line part (String.concat "\n" b.warnings))
    [ (4, "-base_frame_pos_x \"abc\" is not a number: 0 is taken");
      (5, "-base_frame_pos_y \"nan\" is not a number");
      (5, "-base_frame_orient_u0 (no value) is not a number: 1 is taken");
      (5, "-base_frame_pos_z \"1E400\" is not a number");
      (6, "-base_frame_orient_u3 \"0x10\" is not a number");
      (6, "-base_frame_pos_w is not modelled");
      (6, "its base frame is moved by the mechanical unit TRACK_1") ];
  Alcotest.(check (option string)) "the unit" (Some "TRACK_1") r.base_frame.coordinated;
  Alcotest.(check bool) "all defaults: the world frame" true (Rapid_motion_model.Base_frame.is_world (pose r));
  (* a quaternion that is not a unit one, an origin too far: warnings, the world's kept *)
  let dir, b = read "      -name \"ROB_1\" -base_frame_orient_u0 0 -base_frame_pos_x 1E300\n" in
  let r = List.assoc "TASK1" b.robots in
  let p, w = Rapid_run.Backup_setup.base_frame r in
  Alcotest.(check bool) "the world's orientation and origin" true (Rapid_motion_model.Base_frame.is_world p);
  Alcotest.(check int) "two warnings" 2 (List.length w);
  List.iter (fun part ->
      if not (List.exists (fun x -> contains x (dir // "SYSPAR" // "MOC.cfg:4: warning: robot ROB_1: " ^ part)) w) then
        Alcotest.failf "no warning %s in %s" part (String.concat "\n" w))
    [ "its base frame's orientation: the quaternion [0,0,0,0] is not a unit quaternion";
      "its base frame's origin: the origin [1e+303,0,0] mm is not within" ];
  (* q and -q are one orientation: q1 made positive *)
  let _, b = read "      -name \"ROB_1\" -base_frame_orient_u0 -1\n" in
  Alcotest.(check bool) "-1, 0, 0, 0 is the world's" true
    (Rapid_motion_model.Base_frame.is_world (pose (List.assoc "TASK1" b.robots)))

(* --base-frame's text: seven decimal numbers, a unit quaternion. *)
let base_frame_text () =
  let module BF = Rapid_motion_model.Base_frame in
  (match BF.of_text " 200, 0 ,800,0,0,0,1" with
   | Ok p -> Alcotest.(check string) "read" "200,0,800,0,0,0,1" (BF.to_text p)
   | Error m -> Alcotest.fail m);
  List.iter (fun t -> match BF.of_text t with
      | Ok _ -> Alcotest.failf "accepted %S" t
      | Error _ -> ())
    [ ""; "1,2,3"; "1,2,3,1,0,0,0,0"; "1,2,3,nan,0,0,0"; "1,2,3,inf,0,0,0"; "0x10,0,0,1,0,0,0"; "1,2,3,2,0,0,0";
      "1e8,0,0,1,0,0,0"; "1,,3,1,0,0,0"; "a,b,c,d,e,f,g" ]

(* A program file: its modules beside it, in order; a malformed one is an error with its place. *)
let program_file () =
  let dir = temp_backup [ ("p.pgf", "<?xml version=\"1.0\" ?>\n<Program>\n <Module>a.mod</Module>\n \
                                     <Module>b.mod</Module>\n</Program>");
                          ("bad.pgf", "<Program><Module>a.mod</Modul></Program>");
                          ("empty.pgf", "<Program></Program>") ] in
  Alcotest.(check (result (list string) string)) "modules" (Ok [ dir // "a.mod"; dir // "b.mod" ])
    (Backup.read_pgf (dir // "p.pgf"));
  List.iter (fun f -> match Backup.read_pgf (dir // f) with
      | Ok _ -> Alcotest.failf "%s accepted" f
      | Error m -> Alcotest.(check bool) (f ^ ": " ^ m) true
                     (String.length m > String.length (dir // f) && String.sub m 0 (String.length (dir // f)) = dir // f))
    [ "bad.pgf"; "empty.pgf"; "missing.pgf" ]

(* A backup whose configuration files are mutated at random: read or refused, never raising. *)
let hostile_backup () =
  let rs = Random.State.make [| 23 |] in
  let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n \
             -Name \"T_B\" -UseMechanicalUnitGroup \"rob1\"\n#\nMECHANICAL_UNIT_GROUP:\n -Name \"rob1\" -Robot \"ROB_1\"\n#\n\
             CAB_EXEC_HOOKS:\n -Routine \"p\" -Shelf \"POWER_ON\" -AllTask -SeqNo 2\n\
             \ -Routine \"s\" -Shelf \"STOP\" -Task \"T_B\"\n#\n"
  and moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\" -use_joint_0 \"j\"\n#\n\
             ARM:\n -name \"j\" -upper_joint_bound 1 -lower_joint_bound -1\n#\n"
  and info = ">>TASK1: (T_ROB1,,)\nPROGMOD/A.mod @ a.mod\n\n>>TASK2: (T_B,,)\nPROGMOD/B.mod @ b.mod\n>>EOF:\n" in
  let mutate text =
    let b = Bytes.of_string text in
    for _ = 1 to 1 + Random.State.int rs 3 do
      Bytes.set b (Random.State.int rs (Bytes.length b)) (Char.chr (Random.State.int rs 256))
    done;
    Bytes.sub_string b 0 (Random.State.int rs (Bytes.length b + 1)) in
  for _ = 1 to 60 do
    let dir = temp_backup [ ("SYSPAR/SYS.cfg", mutate sys); ("SYSPAR/MOC.cfg", mutate moc);
                            ("BACKINFO/backinfo.txt", mutate info);
                            ("RAPID/TASK1/PROGMOD/A.mod", main_mod "A"); ("RAPID/TASK2/PROGMOD/B.mod", main_mod "B") ] in
    match Backup.read dir with
    | Ok _ | Error _ -> ()
    | exception e -> Alcotest.failf "%s: %s" dir (Printexc.to_string e)
  done

let suite =
  ( "backup",
    [ Alcotest.test_case "cfg format" `Quick format;
      Alcotest.test_case "malformed cfg" `Quick malformed;
      Alcotest.test_case "hostile cfg" `Quick hostile;
      Alcotest.test_case "long cfg lines" `Quick long_lines;
      Alcotest.test_case "hostile backups" `Quick hostile_backup;
      Alcotest.test_case "task folders alone" `Quick bare_folders;
      Alcotest.test_case "tasks configured" `Quick configured;
      Alcotest.test_case "refused backups" `Quick refused;
      Alcotest.test_case "joint bounds" `Quick narrowed;
      Alcotest.test_case "base frames" `Quick base_frames;
      Alcotest.test_case "--base-frame text" `Quick base_frame_text;
      Alcotest.test_case "program file" `Quick program_file;
      Alcotest.test_case "RobotWare release" `Quick robotware;
      Alcotest.test_case "mechanical units as mecunit data" `Quick mechanical_units;
      Alcotest.test_case "a task folder without a program" `Quick no_program;
      Alcotest.test_case "a track of MOC.cfg carrying a robot" `Quick tracks ] )
