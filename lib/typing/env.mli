(** The objects a RAPID program names, and the scopes they are found in (§2.12, §2.20, §4.4,
    §5.3, ch. 13).

    Every module-level object (type, data object, routine) of a task buffer lives in one
    namespace: "two module objects declared in the same module may not share a name". Names are
    compared without regard to letter case (§2.3). *)

open Rapid_syntax

(** What a data object is, for the access-mode table (§5.2) and the assignment rules (§4.5). *)
type data_kind =
  | Variable
  | Persistent
  | Constant
  | Parameter of Tables.access_mode
  | Loop_variable                 (** §4.18: implicitly num, read-only *)
  | Read_only_variable            (** ch. 12: ERRNO, INTNO, updated by the system only *)

type level = Routine_level | Module_level of string | Installed_level
(** Where an object is declared: a routine, a user module (its name), the installed system. *)

type data_object = {
  d_name : string;
  d_type : Types.object_type;
  d_kind : data_kind;
  d_region : Source.region;
  d_level : level;
  d_scope : Ast.declaration_scope;
  d_optional : bool;              (** an optional parameter (§5.2) *)
  d_initial : Ast.expression option;
}

type parameter = {
  p_name : string;
  p_mode : Tables.access_mode;
  p_type : Types.object_type option;   (** [None] for a switch (§5.2: an empty domain) *)
  p_region : Source.region;
}

type parameter_slot =
  | Required_slot of parameter
  | Optional_slot of parameter list    (** one optional parameter, or mutually exclusive ones *)
  | Required_choice of parameter list
      (** ABB's "Signal | PersBool": exactly one of these required parameters takes the argument
          in this place; only installed routines have it (Installed_choices) *)

type routine_kind = Procedure | Function of Types.object_type | Trap

type routine = {
  r_name : string;
  r_kind : routine_kind;
  r_slots : parameter_slot list;
  r_region : Source.region;
  r_level : level;
  r_local : bool;
  r_open : bool;    (** its parameter list holds placeholders (§2.9): calls are not checked *)
}

type type_object = {
  t_name : string;
  t_type : Types.data_type;
  t_alias : bool;                 (** defined by ALIAS (§2.15) *)
  t_region : Source.region;
  t_level : level;
  t_local : bool;
}

type obj =
  | Data of data_object
  | Routine of routine
  | Type of type_object
  | Label of Source.region        (** §4.4 *)
  | Module of Source.region       (** §9.2: a module's name, which hides predefined objects *)

val obj_region : obj -> Source.region
val obj_kind_name : obj -> string
(** "data object", "routine", "data type", "label", for messages. *)

(** {1 Tables of names} *)

type table
(** Names to objects, without regard to letter case. *)

val create_table : unit -> table
val find : table -> string -> obj option
val add : table -> string -> obj -> unit
val copy_table : table -> table
val iter : (string -> obj -> unit) -> table -> unit

(** {1 Scopes} *)

type scope = {
  installed : table;              (** predefined and installed objects *)
  globals : table;                (** global objects of all user modules of the task buffer *)
  module_objects : table;         (** every object of the module being checked *)
  module_names : table;           (** the user modules of the task buffer (§9.2) *)
  routine : table list;           (** innermost first: a FOR loop's variable, the routine's *)
  in_installed_module : bool;     (** ch. 13: installed modules see their own module and the installed level *)
}

val lookup : scope -> string -> obj option
(** The look-up order of ch. 13: own routine, own module, global in the program, installed;
    a module name hides an installed object of the same name (§9.2). *)

val lookup_type : scope -> string -> obj option
(** Like {!lookup}, but a data type is found past other objects of the same name (a parameter
    named like its type); another object is returned only when no type has the name. *)
