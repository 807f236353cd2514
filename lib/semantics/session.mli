(** A task buffer made ready to run: its files read, checked against the static semantics, and
    lowered to the program the machine runs. *)

open Rapid_syntax

type loaded = {
  program : Ir.program;
  warnings : Rapid_typing.Report.t list;
  unknown_summary : string option;   (** {!Rapid_typing.Check.unknown_summary} *)
}

type failure =
  | Front_end of Diagnostic.t list              (** lexical, syntax, fatal, file errors *)
  | Static of Rapid_typing.Report.t list        (** semantic errors (and the warnings) *)
  | Internal of string                          (** the installed environment does not load *)

val load :
  ?strict:bool -> ?allow_unknown:bool -> string list -> (loaded, failure) result

val load_modules :
  ?allow_unknown:bool -> Ast.module_declaration list -> (loaded, failure) result
