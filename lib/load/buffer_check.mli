(** [rapid-sem check] (doc/user-guide.md): task buffers against the whole static semantics, the
    initial values known before a run included ({!Session}: check, lower, evaluate them), and
    with several tasks (ch. 14) the buffers together once each is sound on its own
    ({!Task_check}). What the command line checks, so that it only reads options and writes
    the reports. *)

open Rapid_syntax

type buffer = { name : string; modules : Ast.module_declaration list }
(** A task buffer that parsed: its task's name ([""] for the one buffer without --task). *)

type checked = {
  reports : Rapid_typing.Report.t list;
      (** every buffer's reports in order, then those across the tasks; a report on the
          generated module of the signals at the place the I/O configuration names the signal
          ({!Session.at_io_place}) *)
  unknown_summaries : (string * string) list;
      (** the summary of each buffer's unknown names (--allow-unknown), by the buffer's name *)
}

val check :
  ?testing:bool -> allow_unknown:bool -> io:Rapid_controller.Io_config.t -> several:bool -> buffer list ->
  (checked, Diagnostic.t) result
(** [several]: the buffers are those of --task, checked together too. [Error]: the installed
    environment does not parse (a bug). [testing]: with the assertions of rapid-sem test
    (R-test-a). *)
