(** The data types of RAPID (§2.11-§2.17) as the static semantics sees them.

    Alias types (§2.15) are transparent: an alias name stands for the type it is defined on, so
    a [data_type] never is an alias ("any alias name is first replaced by the type it is defined
    on", §2.17). Record types are nominal: two record definitions are the same type only if they
    are the same definition. *)

type value_class = Value | Non_value | Semi_value   (** §2.16 *)

type data_type =
  | Num                                   (** §2.13 *)
  | Dnum                                  (** §2.13 *)
  | Bool                                  (** §2.13 *)
  | String                                (** §2.13 *)
  | Installed_atomic of installed_atomic  (** an atomic type of the installed system (ch. 13) *)
  | Record of record_type                 (** §2.14 *)
  | Anytype                               (** ch. 11: a mark of installed routines' parameters *)

and installed_atomic = {
  atomic_name : string;
  atomic_class : value_class;
  associated : data_type option;   (** the associated value type of a semi-value type (§2.16) *)
}

and record_type = {
  record_id : int;                 (** identity: one per record definition *)
  record_name : string;            (** as written in the definition *)
  mutable components : (string * data_type) list;
      (** filled once when the definitions of a task buffer are resolved *)
}

(** The shape of a data object: scalar, or an array of 1-3 dimensions (§2.22); a parameter
    declared with [{*}] has its rank but its sizes come from the argument (§5.2). *)
type dims =
  | Scalar
  | Sized of int list
  | Conformant of int

type object_type = { base : data_type; dims : dims }

val scalar : data_type -> object_type
val name : data_type -> string
val to_string : object_type -> string
(** As a programmer writes it: [num], [pos{3}], [num{*,*}]. *)

val value_class : data_type -> value_class
(** §2.16: atomic built-in types are value types; a record is a value type when all its
    components are, a semi-value type when at least one is semi-value and the others value,
    a non-value type otherwise; an installed atomic type has the class the system gives it. *)

val associated_value_type : data_type -> data_type option
(** §2.16: the associated value type of a semi-value type; [None] for other types. *)

val value_size : object_type -> int
(** The number of atomic components of a value of this type (its records and arrays flattened;
    for a [{*}] parameter, of one element), [max_int] when larger. Computed once per record
    type, so records that share component types cost their number, not their paths. *)

val same_data_type : data_type -> data_type -> bool
(** §2.17 rule 1: the same type (aliases already replaced). *)

val equal_types : value_context:bool -> object_type -> object_type -> bool
(** §2.17 for two objects whose types are known (aggregates are typed by their context, see the
    judgement): same structure (rank and sizes; a conformant array matches any size of its rank)
    and the same type, or, in value context only, a value type and a semi-value type whose
    associated type is that value type (rule 3). *)

val new_record_id : unit -> int

val record_ids_used : unit -> int
(** The last id {!new_record_id} gave. *)

val restore_record_ids : int -> unit
(** [restore_record_ids n]: the next id is [n + 1], as after the [n]th: the record types of the
    installed environment's image (made when rapid-sem was built) keep their ids 1 to [n]. *)

val component : record_type -> string -> data_type option
(** A component by name, compared without regard to letter case (§2.3). *)

val same_name : string -> string -> bool
(** Identifiers differing only in letter case are the same identifier (§2.3). *)
