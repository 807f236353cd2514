(** The rule coverage of a fuzzing campaign (doc/fuzz-campaign.md): how often each named rule of
    the machine (doc/semantics.md, {!Rapid_semantics.Machine.rule_names}) applied, written as
    coverage.json and coverage.md, and merged across the shards of a campaign. *)

type t = {
  programs : int;
  failures : int;
  outcomes : (string * int) list;        (** how the runs ended *)
  rules : (string * int) list;           (** every named rule, in the order of doc/semantics.md,
                                             with how often it applied (0: never) *)
  cpu_seconds : float;                   (** summed over the shards *)
}

val rule_names : string list
(** The machine's named rules, each once, in the order of doc/semantics.md; not [done] and
    [stuck], which the document lists as not rules. *)

val of_summary : Campaign.summary -> t

val applied : t -> int
(** Rules applied at least once. *)

val merge : t list -> t

val to_json : t -> Yojson.Safe.t
val of_json : Yojson.Safe.t -> (t, string) result

val to_markdown : t -> string
(** A summary line ([N of T rules applied]) and a table of every rule with its count, the rules
    never applied listed apart. *)

val write : dir:string -> t -> unit
(** [dir]/coverage.json and [dir]/coverage.md, [dir] made if missing. *)

val read : string -> (t, string) result
(** A coverage.json file. *)
