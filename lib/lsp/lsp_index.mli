(** What the editor asks about names: every declaration of a task's modules and of the installed
    environment, and every use of a name in the modules resolved to its declaration by the
    look-up order of ch. 13 (own routine, own module, global in the task, installed; §2.20,
    §5.3, §4.18 for a loop's variable, §4.4 for labels). Names are compared without regard to
    letter case (§2.3). The checker judges the program; this index only says what each name
    denotes, for hover, definition, references, symbols, completion and rename. *)

open Rapid_syntax

type routine_kind = Proc | Func of string | Trap_routine

type param = {
  p_name : string;
  p_mode : string;            (** "", "VAR", "PERS", "INOUT", "REF" *)
  p_type : string option;     (** [None]: a switch *)
  p_dims : int;               (** a conformant array's dimensions *)
}

type slot = Required of param | Optional of param list   (** alternatives: [\a | b] *)

type kind =
  | Module
  | Record of (string * string) list   (** component type, component name *)
  | Alias of string
  | Atomic
  | Data of { storage : string; type_name : string; dims : int; parameter : bool }
      (** storage: VAR, PERS, CONST, a parameter's mode ("IN" for none), or FOR *)
  | Routine of { routine : routine_kind; slots : slot list }
  | Component of { record : string; type_name : string }
  | Label

type decl = {
  name : string;
  kind : kind;
  uri : string option;          (** [None]: installed (the embedded lib/typing/installed/*.sys) *)
  name_start : int;             (** character offsets of the name *)
  name_stop : int;
  decl_start : int;             (** and of the whole declaration *)
  decl_stop : int;
  module_name : string;
  routine : string option;      (** the routine it is declared in *)
  local : bool;                 (** LOCAL, or routine level *)
  installed_file : string option;
}

type occurrence = { o_start : int; o_stop : int; decl : decl }

type source = {
  uri : string;
  text : Lsp_text.t;
  ast : Ast.module_declaration;
  fresh : bool;   (** parsed from the text the editor shows; [false]: the last text that parsed *)
}

type t

val build : source list -> t
(** The index of one task. Never raises on any tree the parser makes. *)

val use_installed : Ast.module_declaration list -> unit
(** The installed environment to index from now on: {!Rapid_load.Session.installed}'s, with the
    signals of an I/O configuration; by default lib/typing/installed alone. *)

val installed_decls : unit -> decl list
(** The installed environment's declarations (ch. 13), read once. *)

val sources : t -> source list
val source : t -> string -> source option

val decls : t -> string -> decl list
(** The declarations of a module, by its URI, in source order. *)

val all_decls : t -> decl list

val occurrence_at : t -> string -> int -> occurrence option
(** The use or declaration of a name that covers the character offset (its end included, so
    that the cursor just after a name finds it). Only for fresh sources. *)

val occurrences_of : t -> decl -> (string * occurrence) list
(** Every use and the declaration of [decl] in the task, with their URIs. *)

val members : t -> decl -> decl list
(** A routine's parameters, a record type's components. *)

val lookup_any : t -> string -> int -> string -> decl option
(** The declaration of any kind (data, routine, type, label) a name denotes at an offset. *)

val same_decl : decl -> decl -> bool

val visible_at : t -> string -> int -> decl list
(** The names in scope at an offset of a module: its routine's (when in one), the module's,
    the task's global ones, the installed ones; an inner declaration hides an outer one. *)

val lookup_at : t -> string -> int -> string -> decl option
(** The declaration a data object or routine name would denote at an offset. *)

val lookup_type : t -> string -> int -> string -> decl option

val components_of_type : t -> string -> int -> string -> decl list
(** The components of a record type by name (aliases followed). *)

val type_of_decl : decl -> string option
(** A data object's type, a function's return type, a component's type. *)

val slot_text : slot -> string
(** [robtarget ToPoint], [\num V | num T], as {!signature} writes it. *)

val signature : decl -> string
(** One line of RAPID that declares it: [PERS tooldata tGripper], [PROC MoveL (\switch Conc, ...)]. *)

val kind_name : decl -> string
(** "persistent", "procedure", "record type", ... for messages and hovers. *)
