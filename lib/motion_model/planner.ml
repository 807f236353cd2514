open Geom

type motion =
  | Linear of Frames.robtarget
  | Circular of Frames.robtarget * Frames.robtarget
  | Joint of Frames.robtarget
  | Abs_joint of float array
  | External_only

type move = {
  motion : motion; timing : Profile.timing; zone : Motion_data.zonedata; z : float option;
  inpos : Motion_data.stoppointdata option; conc : bool; tool : Motion_data.tooldata;
  wobj : Motion_data.wobjdata; label : string; eax : float array;
}

let move ?v ?t ?z ?inpos ?(conc = false) ?(tool = Motion_data.tool0) ?(wobj = Motion_data.wobj0)
    ?(label = "") ?(eax = Array.make 6 Ext_axes.unused) speed zone motion =
  { motion; timing = { Profile.speed; v; t }; zone; z; inpos; conc; tool; wobj; label; eax }

type settings = {
  mutable velset : Profile.velset; mutable conf_l : bool; mutable conf_j : bool;
  mutable sing_area_wrist : bool; mutable look_ahead : float;
  mutable speed_limit : Profile.speed_limit option;
}

type warning = Corner_path_failure of int
type planned = { id : int; ready_time : float; warnings : warning list }

(* ------------------------------------------------------------------ segments *)

type geometry =
  | Line of pos * pos
  | Arc of { centre : pos; e1 : pos; e2 : pos; radius : float; sweep : float }
  | Joints of float array * float array

(* A programmed segment, whole: s runs over [0, 1] in [duration] seconds from [t_start] (path
   time), at constant speed. *)
type segment = {
  id : int; label : string; kind : string; geometry : geometry;
  rot0 : orient; rot1 : orient; q_start : float array; q_end : float array; tframe : pose;
  f : figures; fine : bool; end_tcp : pos;
}

(* All floats: one flat block, not six boxes (the queue holds one per move). *)
and figures = {
  length : float; angle : float; duration : float; t_start : float; zone_tcp : float; zone_ori : float;
  lin_delta : float; rot_delta : float;  (* the largest linear (mm) and rotating (deg) external axis travel *)
  zone_leax : float; zone_reax : float;
}

(* The planner's axis vectors are twelve long: the arm's six axes, then extjoint's eax_a … eax_f
   (9E9 for an axis the robot does not have, constant, so interpolation keeps it exact). *)
(* Literals, not Array.sub, init and append: each of those is a call into the runtime, and a move
   takes a dozen of these vectors apart or puts them together. *)
let arm q = [| q.(0); q.(1); q.(2); q.(3); q.(4); q.(5) |]
(* An unused component stays exactly 9E9 through interpolation's rounding. *)
let ext q =
  let e = [| q.(6); q.(7); q.(8); q.(9); q.(10); q.(11) |] in
  for i = 0 to 5 do if Ext_axes.is_unused e.(i) then e.(i) <- Ext_axes.unused done;
  e
let join q e =
  if Array.length e <> 6 then Array.append (Array.sub q 0 6) e
  else [| q.(0); q.(1); q.(2); q.(3); q.(4); q.(5); e.(0); e.(1); e.(2); e.(3); e.(4); e.(5) |]

(* The flange in the world: through the robot's base frame (law F-base), which a track moves
   (law X-track). *)
let world_flange k q =
  let f = Kinematics.forward k (arm q) in
  match Base_frame.in_world (Kinematics.robot k) (ext q) with
  | None -> f
  | Some b -> pmult b f

let base_inverse k e flange =
  match Base_frame.in_world (Kinematics.robot k) e with
  | None -> flange
  | Some b -> pmult (pinv b) flange

let lerp_q a b s = Array.init (Array.length a) (fun i -> a.(i) +. s *. (b.(i) -. a.(i)))

let tcp_of_flange f tframe = pmult f tframe

let seg_pos k sg s =
  match sg.geometry with
  | Line (p0, p1) -> lerp p0 p1 s
  | Arc a ->
      let th = s *. a.sweep in
      add a.centre (add (scale (a.radius *. cos th) a.e1) (scale (a.radius *. sin th) a.e2))
  | Joints (q0, q1) -> (tcp_of_flange (world_flange k (lerp_q q0 q1 s)) sg.tframe).trans

let seg_pose k sg s =
  match sg.geometry with
  | Joints (q0, q1) -> tcp_of_flange (world_flange k (lerp_q q0 q1 s)) sg.tframe
  | _ -> { trans = seg_pos k sg s; rot = slerp sg.rot0 sg.rot1 s }

(* Axis angles on a Cartesian path: the solution nearest the straight joint-space line between
   the segment's ends, which keeps the arm in one configuration along a segment. *)
let joints_of_tcp k tcp tframe reference =
  let e = ext reference in
  Result.map (fun q -> join q e)
    (Kinematics.inverse k (base_inverse k e (pmult tcp (pinv tframe))) (Kinematics.Nearest (arm reference)))

let seg_joints k sg s =
  match sg.geometry with
  | Joints (q0, q1) -> Ok (lerp_q q0 q1 s)
  | _ -> joints_of_tcp k (seg_pose k sg s) sg.tframe (lerp_q sg.q_start sg.q_end s)

(* ------------------------------------------------------------------ pieces *)

type shape =
  | Part of segment  (* the parameter is the segment's s *)
  | Blend of { a : segment; b : segment; fa : float; fb : float }
      (* The Bezier's control points are A at 1 - fa, A's programmed point, B at fb: computed
         when asked, not kept (the queue holds one corner per fly-by point). *)
  | Joint_blend of { a : segment; b : segment; j0 : float array; j1 : float array;
                     j2 : float array }

(* The parameter goes linearly from p0 at t0 to p1 at t1 (path time). *)
type span = { t0 : float; mutable t1 : float; p0 : float; mutable p1 : float }
type piece = { tm : span; shape : shape }

let param pc tp =
  if pc.tm.t1 <= pc.tm.t0 then pc.tm.p1
  else
    let tau = Float.max 0. (Float.min 1. ((tp -. pc.tm.t0) /. (pc.tm.t1 -. pc.tm.t0))) in
    pc.tm.p0 +. (pc.tm.p1 -. pc.tm.p0) *. tau

let bezier a b c u = add (add (scale ((1. -. u) *. (1. -. u)) a) (scale (2. *. u *. (1. -. u)) b)) (scale (u *. u) c)
let bezier_q a b c u = Array.init (Array.length a) (fun i ->
    (1. -. u) *. (1. -. u) *. a.(i) +. 2. *. u *. (1. -. u) *. b.(i) +. u *. u *. c.(i))

let blend_tframe (a : segment) (b : segment) u =
  { trans = lerp a.tframe.trans b.tframe.trans u; rot = slerp a.tframe.rot b.tframe.rot u }

let piece_pose k pc u =
  match pc.shape with
  | Part sg -> seg_pose k sg u
  | Blend b ->
      let ua = 1. -. b.fa in
      { trans = bezier (seg_pos k b.a ua) b.a.end_tcp (seg_pos k b.b b.fb) u;
        rot = slerp (slerp b.a.rot0 b.a.rot1 ua) (slerp b.b.rot0 b.b.rot1 b.fb) u }
  | Joint_blend b -> tcp_of_flange (world_flange k (bezier_q b.j0 b.j1 b.j2 u)) (blend_tframe b.a b.b u)

let piece_joints k pc u =
  match pc.shape with
  | Part sg -> seg_joints k sg u
  | Blend b ->
      let qa = lerp_q b.a.q_start b.a.q_end (1. -. b.fa) and qb = lerp_q b.b.q_start b.b.q_end b.fb in
      joints_of_tcp k (piece_pose k pc u) (blend_tframe b.a b.b u) (bezier_q qa b.a.q_end qb u)
  | Joint_blend b -> Ok (bezier_q b.j0 b.j1 b.j2 u)

(* ------------------------------------------------------------------ growable arrays *)

(* A growable array whose oldest elements can be forgotten: indices are absolute, from [first v]
   (how many were forgotten) to [stop v - 1], so forgetting the front keeps the others' indices
   (the open segment's piece, the move ids). What is forgotten is given back when it grows. *)
module Vec = struct
  type 'a t = { mutable data : 'a array; mutable start : int; mutable len : int; mutable first : int }
  let create () = { data = [||]; start = 0; len = 0; first = 0 }
  let first v = v.first
  let stop v = v.first + v.len
  let push v x =
    if v.start + v.len = Array.length v.data then begin
      let d = Array.make (max 16 (2 * v.len)) x in
      Array.blit v.data v.start d 0 v.len;
      v.data <- d;
      v.start <- 0
    end;
    v.data.(v.start + v.len) <- x;
    v.len <- v.len + 1
  (* Inlined: the walks through the queue call it for every piece they pass. *)
  let get v i =
    if i < v.first || i >= v.first + v.len then invalid_arg "Planner.Vec.get";
    v.data.(v.start + i - v.first)
  [@@inline]
  let truncate v n = if n < stop v then v.len <- max 0 (n - v.first)
  let forget_before v n =
    let k = min v.len (n - v.first) in
    if k > 0 then begin
      (* The slots forgotten hold the newest element, which is kept anyway. *)
      Array.fill v.data v.start k v.data.(v.start + v.len - 1);
      v.start <- v.start + k; v.len <- v.len - k; v.first <- v.first + k
    end
end

(* ------------------------------------------------------------------ the planner *)

(* A pause of the path, real time, and how long the pauses before it lasted. *)
type pause = { ts : float; te : float; before : float }

(* One path level: its queue, and its own clock of StopMove pauses. *)
type level = {
  start_joints : float array;
  pieces : piece Vec.t;
  mutable end_joints : float array;  (* where the queue leaves the robot *)
  mutable end_flange : pose;
  mutable end_time : float;  (* path time from which the robot stands at the end of the queue *)
  mutable open_seg : (segment * int) option;  (* the last segment if fly-by: its Part's index *)
  pauses : pause Vec.t;  (* StopMove … StartMove, real time, oldest first *)
  mutable paused_before : float;  (* how long the pauses forgotten lasted *)
  mutable stopped_at : float option;
  mutable marks : mark list;  (* the marks on this level's path not yet released (law T-distance) *)
}

(* A moment of a level's path where a trigger acts (law T-distance): its path time [p], and
   [limit], the path time up to which the robot must get on the move for it to count (the
   event's own time, or the move's end for an event delayed beyond it). *)
and mark = { m_level : level; m_p : float; m_limit : float; mutable m_dropped : bool }

(* A move planned: its segment, the path time at which the program may leave it, the same as
   answered by plan (for a move of a level dropped since), and the level it was planned on. *)
type entry = {
  seg : segment; ready : float; ready_real : float; level : level;
  motion_from : float;  (* path time at which the move's motion begins: its incoming corner, or its part *)
}

type t = {
  kin : Kinematics.t;
  settings : settings;
  moves : entry Vec.t;  (* by move id; a run without history forgets the old ones (forget) *)
  mutable forgotten_ready : float;  (* the latest ready time of a move forgotten *)
  mutable cur : level;
  mutable stored : level option;  (* path level 1, kept by StorePath while level 2 runs *)
}

let new_level kin joints ~from =
  { start_joints = Array.copy joints; pieces = Vec.create (); end_joints = Array.copy joints;
    end_flange = world_flange kin joints; end_time = from; open_seg = None; pauses = Vec.create (); paused_before = 0.;
    stopped_at = None; marks = [] }

let create ?(joints = Array.make 6 0.) kin =
  let joints = join joints (Ext_axes.initial (Kinematics.robot kin).externals) in
  let cur = new_level kin joints ~from:0. in
  { kin; settings = { velset = Profile.velset_default; conf_l = true; conf_j = true;
                      sing_area_wrist = false; look_ahead = 0.1;
                      speed_limit = None };
    moves = Vec.create (); forgotten_ready = neg_infinity; cur; stored = None }

let settings t = t.settings
let kinematics t = t.kin
let stopped t = t.cur.stopped_at <> None

(* The last pause [starts] puts before [x], by bisection (the pauses are in time order), or -1. *)
let last_pause (l : level) starts x =
  let lo = ref (Vec.first l.pauses) and hi = ref (Vec.stop l.pauses - 1) and best = ref (-1) in
  while !lo <= !hi do
    let mid = (!lo + !hi) / 2 in
    if starts (Vec.get l.pauses mid) < x then (best := mid; lo := mid + 1) else hi := mid - 1
  done;
  !best

(* Virtual time less the time the robot stood by StopMove: the time the path runs on. *)
let path_time (l : level) real =
  let p = match last_pause l (fun pz -> pz.ts) real with
    | -1 -> real -. l.paused_before
    | k -> let pz = Vec.get l.pauses k in real -. pz.before -. Float.max 0. (Float.min real pz.te -. pz.ts) in
  match l.stopped_at with Some ts when real > ts -> p -. (real -. ts) | _ -> p

let real_time (l : level) path =
  (* A pause begins at path time ts - before; a later path time comes after all of it. *)
  let r = match last_pause l (fun pz -> pz.ts -. pz.before) path with
    | -1 -> path +. l.paused_before
    | k -> let pz = Vec.get l.pauses k in path +. pz.before +. (pz.te -. pz.ts) in
  match l.stopped_at with
  | Some ts when path > path_time l ts +. 1e-12 -> infinity
  | _ -> r

let ( let* ) = Result.bind

(* An axis the arm does not have (a palletiser's 4 and 5) is not checked: MoveAbsJ sets it to 0. *)
let check_range (r : Robot.t) q =
  let bad = ref None in
  Array.iteri (fun i a ->
      let ax = r.axes.(i) in
      if !bad = None && Robot.present r (i + 1) && (a < ax.min -. 1e-9 || a > ax.max +. 1e-9) then
        bad := Some (i + 1)) q;
  match !bad with None -> Ok () | Some k -> Error (Motion_error.Joint_out_of_range k)

(* The circle through three points (law G-circle): centre from the two perpendicular bisector
   planes and the points' plane, a 3x3 system solved by LU decomposition (GSL). *)
let circle s c e =
  let u = sub c s and v = sub e s in
  let n = cross u v in
  let scale_ = norm u *. norm v in
  if norm u < 0.1 || norm v < 0.1 || distance c e < 0.1 || norm n < 1e-6 *. scale_ then
    Error Motion_error.Circle_uncertain
  else
    let m = [| [| u.x; u.y; u.z |]; [| v.x; v.y; v.z |]; [| n.x; n.y; n.z |] |] in
    let rhs = [| (dot c c -. dot s s) /. 2.; (dot e e -. dot s s) /. 2.; dot n s |] in
    match Gsl.Linalg.solve_LU ~protect:true (`AA m) (`A rhs) with
    | exception Gsl.Error.Gsl_exn _ -> Error Motion_error.Circle_uncertain
    | x when not (Array.for_all Float.is_finite x) -> Error Motion_error.Circle_uncertain
    | x ->
    let centre = { x = x.(0); y = x.(1); z = x.(2) } in
    let radius = distance s centre in
    let e1 = scale (1. /. radius) (sub s centre) in
    let e2 = scale (1. /. norm n) (cross n e1) in
    let angle p = let d = sub p centre in
      let a = atan2 (dot d e2) (dot d e1) in if a < 0. then a +. 8. *. atan 1. else a in
    Ok (Arc { centre; e1; e2; radius; sweep = angle e })

(* The share of a segment's length a zone of [zr] mm (or [zo] degrees when the TCP does not
   move) may take, at most half the segment (law Z-clip). *)
(* When neither the TCP moves nor its orientation changes (MoveExtJ), the external axes' zones
   (zone_leax, zone_reax) against their travel (law X-zone). *)
let side_fraction ?(ext = (0., 0., 0., 0.)) ~length ~angle zr zo =
  let lin, rot, zl, zx = ext in
  if length > 0. then Float.min 0.5 (zr /. length)
  else if angle > 0. then Float.min 0.5 (zo /. angle)
  else if lin > 0. || rot > 0. then
    Float.min 0.5 (Float.min (if lin > 0. then zl /. lin else infinity) (if rot > 0. then zx /. rot else infinity))
  else 0.

let ext_of (g : figures) (z : figures) = (g.lin_delta, g.rot_delta, z.zone_leax, z.zone_reax)

let corner_fractions (a : segment) (b : segment) =
  if a.f.length > 0. && b.f.length > 0. then
    let r = Float.min a.f.zone_tcp (Float.min (a.f.length /. 2.) (b.f.length /. 2.)) in
    (r /. a.f.length, r /. b.f.length)
  else
    (side_fraction ~ext:(ext_of a.f a.f) ~length:a.f.length ~angle:a.f.angle a.f.zone_tcp a.f.zone_ori,
     side_fraction ~ext:(ext_of b.f a.f) ~length:b.f.length ~angle:b.f.angle a.f.zone_tcp a.f.zone_ori)

(* A stationary tool: the robot carries the work object along the same flange poses
   (Frames.as_robot_held, R-4.1-o). *)
let robot_held m =
  match Frames.as_robot_held m.tool m.wobj with
  | None -> m
  | Some (tool, wobj, f) ->
      let rt (r : Frames.robtarget) = { r with pose = f r.pose } in
      let motion = match m.motion with
        | Linear r -> Linear (rt r)
        | Circular (c, r) -> Circular (rt c, rt r)
        | Joint r -> Joint (rt r)
        | (Abs_joint _ | External_only) as a -> a in
      { m with tool; wobj; motion }

let build t ~now_p m id =
  let k = t.kin and st = t.settings in
  let robot = Kinematics.robot k in
  let m = robot_held m in
  if not m.tool.tool_robhold then Error Motion_error.Robhold_conflict
  else if m.wobj.wobj_robhold then Error Motion_error.Robhold_conflict
  else
    let tframe = m.tool.tframe in
    let q_start = t.cur.end_joints in
    let start = tcp_of_flange t.cur.end_flange tframe in
    let w = Frames.object_frame m.wobj in
    let world (rt : Frames.robtarget) = pmult w { rt.pose with rot = normalize rt.pose.rot } in
    (* Where the external axes end (law X-target): MoveC's CirPoint gives none of its own. *)
    let* e_end = Ext_axes.resolve robot.externals ~from:(ext q_start) m.eax in
    let goal_joints rt choice =
      let* f = Frames.flange_of_target m.tool m.wobj { rt.Frames.pose with rot = normalize rt.Frames.pose.rot } in
      let choice = match choice with Kinematics.Nearest r -> Kinematics.Nearest (arm r) | c -> c in
      let* q = Kinematics.inverse k (base_inverse k e_end f) choice in
      Ok (join q e_end, f) in
    (* Linear and circular moves: ConfL and SingArea at the programmed point. *)
    let cartesian_end (rt : Frames.robtarget) =
      let* q, f = goal_joints rt (Kinematics.Nearest q_start) in
      let* q =
        if st.conf_l then
          let c = Kinematics.conf_of k q and want = Kinematics.significant k rt.conf in
          if c.cfx <> want.cfx then Error Motion_error.Configuration_error
          else if c.cf1 = want.cf1 && c.cf4 = want.cf4 && c.cf6 = want.cf6 then Ok q
          else let* qc, _ = goal_joints rt (Kinematics.With_conf rt.conf) in Ok qc
        else Ok q in
      if (not st.sing_area_wrist) && Kinematics.wrist_singular k q then Error Motion_error.Close_to_singularity
      else Ok (q, f) in
    let* kind, geometry, rot1, q_end, f_end =
      match m.motion with
      | Linear rt ->
          let* q, f = cartesian_end rt in
          let g = world rt in
          Ok ("MoveL", Line (start.trans, g.trans), g.rot, q, f)
      | Circular (cir, rt) ->
          let* q, f = cartesian_end rt in
          let g = world rt in
          let* arc = circle start.trans (world cir).trans g.trans in
          Ok ("MoveC", arc, g.rot, q, f)
      | Joint rt ->
          let choice = if st.conf_j then Kinematics.With_conf rt.conf else Kinematics.Nearest q_start in
          let* q, f = goal_joints rt choice in
          Ok ("MoveJ", Joints (q_start, q), (tcp_of_flange f tframe).rot, q, f)
      | Abs_joint q ->
          if Array.length q <> 6 || Array.exists (fun a -> not (Float.is_finite a)) q then
            Error (Motion_error.Joint_out_of_range 1)
          else
            let* () = check_range robot q in
            let q = Array.mapi (fun i a -> if Robot.present robot (i + 1) then a else 0.) q in
            let q = join q e_end in
            let f = world_flange k q in
            (* a delta's arms may stand where no plate joins their rods *)
            if Float.is_nan f.trans.x then Error Motion_error.Out_of_reach else
            Ok ("MoveAbsJ", Joints (q_start, q), (tcp_of_flange f tframe).rot, Array.copy q, f)
      | External_only ->
          let q = join q_start e_end in
          let f = world_flange k q in
          Ok ("MoveExtJ", Joints (q_start, q), (tcp_of_flange f tframe).rot, Array.copy q, f)
    in
    let end_tcp = (tcp_of_flange f_end tframe).trans in
    let length = match geometry with
      | Line (p0, p1) -> distance p0 p1
      | Arc a -> a.radius *. a.sweep
      | Joints _ -> distance start.trans end_tcp in
    let angle = deg (angle_between start.rot rot1) in
    (* MoveExtJ programs no TCP: what the track does to it is not its length (law X-zone). *)
    let length, angle = if m.motion = External_only then (0., 0.) else (length, angle) in
    let* duration =
      match geometry with
      | Joints _ when m.motion = External_only ->
          (* MoveExtJ: the external axes' law alone (below), or \T. *)
          Profile.joint robot st.velset m.timing ~deltas:(Array.make 6 0.) ~length:0. ~angle:0.
      | Joints (q0, q1) ->
          Profile.joint robot st.velset m.timing ~deltas:(Array.init 6 (fun i -> q1.(i) -. q0.(i))) ~length ~angle
      | _ -> Profile.cartesian robot st.velset m.timing ~length ~angle in
    (* Law X-time: the external axes move in the same time; \T gives the whole time. *)
    let* duration =
      if m.timing.t <> None then Ok duration
      else
        let sp = m.timing.speed in
        let* te = Ext_axes.time robot.externals ~override:st.velset.override ~v_leax:sp.v_leax
            ~v_reax:sp.v_reax ~from:(ext q_start) e_end in
        Ok (Float.max duration te) in
    (* The speed limitation while LimitSpeed is active (R-13-speedlim1): no faster than the
       TCP's and the axes' limits allow, \T or not. *)
    let duration = match st.speed_limit with
      | None -> duration
      | Some lim ->
          let n = min 6 (min (Array.length q_start) (Array.length q_end)) in
          let deltas = Array.init n (fun i -> q_end.(i) -. q_start.(i)) in
          Float.max duration (Profile.limited_time lim ~length ~deltas) in
    let* () =
      if Float.is_finite duration && Float.is_finite length then Ok ()
      else Error (Motion_error.Invalid_speed "the move's time is not a finite number") in
    let fine = m.zone.finep || m.inpos <> None in
    let travel kind = List.fold_left (fun acc (x : Ext_axes.axis) ->
        if x.kind = kind then Float.max acc (Float.abs (e_end.(x.index) -. q_start.(6 + x.index))) else acc)
        0. robot.externals in
    let f = { length; angle; duration; t_start = now_p;
              zone_tcp = (if fine then 0. else Option.value m.z ~default:m.zone.pzone_tcp);
              zone_ori = (if fine then 0. else m.zone.zone_ori);
              lin_delta = travel Ext_axes.Linear; rot_delta = travel Ext_axes.Rotating;
              zone_leax = (if fine then 0. else m.zone.zone_leax);
              zone_reax = (if fine then 0. else m.zone.zone_reax) } in
    Ok ({ id; label = m.label; kind; geometry; rot0 = start.rot; rot1; q_start; q_end; tframe; f; fine;
          end_tcp }, f_end)

let push_piece t pc = if pc.tm.t1 > pc.tm.t0 || pc.tm.p1 <> pc.tm.p0 then Vec.push t.cur.pieces pc

let plan t ~now m =
  let now_p = path_time t.cur now in
  let id = Vec.stop t.moves in
  let* sg, f_end = build t ~now_p m id in
  let warnings = ref [] in
  (* Where the segment starts in time, and the corner into it (law Z-corner). *)
  let sg, own_from, motion_from =
    match t.cur.open_seg with
    | None -> let ts = Float.max now_p t.cur.end_time in ({ sg with f = { sg.f with t_start = ts } }, 0., ts)
    | Some (a, idx) ->
        let fa, fb = corner_fractions a sg in
        let a_end = a.f.t_start +. a.f.duration in
        let tc0 = a.f.t_start +. (1. -. fa) *. a.f.duration in
        if now_p > tc0 +. 1e-9 then begin
          (* Too late for the corner: the fly-by point becomes a stop point. *)
          warnings := [ Corner_path_failure a.id ];
          let ts = Float.max now_p a_end in
          ({ sg with f = { sg.f with t_start = ts } }, 0., ts)
        end else begin
          let sg = { sg with f = { sg.f with t_start = a_end } } in
          let tc1 = a_end +. fb *. sg.f.duration in
          if fa > 0. || fb > 0. then begin
            (* A's own piece, if it has one (a move of no time has none), now ends at the zone. *)
            if idx >= 0 then begin
              let pa = Vec.get t.cur.pieces idx in
              pa.tm.p1 <- 1. -. fa;
              pa.tm.t1 <- tc0;
              if pa.tm.t1 <= pa.tm.t0 then Vec.truncate t.cur.pieces idx
            end;
            let k = t.kin in
            let shape =
              match a.geometry, sg.geometry with
              | Joints _, _ | _, Joints _ ->
                  let j s g = match seg_joints k s g with Ok q -> q | Error _ -> lerp_q s.q_start s.q_end g in
                  Joint_blend { a; b = sg; j0 = j a (1. -. fa); j1 = a.q_end; j2 = j sg fb }
              | _ ->
                  Blend { a; b = sg; fa; fb }
            in
            push_piece t { tm = { t0 = tc0; t1 = tc1; p0 = 0.; p1 = 1. }; shape }
          end;
          (sg, fb, tc0)
        end
  in
  let t_end = sg.f.t_start +. sg.f.duration in
  let idx = Vec.stop t.cur.pieces in
  push_piece t
    { tm = { t0 = sg.f.t_start +. own_from *. sg.f.duration; t1 = t_end; p0 = own_from; p1 = 1. }; shape = Part sg };
  let arrive_ready =
    match m.inpos with
    | None -> t_end
    | Some sp ->
        (match sp.stop_type with
         | Motion_data.Inpos -> t_end +. sp.inpos_mintime
         | Stoptime -> t_end +. sp.stoptime
         | Fllwtime -> Float.max now_p (t_end -. sp.followtime)) in
  let ready =
    if m.conc then Float.max now_p motion_from
    else if sg.fine then arrive_ready
    else
      let fmax =
        side_fraction ~ext:(ext_of sg.f sg.f) ~length:sg.f.length ~angle:sg.f.angle sg.f.zone_tcp sg.f.zone_ori in
      Float.max now_p (sg.f.t_start +. (1. -. fmax) *. sg.f.duration -. t.settings.look_ahead)
  in
  t.cur.end_joints <- sg.q_end;
  t.cur.end_flange <- f_end;
  t.cur.end_time <- (if sg.fine then Float.max t_end arrive_ready else t_end);
  let idx = if Vec.stop t.cur.pieces > idx then idx else -1 in
  t.cur.open_seg <- (if sg.fine then None else Some (sg, idx));
  let ready_time = real_time t.cur ready in
  Vec.push t.moves { seg = sg; ready; ready_real = ready_time; level = t.cur; motion_from };
  Ok { id; ready_time; warnings = !warnings }

let ready_time t id =
  if id < 0 || id >= Vec.stop t.moves then invalid_arg "Planner.ready_time: unknown move"
  else if id < Vec.first t.moves then t.forgotten_ready
  else
    let e = Vec.get t.moves id in
    let live = e.level == t.cur || (match t.stored with Some s -> e.level == s | None -> false) in
    if live then real_time e.level e.ready else e.ready_real

(* The last piece that has begun by path time [tp], or -1; the oldest kept if pieces were
   forgotten (a time before them is not asked). *)
let find t tp =
  let first = Vec.first t.cur.pieces in
  let lo = ref first and hi = ref (Vec.stop t.cur.pieces - 1) and best = ref (if first > 0 then first else -1) in
  while !lo <= !hi do
    let mid = (!lo + !hi) / 2 in
    if (Vec.get t.cur.pieces mid).tm.t0 <= tp then (best := mid; lo := mid + 1) else hi := mid - 1
  done;
  !best

let pose_at t real =
  let tp = path_time t.cur real in
  match find t tp with
  | -1 -> tcp_of_flange (world_flange t.kin t.cur.start_joints) Motion_data.tool0.tframe
  | i -> let pc = Vec.get t.cur.pieces i in piece_pose t.kin pc (param pc tp)

let axes_at t real =
  let tp = path_time t.cur real in
  match find t tp with
  | -1 -> Ok (Array.copy t.cur.start_joints)
  | i ->
      let pc = Vec.get t.cur.pieces i in
      let u = param pc tp in
      (* The ends of a Part are exact: the programmed point's own solution. *)
      match pc.shape with
      | Part sg when u >= 1. -> Ok (Array.copy sg.q_end)
      | _ -> piece_joints t.kin pc u

let joints_at t real = Result.map arm (axes_at t real)

(* The external axes need no inverse kinematics: they follow the path's parameter (law
   X-interp), also where the arm cannot follow a straight path. *)
let external_at t real =
  let tp = path_time t.cur real in
  match find t tp with
  | -1 -> Ok (ext t.cur.start_joints)
  | i ->
      let pc = Vec.get t.cur.pieces i in
      let u = param pc tp in
      Ok (ext (match pc.shape with
          | Part sg when u >= 1. -> sg.q_end
          | Part sg -> lerp_q sg.q_start sg.q_end u
          | Blend b ->
              let qa = lerp_q b.a.q_start b.a.q_end (1. -. b.fa) and qb = lerp_q b.b.q_start b.b.q_end b.fb in
              bezier_q qa b.a.q_end qb u
          | Joint_blend b -> bezier_q b.j0 b.j1 b.j2 u))

let finished_by t = real_time t.cur t.cur.end_time

let stop t ~at = if t.cur.stopped_at = None then t.cur.stopped_at <- Some at

let start t ~at =
  match t.cur.stopped_at with
  | Some ts ->
      let before = match Vec.stop t.cur.pauses with
        | 0 -> 0.
        | n when n = Vec.first t.cur.pauses -> t.cur.paused_before
        | n -> let pz = Vec.get t.cur.pauses (n - 1) in pz.before +. (pz.te -. pz.ts) in
      Vec.push t.cur.pauses { ts; te = Float.max ts at; before };
      t.cur.stopped_at <- None
  | None -> ()

let clear t ~at =
  let tp = path_time t.cur at in
  let q = match axes_at t at with Ok q -> q | Error _ -> t.cur.end_joints in
  let i = find t tp in
  Vec.truncate t.cur.pieces (i + 1);
  if i >= 0 then begin
    let pc = Vec.get t.cur.pieces i in
    if pc.tm.t1 > tp then (pc.tm.p1 <- param pc tp; pc.tm.t1 <- tp)
  end;
  if tp < t.cur.end_time then begin
    t.cur.end_joints <- q;
    t.cur.end_flange <- world_flange t.kin q;
    t.cur.end_time <- tp
  end;
  t.cur.open_seg <- None;
  (* A trigger the robot does not get to on this path any more goes with it. *)
  List.iter (fun m -> if tp < m.m_limit then m.m_dropped <- true) t.cur.marks;
  t.cur.marks <- List.filter (fun m -> not m.m_dropped) t.cur.marks

type piece_kind = Segment of int | Corner of int * int | Still
type piece_info = { t_from : float; t_to : float; kind : piece_kind }

let pieces t =
  let out = ref [] and last = ref 0. in
  for i = Vec.first t.cur.pieces to Vec.stop t.cur.pieces - 1 do
    let pc = Vec.get t.cur.pieces i in
    if pc.tm.t0 > !last +. 1e-9 then
      out := { t_from = real_time t.cur !last; t_to = real_time t.cur pc.tm.t0; kind = Still } :: !out;
    let kind = match pc.shape with
      | Part sg -> Segment sg.id
      | Blend b -> Corner (b.a.id, b.b.id)
      | Joint_blend b -> Corner (b.a.id, b.b.id) in
    out := { t_from = real_time t.cur pc.tm.t0; t_to = real_time t.cur pc.tm.t1; kind } :: !out;
    last := pc.tm.t1
  done;
  List.rev !out

type segment_info = {
  seg_id : int; seg_label : string; seg_kind : string; target : pos;
  seg_fine : bool; seg_length : float; seg_duration : float;
}

let segments t =
  let first = Vec.first t.moves in
  List.init (Vec.stop t.moves - first) (fun i ->
      let s = (Vec.get t.moves (first + i)).seg in
      { seg_id = s.id; seg_label = s.label; seg_kind = s.kind; target = s.end_tcp; seg_fine = s.fine;
        seg_length = s.f.length; seg_duration = s.f.duration })

let path_level t = if t.stored = None then 1 else 2

let store_path t ~at =
  match t.stored with
  | Some _ -> Error (Motion_error.Path_level "StorePath: a path is stored already (path level 2)")
  | None ->
      let l1 = t.cur in
      let q = match axes_at t at with Ok q -> q | Error _ -> l1.end_joints in
      stop t ~at;
      t.stored <- Some l1;
      t.cur <- new_level t.kin q ~from:at;
      Ok ()

let resto_path t ~at:_ =
  match t.stored with
  | None -> Error (Motion_error.Path_level "RestoPath: no path is stored (path level 1)")
  | Some l1 ->
      List.iter (fun m -> m.m_dropped <- true) t.cur.marks;
      t.cur.marks <- [];
      t.cur <- l1; t.stored <- None; Ok ()

let target_joints t id =
  if id < Vec.first t.moves || id >= Vec.stop t.moves then invalid_arg "Planner.target_joints: unknown move"
  else arm (Vec.get t.moves id).seg.q_end

let target_external t id =
  if id < Vec.first t.moves || id >= Vec.stop t.moves then invalid_arg "Planner.target_external: unknown move"
  else ext (Vec.get t.moves id).seg.q_end

let base t e = Base_frame.in_world (Kinematics.robot t.kin) e

(* A piece's oldest and newest move ids, each by itself: the walks below ask for them on every
   piece they pass, seven walks a move, and a pair would be an allocation each time. *)
let piece_oldest pc = match pc.shape with Part sg -> sg.id | Blend b -> b.a.id | Joint_blend b -> b.a.id
let piece_newest pc = match pc.shape with Part sg -> sg.id | Blend b -> b.b.id | Joint_blend b -> b.b.id

(* Pieces are in time order and segment ids grow with time: the first piece of a move is found by
   bisection on the pieces' newest ids, and its pieces follow it. *)
let first_piece pcs id =
  let lo_i = ref (Vec.first pcs) and hi_i = ref (Vec.stop pcs) in
  while !lo_i < !hi_i do
    let mid = (!lo_i + !hi_i) / 2 in
    if piece_newest (Vec.get pcs mid) < id then lo_i := mid + 1 else hi_i := mid
  done;
  !lo_i

let segment_span t id =
  let pcs = t.cur.pieces in
  let lo = ref infinity and hi = ref neg_infinity in
  let i = ref (first_piece pcs id) and stop = Vec.stop pcs in
  while !i < stop && piece_oldest (Vec.get pcs !i) <= id do
    let pc = Vec.get pcs !i in
    let oldest = piece_oldest pc and newest = piece_newest pc in
    if newest = id || oldest = id then begin
      lo := Float.min !lo pc.tm.t0;
      (* The corner after the move is not its own: it ends where its corner begins. *)
      if newest = id then hi := Float.max !hi pc.tm.t1 else hi := Float.max !hi pc.tm.t0
    end;
    incr i
  done;
  if !lo = infinity then None else Some (real_time t.cur !lo, real_time t.cur !hi)

(* [segment_span t id <> None] without the span's real times: whether a piece of the queue is
   the move's. *)
let has_segment t id =
  let pcs = t.cur.pieces in
  let i = ref (first_piece pcs id) and stop = Vec.stop pcs and found = ref false in
  while (not !found) && !i < stop && piece_oldest (Vec.get pcs !i) <= id do
    let pc = Vec.get pcs !i in
    if piece_newest pc = id || piece_oldest pc = id then found := true;
    incr i
  done;
  !found

(* [segment_span] for several moves in one walk back through the queue: a check of the moves
   still running asks for all of them at once, and one walk per move made that quadratic in
   the moves queued (a long path of zone points). A piece counts for a move as long as no later
   piece is wholly older than the move, which is where [segment_span]'s walk stops. *)
let segment_spans t ids =
  let spans = Hashtbl.create 16 in
  List.iter (fun id -> Hashtbl.replace spans id (infinity, neg_infinity)) ids;
  let oldest = List.fold_left min max_int ids in
  let rec back i runmin =
    if i >= Vec.first t.cur.pieces && runmin >= oldest then begin
      let pc = Vec.get t.cur.pieces i in
      let pids = match pc.shape with
        | Part sg -> [ sg.id ] | Blend b -> [ b.a.id; b.b.id ] | Joint_blend b -> [ b.a.id; b.b.id ] in
      let runmin = min runmin (List.fold_left max min_int pids) in
      List.iter (fun id ->
          if id <= runmin then
            match Hashtbl.find_opt spans id with
            | Some (lo, hi) ->
                let ends_here =
                  match pc.shape with Part _ -> true | Blend b -> b.b.id = id | Joint_blend b -> b.b.id = id in
                let hi = if ends_here then Float.max hi pc.tm.t1 else Float.max hi pc.tm.t0 in
                Hashtbl.replace spans id (Float.min lo pc.tm.t0, hi)
            | None -> ()) (List.sort_uniq compare pids);
      back (i - 1) runmin
    end in
  back (Vec.stop t.cur.pieces - 1) max_int;
  fun id -> match Hashtbl.find_opt spans id with
    | Some (lo, hi) when lo <> infinity -> Some (real_time t.cur lo, real_time t.cur hi)
    | _ -> None

let point_time t id =
  let corner = ref None and own_end = ref None in
  let rec back i =
    if i >= Vec.first t.cur.pieces then begin
      let pc = Vec.get t.cur.pieces i in
      let newest = match pc.shape with
        | Part sg -> sg.id | Blend b -> b.b.id | Joint_blend b -> b.b.id in
      (match pc.shape with
       | (Blend { a; _ } | Joint_blend { a; _ }) when a.id = id -> corner := Some ((pc.tm.t0 +. pc.tm.t1) /. 2.)
       | Part sg when sg.id = id -> own_end := Some pc.tm.t1
       | _ -> ());
      if newest >= id then back (i - 1)
    end in
  back (Vec.stop t.cur.pieces - 1);
  match !corner, !own_end with
  | Some c, _ -> Some (real_time t.cur c)
  | None, Some e -> Some (real_time t.cur e)
  | None, None -> None

let is_open t id = match t.cur.open_seg with Some (sg, _) -> sg.id = id | None -> false

(* Without history (doc/motion.md, "Memory"): what lies wholly before [before] and concerns only
   moves older than [keep] is given back. The newest piece stays (where the robot stands), and so
   do the open segment's piece, the pieces that time [before] and later need, and every move whose
   ready time has not passed. Pauses that have ended are merged into one, which answers the same
   for every time after them. *)
let forget t ~before ~keep =
  let l = t.cur in
  let hp = path_time l before in
  let pcs = l.pieces in
  let open_idx = match l.open_seg with Some (_, i) when i >= 0 -> i | _ -> max_int in
  let rec drop i =
    if i + 1 < Vec.stop pcs && i < open_idx && piece_newest (Vec.get pcs i) < keep
       && (Vec.get pcs (i + 1)).tm.t0 <= hp then drop (i + 1)
    else i in
  Vec.forget_before pcs (drop (Vec.first pcs));
  let rec drop_moves () =
    let id = Vec.first t.moves in
    if id < keep && id + 1 < Vec.stop t.moves then begin
      let r = ready_time t id in
      if r <= before then begin
        t.forgotten_ready <- Float.max t.forgotten_ready r;
        Vec.forget_before t.moves (id + 1);
        drop_moves ()
      end
    end in
  drop_moves ();
  let rec drop_pauses () =
    let k = Vec.first l.pauses in
    if k < Vec.stop l.pauses && (Vec.get l.pauses k).te < before then begin
      let pz = Vec.get l.pauses k in
      l.paused_before <- pz.before +. (pz.te -. pz.ts);
      Vec.forget_before l.pauses (k + 1);
      drop_pauses ()
    end in
  drop_pauses ()

(* ------------------------------------------------------------------ triggers on the path *)

(* Law T-distance: the segment's own time law places a distance along it, s = d / L from its
   start (from its end with [from_end]), clamped to the segment; a move that does not move the
   TCP (L = 0) is at its start for 0 from the start and at its end for any other distance (and
   the other way round from the end). [shift] moves the moment in path time (a lag, a delay);
   it is never before the move's motion begins. *)
let mark_of ?(from_end = false) ?(shift = 0.) t id d =
  if id < Vec.first t.moves || id >= Vec.stop t.moves then invalid_arg "Planner.mark: unknown move";
  let e = Vec.get t.moves id in
  let f = e.seg.f in
  let s =
    if f.length > 0. then Float.max 0. (Float.min 1. (d /. f.length))
    else if d > 0. then 1. else 0. in
  let s = if from_end then 1. -. s else s in
  let own_end = f.t_start +. f.duration in
  let p = Float.max e.motion_from (f.t_start +. s *. f.duration +. shift) in
  { m_level = e.level; m_p = p; m_limit = Float.min p own_end; m_dropped = false }

let real_mark_time t m =
  let live = m.m_level == t.cur || (match t.stored with Some s -> s == m.m_level | None -> false) in
  if m.m_dropped || not live then None else Some (real_time m.m_level m.m_p)

let time_at_distance ?from_end ?shift t id d = real_mark_time t (mark_of ?from_end ?shift t id d)

let mark ?from_end ?shift t id d =
  let m = mark_of ?from_end ?shift t id d in
  m.m_level.marks <- m :: m.m_level.marks;
  m

let mark_time = real_mark_time

let release _ m = m.m_level.marks <- List.filter (fun x -> x != m) m.m_level.marks

let segment_length t id =
  if id < Vec.first t.moves || id >= Vec.stop t.moves then invalid_arg "Planner.segment_length: unknown move"
  else (Vec.get t.moves id).seg.f.length

let segment_speed t id =
  if id < Vec.first t.moves || id >= Vec.stop t.moves then invalid_arg "Planner.segment_speed: unknown move"
  else
    let f = (Vec.get t.moves id).seg.f in
    if f.duration > 0. then f.length /. f.duration else 0.
