(** What rapid-sem test writes of its results (doc/testing.md): a line per test and a summary,
    and JUnit XML. Times are virtual (the controller's clock), so that the same tests give the
    same report byte for byte (doc/rulings.md R-test-e). *)

val line : Test_suite.result -> string list
(** [PASS name  T s] or [FAIL name  T s], then, for a failure, its place and message indented,
    and what the test wrote (TPWrite) under it. *)

val summary : Test_suite.result list -> string
(** [N passed, N failed (N tests, T s virtual)] *)

val junit : Test_suite.result list -> string
(** JUnit XML: a test suite per module, a test case per test (its class the module, its file and
    line), a failure with the message and FILE:LINE:COL, the test's output as system-out. *)
