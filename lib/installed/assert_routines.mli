(** The assertions of rapid-sem test (lib/typing/installed/unit_test.sys, doc/testing.md): each
    passes and returns, or fails with {!Primitive.Assertion_failed} and a message that says what
    was expected and what was found; the engine stops the test at the call (doc/rulings.md
    R-test-b). A malformed argument (a negative tolerance, a pose that is not one) is
    ERR_ARGVALERR, an execution error like any installed routine's. *)

val modelled : string -> bool

val call :
  Primitive.context -> Motion_routines.state -> string -> Primitive.argument array -> Primitive.outcome option
(** [None]: not an assertion. AssertAtTarget reads the robot as CRobT does (its \Tool and \WObj,
    else the active ones), at the current virtual time. *)
