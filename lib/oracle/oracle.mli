(** The oracle: rapid-sem's observable events for a program against another implementation's
    (doc/oracle.md). *)

type program = { name : string; files : string list }
(** A task buffer: one module file, or the module files of a [*.task] folder. *)

val programs_of_paths : string list -> (program list, string) result
(** A file is a program; a folder is searched recursively: each [*.mod] file not inside a
    [*.task] folder is a program, each [*.task] folder (its [.mod] and [.sys] files) is one.
    [Error] names a path that cannot be read. *)

type verdict =
  | Agree of int                                (** the number of events compared *)
  | Diverge of Event_diff.divergence
  | Broken of string                            (** an implementation wrote no usable stream *)

val check :
  ?ignore:string list -> ?timeout:float -> reference:string -> impl:string -> program -> verdict
(** [reference] and [impl] are command templates ({!Implementation.command_line}); the
    reference is rapid-sem's own [run --json]. *)

val run_stream :
  string -> ?timeout:float -> template:string -> string list -> (Event_stream.t, string) result
(** [run_stream who ~template files]: the command's events, read line by line
    ({!Implementation.run}, {!Event_stream.add_line}); [Error] names [who] and says why there
    are none: a line refused, the time out, death by a signal (the first line of its standard
    error added, clipped), or a command that cannot be started. *)

val compare_streams :
  ?ignore:string list -> expected:Event_stream.t -> actual:Event_stream.t -> unit -> verdict
(** rapid-sem's stream against an implementation's: of the same schema, compared whole; an
    implementation of [rapid-sem/1] against rapid-sem's [rapid-sem/2] on what /1 says
    ({!Schema_compat}); another schema is [Broken]. *)

val verdict_report : program -> verdict -> string

val self_reference : unit -> string
(** The reference template of the running rapid-sem ([run --json {files}]); it also sets the
    environment variable [RAPID_SEM] to this executable, for implementations that wrap it. *)
