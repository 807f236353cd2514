(** The properties of doc/oracle.md ("Fuzzing") on a {!Fuzz_case.t}: every module's printer round
    trip, the static semantics accepts the task buffers (with the case's [--allow-unknown]),
    progress, determinism, and the engines' agreement in the same world, observed, run with the
    case's stimulus, limits and options. *)

val several_tasks_closure : bool ref
(** A case of several tasks is judged on the machine (round trip, progress, determinism for its
    schedule seed and for round robin) and, while this holds ([true] unless a caller turns it
    off), compared with the closure engine's run of the same tasks ({!Rapid_closure.Closure_tasks})
    for each of those schedules: the events of every task, each prefixed by its task's name, as
    two streams (the program's and the world's), and every task's outcome. *)

val check_case :
  ?engines:Fuzz_run.engine list -> ?max_steps:int -> Fuzz_case.t -> (Fuzz_run.observed, Fuzz_run.failure) result
(** [Ok] with the machine's observation when every property holds. *)

val observe : ?max_steps:int -> Fuzz_case.t -> (Fuzz_run.observed, string) result
(** The machine's observation, without judging: the expected events saved with a failure. *)
