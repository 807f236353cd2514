(** Running another implementation of RAPID on a program (doc/oracle.md, "Bounds"). *)

type status = [ `Exited of int | `Signaled of int | `Timed_out ]
(** [`Signaled n]: OCaml's number of the signal that killed the shell. *)

type result = {
  status : status;
  stderr : string;           (** its first {!stderr_kept} bytes; the rest is read and dropped *)
  refused : string option;   (** why standard output was not read to its end *)
}

val max_line : int
(** 1 MiB: a longer line of standard output is refused as soon as it is that long. *)

val max_output : int
(** 64 MiB: standard output beyond this is refused. *)

val stderr_kept : int
(** 4 KiB. *)

val replace_all : sub:string -> by:string -> string -> string
(** Every occurrence of [sub] replaced, left to right, without looking again at what was put in. *)

val command_line : template:string -> files:string list -> string
(** The shell command for [files]: [{file}] in the template stands for the program's file
    (the first one), [{files}] for all of them, each quoted for the shell; a template with
    neither gets the files appended. [{tasks}] stands for nothing: the program is one task
    (spec --impl gives it the tasks of a case of several, doc/oracle.md "Several tasks"). *)

val run :
  ?timeout:float -> template:string -> on_line:(int -> string -> (unit, string) Stdlib.result) ->
  string list -> result
(** Runs the command through [/bin/sh -c] in a process group of its own, with no standard
    input, and gives each line of its standard output to [on_line] with its number (from 1;
    a last line without a newline too) as it comes. An [Error] of [on_line], a line longer
    than {!max_line} or more than {!max_output} bytes stops the reading: the message is
    [refused] and the group is killed. [timeout] (seconds, default 60) kills the group and
    reports [`Timed_out]. When the command ends, what is left of its group (a child in the
    background) is killed too, and so it is when rapid-sem gets SIGINT, SIGTERM or SIGHUP. *)

val signal_name : int -> string
(** ["SIGSEGV"] for OCaml's number of a signal (negative) or for Linux's (positive). *)

val death : status -> string option
(** ["killed by signal SIGxxx"] for a shell killed by a signal, or one whose exit status
    128+N says, as POSIX shells do, that its command was killed by signal N. *)
