(** The conformance suite run against another implementation (doc/oracle.md, "The conformance
    suite against your tool"): each case's question asked through the oracle's protocol, the
    answer compared with the case's expectation. *)

type result = {
  case : Spec_case.t;
  passed : bool;
  skipped : bool;
      (** a format this runner does not know, or several tasks (format 4) and a template
          without [{tasks}] *)
  detail : string;
}

val command : ?fs:string list -> template:string -> Spec_case.t -> string
(** The shell command for a case: in the template, [{mode}] is [parse] (format 1), [check]
    (format 2) or [run] (format 3); [{files}] the case's files and [{file}] its first, quoted;
    [{options}] the options the case asks for, spelled as rapid-sem's ([--strict],
    [--allow-unknown], [--io FILE], [--entry NAME], [--retry-limit N], [--statement-time S],
    [--max-time S], [--stub-unmodelled], [--max-steps N], [--robot FILE]), then [fs] ([run_case]
    gives each run of a run case [--fs DIR], a fresh mass memory whose HOME: holds the case's
    [@home] files); [{tasks}] nothing, except in a case of several tasks
    (format 4, [{mode}] [run]): their [--task NAME=FILE,...], [--entry TASK=ROUTINE] (for each
    entry that is not main), [--schedule SEED] and [--motion-task NAME], as rapid-sem run spells
    them, with [{file}] and [{files}] then empty and no [--entry] in [{options}]. *)

val run_case :
  ?timeout:float -> ?reference:string -> ?ignore:string list -> template:string -> Spec_case.t -> result
(** [reference] (a template as [template], for rapid-sem's own [run --json]): a run case passes
    only when the implementation's events also agree with rapid-sem's, compared as
    [rapid-sem oracle] compares them ([ignore]: the kinds left out); the detail of a failure names
    the first divergence's index. A case of several tasks is skipped unless [template] has
    [{tasks}]; its events are compared task by task ({!Rapid_oracle.Task_streams}), and
    [reference] needs [{tasks}] too. *)

val run :
  ?verbose:bool -> ?timeout:float -> ?reference:string -> ?ignore:string list -> ?junit:string ->
  ?json:string -> template:string -> Format.formatter -> string -> int * int
(** Every case below the folder: failures printed, a summary per section, [N passed, N failed];
    [junit] and [json] name files to write the results to (JUnit XML, which CI systems read, and
    JSON); a line says how many cases of several tasks were skipped for want of [{tasks}].
    Returns (passed, failed). *)
