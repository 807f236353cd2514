(** A shard's results as stable, machine-readable JSON ([rapid-sem fuzz --json FILE]), and the
    merge of a campaign's shards into one report ([rapid-sem fuzz --merge-report]), for campaigns
    spread over the tasks of a scheduler (bench/slurm/campaign.sh; doc/fuzz-campaign.md,
    "Campaigns across machines").

    Program [i] of a campaign depends only on the campaign's seed and [i]
    ({!Campaign.program_seed}), and belongs to exactly one shard, so the merge of shards
    [1/N] ... [N/N] has the totals and failures of one unsharded run of the same programs: the
    same programs, failures, outcomes and rule counts, the failures in the order of their
    programs. Only the figures of time, and which host ran what, differ. A campaign that stops at
    its first failure ([--break-rule]) is the exception: each shard stops at its own. *)

type failure_entry = {
  program : int;                         (** the program's index in the campaign *)
  kind : string;                         (** the class of failure: [refused], [exception], [stuck],
                                             [nondeterministic], [engines-differ], [round-trip],
                                             [checker-crashed] *)
  message : string;                      (** {!Fuzz_run.failure_to_string} *)
  original_size : int;
  minimal_size : int;
  reproducer : string;                   (** its file (or folder) name in the shard's [--out] *)
  source : string;                       (** the minimal program, or a scenario's text *)
}

type t = {
  settings : (string * string) list;     (** what makes the campaign's programs: seed, count,
                                             generator and checking options; shards of one
                                             campaign have the same *)
  shard : Campaign.shard;
  host : string;
  programs : int;
  failures : failure_entry list;
  outcomes : (string * int) list;
  rules : (string * int) list;           (** every named rule ({!Coverage.rule_names}) *)
  seconds : float;
  cpu_seconds : float;
}

val format : string
(** The value of the field ["format"], which names this layout and its version. *)

val kind : Fuzz_run.failure -> string

val of_summary :
  settings:(string * string) list -> shard:Campaign.shard -> host:string ->
  reproducer:(Campaign.failure_found -> string) -> Campaign.summary -> t

val to_json : t -> Yojson.Safe.t
val of_json : Yojson.Safe.t -> (t, string) result
val read : string -> (t, string) result

type merged = {
  m_settings : (string * string) list;
  shards : t list;                       (** by index *)
  m_programs : int;
  m_failures : failure_entry list;       (** by program, in each program's order *)
  m_outcomes : (string * int) list;
  m_rules : (string * int) list;
}

val merge : t list -> (merged, string) result
(** An error when the reports are not the shards [1/N] ... [N/N] of one campaign, each once:
    different settings, a shard missing or given twice. *)

val coverage : merged -> Coverage.t

val merged_to_json : merged -> Yojson.Safe.t
(** [{"format", "settings", "totals", "failures", "shards"}]: [totals] (programs, failures,
    outcomes, rules) and [failures] are those of an unsharded run; [shards] holds each shard's
    host and figures of time. *)

val merged_to_markdown : merged -> string
(** Totals, failures with their reproducers ([shard-K/NAME], or [NAME] when the one report is unsharded), and a
    table of the shards. *)
