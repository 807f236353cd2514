(** Running another implementation of RAPID on a program (doc/oracle.md). *)

type result = {
  stdout : string;
  stderr : string;
  status : [ `Exited of int | `Signaled of int | `Timed_out ];
}

val replace_all : sub:string -> by:string -> string -> string
(** Every occurrence of [sub] replaced, left to right, without looking again at what was put in. *)

val command_line : template:string -> files:string list -> string
(** The shell command for [files]: [{file}] in the template stands for the program's file
    (the first one), [{files}] for all of them, each quoted for the shell; a template with
    neither gets the files appended. [{tasks}] stands for nothing: the program is one task
    (spec --impl gives it the tasks of a case of several, doc/oracle.md "Several tasks"). *)

val run : ?timeout:float -> template:string -> string list -> result
(** Runs the command through [/bin/sh -c] with no standard input; [timeout] (seconds,
    default 60) kills it and reports [`Timed_out]. *)
