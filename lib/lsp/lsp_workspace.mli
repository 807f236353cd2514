(** The documents the editor has open, the tasks they belong to, and what the front end and the
    checker say about each task.

    A task (§9.1: a task buffer) is the set of modules of one folder, or, in a controller's
    backup, of its [RAPID/TASKn] folder and every folder below it ([PROGMOD], [SYSMOD]). Its
    modules are the open documents of that folder and the [.mod], [.sys], [.modx] and [.sysx]
    files on disk that are not open. A document that is not a file is a task of its own. *)

type options = {
  allow_unknown : bool;                  (** as [rapid-sem check --allow-unknown] *)
  io : Rapid_controller.Io_config.t;     (** as [--io]: its signals are declared *)
}

type t

val create : options -> t

val set_root : t -> string option -> unit
(** The workspace folder, for workspace/symbol. *)

val open_document : t -> string -> string -> unit
(** [open_document t uri text] *)

val change_document : t -> string -> (Lsp_text.position * Lsp_text.position) option -> string -> unit
(** One content change: [None] replaces the text. An unknown URI is ignored. *)

val close_document : t -> string -> unit

val is_open : t -> string -> bool

val open_uris : t -> string list

val files_changed : t -> unit
(** Files on disk changed (a save, the client's file watcher): every task is read again. *)

val text : t -> string -> Lsp_text.t option
(** An open document's text, or a task file's on disk. *)

val task_key : t -> string -> string
(** The task a document belongs to. *)

val index : t -> string -> Lsp_index.t
(** The index of the task of a document (built on demand, kept until one of its documents
    changes). *)

val diagnostics : t -> string -> (string * Yojson.Safe.t list) list
(** Every open document of the task of this one, with its LSP diagnostics: the syntax error of
    a module that does not parse, and, once every module of the task has a tree (the last text
    that parsed standing in for one that does not parse now), the semantic errors and warnings
    of [rapid-sem check] on the task. *)

val unparsed : t -> string -> string list
(** The modules of the task of this document that do not parse now. *)

val workspace_indexes : t -> Lsp_index.t list
(** The indexes of the tasks of the open documents and of the workspace folder's tasks. *)

val uri_of_file : string -> string
