(** The syntax tree without what {!Ast_dump} leaves out, so that structural equality on the
    results is the dump's equality ("equal trees, locations aside") without writing the dumps:
    the fuzzer's printer round trip compares two trees for every program.

    What is erased: every region, a string literal's bytes (its raw text stays), and the
    difference between a positional argument and a required argument without a name, which
    the dump writes alike. *)

val module_declaration : Ast.module_declaration -> Ast.module_declaration
(** The tree with every region {!Source.no_region}, every string literal's bytes empty and every positional
    argument a required one without a name. *)

val equal : Ast.module_declaration -> Ast.module_declaration -> bool
(** [equal a b] exactly when [Ast_dump.module_declaration a = Ast_dump.module_declaration b], and
    when [module_declaration a = module_declaration b]; compared without building either. *)
