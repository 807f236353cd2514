(** Values of constant expressions (§3.2), as far as the static semantics needs them: array
    dimensions must be positive integers (§2.22), operands of DIV and MOD must represent integers
    when they are constant (§3.12). Numbers are computed exactly, as rationals; an expression whose
    value cannot be known before execution (it names a variable, calls a function, divides by
    zero) has none.

    Bounded: each constant is evaluated once per [cache] (a constant used twice by the next one
    does not double the work down a chain), a constant defined by itself has no value (the cycle
    is reported elsewhere, doc/rulings.md R-3.2-b), and a number or string too large to matter
    (beyond double precision's range, longer than 80 bytes) has none, so that no chain of
    constants makes the evaluation slow or large. The errors of these values at run time are
    judged by the evaluation of initial values (lib/semantics/initial_values.ml). *)

open Rapid_syntax

type value = Number of Q.t | Boolean of bool | Text of string

type cache
(** The values of constants computed so far, by their initial value. *)

val create_cache : unit -> cache
val copy_cache : cache -> cache

val eval :
  ?cache:cache -> lookup:(string -> Ast.expression option) -> Ast.expression -> value option
(** [lookup name] gives the initial value of the constant [name], if [name] is a constant. *)

val integer_of : value -> Z.t option
(** The integer a number represents, if it represents one. *)
