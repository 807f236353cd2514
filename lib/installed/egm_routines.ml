(* Externally Guided Motion in joint and pose mode (ABB's EGM application manual and its RAPID pages:
   EGMGetId, EGMGetState, EGMSetupUC, EGMActJoint, EGMRunJoint, EGMActPose, EGMRunPose, EGMStop,
   EGMReset; egm.sys; doc/rulings.md R-13-egm1 to R-13-egm6). A process is kept beside the motion
   of its task; its sensor is a UDP peer on the loopback (Rapid_controller.Egm_channel), its messages
   Rapid_controller.Egm_protocol's. *)

module V = Value
module W = Rapid_controller.World
module S = Rapid_controller.Services
module C = Rapid_controller.Egm_channel
module E = Rapid_controller.Egm_protocol
module MR = Motion_routines
open Primitive

let same = Rapid_typing.Types.same_name

let names = [ "EGMGetId"; "EGMGetState"; "EGMSetupUC"; "EGMActJoint"; "EGMRunJoint"; "EGMActPose"; "EGMRunPose";
               "EGMStop"; "EGMReset" ]

let modelled name = List.exists (same name) names

let reach name : Installed_routine.reach =
  if same name "EGMRunJoint" || same name "EGMRunPose" then Moves else World

(* egm.sys: EGM_STATE_DISCONNECTED 0, EGM_STATE_CONNECTED 1, EGM_STATE_RUNNING 2. *)
type state = Disconnected | Connected | Running

let state_number = function Disconnected -> 0. | Connected -> 1. | Running -> 2.

(* What EGMActJoint sets (R-13-egm3): the convergence criteria of each axis (degrees), the cycle
   (\SampleRate, s), how far a set point may be from where the robot is, and the speed the
   correction may add. *)
module G = Rapid_motion_model.Geom

(* What EGMActPose adds (R-13-egm6): the sensor frame in the robot's base frame, and the tool
   whose TCP the sensor guides. *)
type pose_frames = { sensor_frame : G.pose; tframe : G.pose }

type activation = {
  minmax : (float * float) array;
  frames : pose_frames option;
  cycle : float;
  max_pos_deviation : float;
  max_speed_deviation : float;
}

type process = {
  mutable state : state;
  mutable channel : C.t option;
  mutable joint_mode : bool;
  mutable comm_timeout : float;
  mutable activation : activation option;
  mutable seqno : int;
  mutable setup_time : float;
  mutable stop_requested : bool;
  mutable running : W.wait option;  (* EGMRunJoint's wait while it runs *)
}

type run = { processes : (int, process) Hashtbl.t; mutable next_id : int }

type MR.extension += Egm of run

let run_of st =
  match List.find_map (function Egm r -> Some r | _ -> None) (MR.extensions st) with
  | Some r -> r
  | None -> let r = { processes = Hashtbl.create 4; next_id = 1 } in MR.add_extension st (Egm r); r

let ( let* ) r f = match r with Ok v -> f v | Error name -> Failed name

let done_ = Returned None

let value_of ctx args name =
  match named_argument ctx args name with
  | Location (box, i, _) -> Some box.(i)
  | Value v -> Some v
  | Switch | Missing -> None

let ident_of ctx args =
  match value_of ctx args "EGMid" with Some (V.Handle h) when V.handle_id h > 0 -> V.handle_id h | _ -> 0

(* The process an egmident holds; one EGMGetId did not give, or EGMReset released, is none
   (R-13-egm2: ERR_ARGVALERR where a process is needed). *)
let process st ctx args =
  match Hashtbl.find_opt (run_of st).processes (ident_of ctx args) with
  | Some p -> Ok p
  | None -> Error "ERR_ARGVALERR"

let positive_or ctx args name ~default =
  match named_num ctx args name with
  | None -> Ok default
  | Some x when x > 0. && Float.is_finite x -> Ok x
  | Some _ -> Error "ERR_ARGVALERR"

let not_negative_or ctx args name ~default =
  match named_num ctx args name with
  | None -> Ok default
  | Some x when x >= 0. && Float.is_finite x -> Ok x
  | Some _ -> Error "ERR_ARGVALERR"

let close_channel ctx p =
  Option.iter (S.close_egm (W.services ctx.world)) p.channel;
  p.channel <- None

(* ------------------------------------------------------------------ the routines but the run *)

let get_id ctx st args =
  let r = run_of st in
  if not (Hashtbl.mem r.processes (ident_of ctx args)) then begin
    let id = r.next_id in
    r.next_id <- id + 1;
    Hashtbl.replace r.processes id
      { state = Disconnected; channel = None; joint_mode = false; comm_timeout = 1.; activation = None; seqno = 0;
        setup_time = 0.; stop_requested = false; running = None };
    named_store ctx args "EGMid" (V.Handle (V.make_handle ~kind:"egmident" id))
  end;
  done_

(* R-13-egm1: the UdpUc device is one of --egm-device's; one the run does not know, or whose
   socket the host refuses, is ERR_UDPUC_COMM. *)
let setup ctx st args =
  let* p = process st ctx args in
  let* timeout = positive_or ctx args "CommTimeout" ~default:1. in
  if named_present ctx args "PathCorr" then Not_modelled
  else
    let device = match value_of ctx args "UCDevice" with Some (V.String s) -> s | _ -> "" in
    match C.find (S.egm_devices (W.services ctx.world)) device with
    | None -> ctx.log (Printf.sprintf "EGMSetupUC: no UdpUc device %S (--egm-device)" device); Failed "ERR_UDPUC_COMM"
    | Some d ->
        close_channel ctx p;
        match S.open_egm (W.services ctx.world) d with
        | Error e -> ctx.log (Printf.sprintf "EGMSetupUC: %s: %s" device e); Failed "ERR_UDPUC_COMM"
        | Ok c ->
            p.channel <- Some c; p.joint_mode <- not (named_present ctx args "Pose");
            p.comm_timeout <- timeout; p.activation <- None;
            p.state <- Connected; p.setup_time <- W.now ctx.world;
            done_

let default_minmax = (-0.1, 0.1)

let criterion_named ctx args name =
  match value_of ctx args name with
  | None -> Ok default_minmax
  | Some v -> (
      match V.components v with
      | [| a; b |] ->
          let lo = V.num_value a and hi = V.num_value b in
          if lo <= hi && Float.is_finite lo && Float.is_finite hi then Ok (lo, hi) else Error "ERR_ARGVALERR"
      | _ -> Error "ERR_ARGVALERR")

let criterion ctx args k = criterion_named ctx args (Printf.sprintf "J%d" k)

let act_joint ctx st args =
  let* p = process st ctx args in
  if named_present ctx args "StreamStart" then Not_modelled
  else if p.state = Disconnected || not p.joint_mode then Failed "ERR_ARGVALERR"
  else
    let rec criteria k acc = if k > 6 then Ok (Array.of_list (List.rev acc)) else
        match criterion ctx args k with Ok m -> criteria (k + 1) (m :: acc) | Error e -> Error e in
    let* minmax = criteria 1 [] in
    let* _ = criterion ctx args 7 in
    let* rate = positive_or ctx args "SampleRate" ~default:4. in
    let* max_pos_deviation = positive_or ctx args "MaxPosDeviation" ~default:1000. in
    let* max_speed_deviation = positive_or ctx args "MaxSpeedDeviation" ~default:1. in
    let* _ = not_negative_or ctx args "LpFilter" ~default:0. in
    (* \SampleRate: ms, a multiple of the 4 ms cycle (R-13-egm3). *)
    if not (Float.is_integer (rate /. 4.)) then Failed "ERR_ARGVALERR"
    else begin
      p.activation <- Some { minmax; frames = None; cycle = rate /. 1000.; max_pos_deviation; max_speed_deviation };
      done_
    end

let stop ctx st args =
  let* p = process st ctx args in
  let* _ = not_negative_or ctx args "RampOutTime" ~default:0. in
  (* The run ends at its next cycle; one whose program point an asynchronous error's handler
     keeps (R-7.2-m) runs no cycle meanwhile, and is connected from now. *)
  if p.state = Running then (p.stop_requested <- true; p.state <- Connected);
  done_

(* R-13-egm2: EGMReset of an egmident that holds no process does nothing (programs reset before
   EGMGetId). *)
let reset ctx st args =
  let r = run_of st in
  let id = ident_of ctx args in
  (match Hashtbl.find_opt r.processes id with
   | Some p -> close_channel ctx p; Hashtbl.remove r.processes id;
       named_store ctx args "EGMid" (V.Handle (V.make_handle ~kind:"egmident" 0))
   | None -> ());
  done_

let get_state ctx st args =
  let s = match Hashtbl.find_opt (run_of st).processes (ident_of ctx args) with
    | Some p -> p.state | None -> Disconnected in
  Returned (Some (V.num (state_number s)))

(* ------------------------------------------------------------------ EGMRunJoint *)

let clamp limit x = Float.max (-. limit) (Float.min limit x)

(* R-13-egm4: the Cartesian feedback of joint mode is the flange (tool0) in the world frame, mm and
   a unit quaternion, as CRobT \Tool:=tool0 \WObj:=wobj0 reads it. *)
let flange st now =
  let { Rapid_motion_model.Geom.trans = t; rot = r } = Rapid_motion_model.Planner.pose_at (MR.planner st) now in
  { E.pos = Some (t.x, t.y, t.z); orient = Some (r.q1, r.q2, r.q3, r.q4); euler = None }

(* What the cycles of a run do in its mode: the joint or pose set point the sensor's message
   gives, whether the criteria are met, the axis angles of the next cycle's step, and the
   feedback. *)
type guidance = {
  take : E.sensor -> float array -> unit;   (* a message, the axis angles now *)
  met : float array -> bool;
  step : ramp:float -> float array -> (float array option, string) result;  (* None: no set point yet *)
  feedback : float array -> E.robot -> E.robot;
}

(* R-13-egm4: one cycle of the robot's part every activation cycle of virtual time: it sends its
   feedback, takes the newest set point the sensor sent (waiting on the host one cycle at most),
   and steps towards it. It ends when the convergence criteria have held for \CondTime, at
   EGMStop, with ERR_UDPUC_COMM when no message came for \CommTimeout, or with the step's
   error. *)
let run_guided ctx st p act channel ~cond_time ~ramp_in (g : guidance) =
  let w = ctx.world in
  let start = W.now w in
  let cycles = ref 0 and last_message = ref start in
  let next_cycle () = start +. (float_of_int !cycles *. act.cycle) in
  let converged_since = ref None in
  let finished = ref false and failure = ref None in
  p.state <- Running; p.stop_requested <- false;
  let finish_run () = finished := true; p.state <- Connected in
  let cycle now =
    let q = MR.axes_now st ~now in
    p.seqno <- p.seqno + 1;
    let tm = int_of_float (Float.round ((now -. p.setup_time) *. 1000.)) in
    C.send channel (E.encode_robot (g.feedback q { E.empty_robot with
                                     r_header = { seqno = Some p.seqno; tm = Some tm; mtype = Some E.mtype_data };
                                     feedback_joints = Some (Array.to_list (Array.sub q 0 6));
                                     motor_on = Some true; mci_running = Some true; convergence_met = Some (g.met q);
                                     rapid_running = Some true }));
    (* A message that is not an EgmSensor is dropped, as a datagram lost (R-13-egm5). *)
    (match C.receive channel ~within:act.cycle with
     | None -> ()
     | Some bytes -> match E.decode_sensor bytes with
       | Error _ -> ()
       | Ok m -> last_message := now; g.take m q);
    (if g.met q then (if !converged_since = None then converged_since := Some now) else converged_since := None);
    if p.stop_requested then finish_run ()
    else if W.seconds (now -. !last_message) >= W.seconds p.comm_timeout then begin
      ctx.log "EGM: no message from the sensor within \\CommTimeout";
      failure := Some "ERR_UDPUC_COMM"; finish_run ()
    end
    else if (match !converged_since with Some t0 -> W.seconds (now -. t0) >= W.seconds cond_time | None -> false)
    then finish_run ()
    else
      let ramp = if ramp_in > 0. then Float.min 1. ((now -. start +. act.cycle) /. ramp_in) else 1. in
      match g.step ~ramp q with
      | Ok None -> ()
      | Error e -> failure := Some e; finish_run ()
      | Ok (Some next) ->
          match MR.servo ctx st next ~duration:act.cycle with
          | Ok () -> ()
          | Error e -> failure := Some e; finish_run () in
  let wait = { W.what = "the EGM sensor"; deadline = None; poll = None;
               satisfied = (fun () ->
                   let now = W.now w in
                   if (not !finished) && W.seconds now >= W.seconds (next_cycle ()) then begin
                     cycle now;
                     incr cycles;
                     if not !finished then W.wake_at w (next_cycle ())
                   end;
                   !finished);
               finish = (fun ~timed_out:_ ->
                   p.state <- Connected; p.running <- None;
                   Option.bind !failure Rapid_observable.Wait.error) } in
  p.running <- Some wait;
  Wait wait

let run_arguments ctx args k =
  let* cond_time = not_negative_or ctx args "CondTime" ~default:1. in
  let* ramp_in = not_negative_or ctx args "RampInTime" ~default:0. in
  let* _ = not_negative_or ctx args "RampOutTime" ~default:0. in
  let* gain = not_negative_or ctx args "PosCorrGain" ~default:1. in
  if named_present ctx args "NoWaitCond" then Not_modelled
  else if gain > 1. then Failed "ERR_ARGVALERR"
  else k ~cond_time ~ramp_in ~gain

(* R-13-egm4: each guided axis moves towards the set point, held within MaxPosDeviation of the
   axis, by PosCorrGain of the deviation plus the sensor's speed reference, at most
   MaxSpeedDeviation (ramped in over \RampInTime) for a cycle. *)
let run_joint ctx st args =
  let* p = process st ctx args in
  run_arguments ctx args @@ fun ~cond_time ~ramp_in ~gain ->
  match p.activation, p.channel with
  | None, _ | _, None -> Failed "ERR_ARGVALERR"
  | Some { frames = Some _; _ }, _ -> Failed "ERR_ARGVALERR"
  | Some act, Some channel ->
      let switches = List.filter (fun k -> named_present ctx args (Printf.sprintf "J%d" k)) [ 1; 2; 3; 4; 5; 6 ] in
      let guided = if switches = [] && not (named_present ctx args "J7") then [ 1; 2; 3; 4; 5; 6 ] else switches in
      let target = ref None and speed = ref None in
      let deviation k t q = t.(k - 1) -. q.(k - 1) in
      let met q = match !target with
        | None -> false
        | Some t -> List.for_all (fun k ->
            let lo, hi = act.minmax.(k - 1) and d = deviation k t q in d >= lo && d <= hi) guided in
      let take (m : E.sensor) q =
        Option.iter (fun js ->
            let t = Array.sub q 0 6 in
            List.iteri (fun i v -> if i < 6 && Float.is_finite v then t.(i) <- v) js;
            target := Some t) m.set_joints;
        speed := m.speed_joints in
      let step ~ramp q = match !target with
        | None -> Ok None
        | Some t ->
            let limit = act.max_speed_deviation *. act.cycle *. ramp in
            let next = Array.copy q in
            List.iter (fun k ->
                let d = clamp act.max_pos_deviation (deviation k t q) in
                let v = match !speed with Some l when List.length l >= k -> List.nth l (k - 1) | _ -> 0. in
                let v = if Float.is_finite v then v else 0. in
                next.(k - 1) <- q.(k - 1) +. clamp limit ((gain *. d) +. (v *. act.cycle))) guided;
            Ok (Some next) in
      let feedback q (r : E.robot) =
        ignore q;
        { r with feedback_pose = Some (flange st (W.now ctx.world));
                 planned_joints = Option.map Array.to_list !target } in
      run_guided ctx st p act channel ~cond_time ~ramp_in { take; met; step; feedback }

(* ------------------------------------------------------------------ pose mode *)

(* egm.sys's egmframetype: EGM_FRAME_BASE 0, TOOL 1, WOBJ 2, WORLD 3, JOINT 4. R-13-egm6: a
   frame of pose mode is given relative to one of base, tool (the TCP where it is at
   EGMActPose), work object (its uframe . oframe, in the world) or world; the guidance works in
   the robot's base frame, so a world or work object frame is brought into it through where the
   cell puts the base (R-bk-12, law F-base; the world frame itself when nothing moves it). JOINT
   is no frame of pose mode (ERR_ARGVALERR). *)
let frame_in_base st ~now q tframe wobj kind relative =
  let module P = Rapid_motion_model.Planner in
  let planner = MR.planner st in
  let kin = P.kinematics planner in
  let in_base (world : G.pose) =
    let base = match P.external_at planner now with Ok e -> P.base planner e | Error _ -> None in
    match base with Some base -> G.pmult (G.pinv base) world | None -> world in
  match int_of_float kind with
  | 0 when Float.is_integer kind -> Ok relative
  | 3 when Float.is_integer kind -> Ok (in_base relative)
  | 1 when Float.is_integer kind ->
      Ok (G.pmult (G.pmult (Rapid_motion_model.Kinematics.forward kin q) tframe) relative)
  | 2 when Float.is_integer kind -> Ok (in_base (G.pmult (Rapid_motion_model.Frames.object_frame wobj) relative))
  | _ -> Error "ERR_ARGVALERR"

(* Euler angles as ABB's EGM gives them (degrees, R-13-egm6: z, y, x about the moving axes, as
   OrientZYX): the quaternion Rz . Ry . Rx. *)
let of_euler (x, y, z) =
  let axis a deg = G.of_axis_angle a (G.rad deg) in
  G.omult (axis { G.x = 0.; y = 0.; z = 1. } z)
    (G.omult (axis { G.x = 0.; y = 1.; z = 0. } y) (axis { G.x = 1.; y = 0.; z = 0. } x))

(* The ZYX Euler angles (degrees) of a rotation: rx, ry, rz. *)
let euler_of (q : G.orient) =
  let m = G.to_matrix (G.normalize q) in
  (* row-major 3x3 *)
  let r i j = m.((3 * i) + j) in
  let ry = Float.asin (Float.max (-1.) (Float.min 1. (-. r 2 0))) in
  let rx = Float.atan2 (r 2 1) (r 2 2) and rz = Float.atan2 (r 1 0) (r 0 0) in
  (G.deg rx, G.deg ry, G.deg rz)

let act_pose ctx st args =
  let* p = process st ctx args in
  if named_present ctx args "StreamStart" then Not_modelled
  else if p.state = Disconnected || p.joint_mode then Failed "ERR_ARGVALERR"
  else
    let rec criteria names acc = match names with
      | [] -> Ok (Array.of_list (List.rev acc))
      | n :: rest -> match criterion_named ctx args n with Ok m -> criteria rest (m :: acc) | Error e -> Error e in
    let* minmax = criteria [ "x"; "y"; "z"; "rx"; "ry"; "rz" ] [] in
    let* rate = positive_or ctx args "SampleRate" ~default:4. in
    let* max_pos_deviation = positive_or ctx args "MaxPosDeviation" ~default:1000. in
    let* max_speed_deviation = positive_or ctx args "MaxSpeedDeviation" ~default:1. in
    let* _ = not_negative_or ctx args "LpFilter" ~default:0. in
    let module D = Rapid_motion_model.Motion_data in
    let tool = match value_of ctx args "Tool" with Some v -> MR.tooldata_of v | None -> D.tool0 in
    let wobj = match value_of ctx args "WObj" with Some v -> MR.wobjdata_of v | None -> D.wobj0 in
    let pose_arg name = match value_of ctx args name with Some v -> MR.pose_of v | None -> G.identity in
    let kind name = match named_num ctx args name with Some k -> k | None -> -1. in
    let now = W.now ctx.world in
    let q = MR.axes_now st ~now in
    let* _ = frame_in_base st ~now q tool.tframe wobj (kind "CorrFrType") (pose_arg "CorrFrame") in
    let* sensor_frame = frame_in_base st ~now q tool.tframe wobj (kind "SensorFrType") (pose_arg "SensorFrame") in
    if not (Float.is_integer (rate /. 4.)) then Failed "ERR_ARGVALERR"
    else if (not tool.tool_robhold) || wobj.wobj_robhold then Failed "ERR_ARGVALERR"
    else begin
      p.activation <- Some { minmax; frames = Some { sensor_frame; tframe = tool.tframe }; cycle = rate /. 1000.;
                             max_pos_deviation; max_speed_deviation };
      done_
    end

let egm_pose (x : G.pose) =
  let t = x.trans and r = G.normalize x.rot in
  { E.pos = Some (t.x, t.y, t.z); orient = Some (r.q1, r.q2, r.q3, r.q4); euler = None }

(* R-13-egm6: the sensor's planned pose (mm, and a quaternion, or else Euler angles) in the
   sensor frame is the TCP's set point; \Offset is composed after the sensor frame. Each cycle
   the guided components move towards it by PosCorrGain (the position held within
   MaxPosDeviation mm), the axis angles that put the TCP there come from the arm's inverse
   kinematics (nearest the axes now; none is ERR_ROBLIMIT), and each axis steps towards them by
   at most MaxSpeedDeviation degrees per second, as in joint mode. *)
let run_pose ctx st args =
  let* p = process st ctx args in
  run_arguments ctx args @@ fun ~cond_time ~ramp_in ~gain ->
  match p.activation, p.channel with
  | None, _ | _, None | Some { frames = None; _ }, _ -> Failed "ERR_ARGVALERR"
  | Some ({ frames = Some fr; _ } as act), Some channel ->
      let kin = Rapid_motion_model.Planner.kinematics (MR.planner st) in
      let offset = match value_of ctx args "Offset" with Some v -> MR.pose_of v | None -> G.identity in
      let frame = G.pmult fr.sensor_frame offset in
      let to_frame = G.pinv frame in
      let names = [| "x"; "y"; "z"; "Rx"; "Ry"; "Rz" |] in
      let switches = List.filter (fun k -> named_present ctx args names.(k)) [ 0; 1; 2; 3; 4; 5 ] in
      let guided = if switches = [] then [ 0; 1; 2; 3; 4; 5 ] else switches in
      let is_guided k = List.mem k guided in
      let tcp q = G.pmult to_frame (G.pmult (Rapid_motion_model.Kinematics.forward kin q) fr.tframe) in
      let target = ref None in
      (* The deviation of the set point from the TCP: mm along the frame's axes, and the ZYX
         Euler angles (degrees) of the rotation from the TCP's orientation to the set point's. *)
      let deviation (t : G.pose) (c : G.pose) =
        let d = G.sub t.trans c.trans in
        let rx, ry, rz = euler_of (G.omult (G.conj c.rot) t.rot) in
        [| d.x; d.y; d.z; rx; ry; rz |] in
      let met q = match !target with
        | None -> false
        | Some t -> let d = deviation t (tcp q) in
            List.for_all (fun k -> let lo, hi = act.minmax.(k) in d.(k) >= lo && d.(k) <= hi) guided in
      let take (m : E.sensor) q =
        Option.iter (fun (sp : E.pose) ->
            let c = tcp q in
            let trans = match sp.pos with
              | Some (x, y, z) when Float.is_finite x && Float.is_finite y && Float.is_finite z -> { G.x; y; z }
              | _ -> c.trans in
            let finite4 (a, b, c, d) =
              List.for_all Float.is_finite [ a; b; c; d ] && (a *. a) +. (b *. b) +. (c *. c) +. (d *. d) > 0. in
            let rot = match sp.orient, sp.euler with
              | Some ((a, b, c', d) as o), _ when finite4 o -> G.normalize { G.q1 = a; q2 = b; q3 = c'; q4 = d }
              | _, Some ((x, y, z) as e) when (let x', y', z' = e in List.for_all Float.is_finite [ x'; y'; z' ]) ->
                  of_euler (x, y, z)
              | _ -> c.rot in
            target := Some { G.trans; rot }) m.set_pose in
      let step ~ramp q = match !target with
        | None -> Ok None
        | Some t ->
            let c = tcp q in
            let d = deviation t c in
            let part k = if is_guided k then gain *. d.(k) else 0. in
            let move = { G.x = part 0; y = part 1; z = part 2 } in
            let n = G.norm move in
            let move = if n > act.max_pos_deviation then G.scale (act.max_pos_deviation /. n) move else move in
            let turn = of_euler (part 3, part 4, part 5) in
            let goal = { G.trans = G.add c.trans move; rot = G.normalize (G.omult c.rot turn) } in
            let flange = G.pmult (G.pmult frame goal) (G.pinv fr.tframe) in
            match Rapid_motion_model.Kinematics.inverse kin flange (Rapid_motion_model.Kinematics.Nearest q) with
            | Error e ->
                ctx.log (Printf.sprintf "EGMRunPose: %s" (Rapid_motion_model.Motion_error.name e));
                Error (Option.value (Rapid_motion_model.Motion_error.errnum e) ~default:"ERR_ROBLIMIT")
            | Ok qt ->
                let limit = act.max_speed_deviation *. act.cycle *. ramp in
                Ok (Some (Array.mapi (fun i a -> if i < 6 then a +. clamp limit (qt.(i) -. a) else a) q)) in
      let feedback q (r : E.robot) =
        { r with feedback_pose = Some (egm_pose (tcp q)); planned_pose = Option.map egm_pose !target } in
      run_guided ctx st p act channel ~cond_time ~ramp_in { take; met; step; feedback }

(* R-13-egm2: a run left by an error or a long jump (a trap's RAISE, §7.2) ends there, the robot
   standing at the end of its last cycle. *)
let wait_abandoned st (wait : W.wait) =
  match List.find_map (function Egm r -> Some r | _ -> None) (MR.extensions st) with
  | None -> ()
  | Some r -> Hashtbl.iter (fun _ p ->
      if (match p.running with Some x -> x == wait | None -> false) then (p.state <- Connected; p.running <- None))
      r.processes

let call ctx st name args =
  let f = String.lowercase_ascii name in
  if not (modelled name) then None
  else Some (match f with
      | "egmgetid" -> get_id ctx st args
      | "egmgetstate" -> get_state ctx st args
      | "egmsetupuc" -> setup ctx st args
      | "egmactjoint" -> act_joint ctx st args
      | "egmrunjoint" -> run_joint ctx st args
      | "egmactpose" -> act_pose ctx st args
      | "egmrunpose" -> run_pose ctx st args
      | "egmstop" -> stop ctx st args
      | _ -> reset ctx st args)
