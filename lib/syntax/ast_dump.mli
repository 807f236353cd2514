(** The syntax tree in a stable text form without locations (the output of
    [rapid-sem parse --ast]). Two modules whose trees are equal, locations aside, give
    byte-identical dumps; this is the equality the round-trip tests use. The form is an
    S-expression, one constructor per node, named as in {!Ast}; identifiers keep their spelling. *)

val module_declaration : Ast.module_declaration -> string
val expression : Ast.expression -> string
