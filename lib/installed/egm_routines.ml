(* Externally Guided Motion in joint mode (ABB's EGM application manual and its RAPID pages:
   EGMGetId, EGMGetState, EGMSetupUC, EGMActJoint, EGMRunJoint, EGMStop, EGMReset; egm.sys;
   doc/rulings.md R-13-egm1 to R-13-egm5). A process is kept beside the motion of its task;
   its sensor is a UDP peer on the loopback (Rapid_controller.Egm_channel), its messages
   Rapid_controller.Egm_protocol's. *)

module V = Value
module W = Rapid_controller.World
module S = Rapid_controller.Services
module C = Rapid_controller.Egm_channel
module E = Rapid_controller.Egm_protocol
module MR = Motion_routines
open Primitive

let same = Rapid_typing.Types.same_name

let names = [ "EGMGetId"; "EGMGetState"; "EGMSetupUC"; "EGMActJoint"; "EGMRunJoint"; "EGMStop"; "EGMReset" ]

let modelled name = List.exists (same name) names

let reach name : Installed_routine.reach = if same name "EGMRunJoint" then Moves else World

(* egm.sys: EGM_STATE_DISCONNECTED 0, EGM_STATE_CONNECTED 1, EGM_STATE_RUNNING 2. *)
type state = Disconnected | Connected | Running

let state_number = function Disconnected -> 0. | Connected -> 1. | Running -> 2.

(* What EGMActJoint sets (R-13-egm3): the convergence criteria of each axis (degrees), the cycle
   (\SampleRate, s), how far a set point may be from where the robot is, and the speed the
   correction may add. *)
type activation = {
  minmax : (float * float) array;
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
  if named_present ctx args "PathCorr" || named_present ctx args "Pose" then Not_modelled
  else
    let device = match value_of ctx args "UCDevice" with Some (V.String s) -> s | _ -> "" in
    match C.find (S.egm_devices (W.services ctx.world)) device with
    | None -> ctx.log (Printf.sprintf "EGMSetupUC: no UdpUc device %S (--egm-device)" device); Failed "ERR_UDPUC_COMM"
    | Some d ->
        close_channel ctx p;
        match S.open_egm (W.services ctx.world) d with
        | Error e -> ctx.log (Printf.sprintf "EGMSetupUC: %s: %s" device e); Failed "ERR_UDPUC_COMM"
        | Ok c ->
            p.channel <- Some c; p.joint_mode <- true; p.comm_timeout <- timeout; p.activation <- None;
            p.state <- Connected; p.setup_time <- W.now ctx.world;
            done_

let default_minmax = (-0.1, 0.1)

let criterion ctx args k =
  match value_of ctx args (Printf.sprintf "J%d" k) with
  | None -> Ok default_minmax
  | Some v -> (
      match V.components v with
      | [| a; b |] ->
          let lo = V.num_value a and hi = V.num_value b in
          if lo <= hi && Float.is_finite lo && Float.is_finite hi then Ok (lo, hi) else Error "ERR_ARGVALERR"
      | _ -> Error "ERR_ARGVALERR")

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
      p.activation <- Some { minmax; cycle = rate /. 1000.; max_pos_deviation; max_speed_deviation };
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

(* R-13-egm4: one cycle of the robot's part every activation cycle of virtual time: it sends its
   feedback, takes the newest set point the sensor sent (waiting on the host one cycle at most),
   and moves each guided axis towards it by PosCorrGain of the deviation plus the sensor's speed
   reference, at most MaxSpeedDeviation (ramped in over \RampInTime) for a cycle, the set point
   itself held within MaxPosDeviation of the axis. It ends when the convergence criteria have
   held for \CondTime, at EGMStop, or with ERR_UDPUC_COMM when no message came for
   \CommTimeout. *)
let run_joint ctx st args =
  let* p = process st ctx args in
  let* cond_time = not_negative_or ctx args "CondTime" ~default:1. in
  let* ramp_in = not_negative_or ctx args "RampInTime" ~default:0. in
  let* _ = not_negative_or ctx args "RampOutTime" ~default:0. in
  let* gain = not_negative_or ctx args "PosCorrGain" ~default:1. in
  if named_present ctx args "NoWaitCond" then Not_modelled
  else if gain > 1. then Failed "ERR_ARGVALERR"
  else match p.activation, p.channel with
    | None, _ | _, None -> Failed "ERR_ARGVALERR"
    | Some act, Some channel ->
        let w = ctx.world in
        let switches = List.filter (fun k -> named_present ctx args (Printf.sprintf "J%d" k)) [ 1; 2; 3; 4; 5; 6 ] in
        let guided = if switches = [] && not (named_present ctx args "J7") then [ 1; 2; 3; 4; 5; 6 ] else switches in
        let start = W.now w in
        let cycles = ref 0 and last_message = ref start in
        let next_cycle () = start +. (float_of_int !cycles *. act.cycle) in
        let target = ref None and speed = ref None and converged_since = ref None in
        let finished = ref false and failure = ref None in
        p.state <- Running; p.stop_requested <- false;
        let finish_run () = finished := true; p.state <- Connected in
        let cycle now =
          let q = MR.axes_now st ~now in
          let deviation k t = t.(k - 1) -. q.(k - 1) in
          let met = match !target with
            | None -> false
            | Some t -> List.for_all (fun k ->
                let lo, hi = act.minmax.(k - 1) and d = deviation k t in d >= lo && d <= hi) guided in
          p.seqno <- p.seqno + 1;
          let tm = int_of_float (Float.round ((now -. p.setup_time) *. 1000.)) in
          C.send channel (E.encode_robot { E.empty_robot with
                                           r_header = { seqno = Some p.seqno; tm = Some tm; mtype = Some E.mtype_data };
                                           feedback_joints = Some (Array.to_list (Array.sub q 0 6));
                                           feedback_pose = Some (flange st now);
                                           planned_joints = Option.map Array.to_list !target;
                                           motor_on = Some true; mci_running = Some true; convergence_met = Some met;
                                           rapid_running = Some true });
          (* A message that is not an EgmSensor is dropped, as a datagram lost (R-13-egm5). *)
          (match C.receive channel ~within:act.cycle with
           | None -> ()
           | Some bytes -> match E.decode_sensor bytes with
             | Error _ -> ()
             | Ok m ->
                 last_message := now;
                 Option.iter (fun js ->
                     let t = Array.sub q 0 6 in
                     List.iteri (fun i v -> if i < 6 && Float.is_finite v then t.(i) <- v) js;
                     target := Some t) m.set_joints;
                 speed := m.speed_joints);
          let met = match !target with
            | None -> false
            | Some t -> List.for_all (fun k ->
                let lo, hi = act.minmax.(k - 1) and d = deviation k t in d >= lo && d <= hi) guided in
          (if met then (if !converged_since = None then converged_since := Some now) else converged_since := None);
          if p.stop_requested then finish_run ()
          else if W.seconds (now -. !last_message) >= W.seconds p.comm_timeout then begin
            ctx.log "EGMRunJoint: no message from the sensor within \\CommTimeout";
            failure := Some "ERR_UDPUC_COMM"; finish_run ()
          end
          else if (match !converged_since with Some t0 -> W.seconds (now -. t0) >= W.seconds cond_time | None -> false)
          then finish_run ()
          else match !target with
            | None -> ()
            | Some t ->
                let ramp = if ramp_in > 0. then Float.min 1. ((now -. start +. act.cycle) /. ramp_in) else 1. in
                let limit = act.max_speed_deviation *. act.cycle *. ramp in
                let next = Array.copy q in
                List.iter (fun k ->
                    let d = clamp act.max_pos_deviation (deviation k t) in
                    let v = match !speed with Some l when List.length l >= k -> List.nth l (k - 1) | _ -> 0. in
                    let v = if Float.is_finite v then v else 0. in
                    next.(k - 1) <- q.(k - 1) +. clamp limit ((gain *. d) +. (v *. act.cycle))) guided;
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
      | "egmstop" -> stop ctx st args
      | _ -> reset ctx st args)
