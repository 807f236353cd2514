(** Statements and expressions (ch. 3, ch. 4; doc/semantics.md, "Statement lists and
    statements", "Assignment", "Expressions", "Places", "Control"), and the step's dispatch: one
    function per kind of focus (a statement, an expression, a value, a place, a location, the
    next thing to do), each a match with one clause per rule (or per frame, where the frame on
    top decides), naming the rule. The clauses of other chapters call Calls, Recovery and Waits,
    which come before; RAISE, RETRY, TRYNEXT and EXIT are statements of ch. 4 and are here.
    Settling, the administrative moves after every step (doc/semantics.md, "Settling"), is here
    too: it undoes nothing a step does not, and Backward and Machine need it. *)

open Configuration

val exec : config -> Ir.stmt -> Rule.t * Event.t list
(** A statement begins (the rule named after the statement), or its end in the handler of an
    asynchronous error (§7.4, Recovery.kept_exit). *)

val next : config -> Rule.t * Event.t list
(** Something completed (a statement, an argument, a list): at a point of response (ch. 8) the
    statement time, the time limit and an interrupt; a wait's step; else the frame on top
    continues (while-again, for-step, for-done, the end of a routine, of a handler, of an UNDO
    handler, an argument, backward-end, ...). *)

val expr_step : config -> Ir.expr -> Rule.t * Event.t list
(** An expression in focus: read, read-place, read-signal, unary-operand, binary-operands, and,
    or, aggregate-first, a function call, execute-placeholder, argument-aggregate. *)

val value_step : config -> Value.t -> Rule.t * Event.t list
(** A value in focus, taken by the frame on top: store, the operators' rules, the conditions of
    IF, WHILE and FOR and TEST's values, RETURN's and RAISE's values, an index, ... *)

val place_step : config -> Ir.place -> Rule.t * Event.t list
(** A place settling could not locate: place-absent, place-unknown. *)

val loc_step : config -> loc -> Rule.t * Event.t list
(** A location in focus: a reference argument's, CONNECT's target, a signal read. *)

val settle : config -> unit
(** The administrative moves after a step, so that the next step is a redex a programmer would
    name; it stops where a step has something to say. *)
