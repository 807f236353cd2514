(** What rapid-sem says about a program it refuses: the error classes of §1.4, a region and a
    message in the manual's words, and where one helps, a hint that says what to write instead. *)

type error_class =
  | Lexical_error        (** §1.4: an illegal token *)
  | Syntax_error         (** §1.4: a grammar rule is violated *)
  | Semantic_error       (** §1.4: a semantic rule is violated *)
  | Fatal_static_error   (** §1.4: a system resource is exceeded (program too complex) *)
  | File_error           (** the file cannot be read: not an error of the program *)

type t = {
  error_class : error_class;
  region : Source.region;
  message : string;
  hint : string option;  (** what to write instead, or where the cause lies *)
}

val make : ?hint:string -> error_class -> Source.region -> string -> t
val with_hint : string option -> t -> t

val class_name : error_class -> string
(** The name printed in a diagnostic: [lexical error], [syntax error], [semantic error],
    [fatal error], [file error]. *)

val headline : t -> string
(** [FILE:LINE:COL: CLASS: MESSAGE], the diagnostic's first line. *)

val hint_line : string -> string
(** ["  hint: " ^ hint]: a hint goes on a line of its own, indented, after the headline. *)

val to_string : t -> string
(** The headline, followed by the hint line when there is a hint (doc/user-guide.md). *)

val sections_of : string -> string list
(** The manual's sections a message cites ("§4.18" gives "4.18"), in order, without repeats. *)
