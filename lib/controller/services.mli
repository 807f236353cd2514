(** The controller's services for one run (doc/services.md): the files of the sandboxed mass
    memory and their devices (iodev), the directories being read (dir), the raw-data buffers
    (rawbytes) and the sockets. Engine-neutral: identities are ints, data are byte strings,
    errors are ERR_ names. *)

type t

val create : ?sandbox:File_sandbox.t -> ?sockets:Sockets.t -> ?max_file_size:int -> unit -> t
(** Without [sandbox], {!File_sandbox.default_root}; without [sockets], loopback only;
    [max_file_size] bytes a file may hold (default {!max_file_size}). *)

val sandbox : t -> File_sandbox.t
val sockets : t -> Sockets.t
val texts : t -> Text_tables.t
(** The text tables installed in the run (chapter 15). *)

val max_files : int
(** Files open at once: 32 (doc/rulings.md R-13-s); one more Open raises ERR_FILEOPEN. *)

val new_object : t -> int
(** An identity for an installed object (a rawbytes buffer) that gets it at its first use. *)

val max_file_size : int
(** 64 MiB: a write that would make a file longer raises ERR_FILESIZE (doc/rulings.md R-13-s). *)

val file_limit : t -> int
(** The run's bound on the size of a file. *)

(** {1 Files (iodev)} *)

type mode = Read | Write | Append

val open_file : t -> string -> mode -> (int, string) result
(** ERR_FILEOPEN when the path is refused or the file cannot be opened. *)

val close_file : t -> int -> unit
val is_open : t -> int -> bool

val input : t -> int -> (in_channel, string) result
(** ERR_FILEACC: not open, or not open for reading. *)

val output : t -> int -> (out_channel, string) result

val rewind : t -> int -> (unit, string) result

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
