(** The controller's mass memory, in a sandbox: the devices a RAPID path names (HOME:, TEMP:,
    RAMDISK:, DISKHOME:, REMOVABLE:) are folders under one root on the host, and no RAPID path
    reaches outside it (doc/services.md, doc/rulings.md R-13-s). *)

type t

val default_root : string
(** [.rapid-sem/fs], under the current folder: the root when [--fs] is not given. *)

val create : string -> t
(** A sandbox at this host folder; the folder and the devices' folders are made when a path is
    first resolved. *)

val root : t -> string

val devices : (string * string) list
(** Each device name (upper case, with its colon) and its folder under the root. *)

type location
(** A file or folder under the root: the components that lead to it from the root, none of them
    a symbolic link when it was located. *)

val locate : ?follow:bool -> t -> string -> (location, string) result
(** The location of a RAPID path: ["HOME:/log/a.txt"], ["TEMP:b.bin"], or a path without a
    device, which is on HOME:. [Error reason] for an unknown device, a [..] component, a host
    path (starting with [/] and no device), or a symbolic link on the way that leads out of the
    root, whether or not its target exists (links are read one by one, never resolved by the
    host). Links that stay inside are replaced by what they name; with [~follow:false] a link
    at the end is checked the same way but is itself the location. *)

val resolve : t -> string -> (string, string) result
(** The host path of {!locate}'s location. *)

(** {1 Operations at a location}

    Each reaches the location's folder from the root without following any link, and does not
    follow a link as the last component: a link put in the way after {!locate} makes it fail.
    [Error] carries the host's reason. *)

val kind : t -> location -> (Unix.file_kind * int) option
(** The kind and size of what is there (a link itself for a link); [None] when nothing is. *)

val open_file : t -> location -> Sandbox_calls.how -> (Unix.file_descr, string) result
(** A regular file opened (created with [Write], [Append] and [Create_new]); [Write]
    truncates it, [Append] is at its end. Anything else (a FIFO, a socket, a device, a folder)
    is refused, and the check never waits. *)

val remove_file : t -> location -> (unit, string) result
val make_folder : t -> location -> (unit, string) result
val remove_folder : t -> location -> (unit, string) result
val rename : t -> location -> location -> (unit, string) result

val read_folder : t -> location -> (string array, string) result
(** The names in a folder, without [.] and [..]. *)

val temporary : unit -> t
(** A new empty sandbox in the host's temporary folder (a conformance case's). *)

val remove : t -> unit
(** The sandbox's folder and everything in it; symbolic links are removed, not followed. *)

val seed : t -> device:string -> string -> unit
(** Copies a host folder's files and folders into the device's folder (a conformance case's
    [! @home]). *)
