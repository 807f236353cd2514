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
  quota : int;
  mutable written : int;  (* bytes written into files in this run, against [quota] *)
  mutable next : int;
  egm_devices : Egm_channel.device list;
  mutable egm_channels : Egm_channel.t list;  (* open, closed with the run's services *)
  operator : Operator_script.t option;        (* the FlexPendant's scripted operator (R-13-ui2) *)
}

let max_file_size = 64 * 1024 * 1024
let max_total_size = 256 * 1024 * 1024

let create ?sandbox ?sockets ?(egm_devices = []) ?(max_file_size = max_file_size) ?(max_total_size = max_total_size)
    ?operator () =
  { sandbox = (match sandbox with Some s -> s | None -> File_sandbox.create File_sandbox.default_root);
    sockets = (match sockets with Some s -> s | None -> Sockets.create ());
    files = Hashtbl.create 4; dirs = Hashtbl.create 2; raw = Hashtbl.create 4; texts = Text_tables.create ();
    file_limit = max_file_size; quota = max_total_size; written = 0; next = 1;
    egm_devices; egm_channels = []; operator }

let sandbox t = t.sandbox
let sockets t = t.sockets
let egm_devices t = t.egm_devices
let operator t = t.operator

let open_egm t d =
  Result.map (fun c -> t.egm_channels <- c :: t.egm_channels; c) (Egm_channel.open_channel d)

let close_egm t c =
  Egm_channel.close c;
  t.egm_channels <- List.filter (fun x -> x != c) t.egm_channels
let texts t = t.texts
let max_files = 32

let fresh t = let id = t.next in t.next <- t.next + 1; id
let new_object = fresh


module FS = File_sandbox

let open_file t path mode =
  if Hashtbl.length t.files >= max_files then Error "ERR_FILEOPEN"
  else match FS.locate t.sandbox path with
    | Error _ -> Error "ERR_FILEOPEN"
    | Ok l ->
        let how : Sandbox_calls.how = match mode with Read -> Read | Write -> Write | Append -> Append in
        match FS.open_file t.sandbox l how with
        | Error _ -> Error "ERR_FILEOPEN"
        | Ok fd ->
            let file = match mode with
              | Read -> { ic = Some (Unix.in_channel_of_descr fd); oc = None }
              | Write | Append -> { ic = None; oc = Some (Unix.out_channel_of_descr fd) } in
            Option.iter (fun ic -> set_binary_mode_in ic true) file.ic;
            Option.iter (fun oc -> set_binary_mode_out oc true) file.oc;
            let id = fresh t in
            Hashtbl.replace t.files id file; Ok id

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

(* A full mass memory: ABB's pages of Write, WriteBin, WriteStrBin and CopyFile give
   ERR_FILEACC for a write that fails (R-13-sandbox1). *)
let over_quota t n = n > t.quota - t.written

let write t id text =
  let n = String.length text in
  match Hashtbl.find_opt t.files id with
  | Some { oc = Some oc; _ } -> (
      match pos_out oc + n > t.file_limit with
      | true -> Error "ERR_FILESIZE"
      | false when over_quota t n -> Error "ERR_FILEACC"
      | false -> (
          try output_string oc text; flush oc; t.written <- t.written + n; Ok ()
          with Sys_error _ -> Error "ERR_FILEACC")
      | exception Sys_error _ -> Error "ERR_FILEACC")
  | _ -> Error "ERR_FILEACC"

let rewind t id = match Hashtbl.find_opt t.files id with
  | Some { ic = Some ic; _ } -> (try seek_in ic 0; Ok () with Sys_error _ -> Error "ERR_FILEACC")
  | Some { oc = Some oc; _ } -> (try flush oc; seek_out oc 0; Ok () with Sys_error _ -> Error "ERR_FILEACC")
  | _ -> Error "ERR_FILEACC"

let open_dir t path =
  match Result.bind (FS.locate t.sandbox path) (FS.read_folder t.sandbox) with
  | Error _ -> Error "ERR_FILEACC"
  | Ok names ->
      let names = List.sort compare (Array.to_list names) in
      let id = fresh t in
      (* "." and ".." come first, as a directory listing of the controller shows them. *)
      Hashtbl.replace t.dirs id (ref ("." :: ".." :: names)); Ok id

let read_dir t id = match Hashtbl.find_opt t.dirs id with
  | None -> Error "ERR_FILEACC"
  | Some r -> (match !r with [] -> Ok None | n :: rest -> r := rest; Ok (Some n))

let close_dir t id = Hashtbl.remove t.dirs id

(* ---------------------------------------------------------------- paths *)

let ( let* ) = Result.bind
let access r = Result.map_error (fun _ -> "ERR_FILEACC") r
let located ?follow t path = access (FS.locate ?follow t.sandbox path)

let file_kind t path =
  let* l = located t path in
  Ok (Option.map fst (FS.kind t.sandbox l))

let file_size t path =
  let* l = located t path in
  match FS.kind t.sandbox l with Some (Unix.S_REG, size) -> Ok size | _ -> Error "ERR_FILEACC"

(* The entry itself: a link (one that stays inside) is removed, not what it names. *)
let remove_file t path =
  let* l = located ~follow:false t path in
  match FS.kind t.sandbox l with
  | Some ((Unix.S_REG | Unix.S_LNK), _) -> access (FS.remove_file t.sandbox l)
  | _ -> Error "ERR_FILEACC"

let make_dir t path =
  let* l = located t path in
  if FS.kind t.sandbox l <> None then Error "ERR_FILEEXIST" else access (FS.make_folder t.sandbox l)

let remove_dir t path =
  let* l = located t path in
  match FS.kind t.sandbox l with
  | Some (Unix.S_DIR, _) -> access (FS.remove_folder t.sandbox l)
  | _ -> Error "ERR_FILEACC"

let with_input t l f =
  let* fd = access (FS.open_file t.sandbox l Sandbox_calls.Read) in
  let ic = Unix.in_channel_of_descr fd in
  set_binary_mode_in ic true;
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> f ic)

let read_file t path =
  let* l = located t path in
  with_input t l (fun ic ->
      try Ok (really_input_string ic (in_channel_length ic)) with Sys_error _ | End_of_file -> Error "ERR_FILEACC")

let rename_file t ~src ~dst =
  let* s = located t src in
  let* d = located t dst in
  match FS.kind t.sandbox s, FS.kind t.sandbox d with
  | Some (Unix.S_REG, _), None -> access (FS.rename t.sandbox s d)
  | Some (Unix.S_REG, _), Some _ -> Error "ERR_FILEEXIST"
  | _ -> Error "ERR_FILEACC"

let copy_file t ~src ~dst =
  let* s = located t src in
  let* d = located t dst in
  match FS.kind t.sandbox s, FS.kind t.sandbox d with
  | Some (Unix.S_REG, _), Some _ -> Error "ERR_FILEEXIST"
  | Some (Unix.S_REG, _), None ->
      with_input t s (fun ic ->
          match in_channel_length ic with
          | exception Sys_error _ -> Error "ERR_FILEACC"
          | size when over_quota t size -> Error "ERR_FILEACC"
          | size ->
              let* fd = access (FS.open_file t.sandbox d Sandbox_calls.Create_new) in
              let oc = Unix.out_channel_of_descr fd in
              set_binary_mode_out oc true;
              let buffer = Bytes.create 65536 in
              (* At most the size the source had when the copy began: a source that grows
                 meanwhile cannot pass the quota. *)
              let rec copy left =
                if left > 0 then
                  match Stdlib.input ic buffer 0 (min left (Bytes.length buffer)) with
                  | 0 -> ()
                  | got -> Stdlib.output oc buffer 0 got; t.written <- t.written + got; copy (left - got) in
              match copy size; close_out oc with
              | () -> Ok ()
              | exception Sys_error _ -> close_out_noerr oc; Error "ERR_FILEACC")
  | _ -> Error "ERR_FILEACC"

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
  Sockets.close_all t.sockets;
  List.iter Egm_channel.close t.egm_channels;
  t.egm_channels <- []
