(** The time of a move (doc/motion.md, "Time"): the default constant-speed profile. A move
    takes the time its most limiting speed component needs; there is no acceleration phase. *)

type velset = { override : float; max : float }
(** VelSet Override Max: programmed speeds (and \T times) scaled by Override %, the TCP speed
    capped at Max mm/s. *)

val velset_default : velset
(** 100 %, 5000 mm/s (VelSet's value at a cold start; UNCERTAIN). *)

type speed_limit = { check_point : float option; axes : (int * float) list }
(** SpeedLimCheckPoint RobSpeed (mm/s, the TCP standing for every checkpoint) and SpeedLimAxis
    AxisSpeed for axis AxisNo (1-6; degrees/s, mm/s for a linear axis): the limits that apply
    while the system input LimitSpeed is active (ABB, RAPID Instructions; doc/rulings.md
    R-13-speedlim1). [None] or no entry: that speed is not limited. *)

val no_speed_limit : speed_limit

val limited_time : speed_limit -> length:float -> deltas:float array -> float
(** The least time a move of TCP path [length] (mm) and axis travels [deltas] (Δq_i, axis i at
    index i-1) takes under the limits: max(length / RobSpeed, |Δq_i| / AxisSpeed_i); 0 when
    nothing is limited. *)

type timing = { speed : Motion_data.speeddata; v : float option; t : float option }
(** A move's Speed argument with its \V (replaces v_tcp) and \T (the whole time, s). *)

val tcp_speed : Robot.t -> velset -> timing -> float
(** The TCP speed the move is planned with: min(v_tcp (or \V) · Override/100, Max,
    MaxRobSpeed). *)

val cartesian : Robot.t -> velset -> timing -> length:float -> angle:float ->
  (float, Motion_error.t) result
(** MoveL, MoveC (law T-cartesian): max(L / v_tcp', θ / v_ori') with θ in degrees,
    v_ori' = v_ori · Override/100; with \T: T · 100/Override. *)

val joint : Robot.t -> velset -> timing -> deltas:float array -> length:float -> angle:float ->
  (float, Motion_error.t) result
(** MoveJ, MoveAbsJ (law T-joint): max over the axes of |Δq_i| / axis speed_i, and not less
    than the Cartesian law of the TCP's chord [length] and reorientation [angle]; with \T:
    T · 100/Override. *)
