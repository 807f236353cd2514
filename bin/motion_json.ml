(* The motion events of a run as JSON (doc/trace-format.md, "Motion events"). *)

module MP = Rapid_installed.Motion_routines

(* Virtual times to the microsecond, lengths to the micrometre, angles to the microdegree. *)
let fixed digits x =
  (* -0 is written 0. *)
  if Float.is_finite x then
    let text = Printf.sprintf "%.*f" digits x in
    `Intlit (if Float.abs x < 0.5 *. (10. ** float_of_int (- digits)) then String.sub text (if x < 0. then 1 else 0) (String.length text - if x < 0. then 1 else 0) else text)
  else `Null

let time = fixed 6

let pose (p : Rapid_motion_model.Geom.pose) =
  `Assoc [ ("trans", `List [ fixed 3 p.trans.x; fixed 3 p.trans.y; fixed 3 p.trans.z ]);
           ("rot", `List [ fixed 6 p.rot.q1; fixed 6 p.rot.q2; fixed 6 p.rot.q3; fixed 6 p.rot.q4 ]) ]

let event (e : Rapid_observable.Motion_event.t) : Yojson.Safe.t =
  match e with
  | Segment_planned { time = t; id; instruction; label; zone; target; joints; ready_time; start_time; end_time } ->
      `Assoc [ ("event", `String "move-planned"); ("time", time t); ("move", `Int id);
               ("instruction", `String instruction); ("target", `String label); ("zone", `String zone);
               ("pose", pose target); ("joints", `List (Array.to_list (Array.map (fixed 4) joints)));
               ("start", time start_time); ("end", time end_time); ("ready", time ready_time) ]
  | Segment_started { time = t; id; label } ->
      `Assoc [ ("event", `String "move-started"); ("time", time t); ("move", `Int id); ("target", `String label) ]
  | Segment_ended { time = t; id; label } ->
      `Assoc [ ("event", `String "move-ended"); ("time", time t); ("move", `Int id); ("target", `String label) ]
  | Segment_dropped { time = t; id; label } ->
      `Assoc [ ("event", `String "move-dropped"); ("time", time t); ("move", `Int id); ("target", `String label) ]
  | Path_command { time = t; command } ->
      `Assoc [ ("event", `String "path-command"); ("time", time t); ("command", `String command) ]
  | Motion_warning { time = t; text } ->
      `Assoc [ ("event", `String "motion-warning"); ("time", time t); ("text", `String text) ]

(* A TCP sample (--samples HZ). *)
let sample t (p : Rapid_motion_model.Geom.pose) joints : Yojson.Safe.t =
  `Assoc ([ ("event", `String "tcp-sample"); ("time", time t); ("pose", pose p) ]
          @ (match joints with
              | Some q -> [ ("joints", `List (Array.to_list (Array.map (fixed 4) q))) ]
              | None -> []))
