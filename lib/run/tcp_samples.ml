module MP = Rapid_installed.Motion_routines
module MM = Rapid_motion_model

type sample = { time : float; pose : Rapid_observable.Pose.t; joints : float array option }

let max_samples = 200_000

let check = function
  | Some hz when not (hz > 0. && hz <= 10_000.) ->
      Error "rapid-sem: --samples takes a rate above 0 and at most 10000 Hz"
  | _ -> Ok ()

type t = { hz : float; mutable next : int; mutable capped : bool; on_capped : unit -> unit }

let create ?(on_capped = ignore) hz = { hz; next = 0; capped = false; on_capped }

let until s motion until =
  let p = MP.planner motion in
  let out = ref [] in
  let rec go () =
    let t = float_of_int s.next /. s.hz in
    if t <= until +. 1e-9 && s.next < max_samples then begin
      let joints = match MM.Planner.joints_at p t with Ok q -> Some q | Error _ -> None in
      out := { time = t; pose = MM.Planner.pose_at p t; joints } :: !out;
      s.next <- s.next + 1; go ()
    end in
  go ();
  if s.next >= max_samples && not s.capped then begin
    s.capped <- true;
    s.on_capped ()
  end;
  List.rev !out

let final s (outcome : Outcome.t) (w : Run.world) =
  let stop = MM.Planner.finished_by (MP.planner w.motion) in
  let now = Rapid_controller.World.now w.controller in
  let stop = Float.min stop (Rapid_controller.World.max_time w.controller) in
  if outcome = Ended && Float.is_finite stop then until s w.motion (Float.max now stop)
  else until s w.motion now
