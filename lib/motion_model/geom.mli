(** Float-level geometry of the motion model: positions (mm), unit quaternions in ABB's order
    [q1 q2 q3 q4] (q1 the scalar part, installed-facts.md §3 "Geometry types", CONFIRMED) and
    poses. The num-level RAPID functions PoseMult, PoseInv, PoseVect, OrientZYX, EulerZYX,
    NOrient and Distance live in lib/semantics/library.ml; these are the model's own, in floats. *)

type pos = Rapid_observable.Pose.pos = { x : float; y : float; z : float }
type orient = Rapid_observable.Pose.orient = { q1 : float; q2 : float; q3 : float; q4 : float }
type pose = Rapid_observable.Pose.t = { trans : pos; rot : orient }

val origin : pos
val unit_orient : orient
val identity : pose

(** {1 Vectors} *)

val add : pos -> pos -> pos
val sub : pos -> pos -> pos
val scale : float -> pos -> pos
val dot : pos -> pos -> float
val cross : pos -> pos -> pos
val norm : pos -> float
val distance : pos -> pos -> float
val lerp : pos -> pos -> float -> pos
(** [lerp a b s] = a + s (b - a). *)

(** {1 Rotations} *)

val deg : float -> float
(** Radians to degrees. *)

val rad : float -> float
(** Degrees to radians. *)

val omult : orient -> orient -> orient
(** Quaternion product. *)

val conj : orient -> orient
val normalize : orient -> orient
val rotate : orient -> pos -> pos
(** [rotate q v]: v turned by q. *)

val of_axis_angle : pos -> float -> orient
(** Rotation about an axis (need not be unit) by an angle in radians. *)

val to_matrix : orient -> float array
(** Row-major 3x3 rotation matrix. *)

val of_matrix : float array -> orient
(** Unit quaternion of a row-major 3x3 rotation matrix, with q1 > 0 (or, when q1 = 0, its first
    non-zero component positive): one quaternion for each orientation. *)

val angle_between : orient -> orient -> float
(** The reorientation angle from one orientation to the other, in radians, in [0, pi]: the
    angle of the shortest rotation (q and -q are the same orientation). *)

val slerp : orient -> orient -> float -> orient
(** Spherical linear interpolation along the shortest arc, at constant angular speed in s. *)

(** {1 Poses} *)

val pmult : pose -> pose -> pose
val pinv : pose -> pose
val pvect : pose -> pos -> pos

(** {1 Position functions of the installed library (ABB: RAPID Instructions, Functions and Data
    types)} *)

val offs : pose -> float -> float -> float -> pose
(** Offs(Point, XOffset, YOffset, ZOffset): the displacement added in the object frame; the
    orientation is unchanged. *)

val rel_tool : pose -> float -> float -> float -> ?rx:float -> ?ry:float -> ?rz:float -> unit -> pose
(** RelTool(Point, Dx, Dy, Dz [\Rx] [\Ry] [\Rz]): the displacement in the tool frame of Point;
    rotations in degrees, first about x, then about the new y, then the new z. *)

val mir_pos : point:pose -> plane:pose -> ?wobj:pose -> ?mir_y:bool -> unit -> pose
(** MirPos(Point, MirPlane [\WObj] [\MirY]): Point (in the frame [wobj], world if absent) mirrored
    in the xy-plane of [plane] (uframe · oframe of MirPlane, in world). Without \MirY the tool
    frame's x and z axes are mirrored (y follows), with \MirY its y and z axes (x follows). *)
