(** Statement and branch coverage of the modules a test run exercises (doc/testing.md,
    "Coverage"), as lcov's tracefile and Cobertura's XML read it.

    The machine (the definition) reports it: before each step, the statement in focus is one
    reached; each step whose rule chooses a way (if-true, if-false, while-true, for-enter,
    test-match, ...) takes a branch of the statement in progress (doc/rulings.md R-test-d).
    Runs that do not ask for coverage are not touched: they run on the closure engine. *)

type key = string * int * int
(** A place in a source file: its name as given, the line and the column (from 1). *)

type t
(** The statements, branches and routines of the modules covered, each with its count. *)

val of_program : Ir.program -> covered:(Ir.routine -> bool) -> t
(** Every statement (but labels), branch and routine of the routines [covered] keeps, at 0. *)

type hits
(** What one run reached: statements, branches, routines entered, with their counts. *)

val record : unit -> hits

val observe : hits -> Rapid_semantics.Machine.config -> (unit -> Rapid_semantics.Rule.t * Event.t list) ->
  Rapid_semantics.Rule.t * Event.t list
(** [observe h cfg step]: the step made (by [step]), with what it reached counted in [h]. *)

type portable
(** The hits of a run in terms of places ({!key}), not of the run's regions: what a child
    process sends back (Marshal), what {!add} counts. *)

val portable : hits -> portable

val add : t -> portable -> unit
(** The counts of a run added to those of the modules covered; places outside them are not. *)

val lcov : t -> string
(** The tracefile: per source file TN, SF, FN/FNDA/FNF/FNH, BRDA/BRF/BRH, DA/LF/LH and
    end_of_record. A branch of a statement never reached is [-]. *)

val cobertura : t -> version:string -> string
(** Cobertura XML (coverage-04.dtd): one package, a class per module, its methods (routines)
    and lines, the lines of branches with their condition coverage. *)

val summary : t -> string
(** [lines: H/F (P%), branches: H/F (P%)] *)
