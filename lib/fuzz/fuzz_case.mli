(** A generated case that is more than one module run with the defaults: several modules of one
    task (a NOSTEPIN module below the user level, §7.3), several tasks on one clock (ch. 14), a
    stimulus of its own (a collision, §7.6), and the options of [rapid-sem run] it runs with
    (doc/fuzz-campaign.md, "Scenarios"). Everything needed to run it again is here, so that a
    failure saved with {!files} reproduces by {!command}. *)

type options = {
  allow_unknown : bool;            (** [--allow-unknown]: unknown names reach ERR_REFUNK... *)
  stub_unmodelled : bool;          (** [--stub-unmodelled] *)
  max_time : float option;         (** [--max-time SECONDS] *)
  max_memory : int option;         (** [--max-memory BYTES] *)
  max_call_depth : int option;     (** [--max-call-depth N] *)
}

val default_options : options
(** As [rapid-sem run] without options. *)

val limits : options -> Rapid_runtime.Limits.t
(** The machine's limits the options ask for (the others as {!Rapid_runtime.Limits.default}). *)

val arguments : options -> string list
(** The options as [rapid-sem run] takes them. *)

type task = {
  task_name : string;                          (** "T_ROB1", "T_B" ... *)
  modules : Program_gen.program list;          (** the task buffer, entry routine main *)
}

type t = {
  tasks : task list;                           (** one, or several on one clock *)
  io_text : string;                            (** the stimulus file (doc/controller.md) *)
  options : options;
  schedule : int option;                       (** [--schedule SEED] of several tasks *)
}

val module_file : Program_gen.program -> string
(** The file a module is saved in: its name (without attributes) with [.mod]. *)

val size : t -> int
(** Statements of every module, counted as {!Program_gen.size}. *)

val shrink : t -> t Seq.t
(** Smaller cases: each module shrunk by {!Program_gen.shrink}, one at a time; the options, the
    stimulus and the tasks stay. *)

val to_text : t -> string
(** Every module's source, each headed by a comment line naming its task and file, with the
    command that runs the case: the form a failure is shown and saved in. *)

val command : t -> string
(** [rapid-sem run] with the options, the stimulus file [fuzz.io] and the modules' files (with
    [--task] for several tasks). *)
