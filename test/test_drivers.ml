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

let suite = ("drivers", [
    Alcotest.test_case "line-protocol command server (open_abb's kind)" `Quick (line_server "closure");
    Alcotest.test_case "line-protocol command server, the machine" `Quick (line_server "machine");
    Alcotest.test_case "binary motion-program executor (rawbytes)" `Quick (program_executor "closure");
    Alcotest.test_case "binary motion-program executor, the machine" `Quick (program_executor "machine");
  ])
