(** A case of the conformance suite (spec/README.md, format 1): a RAPID file and the directives
    written in its comments. *)

type expectation =
  | Accepted                                       (** [! @expect ok] *)
  | Refused of { error_class : string; line : int; col : int }
      (** [! @expect lexical-error 4:10] and the like: the class as spelled in the directive *)

type t = {
  path : string;
  sections : string list;         (** [! @section 2.5], in order *)
  expectation : expectation option;
  strict : bool;                  (** [! @options strict] *)
  description : string option;
  problems : string list;         (** malformed or conflicting directives *)
}

val read : string -> t
(** Reads the directives of the file at this path. A file that cannot be read gives a case with
    a problem. *)

val error_classes : string list
(** The classes an [@expect] may name: [lexical-error], [syntax-error], [fatal-error]. *)

val expectation_to_string : expectation -> string
