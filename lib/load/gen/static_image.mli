(** A marshalled value (OCaml 4.13's format, no custom blocks or code pointers) laid out as the
    blocks [Marshal.from_string] would make of it, as the words of a C array: the build puts
    the installed environment in the executable's data this way (lib/load/installed_image_blob.c,
    read by lib/load/installed_image_stubs.c). *)

type word =
  | Int of int64  (** a whole word: an immediate, a header, bytes or a float's bits *)
  | Pointer of int  (** the value whose header is at this word index *)
  | Atom of int  (** the runtime's empty block of this tag, written in at start-up *)

type t = { words : word array; root : word; scanned : int list }
(** The words, the root value and the header indices of the blocks that have fields. *)

exception Unknown of string
(** The bytes hold what the layout does not know (named). *)

val layout : string -> t
(** The blocks of [Marshal.from_string bytes 0], in the order it makes them, with the same
    sharing. *)

val to_c : name:string -> t -> string
(** The C source defining [NAME_words], [NAME_word_count], [NAME_root], [NAME_atom_count], [NAME_atoms] (word
    index and tag pairs), [NAME_scanned_count] and [NAME_scanned]. *)
