open Geom
open Motion_data

type robtarget = { pose : pose; conf : Kinematics.conf }

let object_frame w = pmult w.uframe w.oframe

let flange_of_target tool wobj target =
  match tool.tool_robhold, wobj.wobj_robhold with
  | true, false -> Ok (pmult (pmult (object_frame wobj) target) (pinv tool.tframe))
  | false, true -> Ok (pmult tool.tframe (pinv (pmult (object_frame wobj) target)))
  | _ -> Error Motion_error.Robhold_conflict

let target_of_flange tool wobj flange =
  match tool.tool_robhold, wobj.wobj_robhold with
  | true, false -> Ok (pmult (pinv (object_frame wobj)) (pmult flange tool.tframe))
  | false, true -> Ok (pinv (pmult (pmult (pinv tool.tframe) flange) (object_frame wobj)))
  | _ -> Error Motion_error.Robhold_conflict

(* R-4.1-o: with a stationary tool the robot carries the work object, whose frame is then the
   TCP of a robot-held tool: the flange is at tframe · (W · target)⁻¹ = (tframe · target⁻¹) · W⁻¹,
   a robot-held tool W reaching tframe · target⁻¹ in the world. *)
let as_robot_held tool wobj =
  match tool.tool_robhold, wobj.wobj_robhold with
  | false, true ->
      Some ({ tool with tool_robhold = true; tframe = object_frame wobj }, Motion_data.wobj0,
            fun target -> pmult tool.tframe (pinv target))
  | _ -> None

(* Laws F-base and X-track: the base is not the world frame; robtargets stay in the world. *)
let on_base base f = match base with None -> f | Some b -> pmult b f
let off_base base f = match base with None -> f | Some b -> pmult (pinv b) f

let calc_rob_t ?base k joints tool wobj =
  Result.map (fun pose -> { pose; conf = Kinematics.conf_of k joints })
    (target_of_flange tool wobj (on_base base (Kinematics.forward k joints)))

let calc_joint_t ?base k (t : robtarget) tool wobj =
  Result.bind (flange_of_target tool wobj t.pose) (fun f ->
      Kinematics.inverse k (off_base base f) (Kinematics.With_conf t.conf))

let c_rob_t ?base k ~joints tool wobj = calc_rob_t ?base k joints tool wobj
let c_pos ?base k ~joints tool wobj = Result.map (fun r -> r.pose.trans) (c_rob_t ?base k ~joints tool wobj)
