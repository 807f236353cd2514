(** The properties of doc/oracle.md ("Fuzzing") on a {!Fuzz_case.t}: every module's printer round
    trip, the static semantics accepts the task buffers (with the case's [--allow-unknown]),
    progress, determinism, and the engines' agreement in the same world, observed, run with the
    case's stimulus, limits and options. *)

val several_tasks_closure : (Fuzz_case.t -> max_steps:int -> Fuzz_run.observed) option ref
(** The switch for programs of several tasks. The closure engine runs one task only on this
    branch, so a case of several tasks is judged on the machine alone (round trip, progress,
    determinism for its schedule seed and for round robin). Once an engine runs several tasks,
    set this to its run (events as {!Fuzz_run.observed} holds them, each prefixed by its task's
    name and a colon, as here) and every such case is compared with the machine too. [None]
    here. *)

val check_case : ?engines:Fuzz_run.engine list -> ?max_steps:int -> Fuzz_case.t -> (Fuzz_run.observed, Fuzz_run.failure) result
(** [Ok] with the machine's observation when every property holds. *)

val observe : ?max_steps:int -> Fuzz_case.t -> (Fuzz_run.observed, string) result
(** The machine's observation, without judging: the expected events saved with a failure. *)
