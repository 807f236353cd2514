(** Backward execution (ch. 6; doc/semantics.md, "Backward execution"): one statement backward
    from the program pointer, a transition of its own that the debugger asks for
    ([Machine.backward]), never taken by [step]. A module of its own because it is not part of
    the step: it comes after Statements, whose settling binds a backward call's arguments. The
    step's share of ch. 6 is where the step meets it: backward-end when the BACKWARD handler
    has returned (Statements.next), raise-in-backward for an error while it runs
    (Recovery.raise_step). *)

open Configuration

val backward : config -> (Rule.t, string) result
(** backward-noop (§6.1) or backward-call (§6.1, §6.2); [Error message] when backward execution
    is refused: nothing changed. *)

val running : config -> bool
(** A BACKWARD handler is running (ch. 6). *)
