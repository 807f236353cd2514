(** The canonical printer: a syntax tree written back as RAPID source in one layout.

    For every module [m] that parses, [module_declaration m] parses to a tree equal to [m]
    (locations aside; equality is that of {!Ast_dump}). The layout: two spaces of indentation
    per level, reserved words in upper case, identifiers and numeric literals as written,
    one statement or declaration per line, comments where the tree has them, optional and
    conditional arguments written without a preceding comma. *)

val module_declaration : Ast.module_declaration -> string
val expression : Ast.expression -> string
val statement : Ast.statement -> string
(** A statement at indentation 0, with its trailing line break. *)
