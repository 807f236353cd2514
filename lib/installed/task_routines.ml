(* The installed routines of several tasks (ch. 14): who the task is, meeting other tasks, and
   the instructions a task without a robot may not run. The routines' other halves (shared
   persistents, the clock) are the scheduler's (Task_set) and the world's. *)

module V = Value
module W = Rapid_controller.World
open Primitive

let same = Rapid_typing.Types.same_name  (* without lowered copies: every call site asks [modelled] *)

(* R-14-e: the instructions that move the robot or act on its path; in a task that is not the
   motion task they raise ERR_NOT_MOVETASK. *)
let motion_instructions = [
  "MoveL"; "MoveJ"; "MoveC"; "MoveAbsJ"; "MoveLDO"; "MoveJDO"; "MoveExtJ"; "SearchL"; "StopMove";
  "StartMove"; "StopMoveReset"; "ClearPath"; "StorePath"; "RestoPath"; "WaitRob"; "StartMoveRetry";
]

let names = [ "GetTaskName"; "WaitSyncTask"; "SyncMoveOn"; "SyncMoveOff"; "SyncMoveUndo"; "IsSyncMoveOn" ]

let modelled name = List.exists (same name) names

(* The task names of a PERS tasks array (system.sys: RECORD tasks string taskname). *)
let task_list = function
  | Location (box, i, _) -> (
      match box.(i) with
      | V.Array es ->
          (* R-14-f-empty: an entry left "" (a list declared larger than the cell) names no task. *)
          Some (List.filter (( <> ) "")
                  (Array.to_list (Array.map (function V.Record [| V.String s |] -> s | _ -> "") es)))
      | _ -> None)
  | _ -> None

(* A synchronisation point (R-14-f, R-14-m): the point is the syncident object's name, the same
   in every task. Each task counts its arrivals; the wait ends when every task of the list has
   arrived as often as this one. With [in_pos] the task arrives only once its robot stands
   still. [met] runs when the tasks have met, not on a time-out. *)
let meet ~standstill ctx args ~instruction ~tasks ~in_pos ~timeout_error ~met =
  let w = ctx.world in
  let point = Option.value (ctx.argument_label "SyncID") ~default:"" in
  let installed = W.task_names w in
  if List.exists (fun t -> not (List.exists (same t) installed)) tasks then Some (Failed "ERR_TASKNAME")
  else
    match named_num ctx args "TimeOut" with
    | Some t when t < 0. || not (Float.is_finite t) -> Some (Failed "ERR_ARGVALERR")
    | timeout ->
        let reached t = W.seconds (W.now w) >= W.seconds t in
        let round = ref 0 in
        let arrive () =
          if !round > 0 then true
          else
            let t = standstill () in
            if (not in_pos) || t = neg_infinity || reached t then (round := W.sync_arrive w point; true)
            else (W.wake_at w t; false) in
        let satisfied () = arrive () && List.for_all (fun t -> W.sync_arrivals w point ~task:t >= !round) tasks in
        let deadline = Option.map (fun t -> W.now w +. t) timeout in
        if satisfied () then (met (); Some (Returned None))
        else
          Some (Wait { W.what = Printf.sprintf "the tasks %s at %s (%s)" (String.concat ", " tasks) point instruction;
                       satisfied; deadline; poll = None;
                       finish = (fun ~timed_out ->
                           if timed_out then Rapid_observable.Wait.error timeout_error else (met (); None)) })

let call ?(standstill = fun () -> neg_infinity) ctx name args =
  let w = ctx.world in
  (* Every primitive call passes here: in the motion task, only the routines of this module
     (10 to 12 characters long) need a look. *)
  let n = String.length name in
  if W.motion_task w && (n < 10 || n > 12) then None
  else if (not (W.motion_task w)) && List.exists (same name) motion_instructions then Some (Failed "ERR_NOT_MOVETASK")
  else if same name "GetTaskName" then begin
    (* R-14-d: \TaskNo the task's own number; \MecTaskNo the motion task's name and number. *)
    if named_present ctx args "MecTaskNo" then begin
      let members = List.mapi (fun i n -> (i + 1, n)) (W.task_names w) in
      let motion_name = if W.motion_task w then W.task_name w else
          (match List.find_opt (fun (_, n) -> n <> W.task_name w) members with
           | Some (_, n) -> n | None -> W.task_name w) in
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
    match task_list (named_argument ctx args "TaskList") with
    | None -> Some (Failed "ERR_ARGVALERR")
    | Some tasks ->
        (* \InPos in the motion task: the robot stands still before the task arrives (R-14-f). *)
        let in_pos = named_present ctx args "InPos" && W.motion_task w in
        meet ~standstill ctx args ~instruction:"WaitSyncTask" ~tasks ~in_pos ~timeout_error:"ERR_WAITSYNCTASK"
          ~met:ignore
  end
  else if same name "SyncMoveOn" then begin
    (* R-14-m: a synchronisation point as WaitSyncTask's, at which the robot stands still; the
       task is then in synchronized movement with the tasks of the list. *)
    match task_list (named_argument ctx args "TaskList") with
    | None -> Some (Failed "ERR_ARGVALERR")
    | Some _ when W.sync_move w <> None -> Some (Failed "ERR_SYNCMOVEON")
    | Some tasks ->
        meet ~standstill ctx args ~instruction:"SyncMoveOn" ~tasks ~in_pos:(W.motion_task w)
          ~timeout_error:"ERR_SYNCMOVEON" ~met:(fun () -> W.set_sync_move w (Some tasks))
  end
  else if same name "SyncMoveOff" then begin
    (* R-14-m: the tasks of SyncMoveOn's list meet again, and each goes back to independent
       movement. *)
    match W.sync_move w with
    | None -> Some (Failed "ERR_SYNCMOVEOFF")
    | Some tasks ->
        meet ~standstill ctx args ~instruction:"SyncMoveOff" ~tasks ~in_pos:(W.motion_task w)
          ~timeout_error:"ERR_SYNCMOVEOFF" ~met:(fun () -> W.set_sync_move w None)
  end
  else if same name "SyncMoveUndo" then begin
    (* R-14-m: independent movement at once, meeting no one. *)
    W.set_sync_move w None; Some (Returned None)
  end
  else if same name "IsSyncMoveOn" then Some (Returned (Some (V.Bool (W.sync_move w <> None))))
  else None
