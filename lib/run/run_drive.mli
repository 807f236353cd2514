(** [rapid-sem run] (doc/user-guide.md): which engine runs, and the run driven to its end, one
    task or several, with --samples and --save, its events handed to the command line as they
    happen ({!sink}). The command line says how each is written (JSON, the program's output) and
    what exit status the end means; everything between is here. *)

type engine = [ `Machine | `Closure ]

val engine : ?requested:engine -> samples:float option -> unit -> engine
(** The engine of a run: the one --engine names; without it the closure engine, once the
    differential campaign passed (doc/fuzz-campaign.md), unless the run asks for what only the
    machine has (--samples; doc/semantics.md, "The second engine"). *)

(** What a run hands over as it goes, each when it happens. With several tasks, [Some name]
    names the task of an event or a sample. *)
type sink = {
  start : string list option -> unit;
      (** the task buffers are loaded and the run is about to start (several: the tasks' names) *)
  event : string option -> Rapid_runtime.Event.t -> unit;
      (** each event the engine reports: all of them with [~json], else the output *)
  stubbed : Rapid_runtime.Event.t list -> unit;
      (** events of a step, or of the whole closure run of one task at its end, among which the
          [Stubbed] ones (--stub-unmodelled) are to be reported *)
  samples : string option -> Tcp_samples.sample list -> unit;   (** --samples, with [~json] *)
  cell : Backup_setup.summary -> unit;
      (** a controller backup: after [start], what runs (its tasks, entry routines, robots, I/O) *)
  task_end : string -> Rapid_runtime.Outcome.t -> int -> unit;   (** several: each task's end *)
  run_end : ?entry_at:Rapid_syntax.Source.region -> Rapid_runtime.Outcome.t -> int -> unit;
      (** the end of the run and its work (steps, or units of fuel), before --save writes; an
          ended run is at its entry routine [entry_at] *)
  flush : unit -> unit;       (** what was written must be out before --save writes files *)
}

type ended = { outcome : Rapid_runtime.Outcome.t; work : int }
(** How the run ended, and the machine's steps or the closure engine's units of fuel. *)

val run :
  notify:(Run_setup.notice -> unit) -> sink -> engine:engine -> json:bool -> samples:float option ->
  save:string option -> Run_options.t -> Run_options.tasks -> (ended, Run_setup.failure) result
(** The run of the options by [engine] ({!engine}), its events to [sink]. [json] (--json): every
    event is wanted, and observed (store writes, arguments, returned values), and --samples
    samples; without it only the output (and with --stub-unmodelled what it stubs). [save]
    (--save DIR, one task): the modules written back with their persistents' values at the end
    ({!Persistent_save}), its problems found before the run where they can be. With several
    tasks, --max-steps bounds the machine's steps of the whole run, and each task's fuel of the
    closure engine. A combination of options that cannot run is a [Usage] failure before
    anything is loaded. One folder that is a controller backup runs as the tasks it configures,
    one .pgf file as the modules it lists ({!Backup_setup.input}); the backup's warnings are
    notified first. *)

val entry_region : Ir.program -> string -> Rapid_syntax.Source.region option
(** Where the entry procedure of this name is declared (schema rapid-sem/2: an ended task is at
    its entry routine; R-4.12-m). *)
