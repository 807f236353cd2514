(** What every command of the command line shares: its exit statuses, how it writes standard
    output, and how it tells of a run's progress, failures and end. Exit statuses are a contract
    other tools rely on (doc/user-guide.md). *)

val version : string

val exit_ok : int
(** 0 *)

val exit_spec_failed : int
(** 1: a failing conformance suite *)

val exit_static_error : int
(** 2: a static error, a command line that cannot be used *)

val exit_internal : int
(** 125: an internal error of rapid-sem *)

val print_line : string -> unit
(** The line and a line break, flushed: each line leaves the process as it is written. *)

val flush_output : unit -> unit

val guard : (unit -> int) -> int
(** The command's status, with what may escape it turned into one: standard output that cannot
    be written (141, 128 + SIGPIPE), a stack overflow or any other exception (125, reported as
    a bug), the machine's memory exhausted (3). *)

val finish : Rapid_runtime.Outcome.t -> int -> max_steps:int -> int
(** The exit status of a run's end (0 ended, 1 stopped, 3 exhausted, 4 not modelled, 125 stuck),
    what it means said on standard error. *)

val report_task_stops : (string * Rapid_runtime.Outcome.t) list -> Rapid_runtime.Outcome.t -> unit
(** Of several tasks' outcomes (name, outcome), each error stop and each routine not modelled
    that is not the run's outcome (given last), one line on standard error naming its task. *)

val report_load_failure : ?json:bool -> Rapid_load.Session.failure -> int
(** A task buffer refused: its diagnostics on standard error; with [json] the stream of a
    refused run on standard output too (doc/oracle.md). *)

val notify : Rapid_run.Run_setup.notice -> unit
(** A notice of the run on standard error. *)

val failure : ?json:bool -> ?files:string list -> Rapid_run.Run_setup.failure -> int
(** A run that did not happen, told, and its exit status. With [json], the stream says so
    ([files]: those of the task buffer whose entry routine is missing). *)

val report_stubbed : Rapid_runtime.Event.t list -> unit
(** --stub-unmodelled: each stubbed routine of these events, as a warning on standard error. *)
