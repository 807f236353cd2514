(* The installed routines of several tasks (ch. 14): who the task is, meeting other tasks, and
   the instructions a task without a robot may not run. The routines' other halves (shared
   persistents, the clock) are the scheduler's (Task_set) and the world's. *)

module V = Value
module W = Rapid_controller.World
open Primitive

let same a b = String.lowercase_ascii a = String.lowercase_ascii b

(* R-14-e: the instructions that move the robot or act on its path; in a task that is not the
   motion task they raise ERR_NOT_MOVETASK. *)
let motion_instructions = [
  "MoveL"; "MoveJ"; "MoveC"; "MoveAbsJ"; "MoveLDO"; "MoveJDO"; "MoveExtJ"; "SearchL"; "StopMove";
  "StartMove"; "StopMoveReset"; "ClearPath"; "StorePath"; "RestoPath"; "WaitRob"; "StartMoveRetry";
]

let names = [ "GetTaskName"; "WaitSyncTask" ]

let modelled name = List.exists (same name) names

(* The task names of a PERS tasks array (system.sys: RECORD tasks string taskname). *)
let task_list = function
  | Location (box, i, _) -> (
      match box.(i) with
      | V.Array es ->
          Some (Array.to_list (Array.map (function V.Record [| V.String s |] -> s | _ -> "") es))
      | _ -> None)
  | _ -> None

let call ?(standstill = fun () -> neg_infinity) ctx name args =
  let w = ctx.world in
  (* Every primitive call passes here: in the motion task, only the two routines of this module
     (11 and 12 characters long) need a look. *)
  let n = String.length name in
  if W.motion_task w && n <> 11 && n <> 12 then None
  else if (not (W.motion_task w)) && List.exists (same name) motion_instructions then Some (Failed "ERR_NOT_MOVETASK")
  else if same name "GetTaskName" then begin
    (* R-14-d: \TaskNo the task's own number; \MecTaskNo the motion task's name and number. *)
    if named_present ctx args "MecTaskNo" then begin
      let members = List.mapi (fun i n -> (i + 1, n)) (W.task_names w) in
      let motion_name = if W.motion_task w then W.task_name w else
          (match List.find_opt (fun (_, n) -> n <> W.task_name w) members with Some (_, n) -> n | None -> W.task_name w) in
      let number = match List.find_opt (fun (_, n) -> n = motion_name) members with Some (k, _) -> k | None -> 1 in
      named_store ctx args "MecTaskNo" (V.num (float_of_int number));
      Some (Returned (Some (V.String motion_name)))
    end
    else begin
      named_store ctx args "TaskNo" (V.num (float_of_int (W.task_number w)));
      Some (Returned (Some (V.String (W.task_name w))))
    end
  end
  else if same name "WaitSyncTask" then begin
    (* The meeting point is the syncident object's name: the same name in every task (R-14-f). *)
    let point = Option.value (ctx.argument_label "SyncID") ~default:"" in
    match task_list (named_argument ctx args "TaskList") with
    | None -> Some (Failed "ERR_ARGVALERR")
    | Some tasks ->
        let installed = W.task_names w in
        if List.exists (fun t -> not (List.exists (same t) installed)) tasks then Some (Failed "ERR_TASKNAME")
        else begin
          (* \InPos in the motion task: the robot stands still before the task arrives (R-14-f). *)
          let in_pos = named_present ctx args "InPos" && W.motion_task w in
          let reached t = W.seconds (W.now w) >= W.seconds t in
          let round = ref 0 in
          let arrive () =
            if !round > 0 then true
            else
              let t = standstill () in
              if (not in_pos) || t = neg_infinity || reached t then (round := W.sync_arrive w point; true)
              else (W.wake_at w t; false) in
          let satisfied () = arrive () && List.for_all (fun t -> W.sync_arrivals w point ~task:t >= !round) tasks in
          let deadline = Option.map (fun t -> W.now w +. t) (named_num ctx args "TimeOut") in
          match named_num ctx args "TimeOut" with
          | Some t when t < 0. || not (Float.is_finite t) -> Some (Failed "ERR_ARGVALERR")
          | _ ->
              if satisfied () then Some (Returned None)
              else
                Some (Wait { W.what = Printf.sprintf "the tasks %s at %s (WaitSyncTask)" (String.concat ", " tasks) point;
                             satisfied; deadline; poll = None;
                             finish = (fun ~timed_out -> if timed_out then Some "ERR_WAITSYNCTASK" else None) })
        end
  end
  else None
