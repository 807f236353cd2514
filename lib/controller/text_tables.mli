(** Text resources (chapter 15): the XML text files that TextTabInstall loads, and the tables
    TextTabGet and TextGet read. A file is a [Resource] element with a [Name] (the table's
    name) and [Text] elements, each with a [Name] (its index, a positive integer) and a
    [Value] (the text); [Comment] elements are for people. *)

type table = { name : string; language : string; texts : (int * string) list }

val parse : string -> (table, string) result
(** The contents of a text file; [Error reason] when it is not one. *)

type t
(** The tables installed in a run, numbered from 1 in the order of installation. *)

val create : unit -> t

val install : t -> table -> unit
(** A table whose name is installed already is not installed again (R-15-b). *)

val free_to_use : t -> string -> bool
(** TextTabFreeToUse: no table of this name is installed. *)

val find : t -> string -> int option
(** TextTabGet: the number of the table of this name. *)

val text : t -> int -> int -> string option
(** TextGet: the text of this index in the table of this number. *)
