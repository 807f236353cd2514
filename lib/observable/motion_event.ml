type t =
  | Segment_planned of {
      time : float; id : int; instruction : string; label : string; zone : string;
      target : Pose.t; joints : float array; ready_time : float; start_time : float; end_time : float }
  | Segment_started of { time : float; id : int; label : string }
  | Segment_ended of { time : float; id : int; label : string }
  | Segment_dropped of { time : float; id : int; label : string }
  | Path_command of { time : float; command : string }
  | Motion_warning of { time : float; text : string }

let to_string = function
  | Segment_planned { time; id; instruction; label; zone; target; ready_time; start_time; end_time; _ } ->
      Printf.sprintf "%.6f s: move %d planned: %s %s %s to [%.2f,%.2f,%.2f], from %.6f s to %.6f s, \
                      program pointer at %.6f s"
        time id instruction label zone target.trans.x target.trans.y target.trans.z start_time end_time ready_time
  | Segment_started { time; id; label } -> Printf.sprintf "%.6f s: move %d (%s) begins" time id label
  | Segment_ended { time; id; label } -> Printf.sprintf "%.6f s: move %d (%s) ends" time id label
  | Segment_dropped { time; id; label } -> Printf.sprintf "%.6f s: move %d (%s) dropped" time id label
  | Path_command { time; command } -> Printf.sprintf "%.6f s: %s" time command
  | Motion_warning { time; text } -> Printf.sprintf "%.6f s: %s" time text

let time = function
  | Segment_planned { time; _ } | Segment_started { time; _ } | Segment_ended { time; _ }
  | Segment_dropped { time; _ } | Path_command { time; _ } | Motion_warning { time; _ } -> time
