module Backup = Rapid_load.Backup
module Robot = Rapid_motion_model.Robot
module Ext_axes = Rapid_motion_model.Ext_axes

type cell = {
  backup : Backup.t; robots : (string * Robot.t) list; stand_in : (string * string) list; warnings : string list;
}
type input = Files of string list | Cell of cell

let same a b = String.lowercase_ascii a = String.lowercase_ascii b

(* The robot library of the motion model, by MOC.cfg's type (ROB1_2400_1.5_10). *)
let library_find = Rapid_motion_model.Robot_library.find

let degrees r = r *. 180. /. Float.pi

(* R-bk-5: the arm's bounds narrow the description's range, never widen it. *)
let narrow (robot : Robot.t) (bounds : Backup.bound list) =
  let warnings = ref [] in
  let axes = Array.mapi (fun k (a : Robot.axis) ->
      match List.find_opt (fun (b : Backup.bound) -> b.axis = k + 1) bounds with
      | None -> a
      | Some b ->
          let lo = Float.max a.min (degrees b.lower) and hi = Float.min a.max (degrees b.upper) in
          if lo > hi then begin
            warnings := Printf.sprintf "%s: warning: axis %d: the joint bounds %g .. %g rad leave nothing of %s's \
                                        range %g .. %g degrees: its range kept" b.bound_at (k + 1) b.lower b.upper
                robot.name a.min a.max :: !warnings;
            a
          end else { a with min = lo; max = hi }) robot.axes in
  ({ robot with axes }, List.rev !warnings)

(* R-bk-12: the cell's base frame of a robot, in mm; a quaternion that is not a unit one, or an
   origin beyond the model's bound, is a warning and the world frame's orientation (origin) kept. *)
let base_frame (r : Backup.robot) =
  let b = r.base_frame in
  let x, y, z = b.pos and q1, q2, q3, q4 = b.orient in
  let module BF = Rapid_motion_model.Base_frame in
  let warn what m = Printf.sprintf "%s: warning: robot %s: its base frame's %s: %s; the world frame's is taken"
      b.base_at r.robot_name what m in
  let trans, w1 = match BF.position (1000. *. x) (1000. *. y) (1000. *. z) with
    | Ok p -> (p, []) | Error m -> (Rapid_motion_model.Geom.origin, [ warn "origin" m ]) in
  let rot, w2 = match BF.orientation q1 q2 q3 q4 with
    | Ok q -> (q, []) | Error m -> (Rapid_motion_model.Geom.unit_orient, [ warn "orientation" m ]) in
  ({ Rapid_motion_model.Geom.trans; rot }, w1 @ w2)

(* R-bk-15: IRBT 4004, 6004 and 7004 tracks travel at up to 2 m/s in ABB's product
   specifications as recalled, not checked against ABB's PDFs: an estimate. *)
let track_speed = 2000.

(* R-bk-15: a track of MOC.cfg is the external axis eax_a, linear, its travel the arm's bounds in
   mm, carrying the base along the x axis of the track's base frame. A description that has its
   own eax_a (--robot FILE with an external line) keeps it. *)
let with_track (arm : Robot.t) (r : Backup.robot) =
  match r.track with
  | None -> (arm, [])
  | Some t when List.exists (fun (a : Ext_axes.axis) -> a.index = 0) arm.externals ->
      (arm, [ Printf.sprintf "%s: warning: robot %s: the track %s is not added: the robot description has its own \
                              eax_a" t.track_at r.robot_name t.track_unit ])
  | Some t ->
      let q1, q2, q3, q4 = t.track_orient in
      let module BF = Rapid_motion_model.Base_frame in
      let module G = Rapid_motion_model.Geom in
      let rot, w = match BF.orientation q1 q2 q3 q4 with
        | Ok q -> (q, [])
        | Error m -> (G.unit_orient, [ Printf.sprintf "%s: warning: track %s: its base frame's orientation: %s; the \
                                                       world's x axis is taken" t.track_at t.track_unit m ]) in
      let lower, upper = t.travel in
      let axis = { Ext_axes.name = "eax_a"; index = 0; kind = Ext_axes.Linear; min = 1000. *. lower;
                   max = 1000. *. upper; speed = track_speed; track = Some (G.rotate rot { G.x = 1.; y = 0.; z = 0. }) } in
      ({ arm with externals = axis :: arm.externals }, w)

(* The robot placed in the cell (the arm of its type, or --robot's): the base frame is the cell's,
   and a track of the cell carries it. *)
let placed (arm : Robot.t) (r : Backup.robot) =
  let b, w = base_frame r in
  let arm, wt = with_track { arm with base_frame = b } r in
  (arm, w @ wt)

let robot_of_type (r : Backup.robot) =
  match library_find r.robot_type with
  | Ok robot ->
      let robot, w = narrow robot r.bounds in
      let robot, wb = placed robot r in
      Ok ((robot, w @ wb), true)
  | Error _ ->
      let what = if r.robot_type = "" then Printf.sprintf "robot %s has no -use_robot_type" r.robot_name
        else Printf.sprintf "robot %s: the type %s is not in the robot library" r.robot_name r.robot_type in
      let robot, wb = placed Robot.irb120 r in
      Ok ((robot, Printf.sprintf "%s: warning: %s: the default IRB 120 moves instead (its joint bounds \
                                  are not applied)" r.robot_at what :: wb), false)

let input ~robot files =
  match files with
  | [ f ] when Sys.file_exists f && Sys.is_directory f ->
      if not (Backup.is_backup f) then
        Error (Printf.sprintf "%s:1:1: backup error: a folder that is not a controller backup (no RAPID/, SYSPAR/ or \
                               BACKINFO/backinfo.txt)" f)
      else
        Result.bind (Backup.read f) (fun (b : Backup.t) ->
            let given = match robot with
              | None -> Ok None
              | Some name -> Result.map Option.some (Rapid_motion_model.Robot_library.load name) in
            Result.bind given (fun given ->
                let robots = List.filter_map (fun (t : Backup.task) ->
                    if not t.motion then None
                    else match given, List.assoc_opt t.name b.robots with
                      | Some r, Some cell -> Some (t.name, (placed r cell, Some "--robot"))
                      | Some r, None -> Some (t.name, ((r, []), Some "--robot"))
                      | None, Some r ->
                          let robot, known = Result.get_ok (robot_of_type r) in
                          Some (t.name, (robot, if known then None else Some "not in the robot library"))
                      | None, None -> Some (t.name, ((Robot.irb120, []), Some "no robot in MOC.cfg"))) b.tasks in
                Ok (Cell { backup = b; robots = List.map (fun (n, ((r, _), _)) -> (n, r)) robots;
                           stand_in = List.filter_map (fun (n, (_, why)) -> Option.map (fun w -> (n, w)) why) robots;
                           warnings = b.warnings @ List.concat_map (fun (_, ((_, w), _)) -> w) robots })))
  | [ f ] when String.lowercase_ascii (Filename.extension f) = ".pgf" ->
      Result.map (fun l -> Files l) (Backup.read_pgf f)
  | files -> Ok (Files files)

type task_summary = {
  task : string; kind : string; entry : string; motion : bool; robot : string option; robot_type : string option;
  stand_in : string option; reads : string option; modules : int; event_routines : (string * string) list;
}

type summary = { dir : string; tasks : task_summary list; io : string option; signals : int; warned : int }

let summary c ~run ~(io : Rapid_controller.Io_config.t) =
  let b = c.backup in
  let tasks = List.map (fun (s : Task_load.spec) ->
      let t = List.find_opt (fun (t : Backup.task) -> same t.name s.name) b.tasks in
      let motion = List.mem_assoc s.name c.robots in
      { task = s.name;
        kind = (match t with Some t -> Backup.kind_name t.kind | None -> "NORMAL");
        entry = s.entry; motion;
        robot = Option.map (fun (r : Robot.t) -> r.name) (List.assoc_opt s.name c.robots);
        robot_type =
          (if motion then Option.map (fun (r : Backup.robot) -> r.robot_type) (List.assoc_opt s.name b.robots)
           else None);
        stand_in = Option.map snd (List.find_opt (fun (n, _) -> same n s.name) c.stand_in);
        reads = (if motion then None else List.assoc_opt s.name b.connected);
        modules = List.length s.files;
        event_routines = (match t with
            | Some t -> List.map (fun (e : Backup.event_routine) -> (e.routine, e.event)) (t.before @ t.after)
            | None -> []) }) run in
  { dir = b.dir; tasks; io = (if io.file = "" then None else Some io.file); signals = List.length io.signals;
    warned = List.length c.warnings }
