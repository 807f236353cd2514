(** The planned path as a robot programmer reads it (doc/motion.md, "Output"): the TCP path as
    SVG (top view x–y beside side view x–z, programmed points labelled, corner paths in their own
    colour), a timeline SVG (moves, corners and standstills against time, with the TCP speed),
    and CSV samples. *)

val csv : ?step:float -> Planner.t -> string
(** One line per [step] seconds (default 0.01) from 0 to the end of the path, and one at the
    end: [t,x,y,z,q1,q2,q3,q4,j1,j2,j3,j4,j5,j6] (s, mm, quaternion, degrees), then a column per
    external axis of the robot, named eax_a … eax_f (mm or degrees; none for a robot without).
    Axis angles that cannot be computed are left empty. A path longer than {!csv_max_rows}
    steps is sampled at its length over {!csv_max_rows} instead. *)

val csv_max_rows : int

val path_svg : ?title:string -> Planner.t -> string
(** The TCP path in the world frame, two views; the robot's base (a triangle, class
    [robot-base]) where the cell mounts it, when its base frame is not the world's (law F-base). *)

(** What the program did, for the timeline: the program pointer waiting (a move, WaitTime, ...),
    traps, signal changes (a mark at [m_from]). *)
val tcp_speeds : ?samples:int -> ?until:float -> Planner.t -> (float * float) array
(** The TCP speed (mm/s) at [samples] (default 600) times from 0 to [until] (default the end of
    the path): the mid time of each sample's window, the distance over it within one moving
    piece of the path (the tool of the move under way), 0 where the robot stands still. *)

val nice_axis : float -> float * float
(** The step (1, 2 or 5 times a power of ten) and the top of an axis from 0 to at least the
    given maximum with 4 to 8 ticks above 0. *)

type lane = Waits | Traps | Signals

type mark = { lane : lane; m_from : float; m_to : float; m_label : string }

val timeline_svg : ?title:string -> ?program:mark list -> Planner.t -> string
(** Moves (labelled by their target), corner paths and standstills against time, and the TCP
    speed below them; with [program], three lanes below: waits, traps, signal changes. *)
