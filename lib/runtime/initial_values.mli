(** The initial values of data, known before the program runs (§3.2, §3.3).

    The initial value of a variable or constant is a constant expression and that of a
    persistent a literal expression: neither names a variable, a persistent or a function, so
    each value is known before the first step. They are computed here, once, with the machine's
    own operators ({!Arith}), so that what is refused here is exactly what would fail at run
    time, and a program that passes never meets these errors when it runs:

    - an operation of an initial value that raises an execution error (ERR_DIVZERO,
      ERR_OVERFLOW, ERR_NOTINTVAL, ERR_MAXINTVAL, ERR_STRTOOLNG; an index out of bounds or not
      an integer), in module data and routine data alike (doc/rulings.md R-3.2-a);
    - a constant whose value depends on itself (R-3.2-b);
    - a numeric literal, anywhere in the program, whose context makes it a num and that is
      beyond the range of single precision (§2.5, R-2.5-c).

    Each is a semantic error at a place. *)

val evaluate : Ir.program -> (Ir.program, Rapid_typing.Report.t list) result
(** [Ok p]: [p] is the program with each module data object's initial value computed
    ([Init_default] of its value), in the order the values depend on one another (a constant
    may be declared after the data that uses it, §2.20). Initial values that hold a placeholder
    or a name allowed by --allow-unknown stay as they are: they fail when they run. Routine
    data keeps its expressions, which the machine evaluates at each call (§2.21). [Error]: the
    reports, in source order. *)

type kept
(** What {!evaluate} keeps of the last program that passed, for the next one over the same
    installed part (the values of its installed data and the verdicts on its installed routines). *)

val kept : unit -> kept option

val keep : kept -> unit
(** The next {!evaluate} starts from this (the installed environment's image, lib/load). *)
