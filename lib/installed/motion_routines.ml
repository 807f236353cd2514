(* The installed routines of motion (lib/typing/installed/motion.sys) as primitives: values to
   the motion model's floats and back, the planner of the run, and the waits of the program
   pointer on the robot (doc/motion.md, "Moves in the machine"). *)

module V = Value
module W = Rapid_controller.World
module MM = Rapid_motion_model
module G = MM.Geom
module D = MM.Motion_data
module P = MM.Planner
open Primitive

module E = Rapid_observable.Motion_event

type track = { t_id : int; t_label : string; mutable started : bool; mutable ended : bool }

(* An asynchronous error (§7.4, §7.6): raised at the move instruction the program pointer is in,
   or at the next one (\SyncLastMoveInst); or in the routine of the move the robot executes
   (\SyncOrgMoveInst, a collision), which the machine finds. *)
type async_mode = Sync_last | Sync_org

type async = { a_name : string; a_move : int option; a_mode : async_mode;
               a_handled : bool  (* false: a collision with motion error handling off (§7.6) *) }

type extension = ..

type state = {
  robot : MM.Robot.t;
  kin : MM.Kinematics.t;
  planner : P.t;
  mutable tracks : track list;                 (* moves not yet ended, oldest first ... *)
  mutable tracks_back : track list;            (* ... then these, newest first (added by add_track) *)
  mutable outputs : (int * int * float) list;  (* MoveLDO/MoveJDO: move, signal, value *)
  mutable fresh : E.t list;                  (* newest first *)
  mutable check_at : float;                    (* the next time a tracked move may change *)
  mutable dirty : bool;                        (* the queue changed since the last look *)
  mutable reshaped : bool;                     (* ... by more than a plan (a path command, a stop) *)
  history_budget : int option;                 (* None: the planner forgets (Planner.forget) *)
  mutable first_target : float array option;   (* move 0's point, which the planner may forget *)
  mutable tool : V.t;                          (* the active tool and work object (CTool, CRobT) *)
  mutable wobj : V.t;
  mutable first_poll : float option;           (* WaitUntil \InPos: polls begin at standstill *)
  mutable async : async option;                (* an asynchronous error not yet raised *)
  mutable interrupted : (int * string) option; (* a move the error was raised at: its RETRY waits for it *)
  mutable last_planned : int option;           (* the last move planned *)
  mutable new_move : int option;               (* for the machine: the move just planned *)
  mutable collisions : float list option;      (* the stimulus's collisions to come, once read *)
  mutable move_waits : W.wait list;            (* the waits of move instructions in progress *)
  mutable async_raised : bool;                 (* the last failure was a \SyncLastMoveInst error *)
  mutable conc_run : int;                      (* \Conc moves in a row, for ERR_CONC_MAX *)
  mutable collision_handling : bool;           (* /SYS/SYS_MISC/CollisionErrorHandling (§7.6) *)
  history : (P.motion * float array * float array) option array;
      (* the last [history_moves] forward moves and their start axes (the arm's, the external
         ones): a ring, its newest at [history_top - 1] *)
  mutable history_top : int;
  mutable history_len : int;
  mutable backward : bool;                     (* a BACKWARD handler runs (ch. 6) *)
  mutable cleared_at : float option;           (* the last ClearPath: when the moves it drops are dropped *)
  mutable extensions : extension list;         (* of the modules built on the motion (Trigg_routines) *)
  mutable drain_hooks : (W.t -> unit) list;
  mutable robots : (string * state) list;      (* a task without a robot: the motion tasks (R-14-pos1) *)
  mutable speed_limit : MM.Profile.speed_limit; (* SpeedLimCheckPoint, SpeedLimAxis (R-13-speedlim1) *)
  mutable tool_name : string;                  (* the names of the active tool and work object, *)
  mutable wobj_name : string;                  (* for GetSysData \ObjectName *)
}

let dummy = V.Bool false

(* The forward moves a BACKWARD handler can retrace: the last 256. *)
let history_moves = 256

let push_history st h =
  st.history.(st.history_top) <- Some h;
  st.history_top <- (st.history_top + 1) mod history_moves;
  st.history_len <- min history_moves (st.history_len + 1)

let pop_history st =
  if st.history_len = 0 then None
  else begin
    let top = (st.history_top + history_moves - 1) mod history_moves in
    let h = st.history.(top) in
    st.history.(top) <- None; st.history_top <- top; st.history_len <- st.history_len - 1;
    h
  end

let create ?(robot = MM.Robot.irb120) ?history () =
  let kin = MM.Kinematics.create robot in
  { robot; kin; planner = P.create kin; tracks = []; tracks_back = []; outputs = []; fresh = [];
    check_at = infinity; dirty = false; reshaped = false; history_budget = history; first_target = None;
    tool = dummy; wobj = dummy; first_poll = None; async = None; interrupted = None;
    last_planned = None; new_move = None; collisions = None; move_waits = [];
    async_raised = false; conc_run = 0; collision_handling = true;
    history = Array.make history_moves None; history_top = 0; history_len = 0; backward = false; cleared_at = None;
    extensions = []; drain_hooks = []; robots = []; speed_limit = MM.Profile.no_speed_limit;
    tool_name = "tool0"; wobj_name = "wobj0" }

let set_backward st b = st.backward <- b
let retracing st = st.backward

let extensions st = st.extensions
let add_extension st e = st.extensions <- e :: st.extensions
let on_drain st f = st.drain_hooks <- st.drain_hooks @ [ f ]

let connect_robots st robots = st.robots <- robots

let planner st = st.planner

(* vmax: v_tcp is the robot's maximum TCP speed (ABB, speeddata; installed-facts.md §3), so the
   installed constant takes the value of the run's robot. *)
(* The engines start each run with this; a fuzzer runs every program three times, so the last
   answer is kept, for the same program (compared physically) and the same vmax. The names are
   compared without lowered copies of them. *)
let last_robot_data : (Ir.program * D.speeddata * Ir.program) option ref = ref None

let robot_data st (program : Ir.program) =
  let vmax = D.vmax st.robot in
  match !last_robot_data with
  | Some (p, v, result) when p == program && v = vmax -> result
  | _ ->
      let same = Rapid_typing.Types.same_name in
      let globals = Array.map (fun (g : Ir.global) ->
          if same g.g_name "vmax" && same g.g_module "Installed_base" then
            let value = V.Record (Array.map V.num [| vmax.v_tcp; vmax.v_ori; vmax.v_leax; vmax.v_reax |]) in
            { g with g_init = Init_expr { e = Literal value; at = g.g_at } }
          else g) program.globals in
      let result = { program with globals } in
      last_robot_data := Some (program, vmax, result);
      result
let robot st = st.robot

let emit st e = st.fresh <- e :: st.fresh

(* ------------------------------------------------------------------ arguments *)

let same = Rapid_typing.Types.same_name  (* without lowered copies: every call site asks [modelled] *)

(* The lower-case name of the routine called, kept for the last name (physically, the callee's
   own string): every move matches on it three times. *)
let last_name = ref "" and last_lower = ref ""
let lower name =
  if name == !last_name then !last_lower
  else begin let l = String.lowercase_ascii name in last_name := name; last_lower := l; l end

let arg = named_argument

let present = named_present
let value ctx args name = match arg ctx args name with
  | Value v -> Some v | Location (box, i, _) -> Some box.(i) | Switch -> Some (V.Bool true) | Missing -> None
let num = named_num
let label ctx name = match ctx.argument_label name with Some l -> l | None -> "*"

(* ------------------------------------------------------------------ values and floats *)

(* Ten of these a move: read in place, and an extjoint's six built as a literal, not through
   Array.map (a call into the runtime for each array). *)
let nums v =
  let c = V.components v in
  if Array.length c = 6 then
    let n i = V.num_value (Array.unsafe_get c i) in [| n 0; n 1; n 2; n 3; n 4; n 5 |]
  else Array.map V.num_value c
let pos_of v = let c = V.components v in
  { G.x = V.num_value c.(0); y = V.num_value c.(1); z = V.num_value c.(2) }
(* Motion instructions check that quaternions are normalised: |q1² + q2² + q3² + q4² - 1| below
   0.1 is normalised here, beyond it is ERR_ILLQUAT (installed-facts.md §4, NOrient's
   thresholds; the error's name UNCERTAIN). *)
exception Illegal_quaternion

let orient_of v =
  let c = V.components v in
  let q1 = V.num_value c.(0) and q2 = V.num_value c.(1) and q3 = V.num_value c.(2) and q4 = V.num_value c.(3) in
  let sum = (q1 *. q1) +. (q2 *. q2) +. (q3 *. q3) +. (q4 *. q4) in
  if not (Float.abs (sum -. 1.) < 0.1) then raise Illegal_quaternion;
  G.normalize { G.q1; q2; q3; q4 }
let pose_of v = let c = V.components v in { G.trans = pos_of c.(0); rot = orient_of c.(1) }

let conf_of v =
  let c = V.components v in
  let i k = let f = V.num_value c.(k) in if Float.is_finite f then int_of_float (Float.round f) else 0 in
  { MM.Kinematics.cf1 = i 0; cf4 = i 1; cf6 = i 2; cfx = i 3 }

let robtarget_of v =
  let c = V.components v in { MM.Frames.pose = pose_of (V.pose c.(0) c.(1)); conf = conf_of c.(2) }

let joints_of_jointtarget v = nums (V.components v).(0)

(* extjoint: eax_a … eax_f, the robtarget's fourth component and the jointtarget's second. *)
let eax_of_robtarget v = nums (V.components v).(3)
let eax_of_jointtarget v = nums (V.components v).(1)

let speed_of v = let c = V.components v in let n i = V.num_value c.(i) in
  { D.v_tcp = n 0; v_ori = n 1; v_leax = n 2; v_reax = n 3 }

let zone_of v =
  let c = V.components v in
  let n i = V.num_value c.(i) in
  { D.finep = V.bool_value c.(0); pzone_tcp = n 1; pzone_ori = n 2; pzone_eax = n 3;
    zone_ori = n 4; zone_leax = n 5; zone_reax = n 6 }

let stoppoint_of v =
  let c = V.components v in
  let inpos = nums c.(2) in
  { D.stop_type = (match V.num_value c.(0) with 2. -> D.Stoptime | 3. -> D.Fllwtime | _ -> D.Inpos);
    progsynch = V.bool_value c.(1); inpos_position = inpos.(0); inpos_speed = inpos.(1);
    inpos_mintime = inpos.(2); inpos_maxtime = inpos.(3);
    stoptime = V.num_value c.(3); followtime = V.num_value c.(4) }

let tool_of v =
  let c = V.components v in
  { D.tool_robhold = V.bool_value c.(0); tframe = pose_of c.(1); tool_mass = V.num_value (V.components c.(2)).(0) }

let wobj_of v =
  let c = V.components v in
  { D.wobj_robhold = V.bool_value c.(0); ufprog = V.bool_value c.(1); ufmec = V.string_value c.(2);
    uframe = pose_of c.(3); oframe = pose_of c.(4) }

let pos_value (p : G.pos) = V.pos p.x p.y p.z
let orient_value (q : G.orient) = V.orient q.q1 q.q2 q.q3 q.q4
let conf_value (c : MM.Kinematics.conf) =
  V.Record (Array.map (fun i -> V.num (float_of_int i)) [| c.cf1; c.cf4; c.cf6; c.cfx |])

(* 9E9: an external axis that is not there (ABB's convention for extjoint). *)
let no_extax () = V.Record (Array.init 6 (fun _ -> V.num 9e9))

let robtarget_value ?extax (r : MM.Frames.robtarget) =
  V.Record [| pos_value r.pose.trans; orient_value r.pose.rot; conf_value r.conf;
              (match extax with Some e -> V.copy e | None -> no_extax ()) |]

let eax_value e = V.Record (Array.map V.num e)

let jointtarget_value ?ext q =
  V.Record [| V.Record (Array.map V.num q); (match ext with Some e -> eax_value e | None -> no_extax ()) |]

(* A robtarget changed in its pose only: its confdata and external axes are kept. *)
let with_pose v (p : G.pose) =
  let c = V.components v in
  V.Record [| pos_value p.trans; orient_value p.rot; V.copy c.(2); V.copy c.(3) |]

(* ------------------------------------------------------------------ errors *)

(* R-4.1-e: a move or position function that the robot cannot do raises ERR_ROBLIMIT (the
   errnum ABB gives CalcJointT for a position outside the robot's reach); bad data raises
   ERR_ARGVALERR. The model's message goes to the event log. *)
let error_name = function
  | MM.Motion_error.Out_of_reach | Joint_out_of_range _ | Configuration_error | Close_to_singularity
  | External_out_of_range _ -> "ERR_ROBLIMIT"
  | Circle_uncertain | Invalid_speed _ | Robhold_conflict | Path_level _ -> "ERR_ARGVALERR"

let fail ctx what e =
  ctx.log (Printf.sprintf "%s: %s" what (MM.Motion_error.name e));
  Failed (error_name e)

(* ------------------------------------------------------------------ waits *)

(* A time beyond the run's --max-time is never reached: the engine's time limit ends the wait. *)
let reached w t = Float.is_finite t && t <= W.max_time w +. 1. && W.seconds (W.now w) >= W.seconds t

(* The program pointer waits until a time the planner computes, and asks again at every look:
   a StopMove or StartMove in a trap moves it. *)

(* A wait's error at once: a \SyncLastMoveInst error is the call's, at the move (§7.4). *)
let raised st (e : Rapid_observable.Wait.raised) =
  if e.at_move then st.async_raised <- true;
  Failed e.error

let until ?move ctx ~what time =
  let w = ctx.world in
  let asked = ref nan in
  (* A move instruction the program pointer waits in takes a \SyncLastMoveInst error (§7.4). *)
  let async_here () = match move with
    | Some (st, _) -> (match st.async with Some { a_mode = Sync_last; _ } -> true | _ -> false)
    | None -> false in
  let satisfied () =
    let t = time () in
    if async_here () then true
    else if reached w t then true
    else begin
      if t <> !asked then (W.wake_at w (Float.min t (W.max_time w +. 1.)); asked := t);
      false
    end in
  let finish ~timed_out:_ =
    match move with
    | Some (st, (id, key)) when async_here () ->
        let a = Option.get st.async in
        st.async <- None; st.interrupted <- Some (id, key);
        Some { Rapid_observable.Wait.error = a.a_name; at_move = true }
    | _ -> None in
  let self = ref None in
  let finish ~timed_out =
    (match move with
     | Some (st, _) ->
         (match !self with Some me -> st.move_waits <- List.filter (fun w -> w != me) st.move_waits | None -> ())
     | None -> ());
    finish ~timed_out in
  if satisfied () then
    (match finish ~timed_out:false, move with
     | None, _ -> Returned None
     | Some e, Some (st, _) -> raised st e
     | Some e, None -> Failed e.error)
  else begin
    let wait = { W.what; satisfied; deadline = None; finish; poll = None } in
    (match move with
     | Some (st, _) -> self := Some wait; st.move_waits <- wait :: st.move_waits
     | None -> ());
    Wait wait
  end

let standstill st () = P.finished_by st.planner

(* ------------------------------------------------------------------ the motion events *)

let all_tracks st =
  if st.tracks_back <> [] then (st.tracks <- st.tracks @ List.rev st.tracks_back; st.tracks_back <- []);
  st.tracks

let add_track st tr = st.tracks_back <- tr :: st.tracks_back

let no_tracks st = st.tracks = [] && st.tracks_back = []

(* What the clock has passed of the tracked moves: their beginnings and ends, and the moves
   dropped. After a plan alone the moves' times only grow with their ids (a move begins where the
   one before it ends, or later), so the walk stops at the first move not ended: nothing later can
   have passed; after a path command every move is looked at again. *)
let check st ~now =
  (* The clock counts microseconds: a time is passed when its microsecond is. *)
  let passed t = t <= now || (t < 1e12 && now < 1e12 && W.seconds t <= W.seconds now) in
  let w_next = ref infinity in
  let events = ref [] in
  let level1 = P.path_level st.planner = 1 in
  let look span tr =
    match span with
    | None ->
        (* Dropped when ClearPath ran, not when an engine next looks: the machine looks a step
           later than the closure engine, and both must write the same time. *)
        let time = Option.value st.cleared_at ~default:now in
        if level1 then (events := E.Segment_dropped { time; id = tr.t_id; label = tr.t_label } :: !events; false)
        else true
    | Some (s, e) ->
        if not tr.started && passed s then begin
          tr.started <- true; events := E.Segment_started { time = s; id = tr.t_id; label = tr.t_label } :: !events
        end;
        if not tr.ended && passed e then begin
          tr.ended <- true; events := E.Segment_ended { time = e; id = tr.t_id; label = tr.t_label } :: !events
        end;
        if not tr.started then w_next := Float.min !w_next s;
        if not tr.ended then w_next := Float.min !w_next e;
        not tr.ended in
  let full tracks =
    let span = P.segment_spans st.planner (List.map (fun tr -> tr.t_id) tracks) in
    List.filter (fun tr -> look (span tr.t_id) tr) tracks in
  (* The moves not looked at stay in [tracks_back]: adding one costs nothing. *)
  let rec ahead = function
    | [] when st.tracks_back <> [] -> let back = List.rev st.tracks_back in st.tracks_back <- []; ahead back
    | [] -> []
    | tr :: rest as tracks -> (
        match P.segment_span st.planner tr.t_id with
        | None -> let back = List.rev st.tracks_back in st.tracks_back <- []; full (tracks @ back)
        | span -> if look span tr then tracks else ahead rest) in
  st.tracks <- (if st.reshaped || not level1 then full (all_tracks st) else ahead st.tracks);
  st.reshaped <- false;
  (* Its drops are all made now: a later one has its own cause and time. *)
  st.cleared_at <- None;
  st.check_at <- !w_next;
  List.stable_sort (fun a b -> compare (E.time a) (E.time b)) (List.rev !events)

(* ------------------------------------------------------------------ memory *)

(* Without history the planner gives back what no move still tracked, no output to place, no
   move an error was raised at and no later look needs (doc/motion.md, "Memory"): what a run
   holds does not grow with the moves it has made. *)
let forget st ~now =
  if st.history_budget = None then begin
    let keep = Option.value st.last_planned ~default:0 in
    let oldest k tr = min k tr.t_id in
    let keep = List.fold_left oldest (List.fold_left oldest keep st.tracks) st.tracks_back in
    let keep = List.fold_left (fun k (id, _, _) -> min k id) keep st.outputs in
    let keep = match st.interrupted with Some (id, _) -> min keep id | None -> keep in
    P.forget st.planner ~before:now ~keep
  end

exception History_exhausted of string

(* With history (--samples, rapid-sem motion), each move kept counts [history_bytes] against
   the budget of --max-memory, apart from RAPID data: about what a move's segment and pieces of
   path take (bench/motion_bench.ml's "planner's data": 850 bytes), and what the drawings of
   rapid-sem motion build from them (its samples of each piece, its marks). *)
let history_bytes = 4096

let charge_history st id =
  match st.history_budget with
  | Some budget when (id + 1) > budget / history_bytes ->
      raise (History_exhausted (Printf.sprintf
        "the motion history of %d moves (%d bytes each, kept for --samples or rapid-sem motion) goes beyond the \
         memory budget of %d bytes (--max-memory)" (id + 1) history_bytes budget))
  | _ -> ()

(* ------------------------------------------------------------------ moves *)

let active_tool st = if st.tool == dummy then None else Some st.tool

let max_conc = 5

(* Where the arm will stand when it has done all it was given: the point of the last move
   still queued, or where it stands. *)
(* Move 0's point (the planner may have forgotten it). *)
let first_target st = match st.first_target with Some q -> q | None -> P.target_joints st.planner 0

let planned st id =
  if id = 0 then st.first_target <- Some (P.target_joints st.planner 0);
  charge_history st id

let arm_end_joints st now =
  match st.last_planned with
  | Some id when P.has_segment st.planner id -> P.target_joints st.planner id
  | _ -> (match P.joints_at st.planner now with Ok q -> q | Error _ -> first_target st)

let tool0_value () =
  V.Record [| V.Bool true; V.pose (V.pos 0. 0. 0.) (V.orient 1. 0. 0. 0.);
              V.Record [| V.num 0.001; V.pos 0. 0. 0.001; V.orient 1. 0. 0. 0.; V.num 0.; V.num 0.; V.num 0. |] |]

(* CTool's and CWObj's answers, GetSysData's too: the active tool and work object (R-13-y),
   tool0 and wobj0 before the first move. *)
let active_tool_value st = match active_tool st with Some t -> V.copy t | None -> tool0_value ()

let active_wobj_value st =
  if st.wobj == dummy then
    V.Record [| V.Bool false; V.Bool true; V.String ""; V.pose (V.pos 0. 0. 0.) (V.orient 1. 0. 0. 0.);
                V.pose (V.pos 0. 0. 0.) (V.orient 1. 0. 0. 0.) |]
  else V.copy st.wobj

(* A move or a search makes its tool and work object the active ones, with the names its
   arguments give them (GetSysData \ObjectName). *)
let activate ctx st tool wobj =
  st.tool <- V.copy tool;
  st.wobj <- (match wobj with Some o -> V.copy o | None -> dummy);
  st.tool_name <- label ctx "Tool";
  st.wobj_name <- (if wobj = None then "wobj0" else label ctx "WObj")

let current_external_at st now =
  match P.external_at st.planner now with
  | Ok e -> e
  | Error _ -> MM.Ext_axes.initial st.robot.externals

(* The flange of a planned move's point, in the world (law X-track). *)
let world_flange st id joints =
  let f = MM.Kinematics.forward st.kin joints in
  match P.base st.planner (P.target_external st.planner id) with Some b -> G.pmult b f | None -> f

(* SpeedLimCheckPoint, SpeedLimAxis (ABB, RAPID Instructions): the limits act while the system
   input LimitSpeed is 1, on the moves planned then (R-13-speedlim1). *)
let apply_speed_limit st w =
  let active = st.speed_limit <> MM.Profile.no_speed_limit && W.system_input_active w ~action:"LimitSpeed" in
  (P.settings st.planner).speed_limit <- (if active then Some st.speed_limit else None)

(* SpeedLimCheckPoint RobSpeed: the speed of the checkpoints in mm/s; SpeedLimAxis MechUnit AxisNo
   AxisSpeed: the speed of one axis (degrees/s, mm/s for a linear one). A speed below 0 or not
   finite: ERR_SPEEDLIM_VALUE; 0 leaves that speed unlimited; an axis that is not one of the
   robot's 1 to 6: ERR_ARGVALERR (R-13-speedlim1). The MechUnit is the task's robot. *)
let speed_lim_check_point ctx st args =
  match num ctx args "RobSpeed" with
  | Some v when v >= 0. && Float.is_finite v ->
      st.speed_limit <- { st.speed_limit with check_point = (if v > 0. then Some v else None) }; Returned None
  | _ -> Failed "ERR_SPEEDLIM_VALUE"

let speed_lim_axis ctx st args =
  match num ctx args "AxisNo", num ctx args "AxisSpeed" with
  | Some a, _ when not (Float.is_integer a && a >= 1. && a <= 6.) -> Failed "ERR_ARGVALERR"
  | Some a, Some v when v >= 0. && Float.is_finite v ->
      let axis = int_of_float a in
      let axes = List.remove_assoc axis st.speed_limit.axes in
      let axes = if v > 0. then (axis, v) :: axes else axes in
      st.speed_limit <- { st.speed_limit with axes = List.sort compare axes }; Returned None
  | _ -> Failed "ERR_SPEEDLIM_VALUE"

let move ctx st name args =
  let w = ctx.world in
  let now = W.now w in
  let get n = value ctx args n in
  let ext = same name "MoveExtJ" in
  match get "Speed", get "Zone", (if ext then Some (tool0_value ()) else get "Tool") with
  | Some speed, Some zone, Some tool -> (
      let start = arm_end_joints st now in
      let start_ext = match st.last_planned with
        | Some id when P.has_segment st.planner id -> P.target_external st.planner id
        | _ -> current_external_at st now in
      let back_eax = ref None in
      (* §6.3: in a BACKWARD handler a move instruction retraces the path of the forward one it
         mirrors, the last not yet retraced, from its end back to its start (R-6.3-m). *)
      let retraced = match if st.backward && not ext then pop_history st else None with
        | Some (forward, from, from_ext) ->
            back_eax := Some from_ext;
            let wobj_d = match get "WObj" with Some o -> wobj_of o | None -> D.wobj0 in
            let back () = MM.Frames.calc_rob_t ?base:(P.base st.planner from_ext) st.kin from (tool_of tool) wobj_d in
            (match forward with
             | P.Linear _ -> Result.to_option (Result.map (fun r -> P.Linear r) (back ()))
             | P.Circular (c, _) -> Result.to_option (Result.map (fun r -> P.Circular (c, r)) (back ()))
             | P.Joint _ | P.Abs_joint _ | P.External_only -> Some (P.Abs_joint from))
        | _ -> None in
      let motion = if Option.is_some retraced then retraced else match lower name with
        | "moveextj" -> Some P.External_only
        | "movel" | "moveldo" | "triggl" -> Option.map (fun p -> P.Linear (robtarget_of p)) (get "ToPoint")
        | "movej" | "movejdo" | "triggj" -> Option.map (fun p -> P.Joint (robtarget_of p)) (get "ToPoint")
        | "movec" | "triggc" -> (match get "CirPoint", get "ToPoint" with
            | Some c, Some p -> Some (P.Circular (robtarget_of c, robtarget_of p)) | _ -> None)
        | _ -> Option.map (fun j -> P.Abs_joint (joints_of_jointtarget j)) (get "ToJointPos") in
      let target_label = label ctx (if same name "MoveAbsJ" || ext then "ToJointPos" else "ToPoint") in
      (* The external axes the move goes to (law X-target); a retraced move goes back to
         where they were at the start of the forward move (R-6.3-m). *)
      let eax = if Option.is_some retraced then !back_eax
        else if same name "MoveAbsJ" || ext then Option.map eax_of_jointtarget (get "ToJointPos")
        else Option.map eax_of_robtarget (get "ToPoint") in
      let key = lower name ^ " " ^ target_label in
      (* The move an asynchronous error was raised at waits for its RETRY, through the moves of
         the error handler (StorePath ... RestoPath), while its path is there. *)
      let interrupted = match st.interrupted with
        | Some (id, _) when List.for_all (fun tr -> tr.t_id <> id) (all_tracks st) -> st.interrupted <- None; None
        | Some (_, k) as i when k = key -> st.interrupted <- None; i
        | _ -> None in
      (* At most five \Conc moves in a row (ABB, MoveL \Conc; installed-facts.md section 5): a
         run ends at a move without \Conc, or when the robot has done all it was given
         (R-4.1-m). The sixth is refused before it is planned. *)
      let conc = present ctx args "Conc" in
      if (not conc) || reached w (P.finished_by st.planner) then st.conc_run <- 0;
      match motion, st.async, interrupted with
      | None, _, _ -> Failed "ERR_ARGVALERR"
      | Some _, None, None when conc && st.conc_run >= max_conc -> Failed "ERR_CONC_MAX"
      | Some _, Some ({ a_mode = Sync_last; _ } as a), _ ->
          (* §7.4: the error waits for the next move instruction, and is raised there. *)
          st.async <- None; st.async_raised <- true; Failed a.a_name
      | Some _, _, Some (id, _) ->
          (* RETRY of the move the asynchronous error was raised at: its path is still there
             (StartMove goes on with it); the move is not planned twice. *)
          until ~move:(st, (id, key)) ctx ~what:(String.concat "" [ "the robot ("; name; " "; target_label; ")" ])
            (fun () -> P.ready_time st.planner id)
      | Some motion, _, _ -> (
          let wobj = get "WObj" in
          (* The tool's and work object's data once (both raise only Illegal_quaternion). *)
          let tool_d = tool_of tool and wobj_d = Option.map wobj_of wobj in
          let zone_d = zone_of zone in
          let m = P.move ?v:(num ctx args "V") ?t:(num ctx args "T") ?z:(num ctx args "Z")
              ?inpos:(Option.map stoppoint_of (get "Inpos")) ~conc
              ~tool:tool_d ?wobj:wobj_d ~label:target_label ?eax
              (speed_of speed) zone_d motion in
          (* What the robot did before this move is observed before it is planned. *)
          if not (no_tracks st) then st.fresh <- List.rev_append (check st ~now) st.fresh;
          forget st ~now;
          apply_speed_limit st ctx.world;
          match P.plan st.planner ~now m with
          | Error e -> fail ctx name e
          | Ok { id; ready_time; warnings } ->
              planned st id;
              (* MoveExtJ has no tool: the active tool and work object stay. *)
              if not ext then activate ctx st tool wobj;
              let joints = P.target_joints st.planner id in
              (* A stationary tool: the pose drawn is the carried work object's (R-4.1-o). *)
              let tframe =
                match MM.Frames.as_robot_held tool_d (match wobj_d with Some o -> o | None -> D.wobj0) with
                | Some (t, _, _) -> t.tframe | None -> tool_d.tframe in
              let target = G.pmult (world_flange st id joints) tframe in
              let start_time, end_time = match P.segment_span st.planner id with
                | Some s -> s | None -> (now, now) in
              let zone_name = if zone_d.finep then "fine" else label ctx "Zone" in
              emit st (E.Segment_planned { time = now; id; instruction = name; label = target_label;
                                         zone = zone_name; target; joints; ready_time; start_time; end_time });
              List.iter (fun (P.Corner_path_failure k) ->
                  let text = Printf.sprintf "corner path failure: move %d stops at its point" k in
                  ctx.log text; emit st (E.Motion_warning { time = now; text })) warnings;
              add_track st { t_id = id; t_label = target_label; started = false; ended = false };
              st.dirty <- true;
              (* MoveLDO, MoveJDO: the output changes where the robot passes the point. *)
              (match lower name with
               | "moveldo" | "movejdo" -> (
                   match arg ctx args "Signal", num ctx args "Value" with
                   | Location (box, i, _), Some v -> (
                       match box.(i) with
                       | V.Handle h when V.handle_id h > 0 && W.signal_kind w (V.handle_id h) <> None ->
                           st.outputs <- st.outputs @ [ (id, V.handle_id h, v) ]
                       | _ -> ())
                   | _ -> ())
               | _ -> ());
              st.last_planned <- Some id; st.new_move <- Some id;
              if conc then st.conc_run <- st.conc_run + 1;
              if not (st.backward || ext) then
                push_history st (motion, start, start_ext);
              until ~move:(st, (id, key)) ctx ~what:(String.concat "" [ "the robot ("; name; " "; target_label; ")" ])
                (fun () -> P.ready_time st.planner id)))
  | _ -> Failed "ERR_ARGVALERR"

let place_outputs st w =
  st.outputs <- List.filter (fun (id, signal, v) ->
      if P.is_open st.planner id then true
      else match P.point_time st.planner id with
        | Some t when Float.is_finite t ->
            let now = W.now w in
            if t > now then W.write_later w signal v ~delay:(t -. now) else W.write w signal v;
            false
        | Some _ -> true
        | None -> false) st.outputs

(* The move the robot executes at a time: the oldest one not yet ended; standing still, the last
   one planned. *)
let motion_pointer st =
  match List.find_opt (fun tr -> not tr.ended) (all_tracks st) with
  | Some tr -> Some tr.t_id
  | None -> st.last_planned

(* §7.6: a collision of the stimulus while the robot moves stops it there and raises ERR_COLL_STOP
   in the routine of the move it was on (the Collision Error Handler is taken as configured,
   R-7.6-a); standing still, nothing collides. *)
let collide st w =
  let pending = match st.collisions with
    | Some c -> c
    | None -> let c = W.collisions w in List.iter (W.wake_at w) c; c in
  let now = W.now w in
  let due, later = List.partition (fun t -> W.seconds t <= W.seconds now) pending in
  st.collisions <- Some later;
  List.iter (fun t ->
      let moving = (not (P.stopped st.planner)) && P.finished_by st.planner > t +. 1e-9 in
      if moving then begin
        P.stop st.planner ~at:t;
        st.dirty <- true; st.reshaped <- true;
        emit st (E.Path_command { time = t; command = "collision" });
        st.async <- Some { a_name = "ERR_COLL_STOP"; a_move = motion_pointer st; a_mode = Sync_org;
                           a_handled = st.collision_handling }
      end
      else emit st (E.Motion_warning { time = t; text = "collision while the robot stands still: nothing happens" }))
    due

let drain st w =
  List.iter (fun f -> f w) st.drain_hooks;
  let now = W.now w in
  if st.outputs <> [] then place_outputs st w;
  let due = st.dirty || W.seconds now >= W.seconds (Float.min st.check_at 1e12) in
  let seen = if not (no_tracks st) && due then (st.dirty <- false; check st ~now) else [] in
  if st.collisions <> Some [] then collide st w;
  let fresh = List.rev st.fresh in
  st.fresh <- [];
  fresh @ seen

let finish st =
  let fresh = List.rev st.fresh in
  st.fresh <- [];
  fresh @ (if no_tracks st then [] else check st ~now:infinity)

(* §7.2: "an active Movex instruction clears part of its path": the move instruction whose wait
   is left by an error or a long jump is cancelled, and the robot stands where it is (ClearPath). *)
let wait_abandoned st w ~now =
  if List.exists (fun m -> m == w) st.move_waits then begin
    st.move_waits <- List.filter (fun m -> m != w) st.move_waits;
    P.clear st.planner ~at:now;
    st.cleared_at <- Some now;
    st.dirty <- true; st.reshaped <- true;
    emit st (E.Path_command { time = now; command = "ClearPath (a move instruction left by an error)" })
  end

let move_waits_in_progress st = List.length st.move_waits


(* SearchL (ABB, RAPID Instructions): a linear move to ToPoint, a stop point, during which the
   signal is watched; at the first hit (a positive flank by default, \NegFlank, \Flanks, or a
   level: \HighLevel, \LowLevel) SearchPoint takes the robot's position; with \Stop, \PStop or
   \SStop the robot stands there and the rest of the path is dropped, otherwise it goes on to
   ToPoint. No hit by the end of the move: ERR_WHLSEARCH. *)
let search ctx st name args =
  let w = ctx.world in
  let get n = value ctx args n in
  (* SearchJ: a joint move; SearchC: a circular one through CirPoint (ABB, RAPID Instructions). *)
  let path target = match lower name with
    | "searchj" -> Some (P.Joint (robtarget_of target))
    | "searchc" -> Option.map (fun c -> P.Circular (robtarget_of c, robtarget_of target)) (get "CirPoint")
    | _ -> Some (P.Linear (robtarget_of target)) in
  (* "Signal | PersBool" (ABB, RobotWare 6 and later): the search watches a digital input or a
     persistent bool alike, its value read at every poll as 0 or 1 (FALSE or TRUE). *)
  let signal = match arg ctx args "Signal", arg ctx args "PersBool" with
    | Location (box, i, _), _ -> (
        match box.(i) with
        | V.Handle h when V.handle_id h > 0 && W.signal_kind w (V.handle_id h) <> None ->
            let id = V.handle_id h in
            Some (fun () -> W.read w id)
        | _ -> None)
    | _, Location (box, i, _) -> (
        match box.(i) with
        | V.Bool _ -> Some (fun () -> match box.(i) with V.Bool true -> 1. | _ -> 0.)
        | _ -> None)
    | _ -> None in
  match signal, get "ToPoint", get "Speed", get "Tool", arg ctx args "SearchPoint" with
  | None, _, _, _, _ -> Failed "ERR_NO_ALIASIO_DEF"
  | Some read, Some target, Some speed, Some tool, Location (box, i, _) when path target <> None -> (
      let stops = present ctx args "Stop" || present ctx args "PStop" || present ctx args "SStop" in
      let level = present ctx args "HighLevel" || present ctx args "LowLevel" in
      let hit ~old ~now =
        if present ctx args "Flanks" then old <> now
        else if present ctx args "NegFlank" then old <> 0. && now = 0.
        else if present ctx args "HighLevel" then now <> 0.
        else if present ctx args "LowLevel" then now = 0.
        else old = 0. && now <> 0. in
      let wobj = get "WObj" in
      let tool_d = tool_of tool and wobj_d = match wobj with Some o -> wobj_of o | None -> D.wobj0 in
      let target_label = label ctx "ToPoint" in
      let fine = Option.get (D.find D.zonedata "fine") in
      let m = P.move ?v:(num ctx args "V") ?t:(num ctx args "T") ~tool:tool_d ?wobj:(Option.map wobj_of wobj)
          ~label:target_label ~eax:(eax_of_robtarget target) (speed_of speed) fine (Option.get (path target)) in
      let now = W.now w in
      apply_speed_limit st ctx.world;
      match P.plan st.planner ~now m with
      | Error e -> fail ctx name e
      | Ok { id = move; ready_time; _ } ->
          planned st move;
          st.conc_run <- 0;
          activate ctx st tool wobj;
          let joints = P.target_joints st.planner move in
          let start_time, end_time = match P.segment_span st.planner move with Some s -> s | None -> (now, now) in
          emit st (E.Segment_planned { time = now; id = move; instruction = name; label = target_label;
                                     zone = "fine"; target = G.pmult (world_flange st move joints) tool_d.tframe;
                                     joints; ready_time; start_time; end_time });
          add_track st { t_id = move; t_label = target_label; started = false; ended = false };
          st.dirty <- true; st.last_planned <- Some move; st.new_move <- Some move;
          let previous = ref (read ()) and found = ref false and asked = ref nan in
          let record () =
            found := true;
            let t = W.now w in
            (match P.joints_at st.planner t, P.external_at st.planner t with
             | Ok joints, Ok e -> (
                 match MM.Frames.c_rob_t ?base:(P.base st.planner e) st.kin ~joints tool_d wobj_d with
                 | Ok r -> box.(i) <- robtarget_value ~extax:(eax_value e) r
                 | Error _ -> ())
             | _ -> ());
            if stops then (P.clear st.planner ~at:t; st.cleared_at <- Some t; st.dirty <- true; st.reshaped <- true;
                           emit st (E.Path_command { time = t; command = name ^ " stop" })) in
          if level && hit ~old:!previous ~now:!previous then record ();
          let satisfied () =
            let v = read () in
            if (not !found) && v <> !previous && hit ~old:!previous ~now:v then record ();
            previous := v;
            let r = P.ready_time st.planner move in
            if (!found && stops) || reached w r then true
            else begin
              if r <> !asked then (W.wake_at w (Float.min r (W.max_time w +. 1.)); asked := r);
              false
            end in
          let finish ~timed_out:_ = if !found then None else Rapid_observable.Wait.error "ERR_WHLSEARCH" in
          if satisfied () then (match finish ~timed_out:false with None -> Returned None | Some e -> raised st e)
          else
            Wait { W.what = "the robot (" ^ name ^ " " ^ target_label ^ ")"; satisfied; deadline = None; finish;
                   poll = None })
  | _ -> Failed "ERR_ARGVALERR"

(* ------------------------------------------------------------------ the routines *)

let names = [
  "MoveL"; "MoveJ"; "MoveC"; "MoveAbsJ"; "MoveExtJ"; "MoveLDO"; "MoveJDO"; "StopMove"; "StartMove"; "StopMoveReset";
  "ClearPath"; "PathLevel"; "StorePath"; "RestoPath"; "WaitRob"; "VelSet"; "AccSet"; "ConfL"; "ConfJ";
  "SingArea"; "MaxRobSpeed"; "ProcerrRecovery"; "StartMoveRetry"; "SearchL"; "SearchJ"; "SearchC"; "CornerPathWarning";
  "SpeedLimCheckPoint"; "SpeedLimAxis";
  "CSpeedOverride"; "Offs"; "RelTool"; "CRobT"; "CJointT";
  "CPos"; "CalcRobT"; "CalcJointT"; "MirPos"; "CTool"; "CWObj"; "GripLoad";
  "WriteCfgData";
  "SetSysData"; "GetSysData";
  "IsStopMoveAct";
  "ExitCycle";
]

let modelled name = List.exists (same name) names

let take_org_error st =
  match st.async with
  | Some { a_mode = Sync_org; a_name; a_move; a_handled } ->
      (* The program pointer is kept (R-7.4-m): a move instruction it waits in goes on waiting
         after RETRY or TRYNEXT. *)
      st.async <- None; Some (a_name, a_move, a_handled)
  | _ -> None


let result_pose ctx what = function
  | Ok v -> Returned (Some v)
  | Error e -> fail ctx what e

let current_joints ctx st =
  P.joints_at st.planner (W.now ctx.world)

let current_external ctx st = current_external_at st (W.now ctx.world)

(* The base a position function computes with, for programmed extjoint components: 9E9 keeps an
   axis where it is now (law X-target). *)
let base_for ctx st eax =
  Result.map (P.base st.planner) (MM.Ext_axes.resolve st.robot.externals ~from:(current_external ctx st) eax)

let path_command ctx st command f =
  let now = W.now ctx.world in
  match f now with
  | Ok () ->
      st.dirty <- true; st.reshaped <- true; emit st (E.Path_command { time = now; command });
      forget st ~now; Returned None
  | Error e -> fail ctx command e

(* R-14-pos1: the motion state whose robot CJointT, CRobT and CPos read (CTool and CWObj too,
   R-14-pos2). \TaskName, or \TaskRef
   (a taskid's identity is its task's number), names a task of the run: a motion task's robot; the
   caller itself, as without either; another task, ERR_NOT_MOVETASK; no task, ERR_TASKNAME. Without
   either, a motion task reads its own robot and a task without one the robot of its motion task
   (as if it used that task's mechanical unit group). *)
let robot_of ctx st args =
  let w = ctx.world in
  let tasks = W.task_names w in
  let named = match value ctx args "TaskName", value ctx args "TaskRef" with
    | Some (V.String n), _ -> Ok (Some n)
    | _, Some (V.Handle h) when V.handle_id h >= 1 && V.handle_id h <= List.length tasks ->
        Ok (Some (List.nth tasks (V.handle_id h - 1)))
    | _, Some _ -> Error "ERR_TASKNAME"
    | _ -> Ok None in
  let connected () = if W.motion_task w then st else match st.robots with (_, r) :: _ -> r | [] -> st in
  match named with
  | Error e -> Error e
  | Ok None -> Ok (connected ())
  | Ok (Some n) when not (List.exists (same n) tasks) -> Error "ERR_TASKNAME"
  | Ok (Some n) when same n (W.task_name w) -> Ok (connected ())
  | Ok (Some n) -> (
      match List.find_opt (fun (m, _) -> same m n) st.robots with
      | Some (_, r) -> Ok r
      | None -> Error "ERR_NOT_MOVETASK")

let call_unguarded (ctx : context) st name args =
  let w = ctx.world in
  let now = W.now w in
  let settings = P.settings st.planner in
  let get n = value ctx args n in
  let wobj_data = function Some v -> wobj_of v | None -> D.wobj0 in
  let lname = lower name in
  match lname with
  | "movel" | "movej" | "movec" | "moveabsj" | "moveldo" | "movejdo" -> Some (move ctx st name args)
  | "triggl" | "triggj" | "triggc" -> Some (move ctx st name args)  (* for Trigg_routines: the move itself *)
  | "moveextj" -> Some (move ctx st name args)
  | "searchl" | "searchj" | "searchc" -> Some (search ctx st name args)
  | "waittime" when present ctx args "InPos" -> (
      match num ctx args "Time" with
      | Some t when t >= 0. && Float.is_finite t ->
          (* \InPos: the time counts from when the robot stands still. *)
          Some (until ctx ~what:"the robot to stand still (WaitTime \\InPos)" (fun () ->
              let s = standstill st () in
              if Float.is_finite s then Float.max now s +. t else infinity))
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | "waituntil" when present ctx args "InPos" && not (reached w (standstill st ())) ->
      (* The condition is first evaluated when the robot stands still (R-4.1-f), then at the
         poll rate, as without \InPos. *)
      let rate = Option.value (num ctx args "PollRate") ~default:W.default_poll_rate in
      let flag = present ctx args "TimeFlag" in
      let max_time = num ctx args "MaxTime" in
      if rate <= 0. || (match max_time with Some m -> not (m >= 0.) | None -> false) then Some (Failed "ERR_ARGVALERR")
      else begin
        let s = standstill st () in
        if Float.is_finite s then st.first_poll <- Some s;
        let finish ~timed_out =
          if flag then
            ((match arg ctx args "TimeFlag" with Location (box, i, _) -> box.(i) <- V.Bool timed_out | _ -> ()); None)
          else if timed_out then Rapid_observable.Wait.error "ERR_WAIT_MAXTIME" else None in
        Some (Wait { W.what = "a condition (WaitUntil \\InPos)"; satisfied = (fun () -> false);
                     deadline = Option.map (fun m -> now +. m) max_time; finish; poll = Some rate })
      end
  | "waitrob" -> Some (until ctx ~what:"the robot to stand still (WaitRob)" (standstill st))
  | "stopmove" -> Some (path_command ctx st "StopMove" (fun at -> P.stop st.planner ~at; Ok ()))
  | "startmove" -> Some (path_command ctx st "StartMove" (fun at -> P.start st.planner ~at; Ok ()))
  | "stopmovereset" -> Some (Returned None)
  | "startmoveretry" ->
      (* StartMove and RETRY in one (ABB: for error handlers; outside one, RETRY's own rule). *)
      P.start st.planner ~at:now; st.dirty <- true; st.reshaped <- true;
      emit st (E.Path_command { time = now; command = "StartMove" });
      Some Retry_requested
  | "clearpath" ->
      Some (path_command ctx st "ClearPath" (fun at -> P.clear st.planner ~at; st.cleared_at <- Some at; Ok ()))
  | "exitcycle" -> (
      (* R-13-exitcycle1 (ABB's ExitCycle): the robot's on-going movement stops and every path
         not done is dropped, of both path levels; the next cycle's moves start from where the
         robot stands (a StopMove in effect is lifted, as by a start from main). *)
      let clear at =
        let back = if P.path_level st.planner = 2 then P.resto_path st.planner ~at else Ok () in
        P.clear st.planner ~at; st.cleared_at <- Some at;
        if P.stopped st.planner then P.start st.planner ~at;
        back in
      match path_command ctx st "ClearPath" clear with
      | Returned _ -> Some Exit_cycle_requested
      | other -> Some other)
  | "storepath" -> Some (path_command ctx st "StorePath" (fun at -> P.store_path st.planner ~at))
  | "restopath" -> Some (path_command ctx st "RestoPath" (fun at -> P.resto_path st.planner ~at))
  | "procerrrecovery" ->
      (* §7.4: the path stops; the error ERR_PATH_STOP goes to the move instruction the program
         pointer is in or comes to next (\SyncLastMoveInst), or to the routine of the move
         that made the robot's path (\SyncOrgMoveInst, also without a switch: R-7.4-a). *)
      P.stop st.planner ~at:now;
      emit st (E.Path_command { time = now; command = "ProcerrRecovery" });
      st.dirty <- true; st.reshaped <- true;
      let mode = if present ctx args "SyncLastMoveInst" then Sync_last else Sync_org in
      st.async <- Some { a_name = "ERR_PATH_STOP"; a_move = motion_pointer st; a_mode = mode; a_handled = true };
      Some (Returned None)
  | "writecfgdata" -> (
      (* §7.6 example 4: the system parameter Collision Error Handling, switched by the program;
         any other parameter is not modelled. *)
      match get "InstancePath", get "Attribute", num ctx args "CfgData" with
      | Some (V.String path), Some (V.String attr), Some v
        when String.lowercase_ascii path = "/sys/sys_misc/collisionerrorhandling"
             && String.lowercase_ascii attr = "value" ->
          if v = 0. || v = 1. then (st.collision_handling <- v = 1.; Some (Returned None))
          else Some (Failed "ERR_ARGVALERR")
      | _ -> None)
  | "pathlevel" -> Some (Returned (Some (V.num (float_of_int (P.path_level st.planner)))))
  | "speedlimcheckpoint" -> Some (speed_lim_check_point ctx st args)
  | "speedlimaxis" -> Some (speed_lim_axis ctx st args)
  | "velset" -> (
      match num ctx args "Override", num ctx args "Max" with
      | Some o, Some m when o > 0. && m > 0. && Float.is_finite o && Float.is_finite m ->
          settings.velset <- { override = o; max = m }; Some (Returned None)
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | "accset" -> Some (Returned None)
  | "cornerpathwarning" | "gripload" -> Some (Returned None)
  | "isstopmoveact" ->
      (* R-13-z: only the motion task can StopMove in rapid-sem (R-14-e), so a stop from a
         non-motion task is never active; without a switch, a stop from either. *)
      Some (Returned (Some (V.Bool (not (present ctx args "FromNonMoveTask") && P.stopped st.planner))))
  | "setsysdata" when not (present ctx args "ObjectName") -> (
      (* R-13-y: the three record types SetSysData takes are told apart by their components;
         a load is accepted and changes nothing, as GripLoad (R-4.1-g). \ObjectName (activate by
         name) is not modelled. *)
      match get "SourceObject" with
      | Some (V.Record [| V.Bool _; V.Record [| _; _ |]; V.Record l |] as t) when Array.length l = 6 ->
          st.tool <- V.copy t; st.tool_name <- label ctx "SourceObject"; Some (Returned None)
      | Some (V.Record [| V.Bool _; V.Bool _; V.String _; V.Record _; V.Record _ |] as o) ->
          st.wobj <- V.copy o; st.wobj_name <- label ctx "SourceObject"; Some (Returned None)
      | Some (V.Record [| V.Num _; V.Record _; V.Record _; V.Num _; V.Num _; V.Num _ |]) -> Some (Returned None)
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | "getsysdata" -> (
      (* GetSysData DestObject [\ObjectName] (ABB, RAPID Instructions): the active tool or work
         object (CTool, CWObj) copied into DestObject, told apart by its components as for
         SetSysData (R-13-y); \ObjectName receives its name. A loaddata: load0, which the
         motion model does not track (R-13-getsysdata1). *)
      let load0 () = V.Record [| V.num 0.; V.pos 0. 0. 0.; V.orient 1. 0. 0. 0.; V.num 0.; V.num 0.; V.num 0. |] in
      let answer = match arg ctx args "DestObject" with
        | Location (box, i, _) -> (
            match box.(i) with
            | V.Record [| V.Bool _; V.Record [| _; _ |]; V.Record l |] when Array.length l = 6 ->
                Some (box, i, active_tool_value st, st.tool_name)
            | V.Record [| V.Bool _; V.Bool _; V.String _; V.Record _; V.Record _ |] ->
                Some (box, i, active_wobj_value st, st.wobj_name)
            | V.Record [| V.Num _; V.Record _; V.Record _; V.Num _; V.Num _; V.Num _ |] ->
                Some (box, i, load0 (), "load0")
            | _ -> None)
        | _ -> None in
      match answer with
      | None -> Some (Failed "ERR_ARGVALERR")
      | Some (box, i, v, object_name) ->
          box.(i) <- v;
          (match arg ctx args "ObjectName" with
           | Location (nb, ni, _) -> nb.(ni) <- V.String object_name
           | _ -> ());
          Some (Returned None))
  | "confl" -> settings.conf_l <- not (present ctx args "Off"); Some (Returned None)
  | "confj" -> settings.conf_j <- not (present ctx args "Off"); Some (Returned None)
  | "singarea" ->
      settings.sing_area_wrist <- present ctx args "Wrist" || present ctx args "LockAxis4"; Some (Returned None)
  | "maxrobspeed" -> Some (Returned (Some (V.num st.robot.max_tcp_speed)))
  | "cspeedoverride" -> Some (Returned (Some (V.num 100.)))
  (* R-14-pos2: CTool and CWObj read the active tool and work object of the task whose robot
     CJointT would read (\TaskRef, \TaskName: R-14-pos1). *)
  | ("ctool" | "cwobj") when Result.is_error (robot_of ctx st args) ->
      Some (match robot_of ctx st args with Error e -> Failed e | Ok _ -> Failed "ERR_TASKNAME")
  | "ctool" ->
      let st = Result.get_ok (robot_of ctx st args) in
      Some (Returned (Some (active_tool_value st)))
  | "cwobj" ->
      let st = Result.get_ok (robot_of ctx st args) in
      Some (Returned (Some (active_wobj_value st)))
  | "offs" -> (
      match get "Point", num ctx args "XOffset", num ctx args "YOffset", num ctx args "ZOffset" with
      | Some p, Some x, Some y, Some z ->
          Some (Returned (Some (with_pose p (G.offs (robtarget_of p).pose x y z))))
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | "reltool" -> (
      match get "Point", num ctx args "Dx", num ctx args "Dy", num ctx args "Dz" with
      | Some p, Some x, Some y, Some z ->
          let r = G.rel_tool (robtarget_of p).pose x y z ?rx:(num ctx args "Rx") ?ry:(num ctx args "Ry")
              ?rz:(num ctx args "Rz") () in
          Some (Returned (Some (with_pose p r)))
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | "mirpos" -> (
      match get "Point", get "MirPlane" with
      | Some p, Some plane ->
          let plane = MM.Frames.object_frame (wobj_of plane) in
          let wobj = Option.map (fun o -> MM.Frames.object_frame (wobj_of o)) (get "WObj") in
          let r = G.mir_pos ~point:(robtarget_of p).pose ~plane ?wobj ~mir_y:(present ctx args "MirY") () in
          Some (Returned (Some (with_pose p r)))
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | ("cjointt" | "crobt" | "cpos") when Result.is_error (robot_of ctx st args) ->
      Some (match robot_of ctx st args with Error e -> Failed e | Ok _ -> Failed "ERR_TASKNAME")
  | "cjointt" ->
      let st = Result.get_ok (robot_of ctx st args) in
      Some (match current_joints ctx st with
      | Ok q -> Returned (Some (jointtarget_value ~ext:(current_external ctx st) q))
      | Error e -> fail ctx name e)
  | "crobt" | "cpos" -> (
      let st = Result.get_ok (robot_of ctx st args) in
      (* Without \Tool and \WObj: the active ones, those of the last move. *)
      let tool = match get "Tool", active_tool st with
        | Some t, _ | None, Some t -> tool_of t | None, None -> D.tool0 in
      let wobj = match get "WObj" with
        | Some o -> wobj_of o | None -> if st.wobj == dummy then D.wobj0 else wobj_of st.wobj in
      Some (match current_joints ctx st with
          | Error e -> fail ctx name e
          | Ok joints ->
              let e = current_external ctx st in
              let base = P.base st.planner e in
              if lname = "crobt" then
                result_pose ctx name
                  (Result.map (robtarget_value ~extax:(eax_value e)) (MM.Frames.c_rob_t ?base st.kin ~joints tool wobj))
              else result_pose ctx name (Result.map pos_value (MM.Frames.c_pos ?base st.kin ~joints tool wobj))))
  | "calcrobt" -> (
      match get "Joint_target", get "Tool" with
      | Some j, Some tool ->
          (* The robtarget's external axes are the jointtarget's (law X-position). *)
          let e = eax_of_jointtarget j in
          Some (result_pose ctx name (Result.bind (base_for ctx st e) (fun base ->
              Result.map (robtarget_value ~extax:(eax_value e))
                (MM.Frames.calc_rob_t ?base st.kin (joints_of_jointtarget j) (tool_of tool) (wobj_data (get "WObj"))))))
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | "calcjointt" -> (
      match get "Rob_target", get "Tool" with
      | Some p, Some tool -> (
          let e = eax_of_robtarget p in
          match Result.bind (base_for ctx st e) (fun base ->
              MM.Frames.calc_joint_t ?base st.kin (robtarget_of p) (tool_of tool) (wobj_data (get "WObj"))) with
          | Ok q -> Some (Returned (Some (jointtarget_value ~ext:e q)))
          | Error e -> (
              match arg ctx args "ErrorNumber", MM.Motion_error.errnum e with
              | Location (box, i, _), Some errname ->
                  (* \ErrorNumber: the error is stored, not raised; the axes are undefined (9E9). *)
                  box.(i) <- V.num (float_of_int (ctx.error_number errname));
                  Some (Returned (Some (jointtarget_value (Array.make 6 9e9))))
              | _ -> Some (fail ctx name e)))
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | _ -> None

type effects = { at_move : bool; new_move : int option; first_poll : float option }

let no_effects = { at_move = false; new_move = None; first_poll = None }

(* What a call did besides its outcome is read here, once, right after it: the routine's body
   leaves it in the state. *)
let call ctx st name args =
  st.async_raised <- false; st.new_move <- None; st.first_poll <- None;
  let outcome = try call_unguarded ctx st name args with Illegal_quaternion -> Some (Failed "ERR_ILLQUAT") in
  let effects =
    if not st.async_raised && st.new_move = None && st.first_poll = None then no_effects
    else { at_move = st.async_raised; new_move = st.new_move; first_poll = st.first_poll } in
  Option.map (fun o -> (o, effects)) outcome

(* ------------------------------------------------------------------ guided motion *)

let axes_now st ~now = match P.joints_at st.planner now with Ok q -> q | Error _ -> arm_end_joints st now

(* One cycle of Externally Guided Motion (Egm_routines): the arm goes to its next axis angles in
   one cycle, a stop point, as a MoveAbsJ \T would; the active tool and work object stay. *)
let tooldata_of = tool_of
let wobjdata_of = wobj_of

let servo ctx st q ~duration =
  let now = W.now ctx.world in
  let fine = Option.get (D.find D.zonedata "fine") and speed = Option.get (D.find D.speeddata "v1000") in
  forget st ~now;
  apply_speed_limit st ctx.world;
  match P.plan st.planner ~now (P.move ~t:duration ~label:"EGM" speed fine (P.Abs_joint q)) with
  | Error e -> ctx.log (Printf.sprintf "EGM: %s" (MM.Motion_error.name e)); Error (error_name e)
  | Ok { id; _ } -> planned st id; st.last_planned <- Some id; Ok ()
