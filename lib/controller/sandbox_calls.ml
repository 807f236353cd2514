external walk_parts : string -> string array -> Unix.file_descr = "rs_sandbox_walk"
let walk root parts = walk_parts root (Array.of_list parts)

type how = Read | Write | Append | Create_new

external open_how : Unix.file_descr -> string -> int -> Unix.file_descr = "rs_sandbox_open_at"
let open_at dir name how =
  open_how dir name (match how with Read -> 0 | Write -> 1 | Append -> 2 | Create_new -> 3)

external kind_code : Unix.file_descr -> string -> int * float = "rs_sandbox_kind_at"
let kinds = [| Unix.S_REG; S_DIR; S_CHR; S_BLK; S_LNK; S_FIFO; S_SOCK |]
let kind_at dir name =
  match kind_code dir name with
  | k, size when k >= 0 && k < Array.length kinds -> Some (kinds.(k), int_of_float size)
  | _ -> None

external unlink_code : Unix.file_descr -> string -> bool -> unit = "rs_sandbox_unlink_at"
let unlink_at dir name ~folder = unlink_code dir name folder
external mkdir_at : Unix.file_descr -> string -> unit = "rs_sandbox_mkdir_at"
external rename_at : Unix.file_descr -> string -> Unix.file_descr -> string -> unit = "rs_sandbox_rename_at"
external read_dir_at : Unix.file_descr -> string -> string array = "rs_sandbox_read_dir_at"
