(** A task buffer made ready to run: its files read, checked against the static semantics, and
    lowered to the program the machine runs. *)

open Rapid_syntax

type loaded = {
  program : Ir.program;
  warnings : Rapid_typing.Report.t list;
}

type failure =
  | Front_end of Diagnostic.t list              (** lexical, syntax, fatal, file errors *)
  | Static of Rapid_typing.Report.t list        (** semantic errors (and the warnings) *)
  | Internal of string                          (** the installed environment does not load *)

val load :
  ?strict:bool -> ?allow_unknown:bool -> ?io:Rapid_controller.Io_config.t -> string list ->
  (loaded, failure) result
(** [io]: the I/O configuration; its signals are installed data objects (§2.16). *)

val load_modules :
  ?allow_unknown:bool -> ?io:Rapid_controller.Io_config.t -> Ast.module_declaration list ->
  (loaded, failure) result

val installed :
  ?io:Rapid_controller.Io_config.t -> unit -> (Ast.module_declaration list, Diagnostic.t) result
(** The installed environment, with a generated module declaring the signals of the I/O
    configuration (VAR signaldi di1; ...). *)

val connect_signals : Rapid_controller.Io_config.t -> Ir.program -> Ir.program
(** Each signal object of the generated module gets the handle of its signal in the run's
    world. *)
