(* Several tasks (ch. 14) through the command line: a hand-shake through a system-global
   persistent, reproducible event streams, the pseudo-random order of --schedule, a deadlock
   and a persistent declared with two types. *)

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

let temp_dir () =
  let d = Filename.temp_file "rapid-sem-tasks" "" in
  Sys.remove d; Unix.mkdir d 0o755; d

let write dir name text =
  let path = Filename.concat dir name in
  let oc = open_out_bin path in
  output_string oc text; close_out oc; path

(* The standard output and exit status of rapid-sem with these arguments. *)
let run args =
  let out = Filename.temp_file "rapid-sem-tasks" ".out" in
  let fd = Unix.openfile out [ O_WRONLY; O_TRUNC ] 0o600 in
  let devnull = Unix.openfile "/dev/null" [ O_RDWR ] 0 in
  let pid = Unix.create_process binary (Array.of_list (binary :: args)) devnull fd devnull in
  let _, status = Unix.waitpid [] pid in
  Unix.close fd; Unix.close devnull;
  let ic = open_in_bin out in
  let text = really_input_string ic (in_channel_length ic) in
  close_in ic; Sys.remove out;
  (text, match status with Unix.WEXITED n -> n | _ -> -1)

let lines s = List.filter (( <> ) "") (String.split_on_char '\n' s)

let hand_shake_a = {|MODULE shake_a
  PERS num state := 0;
  PROC main()
    TPWrite "A sets 1";
    state := 1;
    WaitUntil state = 2;
    TPWrite "A saw 2";
    state := 3;
  ENDPROC
ENDMODULE
|}

let hand_shake_b = {|MODULE shake_b
  PERS num state;
  PROC main()
    WaitUntil state = 1;
    TPWrite "B saw 1";
    state := 2;
    WaitUntil state = 3;
    TPWrite "B saw 3";
  ENDPROC
ENDMODULE
|}

let shake_args dir =
  let a = write dir "a.mod" hand_shake_a and b = write dir "b.mod" hand_shake_b in
  [ "--task"; "T_ROB1=" ^ a; "--task"; "T_B=" ^ b ]

let test_hand_shake () =
  let dir = temp_dir () in
  let out, status = run ("run" :: shake_args dir) in
  Alcotest.(check int) "exit status" 0 status;
  Alcotest.(check (list string)) "the hand-shake, in order" [ "A sets 1"; "B saw 1"; "A saw 2"; "B saw 3" ] (lines out);
  (* Whatever the order of turns, the hand-shake orders the output. *)
  List.iter (fun seed ->
      let out, status = run ("run" :: "--schedule" :: string_of_int seed :: shake_args dir) in
      Alcotest.(check int) "exit status, seeded" 0 status;
      Alcotest.(check (list string)) (Printf.sprintf "the hand-shake, seed %d" seed)
        [ "A sets 1"; "B saw 1"; "A saw 2"; "B saw 3" ] (lines out)) [ 1; 2; 3; 99 ]

let test_json_reproducible () =
  let dir = temp_dir () in
  let once extra = run ("run" :: "--json" :: extra @ shake_args dir) in
  let first, s1 = once [] and second, s2 = once [] in
  Alcotest.(check int) "exit status" 0 s1;
  Alcotest.(check int) "exit status again" 0 s2;
  Alcotest.(check bool) "byte-identical run --json" true (first = second);
  let seeded, _ = once [ "--schedule"; "7" ] and seeded', _ = once [ "--schedule"; "7" ] in
  Alcotest.(check bool) "byte-identical run --json --schedule 7" true (seeded = seeded');
  (* Every event of a run of several tasks names its task (doc/trace-format.md). *)
  List.iter (fun l ->
      let j = Yojson.Safe.from_string l in
      match j with
      | `Assoc fields ->
          let event = match List.assoc_opt "event" fields with Some (`String e) -> e | _ -> "" in
          if event <> "start" && event <> "end" then
            Alcotest.(check bool) ("a task in " ^ l) true
              (match List.assoc_opt "task" fields with Some (`String ("T_ROB1" | "T_B")) -> true | _ -> false)
      | _ -> Alcotest.fail l) (lines first)

(* trace --task: each reduction and each statement line names its task. *)
let test_trace () =
  let dir = temp_dir () in
  let out, status = run ("trace" :: "--format" :: "jsonl" :: shake_args dir) in
  Alcotest.(check int) "exit status" 0 status;
  let steps = List.filter_map (fun l ->
      match Yojson.Safe.from_string l with
      | `Assoc fields when List.mem_assoc "rule" fields -> Some (List.assoc_opt "task" fields)
      | _ -> None) (lines out) in
  Alcotest.(check bool) "reductions" true (steps <> []);
  Alcotest.(check bool) "every reduction names its task" true
    (List.for_all (function Some (`String ("T_ROB1" | "T_B")) -> true | _ -> false) steps);
  Alcotest.(check bool) "both tasks step" true
    (List.mem (Some (`String "T_B")) steps && List.mem (Some (`String "T_ROB1")) steps);
  let out, status = run ("trace" :: "--level" :: "statement" :: shake_args dir) in
  Alcotest.(check int) "statement level: exit 0" 0 status;
  (* One line per statement, its task first; WaitUntil's line before the other task's write. *)
  let tasks_of_lines = List.filter_map (fun l ->
      match String.index_opt l ' ' with Some i when l.[0] = 'T' -> Some (String.sub l 0 i) | _ -> None) (lines out) in
  Alcotest.(check (list string)) "the tasks of the statement lines"
    [ "T_ROB1"; "T_B"; "T_ROB1"; "T_ROB1"; "T_B"; "T_B"; "T_B"; "T_ROB1"; "T_ROB1"; "T_B" ] tasks_of_lines;
  let out, status = run ("trace" :: "--format" :: "jsonl" :: "--samples" :: "10" :: shake_args dir) in
  Alcotest.(check int) "--samples with --task: exit 0" 0 status;
  (* The motion task's robot, T_ROB1's, stands still: a sample at 0 s at least. *)
  Alcotest.(check bool) "tcp-sample of the motion task's robot" true
    (List.exists (fun l -> try ignore (Str.search_forward (Str.regexp_string "\"tcp-sample\"") l 0); true
                   with Not_found -> false) (lines out))

let turns_a = {|MODULE turns_a
  PROC main()
    TPWrite "a1";
    TPWrite "a2";
    TPWrite "a3";
  ENDPROC
ENDMODULE
|}

let turns_b = {|MODULE turns_b
  PROC main()
    TPWrite "b1";
    TPWrite "b2";
    TPWrite "b3";
  ENDPROC
ENDMODULE
|}

let test_schedule () =
  let dir = temp_dir () in
  let a = write dir "a.mod" turns_a and b = write dir "b.mod" turns_b in
  let order extra = lines (fst (run ("run" :: "--task" :: ("A=" ^ a) :: "--task" :: ("B=" ^ b) :: extra))) in
  Alcotest.(check (list string)) "round robin" [ "a1"; "b1"; "a2"; "b2"; "a3"; "b3" ] (order []);
  let orders = List.map (fun seed -> order [ "--schedule"; string_of_int seed ]) [ 1; 2; 3; 4; 5; 6; 7; 8 ] in
  List.iter (fun o ->
      (* Each task's statements keep their order, whatever the interleaving. *)
      Alcotest.(check (list string)) "A in order" [ "a1"; "a2"; "a3" ] (List.filter (fun s -> s.[0] = 'a') o);
      Alcotest.(check (list string)) "B in order" [ "b1"; "b2"; "b3" ] (List.filter (fun s -> s.[0] = 'b') o)) orders;
  Alcotest.(check bool) "seeds give more than one order" true
    (List.length (List.sort_uniq compare orders) > 1);
  Alcotest.(check (list string)) "a seed gives its order again" (List.nth orders 2) (order [ "--schedule"; "3" ])

(* SplitMix64's reference output from state 0. *)
let test_splitmix () =
  let s = ref 0L in
  let a = Rapid_runtime.Task_rules.splitmix s in
  let b = Rapid_runtime.Task_rules.splitmix s in
  Alcotest.(check string) "first" "e220a8397b1dcdaf" (Printf.sprintf "%Lx" a);
  Alcotest.(check string) "second" "6e789e6aa1b965f4" (Printf.sprintf "%Lx" b)

let test_refusals () =
  let dir = temp_dir () in
  let a = write dir "a.mod" "MODULE ma\n  PERS num shared := 1;\n  PROC main()\n  ENDPROC\nENDMODULE\n" in
  let b = write dir "b.mod" "MODULE mb\n  PERS string shared;\n  PROC main()\n  ENDPROC\nENDMODULE\n" in
  let _, status = run [ "run"; "--task"; "A=" ^ a; "--task"; "B=" ^ b ] in
  Alcotest.(check int) "a persistent of two types: exit 2" 2 status;
  let w = write dir "w.mod" "MODULE mw\n  PERS bool lock := TRUE;\n  PROC main()\n    WaitTestAndSet lock;\n  ENDPROC\nENDMODULE\n" in
  let v = write dir "v.mod" "MODULE mv\n  PERS bool lock;\n  PROC main()\n    WaitTestAndSet lock;\n  ENDPROC\nENDMODULE\n" in
  let out, status = run [ "run"; "--json"; "--task"; "A=" ^ w; "--task"; "B=" ^ v ] in
  Alcotest.(check int) "both wait for ever: exit 3" 3 status;
  Alcotest.(check bool) "the end says deadlock" true
    (List.exists (fun l -> try ignore (Str.search_forward (Str.regexp_string "\"outcome\":\"deadlock\"") l 0); true
                   with Not_found -> false) (lines out));
  Alcotest.(check bool) "the reason names each task and its wait" true
    (List.exists (fun l -> try ignore (Str.search_forward (Str.regexp_string "(A for a semaphore set by nobody else; B for a semaphore") l 0); true
                   with Not_found -> false) (lines out));
  let _, status = run [ "run"; "--task"; "A=" ^ a; "--task"; "A=" ^ a ] in
  Alcotest.(check int) "a task twice: exit 2" 2 status;
  let _, status = run [ "run"; "--task"; "A=" ^ a; "--entry"; "B=main" ] in
  Alcotest.(check int) "an entry for no task: exit 2" 2 status;
  let out, status = run [ "run"; "--task"; "A=" ^ a; "--task"; "B=" ^ write dir "e.mod" "MODULE me\n  PERS num shared;\n  PROC go()\n    TPWrite \"go \" \\Num := shared;\n  ENDPROC\nENDMODULE\n"; "--entry"; "B=go" ] in
  Alcotest.(check int) "--entry NAME=ROUTINE: exit 0" 0 status;
  Alcotest.(check (list string)) "the entry routine ran" [ "go 1" ] (lines out)

(* The worlds of two tasks: one clock and the signals shared, interrupts each task's. *)
let test_worlds () =
  let module W = Rapid_controller.World in
  let io = match Rapid_controller.Io_config.parse ~file:"t.io" "signal do1 DO\n" with
    | Ok io -> io | Error m -> Alcotest.fail m in
  let a = W.create ~statement_time:0. io in
  let b = W.add_task a ~name:"T_B" ~motion:false in
  Alcotest.(check (list string)) "tasks" [ "T_ROB1"; "T_B" ] (W.task_names a);
  Alcotest.(check int) "numbers" 2 (W.task_number b);
  Alcotest.(check bool) "motion" true (W.motion_task a && not (W.motion_task b));
  let n = match W.connect b ~trap:7 with Ok n -> n | Error e -> Alcotest.fail e in
  (match W.order_timer b n ~period:1. ~single:true with Ok () -> () | Error e -> Alcotest.fail e);
  Alcotest.(check bool) "A's number is free in A" false (W.connected a n);
  W.advance_to a 1.5;
  Alcotest.(check (float 1e-9)) "one clock" 1.5 (W.now b);
  Alcotest.(check bool) "A takes nothing" true (W.take a = None);
  Alcotest.(check (option (pair int int))) "B's timer" (Some (n, 7)) (W.take b);
  let id = match W.find_signal a "do1" with Some i -> i | None -> Alcotest.fail "do1" in
  W.write a id 1.;
  Alcotest.(check (float 0.)) "one signal" 1. (W.read b id);
  Alcotest.(check int) "A arrives" 1 (W.sync_arrive a "meet");
  Alcotest.(check int) "B has not" 0 (W.sync_arrivals a "MEET" ~task:"t_b");
  ignore (W.sync_arrive b "Meet");
  Alcotest.(check int) "B has" 1 (W.sync_arrivals a "meet" ~task:"T_B")

(* The task-end object of each task (doc/trace-format.md): a task the run's deadlock caught says
   "deadlock" and what it waits for; one cut by the time limit of the run, "exhausted"; one that
   ended, "ended". *)
let test_task_ends () =
  let dir = temp_dir () in
  let outcome_of out task =
    List.find_map (fun l ->
        match Yojson.Safe.from_string l with
        | `Assoc f when List.assoc_opt "event" f = Some (`String "task-end") && List.assoc_opt "task" f = Some (`String task) ->
            Some ((match List.assoc_opt "outcome" f with Some (`String o) -> o | _ -> ""),
                  (match List.assoc_opt "reason" f with Some (`String r) -> r | _ -> ""))
        | _ -> None) (lines out) in
  let contains s sub = try ignore (Str.search_forward (Str.regexp_string sub) s 0); true with Not_found -> false in
  let w = write dir "w.mod" "MODULE mw\n  PERS bool lock := TRUE;\n  PROC main()\n    WaitTestAndSet lock;\n  ENDPROC\nENDMODULE\n" in
  let e = write dir "e.mod" "MODULE me\n  PROC main()\n  ENDPROC\nENDMODULE\n" in
  let out, status = run [ "run"; "--json"; "--task"; "A=" ^ w; "--task"; "B=" ^ e ] in
  Alcotest.(check int) "a deadlock: exit 3" 3 status;
  (match outcome_of out "A" with
   | Some ("deadlock", r) -> Alcotest.(check bool) "A says what it waits for" true (contains r "the task waits for a semaphore")
   | _ -> Alcotest.fail "A's task-end is not a deadlock");
  Alcotest.(check (option string)) "B ended" (Some "ended") (Option.map fst (outcome_of out "B"));
  let p = write dir "p.mod" "MODULE mp\n  PERS bool go := FALSE;\n  PROC main()\n    WaitUntil go;\n  ENDPROC\nENDMODULE\n" in
  let out, status = run [ "run"; "--json"; "--max-time"; "2"; "--task"; "A=" ^ p; "--task"; "B=" ^ e ] in
  Alcotest.(check int) "the time limit: exit 3" 3 status;
  Alcotest.(check (option string)) "A cut by the time limit" (Some "exhausted") (Option.map fst (outcome_of out "A"));
  Alcotest.(check (option string)) "B ended before" (Some "ended") (Option.map fst (outcome_of out "B"))

(* R-14-n: while a task waits on a socket for a peer on the host, its traps run and the other
   task goes on, and the virtual clock follows the host's. The client sends after 0.6 s. *)
let socket_server port = Printf.sprintf {|MODULE sock_a
  VAR socketdev server;
  VAR socketdev peer;
  VAR string text;
  VAR intnum tick;
  VAR num ticks := 0;
  VAR clock c;
  PROC main()
    SocketCreate server;
    SocketBind server, "127.0.0.1", %d;
    SocketListen server;
    SocketAccept server, peer \Time := 10;
    CONNECT tick WITH on_tick;
    ITimer 0.1, tick;
    ClkStart c;
    SocketReceive peer \Str := text \Time := 10;
    IDelete tick;
    TPWrite "received " + text;
    TPWrite "ticks " \Num := ticks;
    TPWrite "waited " \Num := ClkRead(c);
    SocketClose peer;
    SocketClose server;
  ENDPROC
  TRAP on_tick
    ticks := ticks + 1;
  ENDTRAP
ENDMODULE
|} port

let other_task = {|MODULE sock_b
  PROC main()
    FOR i FROM 1 TO 3 DO
      WaitTime 0.1;
      TPWrite "B tick";
    ENDFOR
  ENDPROC
ENDMODULE
|}

let test_socket_wait () =
  let dir = temp_dir () in
  let s0 = Unix.socket Unix.PF_INET Unix.SOCK_STREAM 0 in
  Unix.bind s0 (Unix.ADDR_INET (Unix.inet_addr_loopback, 0));
  let port = match Unix.getsockname s0 with Unix.ADDR_INET (_, p) -> p | _ -> 0 in
  Unix.close s0;
  let a = write dir "a.mod" (socket_server port) and b = write dir "b.mod" other_task in
  let out = Filename.concat dir "out.txt" in
  let fd = Unix.openfile out [ O_WRONLY; O_CREAT; O_TRUNC ] 0o600 in
  let devnull = Unix.openfile "/dev/null" [ O_RDWR ] 0 in
  let pid = Unix.create_process binary [| binary; "run"; "--task"; "T_ROB1=" ^ a; "--task"; "T_B=" ^ b |] devnull fd devnull in
  Unix.close fd; Unix.close devnull;
  let deadline = Unix.gettimeofday () +. 10. in
  let rec connect () =
    let s = Unix.socket Unix.PF_INET Unix.SOCK_STREAM 0 in
    match Unix.connect s (Unix.ADDR_INET (Unix.inet_addr_loopback, port)) with
    | () -> s
    | exception Unix.Unix_error (Unix.ECONNREFUSED, _, _) when Unix.gettimeofday () < deadline ->
        Unix.close s; Unix.sleepf 0.05; connect () in
  let s = connect () in
  Unix.sleepf 0.6;
  ignore (Unix.write_substring s "hi" 0 2);
  let _, status = Unix.waitpid [] pid in
  Unix.close s;
  Alcotest.(check bool) "exit 0" true (status = Unix.WEXITED 0);
  let ic = open_in_bin out in
  let o = lines (really_input_string ic (in_channel_length ic)) in
  close_in ic;
  Alcotest.(check (list string)) "B ran while A waited" [ "B tick"; "B tick"; "B tick" ]
    (List.filteri (fun i _ -> i < 3) o);
  Alcotest.(check string) "the data" "received hi" (List.nth o 3);
  let number prefix line =
    float_of_string (String.sub line (String.length prefix) (String.length line - String.length prefix)) in
  let ticks = number "ticks " (List.nth o 4) and waited = number "waited " (List.nth o 5) in
  Alcotest.(check bool) (Printf.sprintf "traps during the wait (%g)" ticks) true (ticks >= 3.);
  Alcotest.(check bool) (Printf.sprintf "the virtual clock followed the host (%g s)" waited) true
    (waited >= 0.3 && waited < 5.)

(* R-13-sockwait2: two tasks each waiting in SocketAccept, with nothing else in the run: the
   clock holds while they wait on the host, however small --max-time; a client at either port
   wakes that task. The clients come 1.5 s and 2 s after the servers listen, beyond the 1 s of
   --max-time. Both engines. *)
let accept_server name port = Printf.sprintf {|MODULE accept_%s
  VAR socketdev server;
  VAR socketdev peer;
  VAR string text;
  PROC main()
    SocketCreate server;
    SocketBind server, "127.0.0.1", %d;
    SocketListen server;
    SocketAccept server, peer \Time := 30;
    SocketReceive peer \Str := text \Time := 30;
    TPWrite "%s received " + text;
    SocketSend peer \Str := "%s";
    SocketClose peer;
    SocketClose server;
  ENDPROC
ENDMODULE
|} name port name name

(* The loopback helpers of the services' tests. *)
let free_port = Test_services.free_port
let connect_retrying = Test_services.connect_retrying

let test_two_accepts () =
  List.iter (fun engine ->
      let dir = temp_dir () in
      let pa = free_port () and pb = free_port () in
      let a = write dir "a.mod" (accept_server "A" pa) and b = write dir "b.mod" (accept_server "B" pb) in
      let out = Filename.concat dir "out.txt" in
      let fd = Unix.openfile out [ O_WRONLY; O_CREAT; O_TRUNC ] 0o600 in
      let devnull = Unix.openfile "/dev/null" [ O_RDWR ] 0 in
      let pid = Unix.create_process binary
          [| binary; "run"; "--engine"; engine; "--max-time"; "1"; "--task"; "T_A=" ^ a; "--task"; "T_B=" ^ b |]
          devnull fd devnull in
      Unix.close fd; Unix.close devnull;
      let started = Unix.gettimeofday () in
      (* Probe that both listen, then wait beyond --max-time before the first real client. *)
      let answer s text =
        ignore (Unix.write_substring s text 0 (String.length text));
        let buf = Bytes.create 16 in
        let n = try Unix.read s buf 0 16 with Unix.Unix_error _ -> 0 in
        Bytes.sub_string buf 0 n in
      Unix.sleepf 1.5;
      let sb = connect_retrying pb in
      let got_b = answer sb "hi" in
      Unix.sleepf 0.5;
      let sa = connect_retrying pa in
      let got_a = answer sa "ho" in
      let _, status = Unix.waitpid [] pid in
      Unix.close sa; Unix.close sb;
      let ic = open_in_bin out in
      let o = lines (really_input_string ic (in_channel_length ic)) in
      close_in ic;
      Alcotest.(check bool) (engine ^ ": the clients came after the time limit") true
        (Unix.gettimeofday () -. started > 1.9);
      Alcotest.(check bool) (engine ^ ": exit 0") true (status = Unix.WEXITED 0);
      Alcotest.(check (list string)) (engine ^ ": each task served its client, B first")
        [ "B received hi"; "A received ho" ] o;
      Alcotest.(check (pair string string)) (engine ^ ": the answers") ("A", "B") (got_a, got_b))
    [ "closure"; "machine" ]

(* check --task judges the buffers as run --task loads them: every case of spec/14-tasks that
   expects a semantic error is refused by check --task, and no other case is (R-14-c). *)
let test_check_agrees () =
  let dir = "../spec/14-tasks" in
  let cases = Sys.readdir dir |> Array.to_list |> List.filter (fun f -> Filename.check_suffix f ".task")
              |> List.sort compare in
  Alcotest.(check bool) "cases found" true (List.length cases > 10);
  List.iter (fun case ->
      let folder = Filename.concat dir case in
      let files = Sys.readdir folder |> Array.to_list |> List.filter (fun f -> Filename.check_suffix f ".mod")
                  |> List.sort compare in
      let directive file key =
        let ic = open_in_bin (Filename.concat folder file) in
        let text = really_input_string ic (in_channel_length ic) in
        close_in ic;
        let prefix = "! @" ^ key ^ " " in
        List.find_map (fun l ->
            let l = String.trim l in
            if String.length l > String.length prefix && String.sub l 0 (String.length prefix) = prefix then
              Some (String.sub l (String.length prefix) (String.length l - String.length prefix))
            else None) (String.split_on_char '\n' text) in
      let tasks = List.fold_left (fun acc f ->
          let t = Option.get (directive f "task") in
          if List.mem_assoc t acc then List.map (fun (n, fs) -> if n = t then (n, fs @ [ f ]) else (n, fs)) acc
          else acc @ [ (t, [ f ]) ]) [] files in
      let refused = List.exists (fun f -> match directive f "expect" with
          | Some e -> String.length e > 14 && String.sub e 0 14 = "semantic-error" | None -> false) files in
      let args = List.concat_map (fun (n, fs) ->
          [ "--task"; n ^ "=" ^ String.concat "," (List.map (Filename.concat folder) fs) ]) tasks in
      let _, status = run ("check" :: args) in
      Alcotest.(check int) (case ^ ": check --task") (if refused then 2 else 0) status) cases

(* Both engines through run --task --json (doc/semantics.md, "The second engine"): the same
   objects, line for line, and the same exit status, for round robin and several seeds; only
   the step counts are each engine's own (a machine step is not a unit of fuel). *)
let test_engines_agree () =
  let dir = temp_dir () in
  let steps = Str.regexp "\"steps\":[0-9]+" in
  let normal out = List.map (fun l -> Str.global_replace steps "\"steps\":_" l) (lines out) in
  let w = write dir "w.mod" "MODULE mw\n  PERS bool lock := TRUE;\n  PROC main()\n    WaitTestAndSet lock;\n  ENDPROC\nENDMODULE\n" in
  let e = write dir "e.mod" "MODULE me\n  PROC main()\n  ENDPROC\nENDMODULE\n" in
  let p = write dir "p.mod" "MODULE mp\n  PERS bool go := FALSE;\n  PROC main()\n    WaitUntil go;\n  ENDPROC\nENDMODULE\n" in
  let a = write dir "ta.mod" turns_a and b = write dir "tb.mod" turns_b in
  let runs = [
    ("the hand-shake", shake_args dir);
    ("turns", [ "--task"; "A=" ^ a; "--task"; "B=" ^ b ]);
    ("a deadlock", [ "--task"; "A=" ^ w; "--task"; "B=" ^ e ]);
    ("the time limit", [ "--max-time"; "2"; "--task"; "A=" ^ p; "--task"; "B=" ^ e ]);
    (* R-14-o: rounds of empty loops, a busy wait for the other task. *)
    ("empty loops", [ "--task"; "A=../spec/14-tasks/02-empty-loop-round.task/a.mod";
                      "--task"; "B=../spec/14-tasks/02-empty-loop-round.task/b.mod" ]);
    ("a busy wait", [ "--task"; "A=../spec/14-tasks/02-busy-wait-empty-loop.task/a.mod";
                      "--task"; "B=../spec/14-tasks/02-busy-wait-empty-loop.task/b.mod" ]);
  ] in
  List.iter (fun (what, args) ->
      List.iter (fun schedule ->
          let args = schedule @ args in
          let m, ms = run ("run" :: "--json" :: "--engine" :: "machine" :: args) in
          let c, cs = run ("run" :: "--json" :: "--engine" :: "closure" :: args) in
          let what = what ^ " " ^ String.concat " " schedule in
          Alcotest.(check int) (what ^ ": exit status") ms cs;
          Alcotest.(check bool) (what ^ ": events") true (List.length (lines m) > 3);
          Alcotest.(check (list string)) (what ^ ": the same objects") (normal m) (normal c);
          (* The closure engine is run's default with --task too. *)
          let d, ds = run ("run" :: "--json" :: args) in
          Alcotest.(check int) (what ^ ": default exit status") cs ds;
          Alcotest.(check (list string)) (what ^ ": the default is the closure engine") (lines c) (lines d))
        ([] :: List.map (fun s -> [ "--schedule"; string_of_int s ]) [ 1; 2; 3; 7; 99 ])) runs


(* Each task's data counts in the one budget of --max-memory (R-14-cli3): a module that fits the
   budget alone does not fit it twice, in either engine; more tasks than a controller runs are
   refused with a message, 20 run. *)
let big_data = {|MODULE big
  VAR num data{500};
  PROC main()
    data{1} := 1;
    TPWrite "ran";
  ENDPROC
ENDMODULE
|}

let test_task_budget () =
  let dir = temp_dir () in
  let file = write dir "big.mod" big_data in
  List.iter (fun engine ->
      let budget = [ "--engine"; engine; "--max-memory"; "60000" ] in
      let out, status = run ([ "run" ] @ budget @ [ file ]) in
      Alcotest.(check (pair string int)) (engine ^ ": one task fits") ("ran\n", 0) (out, status);
      let out, status = run ([ "run" ] @ budget @ [ "--task"; "A=" ^ file; "--task"; "B=" ^ file ]) in
      Alcotest.(check (pair string int)) (engine ^ ": two tasks exhaust the budget") ("", 3) (out, status);
      let tasks n = List.concat (List.init n (fun i -> [ "--task"; Printf.sprintf "T%d=%s" i file ])) in
      let out, status = run ([ "run"; "--engine"; engine ] @ tasks Rapid_runtime.Task_rules.max_tasks) in
      Alcotest.(check int) (engine ^ ": 20 tasks run") 0 status;
      Alcotest.(check int) (engine ^ ": each writes") Rapid_runtime.Task_rules.max_tasks (List.length (lines out));
      let err = Filename.concat dir "err.txt" in
      let status = Sys.command (Printf.sprintf "%s run --engine %s %s > /dev/null 2> %s" (Filename.quote binary) engine
                                  (String.concat " " (List.map Filename.quote (tasks 300))) (Filename.quote err)) in
      let ic = open_in_bin err in
      let message = really_input_string ic (in_channel_length ic) in
      close_in ic;
      Alcotest.(check (pair int string)) (engine ^ ": 300 tasks refused")
        (2, "rapid-sem: 300 tasks: a run has at most 20 tasks, as a controller with Multitasking (ch. 14)\n")
        (status, message)) [ "closure"; "machine" ]

let suite =
  ( "tasks",
    [ Alcotest.test_case "a two-task hand-shake through a PERS" `Quick test_hand_shake;
      Alcotest.test_case "run --json twice is byte-identical" `Quick test_json_reproducible;
      Alcotest.test_case "round robin and --schedule" `Quick test_schedule;
      Alcotest.test_case "SplitMix64" `Quick test_splitmix;
      Alcotest.test_case "the worlds of two tasks" `Quick test_worlds;
      Alcotest.test_case "trace --task" `Quick test_trace;
      Alcotest.test_case "refusals and deadlock" `Quick test_refusals;
      Alcotest.test_case "check --task agrees with run --task" `Quick test_check_agrees;
      Alcotest.test_case "task-end outcomes" `Quick test_task_ends;
      Alcotest.test_case "a socket wait beside traps and a task" `Quick test_socket_wait;
      Alcotest.test_case "two tasks in SocketAccept beyond --max-time" `Quick test_two_accepts;
      Alcotest.test_case "run --task: both engines, several schedules" `Quick test_engines_agree;
      Alcotest.test_case "the tasks share --max-memory; at most 20 tasks" `Quick test_task_budget ] )
