(** What the static semantics says: errors and warnings, each naming the rule of doc/typing.md
    it comes from and the manual's section. Checking goes on after an error where the rest of
    the program can still be judged, so one run reports every independent error. *)

open Rapid_syntax

type severity = Error | Warning

type t = {
  severity : severity;
  rule : string;            (** the rule's name, as in doc/typing.md *)
  sections : string list;   (** the rule's section first, then those of the context:
                                ["4.5"; "2.17"] for a value of the wrong type assigned *)
  region : Source.region;
  message : string;         (** without the section *)
  hint : string option;     (** what to write instead ("did you mean ..."), on a line of its own *)
}

type collector

val create : unit -> collector
val error :
  collector -> ?hint:string -> rule:string -> section:string -> Source.region -> string -> unit
(** [~section] is one section ("4.5") or several separated by commas ("4.5,2.17"). *)

val warning :
  collector -> ?hint:string -> rule:string -> section:string -> Source.region -> string -> unit
val all : collector -> t list
(** In source order (file, then position). *)

val class_name : t -> string
(** [semantic error] or [warning]. *)

val headline : t -> string
(** [FILE:LINE:COL: semantic error: MESSAGE (§x.y, §z)], or [warning] for a warning. *)

val to_string : t -> string
(** The headline, and the hint on an indented line of its own when there is one. *)

val to_diagnostic : t -> Diagnostic.t
