(** The resources a run may use (§1.4), the same for both engines, and the outcomes of going
    beyond them, each naming the option that sets its limit. *)

type t = {
  max_call_depth : int;                    (** default 10,000 *)
  retry_limit : int;                       (** "No Of Retry": default 4 (§7.1) *)
  max_memory : int;
      (** bytes of RAPID data (module data, routine data and in arguments of the active
          routines, by the model of {!Value.bytes}): default 256 MiB *)
}

val default : t

val call_depth_exceeded : t -> Outcome.t
(** The outcome of a call beyond [max_call_depth] (§1.4). *)

val memory_exhausted_by : t -> string -> Rapid_syntax.Source.region -> Outcome.t
(** The outcome of RAPID data [what] at a place beyond [max_memory]. *)

val move_owners : int
(** How many recent moves an engine remembers the routine activation of, to raise their
    asynchronous errors there (§7.4, §7.6): 64. *)

val for_tasks : t -> count:int -> t
(** The limits of each of [count] tasks: [max_memory] split evenly between them, so that the
    tasks together never hold more RAPID data than the run's budget (R-14-cli3). *)
