(* Externally Guided Motion (issue 18): the protocol buffer codec of the EGM messages
   (lib/controller/egm_protocol.ml) and a joint-mode EGM program end to end, with a sensor of
   this test on the loopback (test/drivers/EgmJoint.mod). *)

module E = Rapid_controller.Egm_protocol
open Test_services

let pose = { E.pos = Some (350.5, -20.25, 400.); orient = Some (0.5, 0.5, -0.5, 0.5); euler = Some (10., -20., 30.) }

let robot = {
              E.r_header = { seqno = Some 300; tm = Some 123456; mtype = Some E.mtype_data };
              feedback_joints = Some [ 1.5; -2.25; 3.; 0.; 1e-9; -179.999 ]; feedback_pose = Some pose;
              planned_joints = Some [ 10.; 20. ]; planned_pose = Some { pose with euler = None };
              motor_on = Some true; mci_running = Some false; convergence_met = Some true; rapid_running = Some true;
              utilization = Some 12.5 }

let sensor = { E.s_header = { seqno = Some 7; tm = Some 0; mtype = Some E.mtype_correction };
               set_joints = Some [ 10.; -20.; 15.; 5.; 30.; -45. ]; set_pose = Some { pose with orient = None };
               set_external = Some [ 250. ]; speed_joints = Some [ 0.5; 0.; -0.5 ] }

let round_trips () =
  Alcotest.(check bool) "robot" true (E.decode_robot (E.encode_robot robot) = Ok robot);
  Alcotest.(check bool) "sensor" true (E.decode_sensor (E.encode_sensor sensor) = Ok sensor);
  Alcotest.(check bool) "empty robot" true (E.decode_robot (E.encode_robot E.empty_robot) = Ok E.empty_robot);
  Alcotest.(check bool) "empty sensor" true (E.decode_sensor "" = Ok E.empty_sensor);
  Alcotest.(check bool) "a large sequence number" true
    (match E.decode_robot (E.encode_robot { robot with r_header = { robot.r_header with seqno = Some 4294967295 } }) with
     | Ok r -> r.r_header.seqno = Some 4294967295 | Error _ -> false)

(* Bytes written by hand from the wire format's definition, not by our encoder. *)
let double f = let b = Buffer.create 8 in Buffer.add_int64_le b (Int64.bits_of_float f); Buffer.contents b

let known_bytes () =
  (* EgmSensor { header { seqno: 1 } planned { joints { joints: 10.0 joints: 20.0 } } } *)
  let joints = "\x09" ^ double 10. ^ "\x09" ^ double 20. in
  let planned = "\x0a" ^ String.make 1 (Char.chr (String.length joints)) ^ joints in
  let msg = "\x0a\x02\x08\x01" ^ "\x12" ^ String.make 1 (Char.chr (String.length planned)) ^ planned in
  (match E.decode_sensor msg with
   | Ok m ->
       Alcotest.(check (option int)) "seqno" (Some 1) m.s_header.seqno;
       Alcotest.(check (option (list (float 0.)))) "joints" (Some [ 10.; 20. ]) m.set_joints
   | Error e -> Alcotest.fail e);
  (* The same joints packed (wire type 2), and an unknown field 15 (varint) and 16 (fixed32)
     skipped; a second planned submessage merges into the first. *)
  let packed = "\x0a\x10" ^ double 10. ^ double 20. in
  let planned = "\x0a" ^ String.make 1 (Char.chr (String.length packed)) ^ packed in
  let more = "\x0a\x0b\x09" ^ double 30. ^ "\x78\x05" in
  let msg = "\x78\x96\x01" ^ "\x85\x01\x01\x02\x03\x04" ^ "\x12" ^ String.make 1 (Char.chr (String.length planned))
            ^ planned ^ "\x12" ^ String.make 1 (Char.chr (String.length more)) ^ more in
  (match E.decode_sensor msg with
   | Ok m -> Alcotest.(check (option (list (float 0.)))) "packed, merged" (Some [ 10.; 20.; 30. ]) m.set_joints
   | Error e -> Alcotest.fail e);
  (* Our encoding of a header is the wire format's: key 0x0a, length, fields 1 to 3. *)
  Alcotest.(check string) "header bytes" "\x0a\x06\x08\x07\x10\x00\x18\x03"
    (E.encode_sensor { E.empty_sensor with s_header = sensor.s_header })

let refused () =
  let bad what bytes =
    match E.decode_sensor bytes with
    | Ok _ -> Alcotest.failf "%s: accepted" what
    | Error _ -> () in
  bad "a truncated varint" "\x08\x80";
  bad "a varint beyond 64 bits" "\x08\xff\xff\xff\xff\xff\xff\xff\xff\xff\x7f";
  bad "a length beyond the message" "\x12\x05\x01";
  bad "a truncated double" "\x09\x01\x02";
  bad "a group (wire type 3)" "\x0b";
  bad "field number 0" "\x00\x01";
  bad "packed doubles of 7 bytes" "\x12\x09\x0a\x07\x01\x02\x03\x04\x05\x06\x07";
  bad "a cartesian position without z" "\x12\x14\x12\x12\x0a\x10\x09\x00\x00\x00\x00\x00\x00\x00\x00\x11\x00\x00\x00\x00\x00\x00\x00\x00"

(* Any bytes give a message or a reason, never an exception: every cut and every byte changed of
   real messages, and random bytes. *)
let hostile () =
  let total = ref 0 in
  let try_both s =
    incr total;
    (match E.decode_robot s with Ok _ | Error _ -> ());
    (match E.decode_sensor s with Ok _ | Error _ -> ()) in
  List.iter (fun m ->
      for n = 0 to String.length m do try_both (String.sub m 0 n) done;
      for i = 0 to String.length m - 1 do
        List.iter (fun c -> let b = Bytes.of_string m in Bytes.set b i c; try_both (Bytes.to_string b))
          [ '\x00'; '\xff'; '\x80'; '\x7f'; '\x0b'; Char.chr (Char.code m.[i] lxor 0x55) ]
      done) [ E.encode_robot robot; E.encode_sensor sensor ];
  let rng = Random.State.make [| 18 |] in
  for _ = 1 to 20000 do
    try_both (String.init (Random.State.int rng 64) (fun _ -> Char.chr (Random.State.int rng 256)))
  done;
  Alcotest.(check bool) "decoded" true (!total > 20000)

(* ------------------------------------------------------------------ end to end *)

let with_dir f =
  let dir = temp_dir () in
  let remove () = ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir))) in
  Fun.protect ~finally:remove (fun () -> f dir)

let targets = [ 10.; -20.; 15.; 5.; 30.; -45. ]

(* The sensor: answers every EgmRobot with the targets, until the robot has been silent for
   1 s; the feedback it received, in order. *)
let joint_reply (_ : E.robot) = { E.empty_sensor with set_joints = Some targets }

let sense ?(reply = joint_reply) sock =
  let buf = Bytes.create 65536 in
  let received = ref [] and seqno = ref 0 in
  let rec go seen =
    match Unix.select [ sock ] [] [] (if seen then 1.0 else 10.0) with
    | [], _, _ -> List.rev !received
    | _ ->
        let n, from = Unix.recvfrom sock buf 0 (Bytes.length buf) [] in
        (match E.decode_robot (Bytes.sub_string buf 0 n) with
         | Error e -> Alcotest.failf "the robot sent no EgmRobot: %s" e
         | Ok r ->
             received := r :: !received;
             incr seqno;
             let reply = E.encode_sensor { (reply r) with
                                           s_header = { seqno = Some !seqno; tm = None; mtype = Some E.mtype_correction } } in
             ignore (Unix.sendto_substring sock reply 0 (String.length reply) [] from));
        go true in
  go false

let run_with_sensor ?(extra = []) ?reply ?(driver = "drivers/EgmJoint.mod") engine dir =
  let sock = Unix.socket Unix.PF_INET Unix.SOCK_DGRAM 0 in
  Fun.protect ~finally:(fun () -> Unix.close sock) (fun () ->
      Unix.bind sock (Unix.ADDR_INET (Unix.inet_addr_loopback, 0));
      let port = match Unix.getsockname sock with Unix.ADDR_INET (_, p) -> p | _ -> assert false in
      let out = Filename.concat dir "out.txt" in
      let fd_out = Unix.openfile out [ Unix.O_WRONLY; Unix.O_CREAT; Unix.O_TRUNC ] 0o600 in
      let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
      let args = [ binary; "run"; "--engine"; engine; "--max-time"; "30";
                   "--egm-device"; Printf.sprintf "EGMSensor=127.0.0.1:%d" port ] @ extra @ [ driver ] in
      let pid = Unix.create_process binary (Array.of_list args) devnull fd_out fd_out in
      Unix.close fd_out; Unix.close devnull;
      let feedback = try sense ?reply sock with e -> ignore (wait_bounded pid 0.); raise e in
      (match wait_bounded pid 10. with
       | Some (Unix.WEXITED 0) -> ()
       | _ -> Alcotest.fail ("the program did not end with status 0: " ^ read_file out));
      (feedback, read_file out))

(* Pose mode (test/drivers/EgmPose.mod): the sensor asks for the TCP 30 mm along x, -20 along y
   and -40 along z of where the first feedback found it in the work object's frame, turned
   6 degrees about its z axis; the feedback pose converges there, within the criteria, and CRobT
   in the same tool and work object finds the TCP there. With [~euler] the orientation is sent
   as ZYX Euler angles in degrees instead of a quaternion. *)
let euler_of (w, x, y, z) =
  let deg r = r *. 180. /. Float.pi in
  (deg (Float.atan2 (2. *. ((y *. z) +. (w *. x))) (1. -. (2. *. ((x *. x) +. (y *. y))))),
   deg (Float.asin (Float.max (-1.) (Float.min 1. (2. *. ((w *. y) -. (x *. z)))))),
   deg (Float.atan2 (2. *. ((x *. y) +. (w *. z))) (1. -. (2. *. ((y *. y) +. (z *. z))))))

let egm_pose ?(euler = false) ?(extra = []) engine () =
  with_dir (fun dir ->
      let goal = ref None in
      let reply (r : E.robot) =
        (match !goal, r.feedback_pose with
         | None, Some { E.pos = Some (x, y, z); orient = Some (a, b, c, d); _ } ->
             let h = Float.pi *. 3. /. 180. in
             let cz = Float.cos h and sz = Float.sin h in
             (* (a, b, c, d) . (cz, 0, 0, sz) *)
             let q = (a *. cz -. d *. sz, b *. cz +. c *. sz, c *. cz -. b *. sz, d *. cz +. a *. sz) in
             goal := Some ((x +. 30., y -. 20., z -. 40.), q)
         | _ -> ());
        match !goal with
        | Some (p, q) ->
            let set = if euler then { E.pos = Some p; orient = None; euler = Some (euler_of q) }
              else { E.pos = Some p; orient = Some q; euler = None } in
            { E.empty_sensor with set_pose = Some set }
        | None -> E.empty_sensor in
      let feedback, out = run_with_sensor ~extra ~reply ~driver:"drivers/EgmPose.mod" engine dir in
      let (gx, gy, gz), (g1, g2, g3, g4) = match !goal with Some g -> g | None -> Alcotest.fail "no feedback pose" in
      Alcotest.(check bool) "more than 50 cycles" true (List.length feedback > 50);
      let last = List.nth feedback (List.length feedback - 1) in
      (match last.feedback_pose with
       | Some { E.pos = Some (x, y, z); orient = Some (a, b, c, d); _ } ->
           List.iter2 (fun t v -> if Float.abs (t -. v) > 0.1 then Alcotest.failf "last feedback %g, target %g" v t)
             [ gx; gy; gz ] [ x; y; z ];
           let dot = Float.abs ((a *. g1) +. (b *. g2) +. (c *. g3) +. (d *. g4)) in
           if dot < 0.99999 then Alcotest.failf "last orientation (%g %g %g %g), |dot| %g" a b c d dot
       | _ -> Alcotest.fail "no Cartesian feedback");
      Alcotest.(check (option bool)) "convergence met at the end" (Some true) last.convergence_met;
      Alcotest.(check bool) "the set point as planned" true
        (match last.planned_pose with Some { E.pos = Some (x, _, _); _ } -> Float.abs (x -. gx) < 1e-9 | _ -> false);
      let sign = if g1 < 0. then -1. else 1. in
      Alcotest.(check string) "program output"
        (Printf.sprintf "egm state before the run 1\negm state after the run 1\ntcp %.1f %.1f %.1f\n\
                         orient %.3f %.3f %.3f %.3f\n" gx gy gz (sign *. g1) (sign *. g2) (sign *. g3) (sign *. g4)) out)

(* A set point the arm cannot reach (5 m along x of where the TCP is): the inverse kinematics of
   the first step's goal has no answer, and EGMRunPose ends with ERR_ROBLIMIT (R-13-egm6), which
   the program's handler takes; the robot stands where it was. *)
let egm_pose_unreachable engine () =
  with_dir (fun dir ->
      let reply (r : E.robot) =
        match r.feedback_pose with
        | Some { E.pos = Some (x, y, z); orient; _ } ->
            { E.empty_sensor with set_pose = Some { E.pos = Some (x +. 5000., y, z); orient; euler = None } }
        | _ -> E.empty_sensor in
      let feedback, out = run_with_sensor ~reply ~driver:"drivers/EgmPose.mod" engine dir in
      Alcotest.(check bool) "the robot sent its feedback" true (feedback <> []);
      Alcotest.(check string) "program output" "egm state before the run 1\nout of reach\n" out)

(* A collision at 0.1 s, while the robot follows the sensor: ERR_COLL_STOP is taken by the
   handler of the routine (§7.6), which keeps EGMRunJoint's program point for RETRY (R-7.2-m): the
   process still runs, no cycle happens, and EGMStop connects it again. *)
let egm_collision engine () =
  with_dir (fun dir ->
      let io = Filename.concat dir "collision.io" in
      write_file io "at 0.1 collision\n";
      let feedback, out = run_with_sensor ~extra:[ "--io"; io ] engine dir in
      Alcotest.(check bool) "cycles until the collision" true (List.length feedback >= 20 && List.length feedback <= 30);
      Alcotest.(check string) "program output" "egm state before the run 1\ncollision, egm state 2\nafter EGMStop 1\n" out)

let egm_joint engine () =
  with_dir (fun dir ->
      let feedback, out = run_with_sensor engine dir in
      Alcotest.(check bool) "more than 50 cycles" true (List.length feedback > 50);
      (* The sequence numbers count the cycles; the time stamps go on by 4 ms a cycle. *)
      List.iteri (fun i (r : E.robot) ->
          Alcotest.(check (option int)) "seqno" (Some (i + 1)) r.r_header.seqno;
          Alcotest.(check (option int)) "mtype" (Some E.mtype_data) r.r_header.mtype) feedback;
      let tms = List.filter_map (fun (r : E.robot) -> r.r_header.tm) feedback in
      List.iteri (fun i t -> if i > 0 && t - List.nth tms (i - 1) <> 4 then
                     Alcotest.failf "time stamps %d then %d" (List.nth tms (i - 1)) t) tms;
      let joints (r : E.robot) = Option.value r.feedback_joints ~default:[] in
      let first = List.hd feedback and last = List.nth feedback (List.length feedback - 1) in
      List.iter (fun v -> Alcotest.(check (float 1e-9)) "first feedback: the robot at 0" 0. v) (joints first);
      List.iter2 (fun t v -> if Float.abs (t -. v) > 0.1 then Alcotest.failf "last feedback %g, target %g" v t)
        targets (joints last);
      Alcotest.(check (option bool)) "convergence met at the end" (Some true) last.convergence_met;
      (* The feedback moves towards the targets and never beyond them. *)
      List.iter (fun (r : E.robot) ->
          List.iter2 (fun t v -> if Float.abs v > Float.abs t +. 1e-6 then Alcotest.failf "feedback %g beyond %g" v t)
            targets (joints r)) feedback;
      (* An axis moves at most \MaxSpeedDeviation (200 degrees/s) for a cycle of 4 ms, ramped in
         over \RampInTime (0.05 s): 0.8 degrees a cycle, 0.064 in the first. *)
      let steps = List.mapi (fun i (r : E.robot) -> (i, joints r)) feedback in
      List.iter (fun (i, q) ->
          if i > 0 then begin
            let before = snd (List.nth steps (i - 1)) in
            let limit = 0.8 *. Float.min 1. (float_of_int i *. 0.004 /. 0.05) +. 1e-6 in
            List.iter2 (fun a b -> if Float.abs (b -. a) > limit then
                           Alcotest.failf "cycle %d: a step of %g degrees, at most %g" i (b -. a) limit) before q
          end) steps;
      Alcotest.(check bool) "J6 needs 56 cycles of 0.8 degrees at least" true (List.length feedback > 56);
      (* The Cartesian feedback is the flange where CRobT finds it. *)
      let x, y, z = match last.feedback_pose with
        | Some { E.pos = Some p; _ } -> p | _ -> Alcotest.fail "no Cartesian feedback" in
      let flange = Printf.sprintf "flange %.2f %.2f %.2f" x y z in
      Alcotest.(check string) "program output"
        ("egm state before the run 1\negm state after the run 1\n\
          joints 10.00 -20.00 15.00 5.00 30.00 -45.00\n" ^ flange ^ "\negm state after the reset 0\n") out)

(* No sensor answers: EGMRunJoint ends with ERR_UDPUC_COMM after \CommTimeout, which the
   program's handler takes. *)
let egm_timeout () =
  with_dir (fun dir ->
      let src = Filename.concat dir "timeout.mod" in
      write_file src (replace ~pattern:"\\CommTimeout:=5" ~by:"\\CommTimeout:=0.3" (read_file "drivers/EgmJoint.mod"));
      let port = free_port () in
      let out = Filename.concat dir "out.txt" in
      let code = Sys.command (Printf.sprintf "%s run --egm-device EGMSensor=127.0.0.1:%d %s > %s 2>&1"
                                binary port (Filename.quote src) (Filename.quote out)) in
      Alcotest.(check int) "status" 0 code;
      Alcotest.(check string) "output" "egm state before the run 1\ncommunication timeout\n" (read_file out))

let suite = ("egm", [
    Alcotest.test_case "codec: round trips" `Quick round_trips;
    Alcotest.test_case "codec: bytes of the wire format" `Quick known_bytes;
    Alcotest.test_case "codec: malformed messages refused" `Quick refused;
    Alcotest.test_case "codec: hostile bytes never raise" `Quick hostile;
    Alcotest.test_case "joint-mode EGM with a sensor on the loopback" `Quick (egm_joint "closure");
    Alcotest.test_case "joint-mode EGM with a sensor, the machine" `Quick (egm_joint "machine");
    Alcotest.test_case "a collision during the run" `Quick (egm_collision "closure");
    Alcotest.test_case "a collision during the run, the machine" `Quick (egm_collision "machine");
    Alcotest.test_case "pose-mode EGM with a sensor on the loopback" `Quick (egm_pose "closure");
    Alcotest.test_case "pose-mode EGM with a sensor, Euler angles, the machine" `Quick (egm_pose ~euler:true "machine");
    (* The robot at a base frame 30 degrees about z and away from the world's origin (R-bk-12):
       the work object frame of the guidance is brought into the base frame. *)
    Alcotest.test_case "pose-mode EGM, the robot at a moved and turned base frame" `Quick
      (egm_pose ~extra:[ "--base-frame"; "300,-200,100,0.9659258,0,0,0.2588190" ] "closure");
    Alcotest.test_case "pose-mode EGM, a set point out of reach: ERR_ROBLIMIT" `Quick (egm_pose_unreachable "closure");
    Alcotest.test_case "pose-mode EGM, a set point out of reach, the machine" `Quick
      (egm_pose_unreachable "machine");
    Alcotest.test_case "no sensor: ERR_UDPUC_COMM after CommTimeout" `Quick egm_timeout;
  ])
