(** A function that can reach its ENDFUNC without RETURN (§5.5): `rapid-sem check` warns, since
    the call raises ERR_FNCNORET there when it runs. *)

open Rapid_syntax

val functions : Ast.module_declaration -> (string * Source.region * Source.region option) list
(** The module's functions whose statements can complete: the name, its region, and the last
    statement on the path that falls off the end ([None]: the function has no statement). *)
