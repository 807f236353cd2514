(** The diagnostics of [rapid-sem check] as text, JSON or SARIF 2.1.0 (doc/user-guide.md). *)

open Rapid_syntax

type item
(** One diagnostic: a front-end error or a report of the static semantics. *)

val of_diagnostic : Diagnostic.t -> item
val of_report : Rapid_typing.Report.t -> item

type format = Text | Json | Sarif

val print : version:string -> format -> item list -> unit
(** Text goes to standard error, one headline per diagnostic and its hint on an indented line;
    JSON and SARIF go to standard output as one document. *)

val uri : string -> string
(** A file name as a relative URI reference: unreserved characters and '/' kept, every other
    byte percent-encoded. *)
