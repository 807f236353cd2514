(** The operators of §3.12 on run-time values.

    The static semantics knows the operand types, so the lowering picks the row of the §3.12
    table once and the machine applies it without looking at types again. AND and OR are not
    here: they evaluate their right operand only when needed (§3.1), which is control, not
    arithmetic.

    An [Error] carries the name of the execution error (ch. 12), e.g. ["ERR_DIVZERO"].
    Rulings: doc/rulings.md R-3.12 (DIV and MOD truncate toward zero) and R-3.12-b to R-3.12-e
    (integer operands, overflow, geometric operators, arrays of different sizes). *)

type binary =
  | Num_add | Dnum_add | Pos_add | String_concat
  | Num_sub | Dnum_sub | Pos_sub
  | Num_mul | Dnum_mul
  | Num_pos_mul          (** num * pos: scales *)
  | Pos_num_mul          (** pos * num: scales *)
  | Pos_cross            (** pos * pos: the cross product *)
  | Orient_mul           (** orient * orient: the quaternion product, q1 the scalar part *)
  | Num_div | Dnum_div
  | Pos_num_div          (** pos / num: each component *)
  | Num_intdiv | Dnum_intdiv
  | Num_mod | Dnum_mod
  | Num_lt | Num_le | Num_ge | Num_gt
  | Dnum_lt | Dnum_le | Dnum_ge | Dnum_gt
  | Equal | Not_equal    (** any value type, arrays included *)
  | Xor

type unary =
  | Num_neg | Dnum_neg | Pos_neg
  | Num_plus | Dnum_plus | Pos_plus
  | Not

val binary : binary -> Value.t -> Value.t -> (Value.t, string) result
(** Errors:
    - ["ERR_DIVZERO"]: [/], DIV or MOD by zero;
    - ["ERR_NOTINTVAL"]: a DIV or MOD operand that is not an integer value, or a negative dnum
      one (§3.12 notes b and c);
    - ["ERR_MAXINTVAL"]: a DIV or MOD operand that is an integer outside the exact integer
      sub-domain of its type (§2.13);
    - ["ERR_OVERFLOW"]: a num or dnum result (or a component of a pos or orient result) beyond
      the largest finite number of its precision (§7.1 names overflow an execution error);
    - ["ERR_STRTOOLNG"]: a concatenation longer than 80 bytes (§2.13);
    - ["ERR_NOTEQDIM"]: [=] or [<>] on arrays of different sizes (ch. 12).
    Operands are checked left before right. Raises {!Value.Type_mismatch} on operands the
    operator does not take. *)

val unary : unary -> Value.t -> (Value.t, string) result
(** Never an execution error: negation is exact. *)

val binary_name : binary -> string
val unary_name : unary -> string
(** For traces: the operator and its operand types, e.g. ["num + num"]. *)

val num_integer_min : float
val num_integer_max : float
val dnum_integer_min : float
val dnum_integer_max : float
(** The exact integer sub-domains of §2.13: -8388607..8388608 and
    -4503599627370496..4503599627370496. *)

(** {1 Building blocks shared with {!Library}} *)

val check_num : float -> (Value.t, string) result
(** [Ok (Num x)] for a finite single, ["ERR_OVERFLOW"] for an infinite one. *)

val check_dnum : float -> (Value.t, string) result

val cross : Value.t -> Value.t -> (Value.t, string) result
(** pos * pos. *)

val quaternion_product : Value.t -> Value.t -> (Value.t, string) result
(** orient * orient. *)

val exact_single : Q.t -> (Value.t, string) result
(** A num from an exact rational result, rounded once. *)
