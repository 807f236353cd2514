(** A run by the machine one reduction at a time, for a view that shows each one
    ([rapid-sem trace]): one task buffer or several tasks (ch. 14) behind one interface, set up
    from the options as [rapid-sem run --engine machine] sets them up ({!Run_setup}), so that the
    view knows nothing of how the run is assembled. *)

type t

val start :
  ?history:bool -> notify:(Run_setup.notice -> unit) -> Run_options.t -> Run_options.tasks ->
  (t, Run_setup.failure) result
(** The machine started on the options' task buffer, or with --task on every task (the files
    then not looked at). [history]: the motion history is kept (--samples). *)

val next : t -> (string option * Rapid_semantics.Machine.config) option
(** The task about to step (its name with several) and its machine, or [None] when the run is
    over or --max-steps are done. Choosing a task of several may move the clock. *)

val step : t -> string * Rapid_runtime.Event.t list
(** The step of the task {!next} gave: its rule and its events. *)

val outcome : t -> Rapid_runtime.Outcome.t
val steps : t -> int

val robot : t -> (Rapid_semantics.Machine.config * Run.world) option
(** The machine and the world whose robot --samples samples: the one task's, or the motion
    task's of several. *)

val entry_at : t -> Rapid_syntax.Source.region option
(** One task: where its entry routine is declared (the place of an ended run, R-4.12-m); several:
    [None]. *)
