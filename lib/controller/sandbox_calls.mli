(** The system calls of {!File_sandbox} that OCaml's Unix library lacks: each works in a folder
    given by its descriptor and never follows a symbolic link as the name's last component, so a
    link put in the way after the sandbox checked a path is an error, not an escape. Errors are
    [Unix.Unix_error]. *)

val walk : string -> string list -> Unix.file_descr
(** The folder reached from the root folder (given by its host path) through these components,
    none of which may be a symbolic link ([ELOOP] or [ENOTDIR] if one is). To be closed. *)

type how = Read | Write | Append | Create_new

val open_at : Unix.file_descr -> string -> how -> Unix.file_descr
(** Opens without waiting (O_NONBLOCK: a FIFO without its peer does not block) and without
    following a link; [Write] and [Append] create a missing file, [Create_new] only creates
    (EEXIST otherwise); nothing is truncated. *)

val kind_at : Unix.file_descr -> string -> (Unix.file_kind * int) option
(** The kind and size of the entry, of the link itself for a link; [None] when it does not exist. *)

val unlink_at : Unix.file_descr -> string -> folder:bool -> unit
val mkdir_at : Unix.file_descr -> string -> unit
val rename_at : Unix.file_descr -> string -> Unix.file_descr -> string -> unit

val read_dir_at : Unix.file_descr -> string -> string array
(** The names in the folder, without [.] and [..], in the order the host gives. *)
