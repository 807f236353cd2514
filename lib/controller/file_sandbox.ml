type t = { root : string; mutable made : bool }

let default_root = Filename.concat ".rapid-sem" "fs"

let create root = { root; made = false }

let root t = t.root

(* The mass-memory units of a controller: HOME: (the system's home folder, also called
   DISKHOME: in the kernel's constant diskhome), TEMP: (disktemp), RAMDISK: (diskram), and a
   removable disk (REMOVABLE:, USB memory). *)
let devices = [
  ("HOME:", "HOME"); ("DISKHOME:", "HOME"); ("TEMP:", "TEMP"); ("RAMDISK:", "RAMDISK");
  ("REMOVABLE:", "REMOVABLE");
]

let rec make_dir path =
  if not (Sys.file_exists path) then begin
    make_dir (Filename.dirname path);
    try Unix.mkdir path 0o755 with Unix.Unix_error (Unix.EEXIST, _, _) -> ()
  end

let ensure t =
  if not t.made then begin
    make_dir t.root;
    List.iter (fun (_, d) -> make_dir (Filename.concat t.root d)) devices;
    t.made <- true
  end

(* The components of a host path, "." and empty ones dropped, ".." taken back lexically; None
   when ".." goes above the first component. *)
let normal parts =
  let step acc p = match acc, p with
    | None, _ -> None
    | Some acc, ("" | ".") -> Some acc
    | Some [], ".." -> None
    | Some (_ :: up), ".." -> Some up
    | Some acc, p -> Some (p :: acc) in
  Option.map List.rev (List.fold_left step (Some []) parts)

let split path = String.split_on_char '/' path

(* The part of an absolute host path under the root (the root's real path, or the root as given
   made absolute), if it is under it. *)
let under_root roots target =
  let rec strip prefix parts = match prefix, parts with
    | [], rest -> Some rest
    | p :: prefix, q :: parts when p = q -> strip prefix parts
    | _ -> None in
  match normal (split target) with
  | None -> None
  | Some parts -> List.find_map (fun root -> strip root parts) roots

let max_links = 40  (* the host's own bound (SYMLOOP_MAX on Linux) *)

type location = { parents : string list; name : string }

(* The components of a path under the root with every symbolic link on the way replaced by
   what it names, read with lstat and readlink, never by the host's own resolution: a link
   that leads out of the root is refused whether or not its target exists, and a link at the
   end is checked even when [follow] is false (then the link itself is the location). What is
   found stays a path under the root: the operations walk it from the root's folder without
   following any link (Sandbox_calls), so a link put in the way later is an error, not an
   escape. *)
let follow_links ~roots ~root ~follow parts =
  let out = Error "a symbolic link leads out of the sandbox" in
  let rec go here todo links =
    match todo with
    | [] -> Ok (List.rev here)
    | ("" | ".") :: rest -> go here rest links
    | ".." :: rest -> (match here with [] -> out | _ :: up -> go up rest links)
    | c :: rest ->
        let host = String.concat "/" (root :: List.rev (c :: here)) in
        match Unix.lstat host with
        | { Unix.st_kind = Unix.S_LNK; _ } when links >= max_links -> Error "too many symbolic links"
        | { Unix.st_kind = Unix.S_LNK; _ } -> (
            match Unix.readlink host with
            | exception Unix.Unix_error _ -> Error "a symbolic link cannot be read"
            | target ->
                let next = if Filename.is_relative target then Ok (here, split target)
                  else match under_root roots target with
                    | Some inside -> Ok ([], inside)
                    | None -> out in
                match next with
                | Error _ as e -> e
                | Ok (start, todo) when rest = [] && not follow ->
                    Result.map (fun _ -> List.rev (c :: here)) (go start todo (links + 1))
                | Ok (start, todo) -> go start (todo @ rest) (links + 1))
        | _ -> go (c :: here) rest links
        | exception Unix.Unix_error _ -> go (c :: here) rest links in
  go [] parts 0

let locate ?(follow = true) t path =
  let device, rest =
    match String.index_opt path ':' with
    | Some i ->
        (String.uppercase_ascii (String.sub path 0 (i + 1)), String.sub path (i + 1) (String.length path - i - 1))
    | None -> ("HOME:", path) in
  match List.assoc_opt device devices with
  | None -> Error (Printf.sprintf "no device %s" device)
  | Some _ when String.index_opt path ':' = None && String.length path > 0 && (path.[0] = '/' || path.[0] = '\\') ->
      Error "a host path, outside the controller's devices"
  | Some folder ->
      let parts = String.split_on_char '/' (String.map (fun c -> if c = '\\' then '/' else c) rest) in
      let parts = List.filter (fun p -> p <> "" && p <> ".") parts in
      if List.mem ".." parts then Error "a path with .. leads out of its device"
      else if List.exists (fun p -> String.contains p '\000') parts then Error "a NUL character in the path"
      else match ensure t with
      | exception (Unix.Unix_error _ | Sys_error _) -> Error "the sandbox's folder cannot be made"
      | () ->
          match Unix.realpath t.root with
          | exception Unix.Unix_error _ -> Error "the sandbox's folder cannot be reached"
          | real ->
              let absolute = if Filename.is_relative t.root then Filename.concat (Sys.getcwd ()) t.root else t.root in
              let roots = List.filter_map (fun r -> normal (split r)) [ real; absolute ] in
              match follow_links ~roots ~root:t.root ~follow (folder :: parts) with
              | Error _ as e -> e
              | Ok [] -> Error "the sandbox's own folder is no file of a device"
              | Ok components ->
                  let rev = List.rev components in
                  Ok { parents = List.rev (List.tl rev); name = List.hd rev }

let host t l = String.concat "/" ((t.root :: l.parents) @ [ l.name ])

let resolve t path = Result.map (host t) (locate t path)

let failure e = Error (Unix.error_message e)

(* The location's folder, reached from the root without following a link. *)
let in_parent t l f =
  match Sandbox_calls.walk t.root l.parents with
  | exception Unix.Unix_error (e, _, _) -> failure e
  | dir ->
      Fun.protect ~finally:(fun () -> Unix.close dir) (fun () ->
          try f dir with Unix.Unix_error (e, _, _) -> failure e)

let kind t l = match in_parent t l (fun dir -> Ok (Sandbox_calls.kind_at dir l.name)) with
  | Ok k -> k
  | Error _ -> None

(* Opened without waiting, then refused unless a regular file: a FIFO, a socket or a device
   would block the host or is no file of a mass memory. Truncated only then. *)
let open_file t l how =
  in_parent t l (fun dir ->
      let fd = Sandbox_calls.open_at dir l.name how in
      match (Unix.fstat fd).Unix.st_kind with
      | Unix.S_REG ->
          if how = Sandbox_calls.Write then Unix.ftruncate fd 0;
          if how = Sandbox_calls.Append then ignore (Unix.lseek fd 0 Unix.SEEK_END);
          Unix.clear_nonblock fd;
          Ok fd
      | _ -> Unix.close fd; Error "not a regular file"
      | exception Unix.Unix_error (e, _, _) -> Unix.close fd; failure e)

let remove_file t l = in_parent t l (fun dir -> Ok (Sandbox_calls.unlink_at dir l.name ~folder:false))
let remove_folder t l = in_parent t l (fun dir -> Ok (Sandbox_calls.unlink_at dir l.name ~folder:true))
let make_folder t l = in_parent t l (fun dir -> Ok (Sandbox_calls.mkdir_at dir l.name))

let rename t a b =
  in_parent t a (fun da -> in_parent t b (fun db -> Ok (Sandbox_calls.rename_at da a.name db b.name)))

let read_folder t l = in_parent t l (fun dir -> Ok (Sandbox_calls.read_dir_at dir l.name))

let temporary () =
  let f = Filename.temp_file "rapid-sem-fs" "" in
  Sys.remove f;
  Unix.mkdir f 0o700;
  create f

let rec remove_tree path =
  match Unix.lstat path with
  | { Unix.st_kind = Unix.S_DIR; _ } ->
      Array.iter (fun n -> remove_tree (Filename.concat path n)) (try Sys.readdir path with Sys_error _ -> [||]);
      (try Unix.rmdir path with Unix.Unix_error _ -> ())
  | _ -> (try Unix.unlink path with Unix.Unix_error _ -> ())
  | exception Unix.Unix_error _ -> ()

let remove t = remove_tree t.root

let rec copy_tree src dst =
  if Sys.is_directory src then begin
    make_dir dst;
    Array.iter (fun n -> copy_tree (Filename.concat src n) (Filename.concat dst n)) (Sys.readdir src)
  end else begin
    let ic = open_in_bin src in
    let data =
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic)) in
    let oc = open_out_bin dst in
    Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc data)
  end

let seed t ~device src =
  ensure t;
  match List.assoc_opt (String.uppercase_ascii device) devices with
  | Some folder -> copy_tree src (Filename.concat t.root folder)
  | None -> invalid_arg ("File_sandbox.seed: no device " ^ device)
