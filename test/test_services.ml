(* The controller's services end to end (doc/services.md): a RAPID command server under
   rapid-sem run, and a client over the loopback; the sandbox's refusal of paths that lead
   out. *)

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

let write_file path text =
  let oc = open_out_bin path in
  Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text)

let replace ~pattern ~by s = Str.global_replace (Str.regexp_string pattern) by s

(* A port nobody listens on now: the kernel's choice for a socket bound to port 0. *)
let free_port () =
  let s = Unix.socket Unix.PF_INET Unix.SOCK_STREAM 0 in
  Fun.protect ~finally:(fun () -> Unix.close s) (fun () ->
      Unix.bind s (Unix.ADDR_INET (Unix.inet_addr_loopback, 0));
      match Unix.getsockname s with Unix.ADDR_INET (_, p) -> p | _ -> assert false)

let temp_dir () =
  let d = Filename.temp_file "rapid-sem-services" "" in
  Sys.remove d; Unix.mkdir d 0o700; d

(* Waits at most [seconds] for the process; kills it when it takes longer. *)
let wait_bounded pid seconds =
  let deadline = Unix.gettimeofday () +. seconds in
  let rec go () =
    match Unix.waitpid [ Unix.WNOHANG ] pid with
    | 0, _ when Unix.gettimeofday () < deadline -> Unix.sleepf 0.05; go ()
    | 0, _ -> Unix.kill pid Sys.sigkill; ignore (Unix.waitpid [] pid); None
    | _, status -> Some status in
  go ()

let connect_retrying port =
  let deadline = Unix.gettimeofday () +. 10. in
  let rec go () =
    let s = Unix.socket Unix.PF_INET Unix.SOCK_STREAM 0 in
    match Unix.connect s (Unix.ADDR_INET (Unix.inet_addr_loopback, port)) with
    | () -> s
    | exception Unix.Unix_error (Unix.ECONNREFUSED, _, _) when Unix.gettimeofday () < deadline ->
        Unix.close s; Unix.sleepf 0.05; go () in
  go ()

(* One line of the server's answer, up to CR LF; the client's reads are bounded in time. *)
let read_line s =
  let b = Buffer.create 16 and c = Bytes.create 1 in
  let rec go () =
    match Unix.select [ s ] [] [] 10. with
    | [], _, _ -> Alcotest.fail "no answer from the server within 10 s"
    | _ ->
        if Unix.read s c 0 1 = 0 then Buffer.contents b
        else if Bytes.get c 0 = '\n' then Buffer.contents b
        else (if Bytes.get c 0 <> '\r' then Buffer.add_bytes b c; go ()) in
  go ()

let send s text = ignore (Unix.write_substring s text 0 (String.length text))

let command_server () =
  let dir = temp_dir () in
  let port = free_port () in
  let source = replace ~pattern:"@PORT@" ~by:(string_of_int port) (read_file "services/CommandServer.mod") in
  let module_file = Filename.concat dir "CommandServer.mod" and out = Filename.concat dir "out.txt" in
  write_file module_file source;
  let fd_out = Unix.openfile out [ Unix.O_WRONLY; Unix.O_CREAT; Unix.O_TRUNC ] 0o600 in
  let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
  let pid = Unix.create_process binary
      [| binary; "run"; "--fs"; Filename.concat dir "fs"; "--map-address"; "192.168.125.1=127.0.0.1"; module_file |]
      devnull fd_out fd_out in
  Unix.close fd_out; Unix.close devnull;
  let answers =
    match connect_retrying port with
    | s ->
        Fun.protect ~finally:(fun () -> Unix.close s) (fun () ->
            let ready = read_line s in
            ready :: List.map (fun c -> send s c; read_line s) [ "PING"; "ADD 2 3"; "ADD 40 -2"; "HELLO"; "QUIT" ])
    | exception e -> ignore (wait_bounded pid 0.); raise e in
  let status = wait_bounded pid 10. in
  Alcotest.(check (list string)) "answers" [ "READY"; "PONG"; "OK 5"; "OK 38"; "ERR unknown command"; "BYE" ] answers;
  (match status with
   | Some (Unix.WEXITED 0) -> ()
   | Some _ -> Alcotest.fail ("the server did not end with status 0: " ^ read_file out)
   | None -> Alcotest.fail "the server did not end within 10 s");
  Alcotest.(check string) "server output"
    "Command client: 127.0.0.1\nStatus after close: 5\nCommand server stopped after commands: 5\n" (read_file out);
  ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir)))

(* A symbolic link inside the sandbox that leads out of it is refused, as are .. and host
   paths; a link that stays inside is followed. *)
let escapes () =
  let module FS = Rapid_controller.File_sandbox in
  let outside = temp_dir () in
  let sandbox = FS.temporary () in
  Fun.protect ~finally:(fun () -> FS.remove sandbox; ignore (Sys.command ("rm -rf " ^ Filename.quote outside))) (fun () ->
      write_file (Filename.concat outside "secret.txt") "secret";
      (match FS.resolve sandbox "HOME:/a.txt" with Ok _ -> () | Error e -> Alcotest.fail e);
      let home = Filename.concat (FS.root sandbox) "HOME" in
      Unix.symlink outside (Filename.concat home "out");
      Unix.mkdir (Filename.concat home "real") 0o755;
      Unix.symlink (Filename.concat home "real") (Filename.concat home "in");
      let refused p = match FS.resolve sandbox p with Error _ -> true | Ok _ -> false in
      List.iter (fun p -> Alcotest.(check bool) p true (refused p))
        [ "HOME:/out/secret.txt"; "HOME:/out"; "HOME:/out/new.txt"; "HOME:/../x"; "TEMP:/a/../../b";
          "/etc/passwd"; "C:/x"; "HOME:/a\000b" ];
      List.iter (fun p -> Alcotest.(check bool) p false (refused p))
        [ "HOME:/in/file.txt"; "home:x.txt"; "RAMDISK:"; "DISKHOME:/a/b"; "REMOVABLE:/x"; "plain.txt" ])

(* --save: a run killed at any moment leaves the module either as it was or as the finished run
   writes it, never a mix. The module is large (many persistents) so that the write takes long
   enough for some kills to land in it; each run is killed at a random moment up to a little
   beyond the time a whole run takes. *)
let kill_during_save () =
  let dir = temp_dir () in
  Fun.protect ~finally:(fun () -> ignore (Sys.command ("rm -rf " ^ Filename.quote dir))) (fun () ->
      let b = Buffer.create (1 lsl 20) in
      Buffer.add_string b "MODULE keep\n  ! The persistents of a cell, saved by --save.\n";
      for i = 1 to 1000 do Buffer.add_string b (Printf.sprintf "  PERS num p%d := %d;  ! count %d\n" i i i) done;
      Buffer.add_string b "  PROC main()\n";
      for i = 1 to 1000 do Buffer.add_string b (Printf.sprintf "    p%d := p%d * 2 + 1;\n" i i) done;
      Buffer.add_string b "  ENDPROC\nENDMODULE\n";
      let old = Buffer.contents b in
      let source = Filename.concat dir "keep.mod" and out = Filename.concat dir "out" in
      write_file source old;
      Unix.mkdir out 0o755;
      let target = Filename.concat out "keep.mod" in
      let start () =
        let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
        let pid = Unix.create_process binary [| binary; "run"; "--save"; out; source |] devnull devnull devnull in
        Unix.close devnull; pid in
      (* One whole run: the new text, and how long a run takes. *)
      write_file target old;
      let t0 = Unix.gettimeofday () in
      (match wait_bounded (start ()) 60. with
       | Some (Unix.WEXITED 0) -> ()
       | _ -> Alcotest.fail "the run with --save did not end with status 0");
      let whole = Unix.gettimeofday () -. t0 in
      let fresh = read_file target in
      Alcotest.(check bool) "the run saved new values" true (fresh <> old);
      Alcotest.(check bool) "p1 saved" true
        (Str.string_match (Str.regexp_string "  PERS num p1 := 3;  ! count 1") (List.nth (String.split_on_char '\n' fresh) 2) 0);
      Random.init 20261123;
      let kinds = Hashtbl.create 2 in
      for _ = 1 to 8 do
        write_file target old;
        let pid = start () in
        Unix.sleepf (Random.float (whole *. 1.2));
        (try Unix.kill pid Sys.sigkill with Unix.Unix_error _ -> ());
        ignore (Unix.waitpid [] pid);
        let now = read_file target in
        if now = old then Hashtbl.replace kinds "old" ()
        else if now = fresh then Hashtbl.replace kinds "new" ()
        else Alcotest.fail "a killed run left a module that is neither the old nor the new one"
      done;
      (* What the kills left besides: at most temporary files, never a second module. *)
      Array.iter (fun f -> if f <> "keep.mod" && not (Filename.check_suffix f ".part") then
                     Alcotest.failf "unexpected file %s" f) (Sys.readdir out))

(* --net and --map-address: what the options read, and that a mapped address reaches the
   loopback while an unmapped one is refused before any packet leaves. *)
let address_policy () =
  let module K = Rapid_controller.Sockets in
  Alcotest.(check bool) "--net list" true
    (K.parse_allowed "10.0.0.5:1025, example:*" = Ok [ ("10.0.0.5", Some 1025); ("example", None) ]);
  Alcotest.(check bool) "--net bad port" true (Result.is_error (K.parse_allowed "10.0.0.5:70000"));
  Alcotest.(check bool) "--net no port" true (Result.is_error (K.parse_allowed "10.0.0.5"));
  Alcotest.(check bool) "--map-address" true
    (K.parse_mapping "192.168.125.1=127.0.0.1" = Ok [ ("192.168.125.1", "127.0.0.1") ]);
  Alcotest.(check bool) "--map-address bad" true (Result.is_error (K.parse_mapping "192.168.125.1"));
  let bind k address =
    match K.socket k ~udp:true with
    | Error e -> Error e
    | Ok id -> let r = K.bind k id address 0 in K.close k id; r in
  let plain = K.create () and mapped = K.create ~mapping:[ ("192.168.125.1", "127.0.0.1") ] () in
  Alcotest.(check bool) "unmapped service port refused" true (bind plain "192.168.125.1" = Error "ERR_SOCK_ADDR_INVALID");
  Alcotest.(check bool) "mapped service port on the loopback" true (bind mapped "192.168.125.1" = Ok ());
  Alcotest.(check bool) "loopback" true (bind plain "127.0.0.1" = Ok ());
  Alcotest.(check bool) "not an address" true (bind plain "1.2.3" = Error "ERR_SOCK_ADDR_INVALID")

(* Values written by --save read back as the same values. *)
let literals () =
  let module P = Rapid_run.Persistent_save in
  let module V = Rapid_runtime.Value in
  List.iter (fun (v, text) -> Alcotest.(check string) text text (P.literal v))
    [ (V.num (1. /. 3.), "0.33333334"); (V.num 0.1, "0.1"); (V.num (-2.5), "-2.5"); (V.num 1e30, "1E+30");
      (V.dnum (1. /. 3.), "0.3333333333333333"); (V.dnum 12345678901234., "12345678901234");
      (V.String "say \"hi\"", "\"say \"\"hi\"\"\""); (V.Bool true, "TRUE");
      (V.Record [| V.num 1.; V.String "" |], "[1,\"\"]") ];
  for _ = 1 to 1000 do
    let f = V.to_single (Random.float 2e6 -. 1e6) in
    let t = P.literal (V.num f) in
    Alcotest.(check (float 0.)) t f (V.to_single (float_of_string t))
  done

(* Runs a module in a world whose services are [services]; its output lines. *)
let run_with services text =
  let module M = Rapid_semantics.Machine in
  match Rapid_syntax.Parse.parse_string ~name:"t.mod" text with
  | Error d -> Alcotest.fail (Rapid_syntax.Diagnostic.to_string d)
  | Ok m -> (
      match Rapid_load.Session.load_modules ~allow_unknown:false ~io:Rapid_controller.Io_config.empty [ m ] with
      | Error _ -> Alcotest.fail "the module does not load"
      | Ok loaded -> (
          let world = Rapid_controller.World.create Rapid_controller.Io_config.empty in
          Rapid_controller.World.set_services world services;
          match M.start ~host:(Rapid_run.Run.setup ~controller:world ()).host loaded.program ~entry:"main" with
          | Error e -> Alcotest.fail e
          | Ok cfg ->
              let out = ref [] in
              while M.outcome cfg = Running && M.steps cfg < 100_000 do
                List.iter (function Rapid_runtime.Event.Output s -> out := s :: !out | _ -> ()) (snd (M.step cfg))
              done;
              List.rev !out))

(* The bounds of the mass memory (R-13-s): a file may not grow beyond the run's limit
   (ERR_FILESIZE; 64 MiB by default, 10 bytes here), and 32 files may be open at once. *)
let file_bounds () =
  let module S = Rapid_controller.Services in
  let sandbox = Rapid_controller.File_sandbox.temporary () in
  Fun.protect ~finally:(fun () -> Rapid_controller.File_sandbox.remove sandbox) (fun () ->
      let out = run_with (S.create ~sandbox ~max_file_size:10 ())
          "MODULE t\n  VAR iodev f;\n  VAR iodev many{33};\n  VAR num k;\n  PROC main()\n\
          \    Open \"HOME:/a.txt\", f \\Write;\n    Write f, \"123456789\";\n    TPWrite \"10 bytes\";\n\
          \    Write f, \"x\" \\NoNewLine;\n    TPWrite \"not reached\";\n  ERROR\n\
          \    TPWrite \"ERR_FILESIZE \" \\Bool:=ERRNO = ERR_FILESIZE;\n    TPWrite \"size \" \\Num:=FileSize(\"HOME:/a.txt\");\n\
          \    Close f;\n    Opens;\n  ENDPROC\n\
          \  PROC Opens()\n    FOR i FROM 1 TO 33 DO\n      k := i;\n      Open \"TEMP:/f\" + ValToStr(i), many{i} \\Write;\n    ENDFOR\n\
          \  ERROR\n    TPWrite \"open \" + ValToStr(k) + \" \" + ValToStr(ERRNO = ERR_FILEOPEN);\n  ENDPROC\nENDMODULE\n" in
      Alcotest.(check (list string)) "output" [ "10 bytes"; "ERR_FILESIZE TRUE"; "size 10"; "open 33 TRUE" ] out)

(* --save by both engines (doc/semantics.md, "The second engine"): the same modules, byte for
   byte, from the values the run left (whole values, components, arrays, a run stopped by an
   error). *)
let save_engines () =
  let dir = temp_dir () in
  Fun.protect ~finally:(fun () -> ignore (Sys.command ("rm -rf " ^ Filename.quote dir))) (fun () ->
      let source = Filename.concat dir "cell.mod" in
      write_file source
        "MODULE cell\n  PERS num count := 0;\n  PERS string name := \"a\";  ! kept\n  PERS pos p := [1,2,3];\n\
        \  PERS num row{3} := [0,0,0];\n  VAR num v := 5;\n  PROC main()\n    count := count + 41 / 4;\n\
        \    name := name + \"b\";\n    p.y := -0.5;\n    FOR i FROM 1 TO 3 DO\n      row{i} := i * i;\n    ENDFOR\n\
        \    v := 1 / (count - count);\n  ENDPROC\nENDMODULE\n";
      let save engine =
        let out = Filename.concat dir engine in
        let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
        let pid = Unix.create_process binary [| binary; "run"; "--engine"; engine; "--save"; out; source |]
            devnull devnull devnull in
        Unix.close devnull;
        let status = match wait_bounded pid 60. with Some (Unix.WEXITED n) -> n | _ -> -1 in
        (status, read_file (Filename.concat out "cell.mod")) in
      let ms, machine = save "machine" and cs, closure = save "closure" in
      Alcotest.(check int) "stopped by ERR_DIVZERO: exit 1" 1 ms;
      Alcotest.(check int) "the same exit status" ms cs;
      Alcotest.(check bool) "the values of the run" true
        (List.for_all (fun l -> List.mem l (String.split_on_char '\n' machine))
           [ "  PERS num count := 10.25;"; "  PERS string name := \"ab\";  ! kept"; "  PERS pos p := [1,-0.5,3];";
             "  PERS num row{3} := [1,4,9];" ]);
      Alcotest.(check string) "the closure engine saves as the machine" machine closure)


(* The first line a run writes reaches a reader while the program still waits on the host (here
   for a client that never comes): each line leaves the process as it is written, so a client
   waiting for it does not deadlock and a run then killed loses nothing (doc/services.md). *)
let waiting_server port = Printf.sprintf {|MODULE waiting
  VAR socketdev listener;
  VAR socketdev client;
  PROC main()
    TPWrite "listening";
    SocketCreate listener;
    SocketBind listener, "127.0.0.1", %d;
    SocketListen listener;
    SocketAccept listener, client \Time:=30;
    TPWrite "never";
  ENDPROC
ENDMODULE
|} port

let first_line_before_wait () =
  let dir = temp_dir () in
  Fun.protect ~finally:(fun () -> ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir)))) (fun () ->
      let file = Filename.concat dir "waiting.mod" in
      write_file file (waiting_server (free_port ()));
      List.iter (fun (what, options, expected) ->
          let out_r, out_w = Unix.pipe ~cloexec:true () in
          let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
          let pid = Unix.create_process binary
              (Array.of_list ([ binary; "run"; "--fs"; Filename.concat dir "fs" ] @ options @ [ file ]))
              devnull out_w devnull in
          Unix.close out_w; Unix.close devnull;
          (* Lines up to [expected], read while the run waits; none may need the process's end. *)
          let seen = Buffer.create 64 and chunk = Bytes.create 4096 in
          let deadline = Unix.gettimeofday () +. 10. in
          let rec read () =
            if not (List.mem expected (String.split_on_char '\n' (Buffer.contents seen))) then
              let left = deadline -. Unix.gettimeofday () in
              if left > 0. then
                match Unix.select [ out_r ] [] [] left with
                | [], _, _ -> ()
                | _ -> let n = Unix.read out_r chunk 0 4096 in if n > 0 then (Buffer.add_subbytes seen chunk 0 n; read ()) in
          read ();
          let still_running = match Unix.waitpid [ Unix.WNOHANG ] pid with 0, _ -> true | _ -> false in
          (try Unix.kill pid Sys.sigkill with Unix.Unix_error _ -> ());
          ignore (Unix.waitpid [] pid); Unix.close out_r;
          Alcotest.(check bool) (what ^ ": the run still waits for its client") true still_running;
          Alcotest.(check bool) (what ^ ": its first line was read meanwhile: " ^ String.escaped (Buffer.contents seen)) true
            (List.mem expected (String.split_on_char '\n' (Buffer.contents seen))))
        [ ("run", [], "listening");
          ("run --engine machine", [ "--engine"; "machine" ], "listening");
          ("run --json", [ "--json" ], {|{"event":"output","text":"listening"}|});
          ("run --json --engine machine", [ "--json"; "--engine"; "machine" ], {|{"event":"output","text":"listening"}|}) ])

(* The warning of a routine that --stub-unmodelled ran as a no-op reaches standard error when the
   call runs, in both engines, while the program then waits on the host: a run killed there has
   said it (before, the closure engine kept its warnings until the run ended). *)
let stubbed_server port = Printf.sprintf {|MODULE stubbed
  VAR socketdev listener;
  VAR socketdev client;
  VAR num count;
  PROC main()
    TPReadNum count, "How many?";
    SocketCreate listener;
    SocketBind listener, "127.0.0.1", %d;
    SocketListen listener;
    SocketAccept listener, client \Time:=30;
  ENDPROC
ENDMODULE
|} port

let stub_warning_before_wait () =
  let dir = temp_dir () in
  Fun.protect ~finally:(fun () -> ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir)))) (fun () ->
      let file = Filename.concat dir "stubbed.mod" in
      write_file file (stubbed_server (free_port ()));
      let expected = "/stubbed.mod:6:5: warning: TPReadNum is not modelled; --stub-unmodelled ran it as a no-op" in
      List.iter (fun engine ->
          let err_r, err_w = Unix.pipe ~cloexec:true () in
          let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
          let pid = Unix.create_process binary
              [| binary; "run"; "--engine"; engine; "--stub-unmodelled"; "--fs"; Filename.concat dir "fs"; file |]
              devnull devnull err_w in
          Unix.close err_w; Unix.close devnull;
          let seen = Buffer.create 64 and chunk = Bytes.create 4096 in
          let deadline = Unix.gettimeofday () +. 10. in
          let has_line () = List.exists (fun l -> String.ends_with ~suffix:expected l)
              (String.split_on_char '\n' (Buffer.contents seen)) in
          let rec read () =
            if not (has_line ()) then
              let left = deadline -. Unix.gettimeofday () in
              if left > 0. then
                match Unix.select [ err_r ] [] [] left with
                | [], _, _ -> ()
                | _ -> let n = Unix.read err_r chunk 0 4096 in if n > 0 then (Buffer.add_subbytes seen chunk 0 n; read ()) in
          read ();
          let still_running = match Unix.waitpid [ Unix.WNOHANG ] pid with 0, _ -> true | _ -> false in
          (try Unix.kill pid Sys.sigkill with Unix.Unix_error _ -> ());
          ignore (Unix.waitpid [] pid); Unix.close err_r;
          Alcotest.(check bool) (engine ^ ": the run still waits for its client") true still_running;
          Alcotest.(check bool) (engine ^ ": the warning was read meanwhile: " ^ String.escaped (Buffer.contents seen))
            true (has_line ()))
        [ "closure"; "machine" ])

(* 200 clients connecting at once all get their connection within a bound, while the server
   accepts them one by one: the listen backlog holds them (R-13-cli1); with a backlog of 8 the
   kernel drops the rest's SYNs, and they retry after 1 s, 3 s, 7 s ... *)
let many_clients_server port n = Printf.sprintf {|MODULE many
  VAR socketdev listener;
  VAR socketdev client;
  PROC main()
    SocketCreate listener;
    SocketBind listener, "127.0.0.1", %d;
    SocketListen listener;
    TPWrite "listening";
    FOR i FROM 1 TO %d DO
      SocketAccept listener, client \Time:=30;
      SocketClose client;
    ENDFOR
    TPWrite "served";
  ENDPROC
ENDMODULE
|} port n

let simultaneous_clients () =
  let dir = temp_dir () in
  let n = 200 in
  Fun.protect ~finally:(fun () -> ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir)))) (fun () ->
      let port = free_port () in
      let file = Filename.concat dir "many.mod" and out = Filename.concat dir "out.txt" in
      write_file file (many_clients_server port n);
      let fd_out = Unix.openfile out [ Unix.O_WRONLY; Unix.O_CREAT; Unix.O_TRUNC ] 0o600 in
      let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
      let pid = Unix.create_process binary [| binary; "run"; "--fs"; Filename.concat dir "fs"; file |] devnull fd_out fd_out in
      Unix.close fd_out; Unix.close devnull;
      (* Listening once one client gets in. *)
      Unix.close (connect_retrying port);
      let t0 = Unix.gettimeofday () in
      let address = Unix.ADDR_INET (Unix.inet_addr_loopback, port) in
      let clients = List.init (n - 1) (fun _ ->
          let s = Unix.socket ~cloexec:true Unix.PF_INET Unix.SOCK_STREAM 0 in
          Unix.set_nonblock s;
          (try Unix.connect s address with Unix.Unix_error ((Unix.EINPROGRESS | Unix.EAGAIN), _, _) -> ());
          s) in
      (* Connected: writable with no pending error. *)
      let rec await pending =
        let left = t0 +. 0.9 -. Unix.gettimeofday () in
        if pending = [] || left <= 0. then pending
        else
          let _, writable, _ = Unix.select [] pending [] left in
          await (List.filter (fun s -> not (List.memq s writable && Unix.getsockopt_error s = None)) pending) in
      let late = await clients in
      let elapsed = Unix.gettimeofday () -. t0 in
      List.iter Unix.close clients;
      let status = wait_bounded pid 20. in
      Alcotest.(check int) (Printf.sprintf "clients not connected within 0.9 s (%.2f s)" elapsed) 0 (List.length late);
      (match status with
       | Some (Unix.WEXITED 0) -> ()
       | _ -> Alcotest.fail ("the server did not serve every client: " ^ read_file out));
      Alcotest.(check string) "server output" "listening\nserved\n" (read_file out))

(* R-13-sockwait1: an unmodified server waits for its client with WAIT_MAX (and accepts with
   the default time-out of 60 s) longer than --max-time lets the virtual clock run: with nothing
   else to happen the clock holds while the host waits, so the server answers each command, and
   the run ends when the client closes, with its virtual time still about 0 s. *)
let patient_server port = Printf.sprintf {|MODULE patient
  VAR socketdev listener;
  VAR socketdev client;
  VAR string request;
  VAR clock c;
  PROC main()
    ClkStart c;
    SocketCreate listener;
    SocketBind listener, "127.0.0.1", %d;
    SocketListen listener;
    SocketAccept listener, client;
    WHILE TRUE DO
      SocketReceive client \Str:=request \Time:=WAIT_MAX;
      IF request = "PING" SocketSend client \Str:="PONG\0A";
    ENDWHILE
  ERROR
    IF ERRNO = ERR_SOCK_CLOSED THEN
      TPWrite "closed at " \Num:=Round(ClkRead(c));
      SocketClose client;
      SocketClose listener;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
|} port

let wait_beyond_max_time () =
  let dir = temp_dir () in
  Fun.protect ~finally:(fun () -> ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote dir)))) (fun () ->
      List.iter (fun engine ->
          let port = free_port () in
          let file = Filename.concat dir "patient.mod" and out = Filename.concat dir "out.txt" in
          write_file file (patient_server port);
          let fd_out = Unix.openfile out [ Unix.O_WRONLY; Unix.O_CREAT; Unix.O_TRUNC ] 0o600 in
          let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
          let pid = Unix.create_process binary
              [| binary; "run"; "--engine"; engine; "--max-time"; "1"; "--fs"; Filename.concat dir "fs"; file |]
              devnull fd_out fd_out in
          Unix.close fd_out; Unix.close devnull;
          (* The client comes after --max-time's second of host time, and pauses as long between
             its commands. *)
          Unix.sleepf 1.2;
          let answers =
            match connect_retrying port with
            | s ->
                Fun.protect ~finally:(fun () -> Unix.close s) (fun () ->
                    List.map (fun c -> Unix.sleepf 1.2; send s c; read_line s) [ "PING"; "PING" ])
            | exception e -> ignore (wait_bounded pid 0.); raise e in
          let status = wait_bounded pid 10. in
          Alcotest.(check (list string)) (engine ^ ": answers") [ "PONG"; "PONG" ] answers;
          (match status with
           | Some (Unix.WEXITED 0) -> ()
           | Some _ -> Alcotest.fail (engine ^ ": the server did not end with status 0: " ^ read_file out)
           | None -> Alcotest.fail (engine ^ ": the server did not end when its client closed"));
          Alcotest.(check string) (engine ^ ": server output") "closed at 0\n" (read_file out))
        [ "closure"; "machine" ])

let suite = ("services", [
    Alcotest.test_case "command server over the loopback" `Quick command_server;
    Alcotest.test_case "sandbox escapes refused" `Quick escapes;
    Alcotest.test_case "bounds of the mass memory" `Quick file_bounds;
    Alcotest.test_case "--net and --map-address" `Quick address_policy;
    Alcotest.test_case "--save writes values that read back" `Quick literals;
    Alcotest.test_case "--save: a killed run leaves the old or the new module" `Quick kill_during_save;
    Alcotest.test_case "--save: both engines write the same modules" `Quick save_engines;
    Alcotest.test_case "a line is read while the run waits on the host" `Quick first_line_before_wait;
    Alcotest.test_case "a stub's warning is read while the run waits on the host" `Quick stub_warning_before_wait;
    Alcotest.test_case "200 simultaneous clients connect at once" `Quick simultaneous_clients;
    Alcotest.test_case "a wait beyond --max-time answers its client (R-13-sockwait1)" `Quick wait_beyond_max_time;
  ])
