type mode = Read | Write | Append

type file = { ic : in_channel option; oc : out_channel option }

type t = {
  sandbox : File_sandbox.t;
  sockets : Sockets.t;
  files : (int, file) Hashtbl.t;
  dirs : (int, string list ref) Hashtbl.t;
  raw : (int, Bytes.t * int ref) Hashtbl.t;
  texts : Text_tables.t;
  file_limit : int;
  mutable next : int;
}

let max_file_size = 64 * 1024 * 1024
let file_limit t = t.file_limit

let create ?sandbox ?sockets ?(max_file_size = max_file_size) () =
  { sandbox = (match sandbox with Some s -> s | None -> File_sandbox.create File_sandbox.default_root);
    sockets = (match sockets with Some s -> s | None -> Sockets.create ());
    files = Hashtbl.create 4; dirs = Hashtbl.create 2; raw = Hashtbl.create 4; texts = Text_tables.create (); file_limit = max_file_size; next = 1 }

let sandbox t = t.sandbox
let sockets t = t.sockets
let texts t = t.texts
let max_files = 32

let fresh t = let id = t.next in t.next <- t.next + 1; id
let new_object = fresh


let open_file t path mode =
  if Hashtbl.length t.files >= max_files then Error "ERR_FILEOPEN"
  else match File_sandbox.resolve t.sandbox path with
    | Error _ -> Error "ERR_FILEOPEN"
    | Ok host when Sys.file_exists host && Sys.is_directory host -> Error "ERR_FILEOPEN"
    | Ok host -> (
        try
          let file = match mode with
            | Read -> { ic = Some (open_in_bin host); oc = None }
            | Write -> { ic = None; oc = Some (open_out_gen [ Open_wronly; Open_creat; Open_trunc; Open_binary ] 0o644 host) }
            | Append -> { ic = None; oc = Some (open_out_gen [ Open_wronly; Open_creat; Open_append; Open_binary ] 0o644 host) } in
          let id = fresh t in
          Hashtbl.replace t.files id file; Ok id
        with Sys_error _ -> Error "ERR_FILEOPEN")

let close_file t id =
  match Hashtbl.find_opt t.files id with
  | Some f ->
      Option.iter close_in_noerr f.ic;
      Option.iter close_out_noerr f.oc;
      Hashtbl.remove t.files id
  | None -> ()

let is_open t id = Hashtbl.mem t.files id

let input t id = match Hashtbl.find_opt t.files id with
  | Some { ic = Some ic; _ } -> Ok ic
  | _ -> Error "ERR_FILEACC"

let output t id = match Hashtbl.find_opt t.files id with
  | Some { oc = Some oc; _ } -> Ok oc
  | _ -> Error "ERR_FILEACC"

let rewind t id = match Hashtbl.find_opt t.files id with
  | Some { ic = Some ic; _ } -> (try seek_in ic 0; Ok () with Sys_error _ -> Error "ERR_FILEACC")
  | Some { oc = Some oc; _ } -> (try flush oc; seek_out oc 0; Ok () with Sys_error _ -> Error "ERR_FILEACC")
  | _ -> Error "ERR_FILEACC"

let open_dir t path =
  match File_sandbox.resolve t.sandbox path with
  | Error _ -> Error "ERR_FILEACC"
  | Ok host -> (
      match Sys.readdir host with
      | names ->
          let names = List.sort compare (Array.to_list names) in
          let id = fresh t in
          (* "." and ".." come first, as a directory listing of the controller shows them. *)
          Hashtbl.replace t.dirs id (ref ("." :: ".." :: names)); Ok id
      | exception Sys_error _ -> Error "ERR_FILEACC")

let read_dir t id = match Hashtbl.find_opt t.dirs id with
  | None -> Error "ERR_FILEACC"
  | Some r -> (match !r with [] -> Ok None | n :: rest -> r := rest; Ok (Some n))

let close_dir t id = Hashtbl.remove t.dirs id

let rawbytes_capacity = 1024

let rawbytes t id =
  match Hashtbl.find_opt t.raw id with
  | Some (b, n) -> (b, !n)
  | None -> let b = Bytes.make rawbytes_capacity '\000' in Hashtbl.replace t.raw id (b, ref 0); (b, 0)

let set_rawbytes_length t id n =
  ignore (rawbytes t id);
  match Hashtbl.find_opt t.raw id with Some (_, r) -> r := n | None -> ()

let close_all t =
  List.iter (close_file t) (List.of_seq (Hashtbl.to_seq_keys t.files));
  Hashtbl.reset t.dirs;
  Sockets.close_all t.sockets
