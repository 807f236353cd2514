(* Golden tests of the command line (Catala's practice): each test/golden/NAME.cmd holds the
   arguments of one rapid-sem run, NAME.out what it must print and its exit status, byte for byte.
   scripts/promote-golden.sh rewrites the .out files after a deliberate change. *)

let golden_dir = "golden"
let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      really_input_string ic (in_channel_length ic))

(* Runs rapid-sem with [args] in [golden_dir]; the transcript is what NAME.out holds. *)
let transcript args =
  let out = Filename.temp_file "rapid-sem" ".out" and err = Filename.temp_file "rapid-sem" ".err" in
  let command =
    Printf.sprintf "cd %s && %s %s > %s 2> %s" (Filename.quote golden_dir) (Filename.quote binary)
      args (Filename.quote out) (Filename.quote err)
  in
  let status = Sys.command command in
  let text = Printf.sprintf "$ rapid-sem %s\n--- stdout\n%s--- stderr\n%s--- exit %d\n" args
      (read_file out) (read_file err) status in
  Sys.remove out; Sys.remove err;
  text

let cases () =
  Sys.readdir golden_dir |> Array.to_list
  |> List.filter (fun f -> Filename.check_suffix f ".cmd")
  |> List.sort compare
  |> List.map Filename.chop_extension

let case name =
  Alcotest.test_case name `Quick (fun () ->
      let args = String.trim (read_file (Filename.concat golden_dir (name ^ ".cmd"))) in
      let expected = read_file (Filename.concat golden_dir (name ^ ".out")) in
      Alcotest.(check string) (name ^ ".out") expected (transcript args))

(* The interactive debugger prompts on a terminal (doc/debugger.md); from a pipe it writes the
   transcript alone. script(1) (util-linux's bsdutils, essential on Debian) gives the terminal. *)
let debugger_prompt () =
  let commands = Filename.temp_file "rapid-sem" ".in" and out = Filename.temp_file "rapid-sem" ".out" in
  Fun.protect ~finally:(fun () -> Sys.remove commands; Sys.remove out) (fun () ->
      let oc = open_out_bin commands in
      output_string oc "step\nquit\n"; close_out oc;
      let run shell =
        let status = Sys.command (Printf.sprintf "cd %s && timeout 20 %s < %s > %s 2>&1" (Filename.quote golden_dir) shell
                                    (Filename.quote commands) (Filename.quote out)) in
        (status, read_file out) in
      let debug = Printf.sprintf "%s debug debug-steps.mod" (Filename.quote binary) in
      let prompts text = List.length (String.split_on_char '(' text |> List.filter (fun p ->
          String.length p >= 11 && String.sub p 0 11 = "rapid-sem) ")) in
      let status, piped = run debug in
      Alcotest.(check int) "piped: exit 0" 0 status;
      Alcotest.(check int) "piped: no prompt" 0 (prompts piped);
      let status, on_terminal = run (Printf.sprintf "script -qec %s /dev/null" (Filename.quote debug)) in
      Alcotest.(check int) "terminal: exit 0" 0 status;
      (* One before each command: step, quit. *)
      Alcotest.(check int) ("terminal: a prompt before each command: " ^ String.escaped on_terminal) 2 (prompts on_terminal);
      (* --prompt TEXT: that prompt, piped too; an empty one: none, on a terminal too. *)
      let status, piped = run (Printf.sprintf "%s debug --prompt '(rapid-sem) ' debug-steps.mod" (Filename.quote binary)) in
      Alcotest.(check int) "--prompt piped: exit 0" 0 status;
      Alcotest.(check int) "--prompt piped: a prompt before each command" 2 (prompts piped);
      let quiet = Printf.sprintf "%s debug --prompt '' debug-steps.mod" (Filename.quote binary) in
      let status, on_terminal = run (Printf.sprintf "script -qec %s /dev/null" (Filename.quote quiet)) in
      Alcotest.(check int) "--prompt '': exit 0" 0 status;
      Alcotest.(check int) "--prompt '' on a terminal: no prompt" 0 (prompts on_terminal))

(* --save with a module read from standard input: the run goes on, and a warning says that module
   is not saved (it has no file), rather than nothing at all. *)
let save_from_stdin () =
  let dir = Filename.temp_file "rapid-sem" ".save" in
  Sys.remove dir;
  let err = Filename.temp_file "rapid-sem" ".err" in
  Fun.protect ~finally:(fun () -> ignore (Sys.command ("rm -rf " ^ Filename.quote dir)); Sys.remove err) (fun () ->
      let status = Sys.command (Printf.sprintf
          "printf 'MODULE S\\n  PERS num p := 1;\\n  PROC main()\\n    p := p + 1;\\n  ENDPROC\\nENDMODULE\\n' | \
           %s run --save %s - 2> %s" (Filename.quote binary) (Filename.quote dir) (Filename.quote err)) in
      Alcotest.(check int) "exit 0" 0 status;
      let text = read_file err in
      Alcotest.(check bool) ("warned: " ^ text) true
        (Str.string_match (Str.regexp ".*standard input (-) is not saved") text 0))

let suite = ("cli", List.map case (cases ()) @ [ Alcotest.test_case "the debugger prompts on a terminal" `Quick debugger_prompt;
                                                 Alcotest.test_case "--save warns of a module from standard input" `Quick
                                                   save_from_stdin ])
