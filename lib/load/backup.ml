(* A controller backup, read as the controller reads it at start (R-bk-1 to R-bk-10). Every
   choice where the backup could be read two ways is a ruling of doc/rulings.md. *)

type kind = Normal | Static | Semistatic

type event_routine = { routine : string; event : string; hook_at : string }

type task = {
  name : string; folder : string; kind : kind; motion : bool; group : string option; entry : string;
  files : string list; at : string; before : event_routine list; after : event_routine list;
  debug_events : event_routine list;
}

type bound = { axis : int; lower : float; upper : float; bound_at : string }
type base_frame = {
  pos : float * float * float; orient : float * float * float * float; coordinated : string option; base_at : string;
}
type track = { track_unit : string; travel : float * float; track_orient : float * float * float * float;
               track_at : string }
type robot = { robot_name : string; robot_type : string; bounds : bound list; robot_at : string;
               base_frame : base_frame; track : track option }

type t = {
  dir : string;
  tasks : task list;
  robots : (string * robot) list;
  connected : (string * string) list;
  eio : string option;
  retry_limit : int option;
  robotware : Rapid_syntax.Robotware.t option;
  units : string list;
  warnings : string list;
}

let kind_name = function Normal -> "NORMAL" | Static -> "STATIC" | Semistatic -> "SEMISTATIC"
let same a b = String.lowercase_ascii a = String.lowercase_ascii b
let ( // ) = Filename.concat
let ( let* ) = Result.bind

let is_dir p = try Sys.is_directory p with Sys_error _ -> false
let is_file p = Sys.file_exists p && not (is_dir p)

(* A sub-folder of the backup by its name, letter case aside (a backup copied from a Windows PC
   may have rapid/ or Syspar/). *)
let child dir name =
  if not (is_dir dir) then None
  else match List.find_opt (same name) (Array.to_list (try Sys.readdir dir with Sys_error _ -> [||])) with
    | Some n -> Some (dir // n)
    | None -> None

let is_backup dir =
  is_dir dir && (child dir "RAPID" <> None || child dir "SYSPAR" <> None
                 || Option.fold ~none:false ~some:(fun b -> child b "backinfo.txt" <> None) (child dir "BACKINFO"))

let module_extensions = [ ".mod"; ".modx"; ".sys"; ".sysx" ]
let is_module_file f = List.mem (String.lowercase_ascii (Filename.extension f)) module_extensions

let read_text file =
  match open_in_bin file with
  | exception Sys_error m -> Error (Printf.sprintf "%s:1:1: backup error: cannot read the file (%s)" file m)
  | ic ->
      Ok (Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic)))

let lines text =
  List.map (fun l -> if l <> "" && l.[String.length l - 1] = '\r' then String.sub l 0 (String.length l - 1) else l)
    (String.split_on_char '\n' text)

(* R-bk-1: backinfo.txt, ">>TASKn: (NAME,PROGRAM,)" and the task's module files after it, each
   "PROGMOD/x.mod @ x.mod", in the order the controller loaded them. *)
type info_task = { number : int; info_name : string; info_files : (string * int) list; info_line : int }

(* R-2.4-rw6: ">>PRODUCTS_ID:" ... "RobotWare Version: 6.13.02.00" names the release the modules
   were written for. A line that does not read as a release names none. *)
let release_of_backinfo text =
  let key = "robotware version:" in
  List.find_map (fun l ->
      let l = String.trim l in
      let n = String.length key in
      if String.length l > n && String.lowercase_ascii (String.sub l 0 n) = key then
        Rapid_syntax.Robotware.of_string (String.trim (String.sub l n (String.length l - n)))
      else None) (lines text)

(* The tasks of backinfo.txt and the release it names, from one reading of the file. *)
let read_backinfo file =
  let* text = read_text file in
  let tasks = ref [] and current = ref None in
  let close () = Option.iter (fun t -> tasks := { t with info_files = List.rev t.info_files } :: !tasks) !current;
    current := None in
  let rec each ln = function
    | [] -> Ok ()
    | l :: rest ->
        let l = String.trim l in
        if String.length l > 6 && String.sub l 0 6 = ">>TASK" then begin
          close ();
          match String.index_opt l ':', String.index_opt l '(' with
          | Some c, Some p when p > c ->
              let number = int_of_string_opt (String.sub l 6 (c - 6)) in
              let inside = String.sub l (p + 1) (String.length l - p - 1) in
              let name = String.trim (List.hd (String.split_on_char ',' inside)) in
              (match number with
               | Some n when n > 0 && name <> "" ->
                   current := Some { number = n; info_name = name; info_files = []; info_line = ln }; each (ln + 1) rest
               | _ -> Error (Printf.sprintf "%s:%d:1: backup error: expected >>TASKn: (NAME,PROGRAM,)" file ln))
          | _ -> Error (Printf.sprintf "%s:%d:1: backup error: expected >>TASKn: (NAME,PROGRAM,)" file ln)
        end
        else if String.length l > 2 && String.sub l 0 2 = ">>" then (close (); each (ln + 1) rest)
        else begin
          (match !current with
           | Some t when l <> "" && l.[0] <> '#' ->
               let path = match String.index_opt l '@' with Some k -> String.trim (String.sub l 0 k) | None -> l in
               (* A backup made on Windows writes PROGMOD\x.mod. *)
               let path = String.map (fun c -> if c = '\\' then '/' else c) path in
               current := Some { t with info_files = (path, ln) :: t.info_files }
           | _ -> ());
          each (ln + 1) rest
        end in
  let* () = each 1 (lines text) in
  close ();
  Ok (List.rev !tasks, release_of_backinfo text)

let robotware_of_backinfo file =
  match read_text file with Error _ -> None | Ok text -> release_of_backinfo text

let sort_names l = List.sort (fun a b -> compare (String.lowercase_ascii a) (String.lowercase_ascii b)) l

let entries dir = match dir with
  | Some d -> sort_names (Array.to_list (try Sys.readdir d with Sys_error _ -> [||]))
  | None -> []

(* R-bk-2: an encrypted module (RobotWare loads modules it encrypted itself) is bytes, not
   text: control characters other than tab, line breaks and form feed among its first bytes. *)
let is_encrypted file =
  match open_in_bin file with
  | exception Sys_error _ -> false
  | ic ->
      let head = Fun.protect ~finally:(fun () -> close_in_noerr ic)
          (fun () -> really_input_string ic (min 64 (in_channel_length ic))) in
      String.exists (fun c -> Char.code c < 0x20 && not (List.mem c [ '\t'; '\n'; '\r'; '\012' ])) head

(* The module files of a task folder: backinfo.txt's list when it has one, else SYSMOD's then
   PROGMOD's module files by name (R-bk-2). What the folder holds beside them is a warning. *)
let rec task_files ~warn ~info_file folder listed =
  List.filter (fun f ->
      if is_encrypted f then
        (warn (Printf.sprintf "%s:1: warning: an encrypted module (not RAPID text): not loaded" f); false)
      else true) (listed_files ~warn ~info_file folder listed)

and listed_files ~warn ~info_file folder (listed : (string * int) list option) =
  let sub name = child folder name in
  let present = List.concat_map (fun s ->
      List.map (fun f -> (s ^ "/" ^ f, Option.get (sub s) // f)) (entries (sub s))) [ "SYSMOD"; "PROGMOD" ] in
  let present = List.filter (fun (_, p) -> is_file p) present in
  let modules, others = List.partition (fun (_, p) -> is_module_file p) present in
  List.iter (fun (_, p) -> warn (Printf.sprintf "%s:1: warning: not a module file (%s): not loaded" p
                                   (String.concat ", " module_extensions))) others;
  match listed with
  | None -> List.map snd modules
  | Some listed ->
      let found = List.filter_map (fun (rel, ln) ->
          match List.find_opt (fun (r, _) -> same r rel) present with
          | Some (_, p) when is_module_file p -> Some p
          | Some (_, p) ->
              warn (Printf.sprintf "%s:%d: warning: %s is not a module file: not loaded" info_file ln p); None
          | None -> warn (Printf.sprintf "%s:%d: warning: %s is not in %s: not loaded" info_file ln rel folder); None)
          listed in
      List.iter (fun (rel, p) ->
          if not (List.exists (fun (r, _) -> same r rel) listed) then
            warn (Printf.sprintf "%s:1: warning: not in the task's list of %s: not loaded" p info_file)) modules;
      found

let cfg_place (c : Cfg_file.t) line = Cfg_file.place c line

(* R-bk-7: what a cfg file holds beyond the sections read, once per file. *)
let unread_sections ~warn (c : Cfg_file.t) read =
  match List.filter (fun (s : Cfg_file.section) -> not (List.exists (same s.name) read)) c.sections with
  | [] -> ()
  | first :: _ as rest ->
      warn (Printf.sprintf "%s: warning: not modelled, the sections %s" (cfg_place c first.line)
              (String.concat ", " (List.map (fun (s : Cfg_file.section) ->
                   Printf.sprintf "%s (line %d)" s.name s.line) rest)))

let instances c name = match Cfg_file.section c name with Some s -> s.instances | None -> []

let unmodelled_attributes ~warn (c : Cfg_file.t) ~what (i : Cfg_file.instance) modelled =
  List.iter (fun (a : Cfg_file.attribute) ->
      if not (List.exists (same a.key) modelled) then
        warn (Printf.sprintf "%s: warning: %s: -%s%s is not modelled" (cfg_place c a.line) what a.key
                (match a.value with Flag -> "" | Text v -> Printf.sprintf " \"%s\"" v)))
    i.attributes

type cab_task = { c_name : string; c_kind : kind; c_motion : bool; c_group : string option; c_entry : string;
                  c_at : string }

(* R-bk-3: CAB_TASKS. *)
let cab_tasks ~warn (c : Cfg_file.t) =
  let rec go acc = function
    | [] -> Ok (List.rev acc)
    | (i : Cfg_file.instance) :: rest -> (
        match Cfg_file.text i "Name" with
        | None -> Error (Printf.sprintf "%s:%d:1: cfg error: a CAB_TASKS instance without -Name" c.file i.at_line)
        | Some name when List.exists (fun t -> same t.c_name name) acc ->
            Error (Printf.sprintf "%s:%d:1: cfg error: the task %s is configured twice" c.file i.at_line name)
        | Some name -> (
            let kind = match Cfg_file.text i "Type" with
              | None -> Ok Semistatic
              | Some t when same t "NORMAL" -> Ok Normal
              | Some t when same t "STATIC" -> Ok Static
              | Some t when same t "SEMISTATIC" -> Ok Semistatic
              | Some t ->
                  let a = Option.get (Cfg_file.find i "Type") in
                  Error (Printf.sprintf
                           "%s:%d:%d: cfg error: task %s: -Type \"%s\" is none of NORMAL, STATIC, SEMISTATIC"
                           c.file a.line a.col name t) in
            match kind with
            | Error e -> Error e
            | Ok kind ->
                (* R-bk-9: -TrustLevel NoSafety (written "None") is what a run does: an error that
                   stops a STATIC or SEMISTATIC task stops that task alone. *)
                let no_safety = match Cfg_file.text i "TrustLevel" with
                  | Some t -> same t "None" || same t "NoSafety" | None -> false in
                unmodelled_attributes ~warn c ~what:("task " ^ name) i
                  ([ "Name"; "Type"; "MotionTask"; "UseMechanicalUnitGroup"; "Entry" ]
                   @ if no_safety then [ "TrustLevel" ] else []);
                if kind <> Normal && Cfg_file.find i "TrustLevel" = None then
                  warn (Printf.sprintf "%s: warning: task %s: its trust level SysFail (no -TrustLevel) is not \
                                        modelled: an error that stops the task stops it alone" (cfg_place c i.at_line)
                          name);
                let entry = Option.value (Cfg_file.text i "Entry") ~default:"main" in
                go ({ c_name = name; c_kind = kind; c_motion = Cfg_file.flag i "MotionTask";
                      c_group = Cfg_file.text i "UseMechanicalUnitGroup"; c_entry = entry;
                      c_at = cfg_place c i.at_line } :: acc) rest))
  in
  go [] (instances c "CAB_TASKS")

(* R-bk-8: CAB_EXEC_HOOKS, the event routines: -Routine, -Shelf (the event), the tasks it runs
   in (-Task, -AllTask, -AllMotionTask), -SeqNo (their order within one event, then SYS.cfg's). *)
type hook = { h_routine : string; h_event : string; h_task : string option; h_all : bool; h_all_motion : bool;
              h_seq : int; h_at : string; h_index : int }

let events = [ "POWER_ON"; "START"; "RESTART"; "STOP"; "QSTOP"; "RESET"; "STEP" ]

let hooks ~warn (c : Cfg_file.t) =
  List.filter_map Fun.id (List.mapi (fun index (i : Cfg_file.instance) ->
      let at = cfg_place c i.at_line in
      match Cfg_file.text i "Routine", Cfg_file.text i "Shelf" with
      | None, _ -> warn (Printf.sprintf "%s: warning: an event routine without -Routine: not run" at); None
      | Some r, None -> warn (Printf.sprintf "%s: warning: the event routine %s has no -Shelf: not run" at r); None
      | Some r, Some e when not (List.exists (same e) events) ->
          warn (Printf.sprintf "%s: warning: the event routine %s: -Shelf \"%s\" is none of %s: not run" at r e
                  (String.concat ", " events)); None
      | Some r, Some e ->
          unmodelled_attributes ~warn c ~what:("event routine " ^ r) i
            [ "Routine"; "Shelf"; "Task"; "AllTask"; "AllMotionTask"; "SeqNo" ];
          let seq = match Cfg_file.text i "SeqNo" with
            | None -> 0
            | Some v -> (match int_of_string_opt v with
                | Some n -> n
                | None -> warn (Printf.sprintf "%s: warning: the event routine %s: -SeqNo %s is not a whole number: 0"
                                  at r v); 0) in
          let task = Cfg_file.text i "Task" and all = Cfg_file.flag i "AllTask"
          and all_motion = Cfg_file.flag i "AllMotionTask" in
          if task = None && not all && not all_motion then begin
            warn (Printf.sprintf "%s: warning: the event routine %s names no task (-Task, -AllTask, -AllMotionTask): \
                                  not run" at r); None
          end else
            Some { h_routine = r; h_event = String.uppercase_ascii e; h_task = task; h_all = all;
                   h_all_motion = all_motion; h_seq = seq; h_at = at; h_index = index })
      (instances c "CAB_EXEC_HOOKS"))

(* R-bk-8: which events a run makes happen in a task, in their order: POWER_ON in every task (the
   controller's start); then, in a NORMAL task (the one the program's buttons and PP to main act
   on), RESET (PP to main) and START (a start from the beginning) before the entry routine, STOP
   after it returned (the program's end stops it). RESTART, STEP and QSTOP do not happen in a
   run, nor the events of the buttons in a STATIC or SEMISTATIC task. *)
let task_events ~warn hooks ~name ~kind ~motion =
  let mine h = h.h_all || (h.h_all_motion && motion) || Option.fold ~none:false ~some:(same name) h.h_task in
  let of_event e = List.filter (fun h -> h.h_event = e && mine h) hooks
                   |> List.stable_sort (fun a b -> compare (a.h_seq, a.h_index) (b.h_seq, b.h_index))
                   |> List.map (fun h -> { routine = h.h_routine; event = h.h_event; hook_at = h.h_at }) in
  let normal = kind = Normal in
  List.iter (fun h ->
      if mine h then
        let why = match h.h_event with
          | "RESTART" when normal -> Some "a run never restarts a stopped program (debug runs it at each continue \
                                          after a stop)"
          | "STEP" when normal -> Some "a run does not step (debug runs it at each step)"
          | ("RESTART" | "STEP") -> Some (Printf.sprintf "the task is %s" (kind_name kind))
          | "QSTOP" -> Some "a run has no quick stop"
          | ("START" | "STOP" | "RESET") when not normal ->
              Some (Printf.sprintf "the task is %s: the start and stop buttons and PP to main act on NORMAL tasks"
                      (kind_name kind))
          | _ -> None in
        Option.iter (fun why ->
            warn (Printf.sprintf "%s: warning: the event routine %s (%s) is not run in task %s: %s" h.h_at h.h_routine
                    h.h_event name why)) why) hooks;
  let before = of_event "POWER_ON" @ (if normal then of_event "RESET" @ of_event "START" else []) in
  let after = if normal then of_event "STOP" else [] in
  (* R-bk-11: what debug makes happen besides POWER_ON and RESET, by the commands. *)
  let debug = if normal then List.concat_map of_event [ "START"; "RESTART"; "STEP"; "STOP" ] else [] in
  (before, after, debug)

(* SYS.cfg's other sections that change what runs: the modules loaded into every task at cold
   start, SYS_MISC's NoOfRetry (§7.1's retry limit). *)
let sys_misc ~warn (c : Cfg_file.t) =
  List.iter (fun (i : Cfg_file.instance) ->
      warn (Printf.sprintf "%s: warning: the module %s of every task at cold start is not loaded from there: the \
                            task folders hold what was loaded"
              (cfg_place c i.at_line) (Option.value (Cfg_file.text i "File") ~default:"?")))
    (instances c "CAB_TASK_MODULES");
  List.fold_left (fun acc (i : Cfg_file.instance) ->
      match Cfg_file.text i "Name" with
      | Some n when same n "NoOfRetry" -> (
          match Option.bind (Cfg_file.text i "Value") int_of_string_opt with
          | Some v when v >= 0 -> Some v
          | _ -> warn (Printf.sprintf "%s: warning: NoOfRetry without a whole -Value: the default kept"
                         (cfg_place c i.at_line)); acc)
      | n -> warn (Printf.sprintf "%s: warning: SYS_MISC %s is not modelled" (cfg_place c i.at_line)
                     (Option.value n ~default:"?")); acc) None (instances c "SYS_MISC")

(* R-bk-4: MECHANICAL_UNIT_GROUP: a group's robot, by MOC.cfg's ROBOT -name. *)
let groups ~warn (c : Cfg_file.t) =
  List.filter_map (fun (i : Cfg_file.instance) ->
      match Cfg_file.text i "Name" with
      | None -> warn (Printf.sprintf "%s: warning: a MECHANICAL_UNIT_GROUP without -Name: not read"
                        (cfg_place c i.at_line)); None
      | Some name ->
          unmodelled_attributes ~warn c ~what:("mechanical unit group " ^ name) i [ "Name"; "Robot" ];
          Some (name, Cfg_file.text i "Robot")) (instances c "MECHANICAL_UNIT_GROUP")

(* R-bk-12: a ROBOT's base frame (ABB, system parameters, topic Motion, type Robot: "Base Frame"
   x, y, z in metres, q1 .. q4, "Base Frame Moved by"; MOC.cfg writes them -base_frame_pos_x ..
   _z, -base_frame_orient_u0 .. _u3, -base_frame_coordinated). An attribute not given is the
   world frame's (0, and u0 = 1); a value that is not a number is a warning and that default. *)
let base_frame_keys =
  [ "base_frame_pos_x"; "base_frame_pos_y"; "base_frame_pos_z";
    "base_frame_orient_u0"; "base_frame_orient_u1"; "base_frame_orient_u2"; "base_frame_orient_u3" ]

(* A cfg value that is a finite decimal number ("0x10", which float_of_string reads, is not). *)
let decimal v =
  let v = String.trim v in
  if not (Rapid_syntax.Decimal.is_decimal v) then None
  else match float_of_string_opt v with Some f when Float.is_finite f -> Some f | _ -> None

let base_frame ~warn (c : Cfg_file.t) ~name (i : Cfg_file.instance) =
  let of_base (a : Cfg_file.attribute) =
    String.length a.key > 11 && same (String.sub a.key 0 11) "base_frame_" in
  let given = List.filter of_base i.attributes in
  let value key default =
    match Cfg_file.find i key with
    | None -> default
    | Some a ->
        match (match a.value with Text v -> decimal v | Flag -> None) with
        | Some f -> f
        | None ->
            warn (Printf.sprintf "%s: warning: robot %s: -%s %s is not a number: %g is taken instead"
                    (cfg_place c a.line) name a.key
                    (match a.value with Flag -> "(no value)" | Text v -> Printf.sprintf "\"%s\"" v) default);
            default in
  List.iter (fun (a : Cfg_file.attribute) ->
      if not (List.exists (same a.key) ("base_frame_coordinated" :: base_frame_keys)) then
        warn (Printf.sprintf "%s: warning: robot %s: -%s is not modelled" (cfg_place c a.line) name a.key)) given;
  let coordinated = match Cfg_file.find i "base_frame_coordinated" with
    | None -> None
    | Some { value = Text u; _ } -> Some u
    | Some a ->
        warn (Printf.sprintf "%s: warning: robot %s: -base_frame_coordinated without a unit: not read"
                (cfg_place c a.line) name);
        None in
  let v k d = value (List.nth base_frame_keys k) d in
  { pos = (v 0 0., v 1 0., v 2 0.); orient = (v 3 1., v 4 0., v 5 0., v 6 0.); coordinated;
    base_at = (match given with a :: _ -> cfg_place c a.line | [] -> cfg_place c i.at_line) }

(* R-bk-15: the unit that moves a robot's base frame, when it is a track: a MECHANICAL_UNIT whose
   -use_single_0 names a SINGLE, the arm of that single's joint (ARM -use_arm_type) giving its
   travel in metres, the single's base frame orientation the direction it moves along (its x
   axis). Anything else (a gantry, a unit not found) is None, and the caller warns. *)
let track_of (c : Cfg_file.t) unit_name =
  let named section n =
    List.find_opt (fun i -> match Cfg_file.text i "name" with Some m -> same m n | None -> false)
      (instances c section) in
  let finite k i = Option.bind (Cfg_file.text i k) decimal in
  let ( let* ) = Option.bind in
  let* mu = named "MECHANICAL_UNIT" unit_name in
  let* single_name = Cfg_file.text mu "use_single_0" in
  let* single = named "SINGLE" single_name in
  let* joint = Cfg_file.text single "use_joint" in
  let* arm = List.find_opt (fun i -> match Cfg_file.text i "use_arm_type" with
      | Some t -> same t joint | None -> false) (instances c "ARM") in
  let* lower = finite "lower_joint_bound" arm in
  let* upper = finite "upper_joint_bound" arm in
  let q k d = Option.value (finite ("base_frame_orient_u" ^ string_of_int k) single) ~default:d in
  if lower >= upper then None
  else Some { track_unit = unit_name; travel = (lower, upper); track_orient = (q 0 1., q 1 0., q 2 0., q 3 0.);
              track_at = cfg_place c single.at_line }

(* A gantry's "robot" (Gantry11_X_Y_Z_NOTCP) moves external axes, not an arm of the library. *)
let no_tcp_type r = String.length r.robot_type >= 5
                       && same (String.sub r.robot_type (String.length r.robot_type - 5) 5) "NOTCP"

(* R-bk-5: MOC.cfg's robots and the joint bounds of their arms. *)
let robots ~warn (c : Cfg_file.t) =
  let arms = instances c "ARM" in
  let arm name =
    List.find_opt (fun i -> match Cfg_file.text i "name" with Some n -> same n name | None -> false) arms in
  let number (i : Cfg_file.instance) key =
    match Cfg_file.find i key with
    | None -> Ok None
    | Some { value = Text v; line; col; _ } -> (
        match float_of_string_opt v with
        | Some f when Float.is_finite f -> Ok (Some f)
        | _ -> Error (Printf.sprintf "%s:%d:%d: cfg error: -%s %s is not a number" c.file line col key v))
    | Some { value = Flag; line; col; _ } ->
        Error (Printf.sprintf "%s:%d:%d: cfg error: -%s has no value" c.file line col key) in
  let rec each acc = function
    | [] -> Ok (List.rev acc)
    | (i : Cfg_file.instance) :: rest ->
        let name = Option.value (Cfg_file.text i "name") ~default:"" in
        let rec axes k acc_b =
          if k > 6 then Ok (List.rev acc_b)
          else match Cfg_file.text i (Printf.sprintf "use_joint_%d" (k - 1)) with
            | None -> axes (k + 1) acc_b
            | Some joint -> (
                match arm joint with
                | None -> axes (k + 1) acc_b
                | Some a -> (
                    match number a "lower_joint_bound", number a "upper_joint_bound" with
                    | Error e, _ | _, Error e -> Error e
                    | Ok (Some lower), Ok (Some upper) ->
                        if lower > upper then
                          Error (Printf.sprintf "%s:%d:1: cfg error: arm %s: -lower_joint_bound %g is above \
                                                 -upper_joint_bound %g" c.file a.at_line joint lower upper)
                        else axes (k + 1) ({ axis = k; lower; upper; bound_at = cfg_place c a.at_line } :: acc_b)
                    | _ -> axes (k + 1) acc_b)) in
        match axes 1 [] with
        | Error e -> Error e
        | Ok bounds ->
            let base_frame = base_frame ~warn c ~name i in
            let track = Option.bind base_frame.coordinated (track_of c) in
            Option.iter (fun u ->
                if track = None then
                  warn (Printf.sprintf "%s: warning: robot %s: its base frame is moved by the mechanical unit %s \
                                        (-base_frame_coordinated), which is not modelled (not a track): the base frame \
                                        stands where the unit's 0 puts it, given in the world frame"
                          (match Cfg_file.find i "base_frame_coordinated" with
                           | Some a -> cfg_place c a.line | None -> base_frame.base_at) name u)) base_frame.coordinated;
            each ({ robot_name = name; robot_type = Option.value (Cfg_file.text i "use_robot_type") ~default:"";
                    bounds; robot_at = cfg_place c i.at_line; base_frame; track } :: acc) rest in
  let* rs = each [] (instances c "ROBOT") in
  (* A track that carries a robot is modelled (R-bk-15). *)
  let is_track n = List.exists (fun r -> match r.track with Some t -> same t.track_unit n | None -> false) rs in
  (* A unit that is a robot of the library's (-use_robot naming a ROBOT with a type) is that robot. *)
  let is_robot (i : Cfg_file.instance) = match Cfg_file.text i "use_robot" with
    | Some r -> List.exists (fun x -> same x.robot_name r && x.robot_type <> "" && not (no_tcp_type x)) rs
    | None -> false in
  List.iter (fun (i : Cfg_file.instance) ->
      let name = Option.value (Cfg_file.text i "name") ~default:"?" in
      if not (is_track name || is_robot i) then
        warn (Printf.sprintf "%s: warning: the mechanical unit %s (an external axis) is not modelled"
                (cfg_place c i.at_line) name))
    (instances c "MECHANICAL_UNIT");
  Ok rs

let read_cfg dir name = match Option.bind (child dir "SYSPAR") (fun s -> child s name) with
  | Some f when is_file f -> Result.map Option.some (Cfg_file.read_file f)
  | _ -> Ok None

let read dir =
  let warnings = ref [] in
  let warn w = warnings := w :: !warnings in
  let* sys = read_cfg dir "SYS.cfg" in
  let* moc = read_cfg dir "MOC.cfg" in
  let eio = match Option.bind (child dir "SYSPAR") (fun s -> child s "EIO.cfg") with
    | Some f when is_file f -> Some f | _ -> None in
  let info_file = Option.bind (child dir "BACKINFO") (fun b -> child b "backinfo.txt") in
  let* info, robotware = match info_file with Some f -> read_backinfo f | None -> Ok ([], None) in
  let info_file_name = Option.value info_file ~default:(dir // "BACKINFO" // "backinfo.txt") in
  let* cab = match sys with Some c -> cab_tasks ~warn c | None -> Ok [] in
  let retry_limit = Option.bind sys (sys_misc ~warn) in
  let groups = Option.fold ~none:[] ~some:(groups ~warn) sys in
  let* moc_robots = match moc with Some c -> robots ~warn c | None -> Ok [] in
  Option.iter (fun c -> unread_sections ~warn c
                  [ "CAB_TASKS"; "CAB_EXEC_HOOKS"; "CAB_TASK_MODULES"; "SYS_MISC"; "MECHANICAL_UNIT_GROUP" ]) sys;
  Option.iter (fun c -> unread_sections ~warn c [ "ROBOT"; "ARM"; "MECHANICAL_UNIT"; "SINGLE" ]) moc;
  (* The other files of SYSPAR, and HOME: once each. *)
  Option.iter (fun s ->
      List.iter (fun f ->
          if not (List.exists (same f) [ "SYS.cfg"; "MOC.cfg"; "EIO.cfg" ]) && is_file (s // f) then
            warn (Printf.sprintf "%s:1: warning: not modelled (the configuration of %s)" (s // f)
                    (String.uppercase_ascii (Filename.remove_extension f)))) (entries (Some s))) (child dir "SYSPAR");
  Option.iter (fun h ->
      warn (Printf.sprintf "%s: warning: the controller's mass memory HOME: is not used: --fs names the folder a \
                            run's files are in (a run may write there)" h)) (child dir "HOME");
  (* The task folders: RAPID/TASKn, named by backinfo.txt, else by CAB_TASKS in order. *)
  let rapid = child dir "RAPID" in
  let folders = List.filter_map (fun f ->
      let n = String.length f in
      if n > 4 && same (String.sub f 0 4) "TASK" then
        Option.map (fun k -> (k, Option.get rapid // f)) (int_of_string_opt (String.sub f 4 (n - 4)))
      else None) (entries rapid) in
  let folders = List.sort compare (List.filter (fun (_, p) -> is_dir p) folders) in
  let named = List.mapi (fun k (number, folder) ->
      match List.find_opt (fun t -> t.number = number) info with
      | Some t -> (t.info_name, folder, Some t.info_files, Printf.sprintf "%s:%d" info_file_name t.info_line)
      | None ->
          let name = match List.nth_opt cab k with
            | Some c when info = [] -> c.c_name
            | _ -> Printf.sprintf "TASK%d" number in
          if info_file <> None then
            warn (Printf.sprintf "%s:1: warning: %s is not in backinfo.txt: named %s" info_file_name folder name);
          (name, folder, None, folder)) folders in
  List.iter (fun t ->
      if not (List.exists (fun (n, _, _, _) -> same n t.info_name) named) then
        warn (Printf.sprintf "%s:%d: warning: the task %s has no folder RAPID/TASK%d: not run" info_file_name
                t.info_line t.info_name t.number)) info;
  (* A name backinfo.txt gives two folders: the first folder is the task's. *)
  let named = List.rev (List.fold_left (fun acc ((name, folder, _, info_at) as t) ->
      if List.exists (fun (n, _, _, _) -> same n name) acc then begin
        warn (Printf.sprintf "%s: warning: a second folder %s for the task %s: not run" info_at folder name); acc
      end else t :: acc) [] named) in
  let tasks = List.filter_map (fun (name, folder, listed, info_at) ->
      let cab_task = List.find_opt (fun c -> same c.c_name name) cab in
      match cab_task, sys with
      | None, Some c ->
          warn (Printf.sprintf "%s: warning: the task %s is not one of %s's CAB_TASKS (a task of a RobotWare \
                                option): not run" info_at name c.file);
          None
      | _ ->
          let files = task_files ~warn ~info_file:info_file_name folder listed in
          (* R-bk-14: without SYS.cfg, a folder of system modules alone is a task without a
             program (an option's task, an idle one): nothing says it is started. *)
          let program_module f = same (Filename.basename (Filename.dirname f)) "PROGMOD" in
          if sys = None && files <> [] && not (List.exists program_module files) then begin
            warn (Printf.sprintf "%s: warning: the task %s has no program module (PROGMOD) and no SYS.cfg \
                                  configures it: not started" info_at name);
            None
          end else
          let c = match cab_task with
            | Some c -> c
            | None -> { c_name = name; c_kind = Normal; c_motion = false; c_group = None; c_entry = "main";
                        c_at = info_at } in
          Some { name; folder; kind = c.c_kind; motion = c.c_motion; group = c.c_group; entry = c.c_entry; files;
                 at = c.c_at; before = []; after = []; debug_events = [] }) named in
  List.iter (fun c ->
      if not (List.exists (fun t -> same t.name c.c_name) tasks) then
        warn (Printf.sprintf "%s: warning: the task %s has no folder in RAPID/: not run" c.c_at c.c_name)) cab;
  (* R-bk-3: without SYS.cfg, or without a motion task in it, the first task has the robot. *)
  let tasks = if List.exists (fun t -> t.motion) tasks then tasks
    else match tasks with
      | t :: rest ->
          warn (Printf.sprintf "%s: warning: no task is a -MotionTask: %s, the first, has the robot" t.at t.name);
          { t with motion = true } :: rest
      | [] -> [] in
  (* R-bk-8: each task's event routines, once the motion tasks are known. *)
  let hooks = Option.fold ~none:[] ~some:(hooks ~warn) sys in
  List.iter (fun h -> match h.h_task with
      | Some n when not h.h_all && not (List.exists (fun t -> same t.name n) tasks) ->
          warn (Printf.sprintf "%s: warning: the event routine %s (%s): no task %s runs: not run" h.h_at h.h_routine
                  h.h_event n)
      | _ -> ()) hooks;
  let tasks = List.map (fun t ->
      let before, after, debug_events = task_events ~warn hooks ~name:t.name ~kind:t.kind ~motion:t.motion in
      { t with before; after; debug_events }) tasks in
  if tasks = [] then
    Error (Printf.sprintf "%s:1:1: backup error: no task to run (no RAPID/TASKn folder of a configured task)"
             (Option.value rapid ~default:(dir // "RAPID")))
  else begin
    (* R-bk-4: each motion task's robot: its group's -Robot, else MOC.cfg's robots in order. *)
    let default_group = match groups with (g, _) :: _ -> Some g | [] -> None in
    let group_of t = match t.group with Some g -> Some g | None -> default_group in
    let motion_tasks = List.filter (fun t -> t.motion) tasks in
    let robots = List.mapi (fun k t ->
        let by_group = Option.bind (group_of t) (fun g ->
            match List.find_opt (fun (n, _) -> same n g) groups with
            | Some (_, Some r) -> List.find_opt (fun r' -> same r'.robot_name r) moc_robots
            | _ -> None) in
        match by_group, List.nth_opt moc_robots k with
        | Some r, _ | None, Some r -> Some (t.name, r)
        | None, None -> None) motion_tasks in
    let robots = List.filter_map Fun.id robots in
    List.iter (fun t -> if not (List.mem_assoc t.name robots) then
                  warn (Printf.sprintf "%s: warning: the motion task %s has no robot in MOC.cfg: the default IRB 120"
                          t.at t.name)) motion_tasks;
    let connected = List.filter_map (fun t ->
        if t.motion then None
        else
          let mine = group_of t in
          match List.find_opt (fun m -> mine <> None && Option.equal same (group_of m) mine) motion_tasks,
                motion_tasks with
          | Some m, _ -> Some (t.name, m.name)
          | None, m :: _ ->
              if t.group <> None then
                warn (Printf.sprintf "%s: warning: task %s: no motion task uses the group %s: it reads %s's robot"
                        t.at t.name (Option.get t.group) m.name);
              Some (t.name, m.name)
          | None, [] -> None) tasks in
    (* R-bk-13: MOC.cfg's mechanical units, by their names. *)
    let units = match moc with
      | None -> []
      | Some c -> List.filter_map (fun i -> Cfg_file.text i "name") (instances c "MECHANICAL_UNIT") in
    Ok { dir; tasks; robots; connected; eio; retry_limit; robotware; units; warnings = List.rev !warnings }
  end

(* A program file: <Program><Module>FILE</Module>...</Program>, the files beside it. *)
let read_pgf file =
  match open_in_bin file with
  | exception Sys_error m -> Error (Printf.sprintf "%s:1:1: program file error: cannot read the file (%s)" file m)
  | ic ->
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
          let input = Xmlm.make_input ~strip:true (`Channel ic) in
          let dir = Filename.dirname file in
          let error () = let l, c = Xmlm.pos input in
            Printf.sprintf "%s:%d:%d: program file error" file l c in
          try
            let rec skip depth = if depth > 0 then match Xmlm.input input with
                | `El_start _ -> skip (depth + 1) | `El_end -> skip (depth - 1) | _ -> skip depth in
            let rec modules acc = match Xmlm.input input with
              | `El_start ((_, tag), _) when same tag "Module" -> (
                  match Xmlm.input input with
                  | `Data d -> (match Xmlm.input input with
                      | `El_end -> modules ((dir // String.trim d) :: acc)
                      | _ -> Error (error () ^ ": a <Module> holds only a file name"))
                  | `El_end -> Error (error () ^ ": an empty <Module>")
                  | _ -> Error (error () ^ ": a <Module> holds only a file name"))
              | `El_start _ -> skip 1; modules acc
              | `El_end -> Ok (List.rev acc)
              | `Data _ | `Dtd _ -> modules acc in
            let rec root () = match Xmlm.input input with
              | `Dtd _ -> root ()
              | `El_start ((_, tag), _) when same tag "Program" -> modules []
              | _ -> Error (error () ^ ": expected <Program>") in
            match root () with
            | Ok [] -> Error (Printf.sprintf "%s:1:1: program file error: it lists no module" file)
            | r -> r
          with Xmlm.Error ((l, c), e) ->
            Error (Printf.sprintf "%s:%d:%d: program file error: %s" file l c (Xmlm.error_message e)))
