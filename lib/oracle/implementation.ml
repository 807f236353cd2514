type result = {
  stdout : string;
  stderr : string;
  status : [ `Exited of int | `Signaled of int | `Timed_out ];
}

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

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

let run ?(timeout = 60.) ~template files =
  let cmd = command_line ~template ~files in
  let out = Filename.temp_file "rapid-oracle" ".out" and err = Filename.temp_file "rapid-oracle" ".err" in
  Fun.protect ~finally:(fun () -> (try Sys.remove out with _ -> ()); (try Sys.remove err with _ -> ())) @@ fun () ->
  let fd_out = Unix.openfile out [ Unix.O_WRONLY; O_TRUNC ] 0o600
  and fd_err = Unix.openfile err [ Unix.O_WRONLY; O_TRUNC ] 0o600
  and fd_in = Unix.openfile "/dev/null" [ Unix.O_RDONLY ] 0 in
  let pid =
    Fun.protect ~finally:(fun () -> List.iter Unix.close [ fd_out; fd_err; fd_in ]) (fun () ->
        Unix.create_process "/bin/sh" [| "/bin/sh"; "-c"; cmd |] fd_in fd_out fd_err)
  in
  let deadline = Unix.gettimeofday () +. timeout in
  let rec wait () =
    match Unix.waitpid [ Unix.WNOHANG ] pid with
    | 0, _ ->
        if Unix.gettimeofday () > deadline then begin
          (try Unix.kill pid Sys.sigkill with Unix.Unix_error _ -> ());
          ignore (Unix.waitpid [] pid);
          `Timed_out
        end
        else (Unix.sleepf 0.002; wait ())
    | _, Unix.WEXITED n -> `Exited n
    | _, (Unix.WSIGNALED n | Unix.WSTOPPED n) -> `Signaled n
    | exception Unix.Unix_error (Unix.EINTR, _, _) -> wait ()
  in
  let status = wait () in
  { stdout = read_file out; stderr = read_file err; status }
