(** Reading a module file as controllers store it (§2.1): UTF-8 with or without a byte-order
    mark, or Latin-1 (ISO 8859-1) when the file is not valid UTF-8, as older controllers export
    it. The result is UTF-8 text for the lexer and the start of every line, counted in
    characters. *)

type t = {
  text : string;            (** UTF-8, without the byte-order mark *)
  line_starts : int array;  (** character offset at which each line starts *)
  byte_order_mark : bool;   (** the file began with U+FEFF *)
  latin1 : bool;            (** the file was not valid UTF-8 and was read as Latin-1 *)
  final_newline : bool;     (** the file is empty or ends with a line break *)
  length : int;             (** in characters *)
}

val decode : string -> t
(** Line breaks are LF, CRLF and a CR not followed by LF. *)
