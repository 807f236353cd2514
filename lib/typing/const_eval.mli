(** Values of constant expressions (§3.2), as far as the static semantics needs them: array
    dimensions must be positive integers (§2.22), operands of DIV and MOD must represent integers
    when they are constant (§3.12). Numbers are computed exactly, as rationals; an expression whose
    value cannot be known before execution (it names a variable, calls a function, divides by
    zero) has none. *)

open Rapid_syntax

type value = Number of Q.t | Boolean of bool | Text of string

val eval : lookup:(string -> Ast.expression option) -> Ast.expression -> value option
(** [lookup name] gives the initial value of the constant [name], if [name] is a constant. *)

val integer_of : value -> Z.t option
(** The integer a number represents, if it represents one. *)
