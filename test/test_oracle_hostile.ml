(* Hostile implementations behind rapid-sem oracle and spec --impl (issue 21, doc/oracle.md
   "Bounds"): each is a small shell script written into a temporary folder; the verdict must
   say what the implementation did wrong, in a short report, and leave nothing running. *)

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"
let program = "golden/oracle-program.mod"
let reference = Filename.quote binary ^ " run --json {files}"

let contains s sub =
  let n = String.length sub and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = sub || go (i + 1)) in
  go 0

let folder = lazy (
  let d = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "rapid-hostile-%d" (Unix.getpid ())) in
  (try Unix.mkdir d 0o700 with Unix.Unix_error (Unix.EEXIST, _, _) -> ());
  d)

let script name body =
  let path = Filename.concat (Lazy.force folder) name in
  let oc = open_out_bin path in
  output_string oc body; close_out oc;
  path

let pid_file name = Filename.concat (Lazy.force folder) (name ^ ".pid")

(* A process is gone when /proc no longer has it or has only its zombie, which init reaps. *)
let gone pid =
  match open_in (Printf.sprintf "/proc/%d/stat" pid) with
  | exception Sys_error _ -> true
  | ic ->
      let line = try input_line ic with End_of_file -> "" in
      close_in ic;
      match String.rindex_opt line ')' with
      | Some i when i + 2 < String.length line -> line.[i + 2] = 'Z' || line.[i + 2] = 'X'
      | _ -> true

(* SIGKILL takes a moment to land: a process still there after two seconds was left behind. *)
let gone pid =
  let rec wait n = gone pid || (n > 0 && (Unix.sleepf 0.02; wait (n - 1))) in
  wait 100

let pid_in file =
  let ic = open_in file in
  let pid = int_of_string (String.trim (input_line ic)) in
  close_in ic; pid

let verdict ?(timeout = 20.) body =
  Unix.putenv "RAPID_SEM" binary;
  let impl = "sh " ^ Filename.quote (script "impl.sh" body) ^ " {file}" in
  let p = { Rapid_oracle.Oracle.name = "p.mod"; files = [ program ] } in
  Rapid_oracle.Oracle.verdict_report p (Rapid_oracle.Oracle.check ~timeout ~reference ~impl p)

let says what report sub =
  Alcotest.(check bool) (Printf.sprintf "%s: %S in %S" what sub report) true (contains report sub)

let short what report =
  Alcotest.(check bool) (Printf.sprintf "%s: a short report (%d bytes)" what (String.length report)) true
    (String.length report < 700)

let start = {|echo '{"event":"start","schema":"rapid-sem/2"}'|}

let deep_nesting () =
  let r = verdict (start ^ "\npython3 -c 'print(\"[\" * 500000)'\n") in
  says "deep" r "line 2: nested deeper than 100 arrays and objects"

let long_line () =
  let r = verdict "head -c 3000000 /dev/zero | tr '\\0' a\n" in
  says "no newline" r "line 1 is longer than 1048576 bytes (1 MiB)"; short "no newline" r

let endless_events () =
  let r = verdict (start ^ "\nyes '{\"event\":\"output\",\"text\":\"x\"}'\n") in
  says "endless" r "line 1000001: more than 1000000 events"

let long_event_clipped () =
  let line = {|print("{\"event\":\"output\",\"text\":\"" + "x" * 100000 + "\"}")|} in
  let r = verdict (start ^ "\npython3 -c " ^ Filename.quote line ^ "\n") in
  says "clipped" r "... (100028 bytes)"; short "clipped" r

(* The reading is bounded whatever the implementation writes on standard error: 600 MB of it in
   a rapid-sem limited to 400 MB of address space. *)
let stderr_drained () =
  let impl = "head -c 600000000 /dev/zero >&2; exec \"$RAPID_SEM\" run --json {file}" in
  let out = Filename.concat (Lazy.force folder) "stderr.out" in
  let cmd = Printf.sprintf "ulimit -v 400000; cd golden && %s oracle --impl %s oracle-program.mod > %s 2>&1"
      (Filename.quote binary) (Filename.quote impl) (Filename.quote out) in
  let status = Sys.command cmd in
  let ic = open_in_bin out in
  let text = really_input_string ic (in_channel_length ic) in
  close_in ic;
  Alcotest.(check (pair int string)) "agrees" (0, "oracle-program.mod: agree (29 events)\n1 agree, 0 diverge\n")
    (status, text)

(* The implementation's text in a report is valid UTF-8, cut between characters, and its
   control bytes are shown escaped: written as they are, ESC and its friends drive the
   terminal of whoever reads the verdict (issue 21). *)
let text_escaped () =
  let pairs = String.concat "" (List.init 1000 (fun _ -> "\xc3\xa9\xe2\x82\xac")) in
  let r = verdict (start ^ "\necho '{\"event\":\"routine-entered\",\"routine\":\"main\"}'\n"
                   ^ "echo '{\"event\":\"output\",\"text\":\"" ^ pairs ^ "\"}'\n") in
  says "cut between characters" r "\xe2\x82\xac\xc3\xa9... (5028 bytes)";
  let r = verdict "printf '\\377\\376\\033[2J{}\\n'\n" in
  says "escaped" r {|Invalid token '\FF\FE\1B[2J{}'|};
  Alcotest.(check bool) (Printf.sprintf "no raw control byte in %S" r) false
    (String.exists (fun c -> c = '\027' || Char.code c >= 0x80) r);
  Alcotest.(check string) "C1 control, DEL and tab escaped, a valid character kept" {|a\C2\9B\7F\09\C3(é|}
    (Rapid_oracle.Event_stream.clip "a\xc2\x9b\x7f\t\xc3(\xc3\xa9")

(* The oracle's memory is bounded by a line, not by what the implementation writes: 16 MB of
   values within every bound, and a million events, under 300 MB of address space (they took
   500 MB and a stack overflow when every event was kept). *)
let memory_bounded () =
  let file name body times =
    let path = Filename.concat (Lazy.force folder) name in
    let oc = open_out_bin path in
    output_string oc "{\"event\":\"start\",\"schema\":\"rapid-sem/2\"}\n";
    for _ = 1 to times do output_string oc body done;
    close_out oc; path in
  let zeros = "{\"event\":\"output\",\"a\":[0" ^ String.concat "" (List.init 79_989 (fun _ -> ",0")) ^ "]}\n" in
  let out = Filename.concat (Lazy.force folder) "memory.out" in
  List.iter (fun (what, path) ->
      let impl = "cat " ^ Filename.quote path ^ " # {file}" in
      let cmd = Printf.sprintf "ulimit -v 300000; exec %s oracle --impl %s %s > %s 2>&1" (Filename.quote binary)
          (Filename.quote impl) program (Filename.quote out) in
      let status = Sys.command (Printf.sprintf "sh -c %s" (Filename.quote cmd)) in
      let ic = open_in_bin out in
      let text = really_input_string ic (in_channel_length ic) in
      close_in ic;
      Alcotest.(check int) (what ^ ": the verdict, not a death: " ^ Rapid_oracle.Event_stream.clip text) 1 status;
      says what text "diverges at event 1")
    [ ("16 MB of values", file "values.txt" zeros 100);
      ("1,000,000 events", file "events.txt" "{\"event\":\"x\"}\n" 999_999) ]

let background_child_ended () =
  let pids = pid_file "background" in
  let r = verdict (Printf.sprintf "sleep 60 & echo $! > %s\nexec \"$RAPID_SEM\" run --json \"$1\"\n"
                     (Filename.quote pids)) in
  says "background" r "agree";
  Alcotest.(check bool) "the background child is gone" true (gone (pid_in pids))

let timed_out_group_ended () =
  let pids = pid_file "timeout" in
  let r = verdict ~timeout:0.5 (Printf.sprintf "sleep 60 & echo $! > %s\nsleep 60\n" (Filename.quote pids)) in
  says "timeout" r "the implementation did not finish in time";
  Alcotest.(check bool) "its child is gone" true (gone (pid_in pids))

let killed_by_signal () =
  let r = verdict (start ^ "\nkill -SEGV $$\n") in
  says "through the shell" r "the implementation was killed by signal SIGSEGV (the shell's exit status 139)";
  let r = verdict (start ^ "\nexec sh -c 'kill -TERM $$'\n") in
  says "the shell itself" r "killed by signal SIGTERM";
  let r = verdict (start ^ "\nexec python3 -c 'import os, signal; os.kill(os.getpid(), 40)'\n") in
  says "a real-time signal" r "killed by signal SIGRTMIN+6"

let spec_impl () =
  Unix.putenv "RAPID_SEM" binary;
  let case = Rapid_conformance.Spec_case.read "golden/spec-impl-cases/18-for-step.mod" in
  let run body =
    let template = "sh " ^ Filename.quote (script "spec-impl.sh" body) ^ " {mode} {options} {files}" in
    (Rapid_conformance.Impl_runner.run_case ~timeout:20. ~reference ~template case).detail in
  says "spec deep" (run (start ^ "\npython3 -c 'print(\"{\\\"a\\\":\" * 200000)'\n")) "nested deeper than 100";
  says "spec killed" (run (start ^ "\nkill -ABRT $$\n")) "killed by signal SIGABRT";
  let pids = pid_file "spec" in
  let detail = run (Printf.sprintf "sleep 60 & echo $! > %s\nshift\nexec \"$RAPID_SEM\" run --json \"$@\"\n"
                      (Filename.quote pids)) in
  Alcotest.(check string) "spec background: passes" "" detail;
  Alcotest.(check bool) "spec background: the child is gone" true (gone (pid_in pids))

let suite =
  ("oracle-hostile", [
      Alcotest.test_case "deep nesting refused before yojson" `Quick deep_nesting;
      Alcotest.test_case "a line longer than 1 MiB" `Quick long_line;
      Alcotest.test_case "endless events: at most 1,000,000" `Quick endless_events;
      Alcotest.test_case "a long event clipped in the report" `Quick long_event_clipped;
      Alcotest.test_case "the implementation's text escaped in a report" `Quick text_escaped;
      Alcotest.test_case "memory bounded by a line" `Quick memory_bounded;
      Alcotest.test_case "standard error drained, not held" `Quick stderr_drained;
      Alcotest.test_case "a background child killed at the end" `Quick background_child_ended;
      Alcotest.test_case "the group killed at the timeout" `Quick timed_out_group_ended;
      Alcotest.test_case "death by a signal named" `Quick killed_by_signal;
      Alcotest.test_case "spec --impl: the same bounds" `Quick spec_impl ])
