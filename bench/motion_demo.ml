(* A small RAPID-like motion program, planned by the motion model and written out as the path
   SVG, the timeline SVG and CSV (doc/motion.md, "Output"). bench/motion-screenshot.sh renders
   the SVGs in a headless browser, to check that they read well.

   motion_demo.exe DIR   writes DIR/path.svg, DIR/timeline.svg, DIR/path.csv *)

open Rapid_motion_model

let down = { Geom.q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. }
let target x y z = { Frames.pose = { Geom.trans = { x; y; z }; rot = down };
                     conf = { Kinematics.cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } }
let speed n = Option.get (Motion_data.find Motion_data.speeddata n)
let zone n = Option.get (Motion_data.find Motion_data.zonedata n)

let () =
  let dir = if Array.length Sys.argv > 1 then Sys.argv.(1) else "." in
  let k = Kinematics.create Robot.irb120 in
  let p = Planner.create ~joints:[| 0.; 0.; 0.; 0.; 90.; 0. |] k in
  let now = ref 0. in
  let go label m =
    match Planner.plan p ~now:!now { m with Planner.label } with
    | Ok r -> now := Float.max !now r.ready_time
    | Error e -> prerr_endline (label ^ ": " ^ Motion_error.name e); exit 1 in
  go "pApproach" (Planner.move (speed "v500") (zone "z20") (Joint (target 350. (-150.) 350.)));
  go "p10" (Planner.move (speed "v200") (zone "z10") (Linear (target 350. (-150.) 250.)));
  go "p20" (Planner.move (speed "v200") (zone "z50") (Linear (target 450. (-150.) 250.)));
  go "p30" (Planner.move (speed "v200") (zone "z50") (Linear (target 450. 50. 250.)));
  go "p40" (Planner.move (speed "v100") (zone "z10")
              (Circular (target 400. 120. 250., target 330. 50. 250.)));
  go "p50" (Planner.move (speed "v200") (zone "fine") (Linear (target 330. (-100.) 250.)));
  go "pDepart" (Planner.move (speed "v500") (zone "fine") (Linear (target 330. (-100.) 380.)));
  let write name s =
    let oc = open_out_bin (Filename.concat dir name) in
    output_string oc s; close_out oc in
  write "path.svg" (Path_output.path_svg ~title:"TCP path of the demo program (IRB 120, tool0)" p);
  write "timeline.svg" (Path_output.timeline_svg ~title:"Timeline of the demo program" p);
  write "path.csv" (Path_output.csv ~step:0.05 p)
