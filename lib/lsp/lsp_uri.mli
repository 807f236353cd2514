(** file URIs (RFC 8089) and the paths they name: what the editor calls a document, and what the
    front end reads. *)

val to_path : string -> string option
(** [file:///a/b%20c.mod] gives [/a/b c.mod]; another scheme or a remote host gives [None]. *)

val of_path : string -> string
(** An absolute path as a file URI, its bytes other than unreserved ones and [/] percent-encoded. *)
