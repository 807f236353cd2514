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

let inside ~root path =
  let root = if String.length root > 1 && root.[String.length root - 1] = '/' then root else root ^ "/" in
  path ^ "/" = root || (String.length path >= String.length root && String.sub path 0 (String.length root) = root)

(* The real location of the longest existing prefix of the path: a symbolic link anywhere on
   the way that leads out of the root is refused. *)
let rec real path =
  match Unix.realpath path with
  | r -> Some r
  | exception Unix.Unix_error ((Unix.ENOENT | Unix.ENOTDIR), _, _) ->
      let parent = Filename.dirname path in
      if parent = path then None else Option.map (fun p -> Filename.concat p (Filename.basename path)) (real parent)
  | exception Unix.Unix_error _ -> None

let resolve t path =
  let device, rest =
    match String.index_opt path ':' with
    | Some i -> (String.uppercase_ascii (String.sub path 0 (i + 1)), String.sub path (i + 1) (String.length path - i - 1))
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
        let host = List.fold_left Filename.concat (Filename.concat t.root folder) parts in
        match Unix.realpath t.root, real host with
        | r, Some h when inside ~root:r h -> Ok host
        | _ -> Error "a symbolic link leads out of the sandbox"
        | exception Unix.Unix_error _ -> Error "the sandbox's folder cannot be reached"

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
    let data = Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic)) in
    let oc = open_out_bin dst in
    Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc data)
  end

let seed t ~device src =
  ensure t;
  match List.assoc_opt (String.uppercase_ascii device) devices with
  | Some folder -> copy_tree src (Filename.concat t.root folder)
  | None -> invalid_arg ("File_sandbox.seed: no device " ^ device)
