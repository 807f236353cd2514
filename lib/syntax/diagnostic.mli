(** What rapid-sem says about a program it refuses: the error classes of §1.4, a region and a
    message in the manual's words. *)

type error_class =
  | Lexical_error        (** §1.4: an illegal token *)
  | Syntax_error         (** §1.4: a grammar rule is violated *)
  | Semantic_error       (** §1.4: a semantic rule is violated *)
  | Fatal_static_error   (** §1.4: a system resource is exceeded (program too complex) *)
  | File_error           (** the file cannot be read: not an error of the program *)

type t = { error_class : error_class; region : Source.region; message : string }

val make : error_class -> Source.region -> string -> t

val class_name : error_class -> string
(** The name printed in a diagnostic: [lexical error], [syntax error], [semantic error],
    [fatal error], [file error]. *)

val to_string : t -> string
(** [FILE:LINE:COL: CLASS: MESSAGE] *)
