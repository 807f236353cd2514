(** A pose of the motion model in floats: a position (mm) and a unit quaternion in ABB's order
    [q1 q2 q3 q4], q1 the scalar part (installed-facts.md §3). {!Rapid_motion_model.Geom} computes
    with it; a motion event carries it. *)

type pos = { x : float; y : float; z : float }
type orient = { q1 : float; q2 : float; q3 : float; q4 : float }
type t = { trans : pos; rot : orient }
