(* The motion model's benchmark (bench/README.md, "The motion model"): a generated CAD-style path
   of 100,000 MoveL and MoveC with fly-by zones is planned and timed by Planner, as a program
   would hand the moves over (each at the time the program pointer leaves the one before).

   Reported: moves planned per second of processor time, the simulated robot time over the
   processor time (how much faster than real time the model runs), pose queries per second, and
   the peak resident set. Targets (the issue): 100,000 moves/s or more, 10,000x real time or
   more.

   motion_bench.exe [--moves N] [--conf-l] *)

open Rapid_motion_model
open Geom

let cpu () = let t = Unix.times () in t.tms_utime +. t.tms_stime

let vm_hwm_kb () =
  let ic = open_in "/proc/self/status" in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () ->
      let rec find () =
        match input_line ic with
        | l when String.length l > 6 && String.sub l 0 6 = "VmHWM:" ->
            Scanf.sscanf (String.sub l 6 (String.length l - 6)) " %d kB" Fun.id
        | _ -> find ()
        | exception End_of_file -> 0 in
      find ())

(* A deterministic CAD path: contours of a pocket on a plate in front of the robot, milled in
   passes 1 mm deeper each; straight edges (MoveL, 2 to 40 mm) and rounded corners (MoveC), the
   tool tilted a little from vertical as CAM output does; zones z1 to z10, speeds v100 to v400. *)
let generate n =
  let rng = Random.State.make [| 2026 |] in
  let speeds = Array.map (fun s -> Option.get (Motion_data.find Motion_data.speeddata s)) [| "v100"; "v200"; "v300"; "v400" |] in
  let zones = Array.map (fun s -> Option.get (Motion_data.find Motion_data.zonedata s)) [| "z1"; "z5"; "z10" |] in
  let conf = { Kinematics.cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } in
  let down = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } in
  let tilt () = normalize (omult down (of_axis_angle { x = Random.State.float rng 1. -. 0.5; y = Random.State.float rng 1. -. 0.5; z = 0. }
                                        (rad (Random.State.float rng 5.)))) in
  let tg p = { Frames.pose = { trans = p; rot = tilt () }; conf } in
  let cx = 370. and cy = 0. in
  let angle = ref 0. and pass = ref 0 in
  let point a depth r = { x = cx +. r *. cos a; y = cy +. r *. sin a; z = 300. -. depth } in
  Array.init n (fun i ->
      let depth = float_of_int (!pass mod 60) in
      let r = 60. +. 40. *. sin (3. *. !angle) in
      let speed = speeds.(i / 500 mod 4) and zone = zones.(i mod 3) in
      let step = (2. +. Random.State.float rng 38.) /. r in
      let motion =
        if i mod 4 = 3 then begin
          let mid = point (!angle +. step /. 2.) depth (r +. 3.) in
          angle := !angle +. step;
          Planner.Circular (tg mid, tg (point !angle depth (60. +. 40. *. sin (3. *. !angle))))
        end else begin
          angle := !angle +. step;
          Planner.Linear (tg (point !angle depth (60. +. 40. *. sin (3. *. !angle))))
        end in
      if !angle > 8. *. atan 1. then (angle := 0.; incr pass);
      Planner.move speed zone motion)

let () =
  let n = ref 100_000 and conf_l = ref false in
  Arg.parse [ ("--moves", Arg.Set_int n, "N  number of moves (default 100000)");
              ("--conf-l", Arg.Set conf_l, " plan with ConfL \\On (default \\Off, as CAD output)") ]
    (fun _ -> ()) "motion_bench.exe [--moves N] [--conf-l]";
  (* The collector's pace of `rapid-sem run` (bin/main.ml), which will run the planner: the
     path planned is kept, so marking it again and again is wasted work. *)
  Gc.set { (Gc.get ()) with space_overhead = 400 };
  let base = vm_hwm_kb () in
  let moves = generate !n in
  let kin = Kinematics.create Robot.irb120 in
  let p = Planner.create ~joints:[| 0.; 20.; 10.; 0.; 60.; 0. |] kin in
  (Planner.settings p).conf_l <- !conf_l;
  Gc.compact ();
  let w0 = Unix.gettimeofday () and c0 = cpu () in
  let now = ref 0. and failures = ref 0 in
  Array.iteri (fun i m ->
      match Planner.plan p ~now:!now m with
      | Ok r -> now := Float.max !now r.ready_time; if r.warnings <> [] then incr failures
      | Error e -> Printf.eprintf "move %d: %s\n" i (Motion_error.name e); exit 1) moves;
  let cpu_s = cpu () -. c0 and wall = Unix.gettimeofday () -. w0 in
  let robot_time = Planner.finished_by p in
  let q = 1_000_000 in
  let c1 = cpu () in
  let acc = ref 0. in
  for i = 0 to q - 1 do
    acc := !acc +. (Planner.pose_at p (robot_time *. float_of_int i /. float_of_int q)).trans.x
  done;
  ignore (Sys.opaque_identity !acc);
  let qcpu = cpu () -. c1 in
  let pieces = List.length (Planner.pieces p) in
  Printf.printf "moves planned            %d (MoveL 75 %%, MoveC 25 %%, zones z1-z10, ConfL %s)\n" !n
    (if !conf_l then "\\On" else "\\Off");
  Printf.printf "pieces of path           %d (corner path failures: %d)\n" pieces !failures;
  Printf.printf "planning                 %.3f s processor, %.3f s wall\n" cpu_s wall;
  Printf.printf "moves per second         %.0f (processor), %.0f (wall)   target >= 100000\n"
    (float_of_int !n /. cpu_s) (float_of_int !n /. wall);
  Printf.printf "simulated robot time     %.1f s = %.0f x the processor time   target >= 10000\n"
    robot_time (robot_time /. cpu_s);
  Printf.printf "pose_at queries          %.0f per second (processor)\n" (float_of_int q /. qcpu);
  Printf.printf "peak resident set        %d KB (%d KB above the start)\n" (vm_hwm_kb ()) (vm_hwm_kb () - base);
  let words x = Obj.reachable_words (Obj.repr x) in
  Printf.printf "planner's data           %.1f MB (%.0f bytes per move); the generated moves %.1f MB\n"
    (float_of_int (words p * 8) /. 1e6) (float_of_int (words p * 8) /. float_of_int !n)
    (float_of_int (words moves * 8) /. 1e6)
