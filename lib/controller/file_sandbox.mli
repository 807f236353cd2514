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

val resolve : t -> string -> (string, string) result
(** The host path of a RAPID path: ["HOME:/log/a.txt"], ["TEMP:b.bin"], or a path without a
    device, which is on HOME:. [Error reason] for an unknown device, a [..] component, a host
    path (starting with [/] and no device), or a symbolic link that leads out of the root. *)

val temporary : unit -> t
(** A new empty sandbox in the host's temporary folder (a conformance case's). *)

val remove : t -> unit
(** The sandbox's folder and everything in it; symbolic links are removed, not followed. *)

val seed : t -> device:string -> string -> unit
(** Copies a host folder's files and folders into the device's folder (a conformance case's
    [! @home]). *)
