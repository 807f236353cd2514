(** The conformance suite run against another implementation (doc/oracle.md, "The conformance
    suite against your tool"): each case's question asked through the oracle's protocol, the
    answer compared with the case's expectation. *)

type result = {
  case : Spec_case.t;
  passed : bool;
  skipped : bool;                    (** a format this runner does not know *)
  detail : string;
}

val command : template:string -> Spec_case.t -> string
(** The shell command for a case: in the template, [{mode}] is [parse] (format 1), [check]
    (format 2) or [run] (format 3); [{files}] the case's files and [{file}] its first, quoted;
    [{options}] the options the case asks for, spelled as rapid-sem's ([--strict],
    [--allow-unknown], [--io FILE], [--entry NAME], [--retry-limit N], [--statement-time S],
    [--max-time S], [--stub-unmodelled]). *)

val run_case : ?timeout:float -> template:string -> Spec_case.t -> result

val run :
  ?verbose:bool -> ?timeout:float -> ?junit:string -> ?json:string -> template:string ->
  Format.formatter -> string -> int * int
(** Every case below the folder: failures printed, a summary per section, [N passed, N failed];
    [junit] and [json] name files to write the results to (JUnit XML, which CI systems read, and
    JSON). Returns (passed, failed). *)
