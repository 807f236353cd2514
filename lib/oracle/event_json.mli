(** The observable events of a run as JSON objects, schema rapid-sem/2 (doc/observable.md,
    doc/trace-format.md): what [rapid-sem run --json] and [trace --format jsonl] write, and what
    the oracle compares another implementation's stream against. It lives here, beside the
    oracle, rather than in the command line, because it is the protocol itself; it names no
    engine (only the neutral types of lib/runtime and lib/observable), so that either engine's
    events, and the tests', go through the same encoder. The objects are written with
    {!Rapid_runtime.Json_text}. *)

val schema : string
(** ["rapid-sem/2"] ({!Schema_compat.current}). *)

val text : string -> Yojson.Safe.t
(** A RAPID string or name as JSON text: valid UTF-8 kept, any other byte read as Latin-1
    (RAPID strings are bytes; doc/trace-format.md). *)

val region : Rapid_syntax.Source.region -> Yojson.Safe.t
(** [{"file", "line", "col", "end_line", "end_col"}]. *)

val time : float -> Yojson.Safe.t
(** A virtual time: seconds to the microsecond, written as such (not as the nearest double). *)

(** {1 Events} *)

type t
(** The encoder of one run's events. Its one piece of state is the error in flight: the number
    of the error last raised or propagated, which is the one an error handler takes (an error
    in an UNDO handler stops the task), and which error-handled carries (the value ERRNO takes).
    A run of several tasks has one encoder for all of them, as their events come. *)

val create : unit -> t
(** No error in flight (0). *)

val note : t -> Rapid_runtime.Event.t -> unit
(** The error in flight of an event that is not written (the steps a trace leaves out); [event]
    notes its own. *)

val event : t -> Rapid_runtime.Event.t -> Yojson.Safe.t
(** The event's object, [{"event": KIND, ...}]. *)

val motion : Rapid_observable.Motion_event.t -> Yojson.Safe.t
(** A motion event (doc/trace-format.md, "Motion events"): times to the microsecond, lengths to
    the micrometre, angles to the microdegree. *)

val observation : Rapid_runtime.Observation.t -> Yojson.Safe.t
(** The events schema rapid-sem/2 adds: store, arguments, returned, error-propagated, retry,
    trynext. *)

val sample : float -> Rapid_observable.Pose.t -> float array option -> Yojson.Safe.t
(** A tcp-sample of [--samples HZ]: its time, the TCP pose and the axis angles where the model
    has them. *)

val with_task : string -> Yojson.Safe.t -> Yojson.Safe.t
(** The object of a run of several tasks: the task's name second, after ["event"]. *)

(** {1 The start and the end of a stream} *)

val start : ?tasks:string list -> unit -> Yojson.Safe.t
(** The first line: [{"event":"start","schema":...}], with the names of the tasks of a run of
    several. *)

val outcome : ?entry_at:Rapid_syntax.Source.region -> Rapid_runtime.Outcome.t -> int -> Yojson.Safe.t
(** The end object, with the work done ([steps]). Every end object has [at]: an ended task is
    at its entry routine ([entry_at], R-4.12-m); an end no source place explains has [null]. *)

val task_end : string -> Rapid_runtime.Outcome.t -> int -> Yojson.Safe.t
(** One task's end in a run of several: as {!outcome}, the event [task-end] with the task's name. *)

type cell_task = {
  name : string; kind : string; entry : string; motion : bool; robot : string option; robot_type : string option;
  stand_in : string option; reads : string option; modules : int;
  event_routines : (string * string) list;   (** the routines run and their events (R-bk-8) *)
}

val cell : backup:string -> io:string option -> signals:int -> warnings:int -> cell_task list -> Yojson.Safe.t
(** A controller backup's run, right after [start]: [{"event":"cell","backup":DIR,"tasks":[...],
    "io":FILE|null,"signals":N,"warnings":N}], each task with its type (NORMAL, STATIC,
    SEMISTATIC), entry routine, whether it has a robot, the robot's name and MOC.cfg type (and
    [stand_in]: why another robot moves in place of that type's: ["--robot"], ["not in the robot
    library"], ["no robot in MOC.cfg"], else null), the
    motion task whose robot a task without one reads, its number of modules, and the event
    routines it runs, in order, each [{"routine":NAME,"event":EVENT}] (doc/trace-format.md). *)

val refused_entry : files:string list -> entry:string -> Yojson.Safe.t
(** R-9.1-m: a task buffer without the entry procedure is refused before it runs; the stream
    says so as for any static error, the same from both engines. It has no place of its own: the
    first file's beginning, as for a file error. *)

(** {1 Call chains} *)

val chain : string list -> string list
(** A call chain as the end object shows it. A recursion as deep as --max-call-depth made the
    message one line of hundreds of kilobytes (issue 21): a chain of more than 20 routines keeps
    its first and last 10, with ["... N more ..."] between, N the calls left out: a marker no
    routine name can be (R-7.1-small1). *)

val chain_text : string list -> string
(** The text of a chain, as the message of a stopped run writes it: ["A <- B <- C"]. A long one
    writes a run of one routine called K times in a row as ["NAME xK"] (the common case, a
    recursion), then is bounded as {!chain}; a chain of at most 20 routines is written in full. *)
