(** The syntax tree in a stable text form without locations (the output of
    [rapid-sem parse --ast]). Two modules whose trees are equal, locations aside, give
    byte-identical dumps, and two different trees give different dumps; this is the equality the
    round-trip tests use.

    The form is an S-expression, one constructor per node, named as in {!Ast}: a constructor
    without arguments is an atom ([Break], [EXP_placeholder]), one with arguments a list headed
    by its name ([(Binary Plus ...)]); record fields are lists headed by the field's name
    ([(scope Local)]), and an optional list field (ELSE, DEFAULT, BACKWARD, ERROR, UNDO, a step,
    an initial value, the %%% header, the comment lines before MODULE) is present exactly when
    the tree has it. Identifiers keep their spelling and are written bare, without the
    constructor [Ident] (the placeholder <ID> as [<ID>]), numeric literals as written; string
    literals (their raw text), comments and header lines are quoted, with the double quote, the
    backslash and control characters escaped. Declarations, statements and record components
    each start a line, indented by their depth; an expression stays on the line of its node. *)

val module_declaration : Ast.module_declaration -> string
(** Ends with a line break. *)

val expression : Ast.expression -> string
(** One line, no line break. *)
