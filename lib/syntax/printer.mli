(** The canonical printer: a syntax tree written back as RAPID source in one layout.

    For every module [m] that parses, [module_declaration m] parses to a tree equal to [m]
    (locations aside; equality is that of {!Ast_dump}), and printing that tree again gives the
    same text. The layout:
    - two spaces of indentation per level; the items of a module are one level in, a routine's
      declarations and statements one level further, BACKWARD, ERROR and UNDO at the level of
      PROC; ELSEIF, ELSE, CASE, DEFAULT and placeholders <EIT>, <CSE> at the level of their
      statement;
    - reserved words in upper case; identifiers, numeric literals (§2.5) and string literals
      (their raw text, §2.7) as written; switch parameters as [switch name] (§5.2);
    - one declaration, statement or record component per line; a compact IF (§4.17) on one line;
    - a comment as [!] and its text, ending its line; in a record a comment stands on the line
      of the name or component before it, and on a line of its own after another comment or
      where it stood on a line of its own in the text it was read from (its region starts on a
      later line than the item before it ends: the dialect's comment lines, doc/dialect.md);
    - type definitions, then data declarations, then routines (§9.2);
    - the %%% header block (doc/dialect.md) before MODULE when the tree has one, then the
      comment lines that preceded MODULE, one per line;
    - expressions with spaces around binary operators and the fewest parentheses that give the
      tree back (§3.1: NOT heads an <expr>, a sign heads a <simple expr>, relations do not
      chain);
    - required arguments and parameters separated by [", "]; optional and conditional
      arguments ([\Name:=e], [\Name?p]) and optional parameters ([\num a | num b]) preceded by a
      space and no comma (§3.11, §4.6, §5.2).

    A tree that no text derives (for example <EXP> inside an operand) is printed all the same,
    without raising; the text may then not parse. Recursion follows the nesting of the tree
    only, never the length of a list. *)

val module_declaration : Ast.module_declaration -> string

val expression : Ast.expression -> string
(** An expression where the grammar says <expression>. *)

val statement : Ast.statement -> string
(** A statement at indentation 0, with its trailing line break. *)
