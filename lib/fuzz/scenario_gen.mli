(** Scenarios: generated cases that reach the rules the one-module programs of {!Program_gen}
    cannot (doc/fuzz-campaign.md, "Scenarios"): each is drawn from a random state, with its
    options and stimulus drawn from it too, and recorded in the case so that a failure
    reproduces.

    - [--allow-unknown] with names neither declared nor installed (place-unknown, call-unknown,
      call-unknown-function), installed routines rapid-sem does not model, with or without
      [--stub-unmodelled] (call-not-modelled, call-stubbed);
    - small limits: [--max-time] with long or unbounded waits and long loops (time-limit,
      wait-time-limit, wait-deadlock), [--max-memory] with large routine data
      (memory-exhausted), [--max-call-depth] with bounded recursion (call-depth-exceeded);
    - CONNECT targets passed through VAR and INOUT parameters (connect-not-variable, §4.15);
    - moves that fail asynchronously, by a collision of the stimulus or ProcerrRecovery from a
      trap, with handlers that RETRY, TRYNEXT, EXIT, RAISE or RETURN, or none (async-*, §7.4,
      §7.6);
    - a NOSTEPIN module below the user level with RaiseToUser \Continue, \BreakOff and
      \ErrorNumber, and user handlers that RETRY or TRYNEXT (raise-to-user-*, resume-*, §7.3);
    - two tasks on one clock: a shared persistent, WaitUntil on it, WaitSyncTask,
      WaitTestAndSet (wait-yield, wait-deadlock, ch. 14).

    Three scenarios of one task in ten also hold a program of {!Program_gen}, called at the end
    of the scenario's main.

    Every scenario terminates: recursion and retries are bounded, waits have a bound, a time
    limit or end in a deadlock the scheduler sees. *)

val kinds : string list
(** The names of the kinds of scenario, in the order {!generate_kind} takes them. *)

val generate : Random.State.t -> Fuzz_case.t
(** A scenario of a kind drawn from the state. *)

val generate_kind : string -> Random.State.t -> Fuzz_case.t
(** A scenario of the named kind. *)
