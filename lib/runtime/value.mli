(** Run-time values of RAPID (§2.13-§2.16, §2.22).

    A num is an IEEE 754 single-precision number and a dnum a double-precision one
    (§2.13; installed-facts.md §1, CONFIRMED). Both are carried as OCaml floats; the float of a
    [Num] is always exactly representable in single precision, which {!num} and
    {!of_literal} guarantee and every operation of {!Arith} and {!Library} keeps. *)

type handle
(** An object of an installed non-value or semi-value type (an I/O device, a signal, a clock;
    §2.16): a kind name and an identity. *)

type t =
  | Num of float               (** exactly representable in single precision *)
  | Dnum of float
  | Bool of bool
  | String of string           (** bytes of UTF-8, at most 80 (§2.13) *)
  | Record of t array          (** components in declaration order; mutable in place *)
  | Array of t array           (** elements; a 2-dimensional array is an [Array] of [Array]s *)
  | Handle of handle

exception Type_mismatch of string
(** Raised by the operations of this library when a value is not of the type the operation
    takes. The static semantics excludes this for checked programs, so it is a bug of
    rapid-sem, which the machine reports as a stuck state. *)

val type_mismatch : string -> 'a
(** [raise (Type_mismatch what)]. *)

(** {1 Numbers} *)

val to_single : float -> float
(** Rounds a double to the nearest single (ties to even), overflowing to an infinity. *)

val num : float -> t
(** [Num] of the float rounded to single precision. *)

val dnum : float -> t

val single_of_q : Q.t -> float
(** The rational rounded once, to nearest with ties to even, to single precision (subnormals
    included; infinity beyond the largest finite single). The result is a float exactly
    representable in single precision. *)

val double_of_q : Q.t -> float
(** Likewise to double precision. *)

val of_literal : Rapid_syntax.Num_literal.t -> [ `Num | `Dnum ] -> t
(** The literal's exact value rounded once to the precision of num or dnum (§2.5, §2.13).
    Rounding through double precision first would round twice and can miss the nearest
    single. A literal beyond the range of single precision gives an infinite [Num]. *)

val num_value : t -> float
(** The float of a [Num] or [Dnum]. *)

val bool_value : t -> bool
val string_value : t -> string
val components : t -> t array
(** The array of a [Record] or an [Array]. *)

(** {1 Handles} *)

val make_handle : kind:string -> int -> handle
val handle_kind : handle -> string
val handle_id : handle -> int

(** {1 Value semantics} *)

val copy : t -> t
(** A deep copy: assignment and in parameters give the target a value of its own (§4.5,
    §5.2). Handles are shared: they denote an installed object, not a value. *)

val equal : t -> t -> bool
(** The [=] of §3.12: num and dnum by IEEE equality ([0 = -0]), strings byte for byte, records
    and arrays component by component. Arrays of different sizes are not equal. Handles are
    equal when they denote the same object. *)

val same_dimensions : t -> t -> bool
(** Two arrays (or two non-arrays) of the same sizes in every dimension. *)

(** {1 Initial values (§2.22, §2.23)} *)

(** The structure of a type, enough to build its initial value and to read a value of it from
    text (StrToVal). *)
type shape =
  | S_num
  | S_dnum
  | S_bool
  | S_string
  | S_handle of string           (** an installed atomic type, by name *)
  | S_record of shape array      (** the components in order *)
  | S_array of int * shape       (** [n] elements; 2 dimensions: [S_array (n, S_array (m, s))] *)

val default_of : shape -> t
(** 0 for num and dnum, FALSE, "", and a handle of identity 0 ("all bits 0") for an installed
    atomic type; records and arrays component by component. *)

(** {1 Memory accounting}

    The memory budget of a run (doc/user-guide.md, "Resources") counts RAPID data in bytes by
    this model, close to what the values occupy: a num, dnum, bool or handle 32 bytes, a
    string 32 bytes and its length, a record or an array 16 bytes, 8 a component or element,
    and its components or elements. Sums saturate at [max_int]. *)

val shape_bytes : shape -> int
(** The size of {!default_of} of the shape, computed without building it. *)

val fixed_size : shape -> bool
(** Whether every value of the shape has the same size, {!shape_bytes}: a shape without
    strings. *)

val bytes : t -> int
(** The size of a value. *)

val conform : shape -> t -> t option
(** The value as a value of the shape, if it fits: an aggregate has no type of its own and
    takes that of its context (§3.10), so an array value fits a record shape of as many
    components, and a num fits a dnum (a numeric literal member read as num, then widened
    exactly). [None] when the structure or a scalar's type differs. *)

val shape_of_type : Rapid_typing.Types.object_type -> shape
(** The shape of a declared type. Raises [Invalid_argument] for [anytype] and for an array
    parameter declared with [{*}], whose sizes only a value has. *)

val pos_shape : shape
val orient_shape : shape
val pose_shape : shape

(** {1 Built-in records (§2.14)} *)

val pos : float -> float -> float -> t
(** Components rounded to single precision. *)

val orient : float -> float -> float -> float -> t
val pose : t -> t -> t

val to_debug_string : t -> string
(** Every digit of every number (9 significant digits for num, 17 for dnum), for traces and
    test messages; not the controller's formatting (see {!Format}). *)
