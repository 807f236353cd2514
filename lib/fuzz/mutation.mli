(** The mutation check (doc/fuzz-campaign.md, "The mutation check"): an engine with one rule
    deliberately broken, which a campaign must catch within a bounded number of programs, to show
    that the harness finds a wrong semantics.

    A mutant engine is an engine run on a program rewritten so that the broken rule's effect is
    exactly what the engine shows: TRYNEXT statements become RETRY (the rule trynext behaving as
    retry), a FOR loop's bound moves back by one step (the loop skips its last iteration, §4.18:
    the iterations [from + k*step] that are within the bound all run but the last). The machine,
    the definition, runs the program as written, so the engines differ where the rule matters. *)

type t = Trynext_as_retry | For_skips_last

val all : t list
val name : t -> string
(** [trynext-as-retry], [for-skips-last] *)

val of_string : string -> t option

val apply : t -> Rapid_runtime.Ir.program -> Rapid_runtime.Ir.program

val engine : t -> Fuzz_run.engine -> Fuzz_run.engine
(** The engine, broken: named [ENGINE+NAME]. *)
