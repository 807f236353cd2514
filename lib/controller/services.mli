(** The controller's services for one run (doc/services.md): the files of the sandboxed mass
    memory and their devices (iodev), the directories being read (dir), the raw-data buffers
    (rawbytes) and the sockets. Engine-neutral: identities are ints, data are byte strings,
    errors are ERR_ names. *)

type t

val create :
  ?sandbox:File_sandbox.t -> ?sockets:Sockets.t -> ?egm_devices:Egm_channel.device list -> ?max_file_size:int ->
  ?max_total_size:int -> ?operator:Operator_script.t -> unit -> t
(** Without [sandbox], {!File_sandbox.default_root}; without [sockets], loopback only;
    [max_file_size] bytes a file may hold (default {!max_file_size}), [max_total_size] bytes
    the run may write into files in all (default {!max_total_size}); [operator] the answers of
    the FlexPendant's operator (--operator, R-13-ui2), none by default. *)

val sandbox : t -> File_sandbox.t
val sockets : t -> Sockets.t

val operator : t -> Operator_script.t option
(** The scripted operator at the FlexPendant, shared by the run's tasks (R-13-ui2). *)

val egm_devices : t -> Egm_channel.device list
(** The UdpUc devices of EGM the run knows (--egm-device); none by default. *)

val open_egm : t -> Egm_channel.device -> (Egm_channel.t, string) result
(** The channel of an EGM process; those still open close with the run's other services. *)

val close_egm : t -> Egm_channel.t -> unit

val texts : t -> Text_tables.t
(** The text tables installed in the run (chapter 15). *)

val max_files : int
(** Files open at once: 32 (doc/rulings.md R-13-s); one more Open raises ERR_FILEOPEN. *)

val new_object : t -> int
(** An identity for an installed object (a rawbytes buffer) that gets it at its first use. *)

val max_file_size : int
(** 64 MiB: a write that would make a file longer raises ERR_FILESIZE (doc/rulings.md R-13-s). *)

val max_total_size : int
(** 256 MiB: the quota of the bytes a run writes into files (Write and the other writes,
    CopyFile); a write beyond it raises ERR_FILEACC, as on a full mass memory
    (doc/rulings.md R-13-sandbox1). *)

(** {1 Files (iodev)} *)

type mode = Read | Write | Append

val open_file : t -> string -> mode -> (int, string) result
(** ERR_FILEOPEN when the path is refused or the file cannot be opened. *)

val close_file : t -> int -> unit
val is_open : t -> int -> bool

val input : t -> int -> (in_channel, string) result
(** ERR_FILEACC: not open, or not open for reading. *)

val write : t -> int -> string -> (unit, string) result
(** Writes and flushes; ERR_FILESIZE beyond the file's bound, ERR_FILEACC beyond the quota or
    when the file is not open for writing. *)

val rewind : t -> int -> (unit, string) result

(** {1 Paths}

    The routines that name a file or folder. A path the sandbox refuses (File_sandbox.locate)
    gives ERR_FILEACC; so does a file that is not a regular one where a file is read. *)

val file_kind : t -> string -> (Unix.file_kind option, string) result
(** What is at the path, [None] when nothing is (IsFile). *)

val file_size : t -> string -> (int, string) result
val remove_file : t -> string -> (unit, string) result
(** A regular file, or a symbolic link (that stays inside): the link, not what it names. *)

val make_dir : t -> string -> (unit, string) result
(** ERR_FILEEXIST when something is there. *)

val remove_dir : t -> string -> (unit, string) result
val read_file : t -> string -> (string, string) result
(** The whole of a regular file (TextTabInstall). *)

val rename_file : t -> src:string -> dst:string -> (unit, string) result
val copy_file : t -> src:string -> dst:string -> (unit, string) result
(** Both: [src] a regular file, ERR_FILEEXIST when [dst] exists; a copy counts against the
    quota. *)

(** {1 Directories (dir)} *)

val open_dir : t -> string -> (int, string) result
val read_dir : t -> int -> (string option, string) result
val close_dir : t -> int -> unit

(** {1 Raw data (rawbytes)} *)

val rawbytes_capacity : int
(** 1024 bytes. *)

val rawbytes : t -> int -> Bytes.t * int
(** The buffer of a rawbytes object and its valid length (a new object: empty). *)

val set_rawbytes_length : t -> int -> int -> unit

val close_all : t -> unit
(** The end of a run: every file, directory and socket is closed. *)
