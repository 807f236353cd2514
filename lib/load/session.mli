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
  ?strict:bool -> ?robotware:Robotware.t -> ?testing:bool -> ?allow_unknown:bool -> ?io:Rapid_controller.Io_config.t ->
  string list -> (loaded, failure) result
(** [io]: the I/O configuration; its signals are installed data objects (§2.16). [testing]: the
    assertions of rapid-sem test are installed too (doc/rulings.md R-test-a). [robotware]: the
    release whose reserved words the files are read with (R-2.4-rw6). *)

val load_modules :
  ?testing:bool -> ?allow_unknown:bool -> ?io:Rapid_controller.Io_config.t -> Ast.module_declaration list ->
  (loaded, failure) result

val installed :
  ?testing:bool -> ?io:Rapid_controller.Io_config.t -> unit -> (Ast.module_declaration list, Diagnostic.t) result
(** The installed environment, with a generated module declaring the signals of the I/O
    configuration (VAR signaldi di1; ...). *)

val lower :
  ?io:Rapid_controller.Io_config.t -> installed:Ast.module_declaration list ->
  modules:Ast.module_declaration list -> Rapid_typing.Check.result ->
  (Ir.program, Rapid_typing.Report.t list) result
(** The program of a task that checked without error: lowered, its signals connected, and the
    initial values of its data computed before the run (§3.2, doc/rulings.md R-3.2-a); [Error]
    holds the semantic errors of initial values that cannot be computed. *)

val at_io_place : Rapid_controller.Io_config.t -> Rapid_typing.Report.t -> Rapid_typing.Report.t
(** A report on the generated module of the signals (a signal named after an installed object,
    §13) moved to where the I/O configuration names that signal; any other report as it is.
    [load] and [load_modules] apply it. *)

val connect_signals : Rapid_controller.Io_config.t -> Ir.program -> Ir.program
(** Each signal object of the generated module gets the handle of its signal in the run's
    world. *)

val is_test_name : string -> bool
(** A name of rapid-sem test's tests: test_..., letter case aside (doc/testing.md). *)

val declares_tests : Ast.module_declaration -> bool
(** The module declares a test, a parameterless procedure of such a name: its task buffer has the
    assertions installed (R-test-a), under rapid-sem test and in the language server. *)
