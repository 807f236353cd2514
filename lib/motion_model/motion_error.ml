type t =
  | Out_of_reach
  | Joint_out_of_range of int
  | Configuration_error
  | Close_to_singularity
  | Circle_uncertain
  | Invalid_speed of string
  | Robhold_conflict
  | Path_level of string
  | External_out_of_range of string

let name = function
  | Out_of_reach -> "position outside reach"
  | Joint_out_of_range k -> Printf.sprintf "joint %d out of range" k
  | Configuration_error -> "configuration error"
  | Close_to_singularity -> "close to singularity"
  | Circle_uncertain -> "circle uncertain: the circle point is too close to the start or end \
                         point, or on their line"
  | Invalid_speed m -> "invalid speed: " ^ m
  | Path_level m -> m
  | External_out_of_range n -> Printf.sprintf "external axis %s out of range" n
  | Robhold_conflict -> "the tool and the work object cannot both be held (or both not be held) \
                         by the robot"

let errnum = function
  | Out_of_reach | Joint_out_of_range _ | Configuration_error | Close_to_singularity
  | External_out_of_range _ -> Some "ERR_ROBLIMIT"
  | _ -> None
