type status = [ `Exited of int | `Signaled of int | `Timed_out ]
type result = { status : status; stderr : string; refused : string option }

let max_line = 1 lsl 20
let max_output = 64 lsl 20
let stderr_kept = 4096

let replace_all ~sub ~by s =
  let n = String.length sub in
  let b = Buffer.create (String.length s) in
  let rec go i =
    if i > String.length s - n then Buffer.add_string b (String.sub s i (String.length s - i))
    else if String.sub s i n = sub then (Buffer.add_string b by; go (i + n))
    else (Buffer.add_char b s.[i]; go (i + 1))
  in
  go 0; Buffer.contents b

let contains ~sub s = replace_all ~sub ~by:"" s <> s

let command_line ~template ~files =
  (* A program here is one task: a template written for spec --impl's cases of several tasks
     serves too. *)
  let template = replace_all ~sub:"{tasks}" ~by:"" template in
  let quoted = List.map Filename.quote files in
  let all = String.concat " " quoted in
  let first = match quoted with f :: _ -> f | [] -> "" in
  if contains ~sub:"{file}" template || contains ~sub:"{files}" template then
    replace_all ~sub:"{file}" ~by:first (replace_all ~sub:"{files}" ~by:all template)
  else template ^ " " ^ all

(* Linux's numbers, which a shell's status 128+N reports (POSIX 2.8.2); OCaml's own (negative)
   numbers for a process that died itself. *)
let linux_signals = [
  (1, "SIGHUP"); (2, "SIGINT"); (3, "SIGQUIT"); (4, "SIGILL"); (5, "SIGTRAP"); (6, "SIGABRT");
  (7, "SIGBUS"); (8, "SIGFPE"); (9, "SIGKILL"); (10, "SIGUSR1"); (11, "SIGSEGV"); (12, "SIGUSR2");
  (13, "SIGPIPE"); (14, "SIGALRM"); (15, "SIGTERM"); (16, "SIGSTKFLT"); (17, "SIGCHLD");
  (18, "SIGCONT"); (19, "SIGSTOP"); (20, "SIGTSTP"); (21, "SIGTTIN"); (22, "SIGTTOU");
  (23, "SIGURG"); (24, "SIGXCPU"); (25, "SIGXFSZ"); (26, "SIGVTALRM"); (27, "SIGPROF");
  (28, "SIGWINCH"); (29, "SIGIO"); (30, "SIGPWR"); (31, "SIGSYS") ]

let ocaml_signals = Sys.[
  (sighup, "SIGHUP"); (sigint, "SIGINT"); (sigquit, "SIGQUIT"); (sigill, "SIGILL");
  (sigtrap, "SIGTRAP"); (sigabrt, "SIGABRT"); (sigbus, "SIGBUS"); (sigfpe, "SIGFPE");
  (sigkill, "SIGKILL"); (sigusr1, "SIGUSR1"); (sigsegv, "SIGSEGV"); (sigusr2, "SIGUSR2");
  (sigpipe, "SIGPIPE"); (sigalrm, "SIGALRM"); (sigterm, "SIGTERM"); (sigchld, "SIGCHLD");
  (sigcont, "SIGCONT"); (sigstop, "SIGSTOP"); (sigtstp, "SIGTSTP"); (sigttin, "SIGTTIN");
  (sigttou, "SIGTTOU"); (sigurg, "SIGURG"); (sigxcpu, "SIGXCPU"); (sigxfsz, "SIGXFSZ");
  (sigvtalrm, "SIGVTALRM"); (sigprof, "SIGPROF"); (sigpoll, "SIGIO"); (sigsys, "SIGSYS") ]

let signal_name n =
  match List.assoc_opt n (if n < 0 then ocaml_signals else linux_signals) with
  | Some name -> name
  | None -> if n >= 34 && n <= 64 then Printf.sprintf "SIGRTMIN+%d" (n - 34) else Printf.sprintf "signal %d" n

let death = function
  | `Signaled n -> Some ("killed by signal " ^ signal_name n)
  | `Exited s when s > 128 && s <= 128 + 64 ->
      Some (Printf.sprintf "killed by signal %s (the shell's exit status %d)" (signal_name (s - 128)) s)
  | `Exited _ | `Timed_out -> None

let kill_group pid = try Unix.kill (-pid) Sys.sigkill with Unix.Unix_error _ -> ()

(* Before it is reaped, the command itself too: it may not have made its group yet (and then
   has no child). Once reaped its number may be another's, but not its group's while the
   group has a member. *)
let kill_unreaped pid = kill_group pid; try Unix.kill pid Sys.sigkill with Unix.Unix_error _ -> ()

let rec restart f = try f () with Unix.Unix_error (Unix.EINTR, _, _) -> restart f

(* The command in a session and process group of its own (OCaml 4.13's Unix has setsid, not
   setpgid), so that what it leaves behind (a child in the background, a child still writing
   when the time is up) can be ended with it. *)
let spawn cmd ~stdout ~stderr =
  let null = Unix.openfile "/dev/null" [ Unix.O_RDONLY; O_CLOEXEC ] 0 in
  match Unix.fork () with
  | exception e -> Unix.close null; raise e
  | 0 -> (
      try
        ignore (Unix.setsid ());
        (* rapid-sem ignores SIGPIPE, and an ignored signal stays ignored across exec. *)
        Sys.set_signal Sys.sigpipe Sys.Signal_default;
        Unix.dup2 null Unix.stdin; Unix.dup2 stdout Unix.stdout; Unix.dup2 stderr Unix.stderr;
        Unix.execv "/bin/sh" [| "/bin/sh"; "-c"; cmd |]
      with _ -> Unix._exit 127)
  | pid ->
      Unix.close null;
      pid

(* rapid-sem interrupted while the command runs takes the command's group with it. *)
let with_group_ended_on_signals pid f =
  let fatal = [ Sys.sigint; Sys.sigterm; Sys.sighup ] in
  let previous = List.map (fun s ->
      (s, Sys.signal s (Sys.Signal_handle (fun s ->
           kill_group pid;
           Sys.set_signal s Sys.Signal_default;
           Unix.kill (Unix.getpid ()) s)))) fatal in
  Fun.protect f ~finally:(fun () ->
      kill_group pid;
      List.iter (fun (s, b) -> Sys.set_signal s b) previous)

let run ?(timeout = 60.) ~template ~on_line files =
  let cmd = command_line ~template ~files in
  let out_r, out_w = Unix.pipe ~cloexec:true () in
  let err_r, err_w = Unix.pipe ~cloexec:true () in
  let pid =
    Fun.protect ~finally:(fun () -> Unix.close out_w; Unix.close err_w) (fun () ->
        try spawn cmd ~stdout:out_w ~stderr:err_w
        with e -> Unix.close out_r; Unix.close err_r; raise e)
  in
  with_group_ended_on_signals pid @@ fun () ->
  Fun.protect ~finally:(fun () -> Unix.close out_r; Unix.close err_r) @@ fun () ->
  (* [open_fds]: the pipes not yet at their end; both are closed once, at the end. *)
  let deadline = Unix.gettimeofday () +. timeout in
  let chunk = Bytes.create 65536 in
  let line = Buffer.create 256 and err = Buffer.create 256 in
  let line_no = ref 1 and total = ref 0 and refused = ref None and status = ref None in
  let open_fds = ref [ out_r; err_r ] in
  let refuse m = if !refused = None then refused := Some m in
  let give_line () =
    let text = Buffer.contents line in
    Buffer.clear line;
    (match on_line !line_no text with Ok () -> () | Error m -> refuse m);
    incr line_no
  in
  let take_output n =
    total := !total + n;
    let rec go i =
      if i < n && !refused = None then
        match Bytes.index_from_opt chunk i '\n' with
        | Some j when j < n ->
            if Buffer.length line + (j - i) > max_line then refuse_long ()
            else (Buffer.add_subbytes line chunk i (j - i); give_line (); go (j + 1))
        | _ ->
            if Buffer.length line + (n - i) > max_line then refuse_long ()
            else Buffer.add_subbytes line chunk i (n - i)
    and refuse_long () =
      refuse (Printf.sprintf "line %d is longer than %d bytes (1 MiB)" !line_no max_line)
    in
    go 0;
    if !total > max_output && !refused = None then
      refuse (Printf.sprintf "more than %d bytes (64 MiB) on standard output" max_output)
  in
  let close fd = open_fds := List.filter (( <> ) fd) !open_fds in
  let reap () =
    if !status = None then
      match restart (fun () -> Unix.waitpid [ Unix.WNOHANG ] pid) with
      | 0, _ -> ()
      | _, Unix.WEXITED n -> status := Some (`Exited n); kill_group pid
      | _, (Unix.WSIGNALED n | Unix.WSTOPPED n) -> status := Some (`Signaled n); kill_group pid
      (* WSTOPPED only comes with WUNTRACED: a stopped command waits for its timeout. *)
  in
  let finish s = kill_unreaped pid; ignore (restart (fun () -> Unix.waitpid [] pid)); status := Some s in
  let rec loop () =
    reap ();
    if !refused <> None && List.mem out_r !open_fds then begin
      (* Nothing more of standard output is read: what still writes there is killed. *)
      close out_r;
      if !status = None then finish (`Signaled Sys.sigkill);
      loop ()
    end
    (* Standard error is drained while the command runs, lest it block on a full pipe; once it
       has ended, only standard output's end is waited for. *)
    else if (not (List.mem out_r !open_fds)) && !status <> None then ()
    else
      let left = deadline -. Unix.gettimeofday () in
      if left <= 0. then (if !status = None then finish `Timed_out)
      else if !open_fds = [] then (Unix.sleepf (Float.min left 0.002); loop ())
      else begin
        (match restart (fun () -> Unix.select !open_fds [] [] (Float.min left 0.1)) with
         | ready, _, _ ->
             List.iter (fun fd ->
                 match restart (fun () -> Unix.read fd chunk 0 (Bytes.length chunk)) with
                 | 0 -> close fd
                 | n ->
                     if fd = out_r then (if !refused = None then take_output n)
                     else Buffer.add_subbytes err chunk 0 (max 0 (min n (stderr_kept - Buffer.length err)))
                 | exception Unix.Unix_error (_, _, _) -> close fd) ready);
        loop ()
      end
  in
  loop ();
  (* A last line without its newline is a line. *)
  if !refused = None && Buffer.length line > 0 && not (List.mem out_r !open_fds) then give_line ();
  let status = match !status with Some s -> s | None -> `Timed_out in
  { status; stderr = Buffer.contents err; refused = !refused }
