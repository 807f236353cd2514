(** Running the conformance suite: every [.mod] file below a folder, checked against its
    directives, with a summary per manual section and the line [N passed, N failed]. *)

type verdict = Passed | Failed | Skipped   (** skipped: a format this runner does not read *)
type engine = Machine | Closure
(** Which engine runs the cases of format 3: the small-step machine or the closure engine. *)

type outcome = { case : Spec_case.t; verdict : verdict; detail : string }

val run_case : ?engine:engine -> Spec_case.t -> outcome
(** Parses the case's file (in strict mode when it says so) and compares with its expectation. *)

val find_cases : string -> string list
(** The [.mod] files below a folder, in a stable order. *)

val collect : string -> string list * (string * string) list
(** The cases below a folder ([.mod] files and [.task] folders, in a stable order), and what could
    not be looked at, with the reason: an unreadable folder, a symbolic link loop, a [.mod] entry
    that is a FIFO or a device or cannot be looked at. Never blocks, never raises. *)

val run : ?verbose:bool -> ?engine:engine -> Format.formatter -> string -> int * int
(** [run out dir] runs every case below [dir] with the engine (the machine by default), prints
    each failure, each path it could not look at ([ERROR PATH: reason], counted as failed), the
    summary per section and [N passed, N failed], and returns (passed, failed). *)
