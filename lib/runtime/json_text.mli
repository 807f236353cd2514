(** JSON as rapid-sem writes it: valid UTF-8 whatever bytes its strings carry (a file name, a
    RAPID string, the output of an implementation under test). Every writer of JSON goes through
    here, so that no call site can forget the conversion (doc/rulings.md R-2.1-utf8n). *)

val valid : Yojson.Safe.t -> Yojson.Safe.t
(** The same document with every string and every object key through {!Utf8_text.of_bytes}:
    valid UTF-8 unchanged, any other byte read as Latin-1. *)

val to_string : Yojson.Safe.t -> string
(** [Yojson.Safe.to_string] of {!valid}. *)

val pretty_to_string : Yojson.Safe.t -> string
(** [Yojson.Safe.pretty_to_string] of {!valid}. *)
