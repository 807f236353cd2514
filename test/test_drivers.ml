(* Real robot drivers end to end (issue 18): RAPID programs of our own in test/drivers/, each
   under `rapid-sem run` with a client of this test over the loopback, on a port chosen now and
   written into the run's sandbox (HOME:), which the program reads. Every wait of the client is
   bounded, and a server that does not end in time is killed. *)

open Test_services

let with_dir f =
  let dir = temp_dir () in
  let remove () = ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir))) in
  Fun.protect ~finally:remove (fun () -> f dir)

(* A sandbox under [dir] whose HOME: holds [files] (name, contents). *)
let seed_home dir files =
  let fs = Filename.concat dir "fs" in
  let home = Filename.concat fs "HOME" in
  Unix.mkdir fs 0o700; Unix.mkdir home 0o700;
  List.iter (fun (name, text) -> write_file (Filename.concat home name) text) files;
  fs

(* Starts `rapid-sem run ARGS`, its output into [dir]/out.txt; the pid and that file. *)
let start dir args =
  let out = Filename.concat dir "out.txt" in
  let fd_out = Unix.openfile out [ Unix.O_WRONLY; Unix.O_CREAT; Unix.O_TRUNC ] 0o600 in
  let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
  let pid = Unix.create_process binary (Array.of_list (binary :: "run" :: args)) devnull fd_out fd_out in
  Unix.close fd_out; Unix.close devnull;
  (pid, out)

(* Runs [client] against the server [pid]; the server is killed when the client fails, and must
   otherwise end with status 0 within 10 s. *)
let serve pid out client =
  let result = try client () with e -> ignore (wait_bounded pid 0.); raise e in
  (match wait_bounded pid 10. with
   | Some (Unix.WEXITED 0) -> ()
   | Some _ -> Alcotest.fail ("the server did not end with status 0: " ^ read_file out)
   | None -> Alcotest.fail ("the server did not end within 10 s: " ^ read_file out));
  result

(* Bytes from [s] until [stop] says the buffer is complete; every read waits at most 10 s. *)
let read_until s stop =
  let b = Buffer.create 64 and chunk = Bytes.create 1 in
  let rec go () =
    if stop b then Buffer.contents b
    else
      match Unix.select [ s ] [] [] 10. with
      | [], _, _ -> Alcotest.fail ("no answer from the server within 10 s after " ^ String.escaped (Buffer.contents b))
      | _ ->
          if Unix.read s chunk 0 1 = 0 then Alcotest.fail ("the server closed after " ^ Buffer.contents b)
          else (Buffer.add_bytes b chunk; go ()) in
  go ()

let words s = List.filter (( <> ) "") (String.split_on_char ' ' s)

let close_to what ~eps expected actual =
  Alcotest.(check int) (what ^ ": count") (List.length expected) (List.length actual);
  List.iteri (fun i (e, a) ->
      if Float.abs (e -. a) > eps then Alcotest.failf "%s: value %d is %g, expected %g" what (i + 1) a e)
    (List.combine expected actual)

(* 1. The line-protocol server (test/drivers/LineServer.mod, in the manner of open_abb): ping,
   a linear move, the pose read back is the target; a joint move, the joints read back; close,
   reconnect, the robot is where it was left; stop. *)
let line_server engine () =
  with_dir (fun dir ->
      let port = free_port () in
      let fs = seed_home dir [ ("line_server.cfg", string_of_int port ^ "\n") ] in
      let pid, out = start dir [ "--engine"; engine; "--fs"; fs; "--max-time"; "30"; "drivers/LineServer.mod" ] in
      let request s text =
        send s text;
        let reply = read_until s (fun b -> Buffer.length b > 0 && Buffer.nth b (Buffer.length b - 1) = '#') in
        match words reply with
        | code :: "ok" :: rest -> (code, List.map float_of_string (List.filter (( <> ) "#") rest))
        | _ -> Alcotest.failf "request %S: reply %S" text reply in
      let session f = let s = connect_retrying port in Fun.protect ~finally:(fun () -> Unix.close s) (fun () -> f s) in
      serve pid out (fun () ->
          session (fun s ->
              Alcotest.(check string) "ping" "00" (fst (request s "00 #"));
              Alcotest.(check string) "cartesian move" "01" (fst (request s "01 350 50 450 0 0 1 0 #"));
              close_to "pose after the move" ~eps:0.011 [ 350.; 50.; 450.; 0.; 0.; 1.; 0. ] (snd (request s "03 #"));
              Alcotest.(check string) "joint move" "02" (fst (request s "02 10 -20 30 0 40 15 #"));
              close_to "joints after the move" ~eps:0.011 [ 10.; -20.; 30.; 0.; 40.; 15. ] (snd (request s "04 #"));
              Alcotest.(check string) "close" "99" (fst (request s "99 #")));
          session (fun s ->
              Alcotest.(check string) "ping again" "00" (fst (request s "00 #"));
              close_to "joints after reconnecting" ~eps:0.011 [ 10.; -20.; 30.; 0.; 40.; 15. ] (snd (request s "04 #"));
              Alcotest.(check string) "stop" "98" (fst (request s "98 #"))));
      Alcotest.(check string) "server output"
        "line server listening\nsession 1\nsession 2\nline server stopped\n" (read_file out))

(* A little-endian int32 and float32 (IEEE single) as bytes. *)
let int32_le b i = Buffer.add_int32_le b (Int32.of_int i)
let float32_le b f = Buffer.add_int32_le b (Int32.bits_of_float f)

(* 3. The motion-program executor (test/drivers/ProgramExecutor.mod): a binary program written
   into the sandbox's HOME: (header "RSMP", version, count; records of an int32 opcode and 7
   float32s), executed record by record; the reports come in the program's order and the robot
   ends at the last target. *)
let program_executor engine () =
  with_dir (fun dir ->
      let records =
        [ (2, [ 350.; 0.; 450.; 0.; 0.; 1.; 0. ]); (1, [ 350.; 100.; 450.; 0.; 0.; 1.; 0. ]);
          (3, [ 0.5; 0.; 0.; 0.; 0.; 0.; 0. ]); (1, [ 300.; -100.; 400.; 0.; 0.; 1.; 0. ]);
          (2, [ 320.; 50.; 420.; 0.; 0.; 1.; 0. ]); (3, [ 0.25; 0.; 0.; 0.; 0.; 0.; 0. ]) ] in
      let b = Buffer.create 256 in
      Buffer.add_string b "RSMP"; int32_le b 1; int32_le b (List.length records);
      List.iter (fun (op, args) -> int32_le b op; List.iter (float32_le b) args) records;
      let fs = seed_home dir [ ("program.bin", Buffer.contents b) ] in
      let pid, out = start dir [ "--engine"; engine; "--fs"; fs; "--max-time"; "60"; "drivers/ProgramExecutor.mod" ] in
      serve pid out (fun () -> ());
      Alcotest.(check string) "reports and final position"
        "program of records: 6\nrecord 1 MoveJ done\nrecord 2 MoveL done\nrecord 3 WaitTime 0.50 done\n\
         record 4 MoveL done\nrecord 5 MoveJ done\nrecord 6 WaitTime 0.25 done\nfinal position 320.0 50.0 420.0\n"
        (read_file out))

(* Exactly [n] bytes from [s]; every read waits at most 10 s. *)
let read_exact s n =
  let b = Bytes.create n in
  let rec go k =
    if k < n then
      match Unix.select [ s ] [] [] 10. with
      | [], _, _ -> Alcotest.failf "no message within 10 s (%d of %d bytes)" k n
      | _ ->
          let got = Unix.read s b k (n - k) in
          if got = 0 then Alcotest.failf "the server closed after %d of %d bytes" k n else go (k + got) in
  go 0; b

let int32_at b i = Int32.to_int (Bytes.get_int32_le b i)
let float32_at b i = Int32.float_of_bits (Bytes.get_int32_le b i)

(* 2. The ROS-Industrial simple_message pair (test/drivers/RosMotion.mod in T_ROB1, RosState.mod
   in a task without a robot): the published format, little-endian as ABB's ROS driver packs
   it (PackRawBytes without \Network). The client takes the state server's JOINT_POSITION
   messages (length 56, msg_type 10, comm_type 1 TOPIC, reply_code 0, sequence, 10 float32
   joints in radians) and sends JOINT_TRAJ_PT service requests (length 64, msg_type 11,
   comm_type 2, sequence, 10 joints, velocity, duration); each is answered (comm_type 3,
   reply_code 1 SUCCESS) once the robot is there, and the state server, reading CJointT in its
   own task, reports the robot on its way: joints moving monotonically from where it stood to
   the target, through intermediate positions. A message of another type is answered with
   FAILURE. The motion client going away stops both servers. *)
let ros_pair engine () =
  with_dir (fun dir ->
      let motion_port = free_port () and state_port = free_port () in
      let fs = seed_home dir [ ("ros_ports.cfg", Printf.sprintf "%d\n%d\n" motion_port state_port) ] in
      let pid, out = start dir [ "--engine"; engine; "--fs"; fs; "--max-time"; "60";
                                 "--task"; "T_ROB1=drivers/RosMotion.mod"; "--task"; "T_STATE=drivers/RosState.mod" ] in
      let state s =
        let b = read_exact s 60 in
        Alcotest.(check (list int)) "JOINT_POSITION header" [ 56; 10; 1; 0 ]
          [ int32_at b 0; int32_at b 4; int32_at b 8; int32_at b 12 ];
        (int32_at b 16, List.init 6 (fun i -> float32_at b (20 + 4 * i))) in
      let point ?(msg_type = 11) sequence joints =
        let b = Buffer.create 68 in
        List.iter (int32_le b) [ 64; msg_type; 2; 0; sequence ];
        List.iter (float32_le b) (joints @ [ 0.; 0.; 0.; 0.; 0.5; 0. ]);
        Buffer.contents b in
      let near a b = List.for_all2 (fun x y -> Float.abs (x -. y) < 1e-3) a b in
      (* A point sent; the states until the reply, and after it until the robot is reported at
         the target: the reply, and the joints reported on the way. *)
      let move motion st sequence target =
        send motion (point sequence target);
        let rec until_reply acc =
          match Unix.select [ motion; st ] [] [] 10. with
          | [], _, _ -> Alcotest.fail "neither a reply nor a state within 10 s"
          | ready, _, _ when List.mem motion ready -> (read_exact motion 68, List.rev acc)
          | _ -> until_reply (snd (state st) :: acc) in
        let reply, during = until_reply [] in
        let rec until_there acc k =
          if k > 200 then Alcotest.fail "the state server never reported the target" else
            let j = snd (state st) in
            if near j target then List.rev (j :: acc) else until_there (j :: acc) (k + 1) in
        (reply, during @ until_there [] 0) in
      let check_way what from target states =
        List.iteri (fun axis (a, b) ->
            if Float.abs (b -. a) > 1e-3 then begin
              let values = List.map (fun j -> List.nth j axis) states in
              let toward = if b > a then ( <= ) else ( >= ) in
              ignore (List.fold_left (fun prev v ->
                  if not (toward (prev -. (if b > a then 1e-4 else -1e-4)) v) then
                    Alcotest.failf "%s: axis %d went back from %g to %g" what (axis + 1) prev v;
                  v) a values);
              let between = List.filter (fun v -> Float.abs (v -. a) > 1e-3 && Float.abs (v -. b) > 1e-3) values in
              if List.length between < 3 then
                Alcotest.failf "%s: axis %d reported on its way only %d times" what (axis + 1) (List.length between)
            end) (List.combine from target) in
      let reply_of b = [ int32_at b 0; int32_at b 4; int32_at b 8; int32_at b 12; int32_at b 16 ] in
      serve pid out (fun () ->
          let st = connect_retrying state_port in
          Fun.protect ~finally:(fun () -> Unix.close st) (fun () ->
              let seq0, home = state st in
              Alcotest.(check int) "the first state's sequence" 0 seq0;
              let motion = connect_retrying motion_port in
              let first = [ 0.5; -0.3; 0.4; 0.; 0.6; 0.2 ] and second = [ -0.2; 0.1; 0.3; 0.5; -0.4; 1.0 ] in
              let reply, way = move motion st 1 first in
              Alcotest.(check (list int)) "first reply: SERVICE_REPLY, SUCCESS" [ 64; 11; 3; 1; 1 ] (reply_of reply);
              check_way "first point" home first way;
              let reply, way = move motion st 2 second in
              Alcotest.(check (list int)) "second reply" [ 64; 11; 3; 1; 2 ] (reply_of reply);
              check_way "second point" first second way;
              send motion (point ~msg_type:99 3 first);
              Alcotest.(check (list int)) "another type: FAILURE" [ 64; 99; 3; 2; 3 ] (reply_of (read_exact motion 68));
              Alcotest.(check bool) "the robot stayed" true (near (snd (state st)) second);
              Unix.close motion;
              (* The state server stops too: its socket ends. *)
              let rec drain k =
                if k > 1000 then Alcotest.fail "the state server did not stop" else
                  match Unix.select [ st ] [] [] 10. with
                  | [], _, _ -> Alcotest.fail "the state server neither sent nor stopped within 10 s"
                  | _ -> if Unix.read st (Bytes.create 60) 0 60 = 0 then () else drain (k + 1) in
              drain 0));
      Alcotest.(check string) "server output"
        "motion server listening\nstate server listening\nmotion server stopped after points: 2\nstate server stopped\n"
        (read_file out))

let suite = ("drivers", [
    Alcotest.test_case "line-protocol command server (open_abb's kind)" `Quick (line_server "closure");
    Alcotest.test_case "line-protocol command server, the machine" `Quick (line_server "machine");
    Alcotest.test_case "binary motion-program executor (rawbytes)" `Quick (program_executor "closure");
    Alcotest.test_case "binary motion-program executor, the machine" `Quick (program_executor "machine");
    Alcotest.test_case "ROS-Industrial simple_message motion and state servers" `Quick (ros_pair "closure");
    Alcotest.test_case "ROS-Industrial simple_message servers, the machine" `Quick (ros_pair "machine");
  ])
