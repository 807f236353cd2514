let mentions_socket text =
  let lower = String.lowercase_ascii text and key = "socket" in
  let n = String.length lower and k = String.length key in
  let rec from i = i + k <= n && (String.sub lower i k = key || from (i + 1)) in
  from 0

let read_file path =
  match open_in_bin path with
  | exception Sys_error _ -> ""
  | ic -> Fun.protect (fun () -> try really_input_string ic (in_channel_length ic) with Sys_error _ | End_of_file -> "")
            ~finally:(fun () -> close_in_noerr ic)

let uses_loopback (case : Spec_case.t) = List.exists (fun f -> mentions_socket (read_file f)) case.files

(* One file in the temporary folder: every checkout and process of the machine finds the same. *)
let lock_path = Filename.concat (Filename.get_temp_dir_name ()) "rapid-sem-loopback.lock"

let exclusive case f =
  if not (uses_loopback case) then f ()
  else
    match Unix.openfile lock_path [ Unix.O_RDWR; Unix.O_CREAT ] 0o666 with
    | exception Unix.Unix_error _ -> f ()
    | fd ->
        let rec lock () = try Unix.lockf fd Unix.F_LOCK 0 with Unix.Unix_error (Unix.EINTR, _, _) -> lock () in
        (match lock () with () -> () | exception Unix.Unix_error _ -> ());
        Fun.protect f ~finally:(fun () -> Unix.close fd)
