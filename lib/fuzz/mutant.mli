(** Ill-typed mutants of generated programs and hostile texts, for the property that the checker
    never crashes (doc/oracle.md, "Fuzzing"): whatever the text, parsing and checking answer with
    a tree or with diagnostics that each name their place ([FILE:LINE:COL]) and their class, and
    a mutant that passes the static semantics runs without reaching a state with no rule. *)

val mutate : Random.State.t -> string -> string
(** One to three mutations of a source text: a literal of another type in place of one, a name
    swapped for another name of the program, a token deleted, inserted or doubled, a line deleted,
    doubled or moved, a keyword swapped for another, a parameter mode added, the text cut short. *)

val hostile : Random.State.t -> string
(** A text made to hurt a front end: random bytes (NUL, invalid UTF-8), deep nesting of
    parentheses, aggregates and compound statements, very long names, numbers, strings and
    lines, unterminated strings and comments, a byte order mark, lone carriage returns. *)

val check_text : ?max_steps:int -> string -> (unit, string) result
(** The property on one text: [Error] says what went wrong (an OCaml exception, a diagnostic
    without its place or class, a checked mutant that reaches a state with no rule). *)

val shrink_text : (string -> bool) -> string -> string
(** The smallest text found, by deleting lines, then words, then characters, on which [fails] still
    holds. *)
