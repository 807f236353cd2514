(** The controller around a program: what an engine (the small-step machine, or any other
    evaluator) asks of the world it runs in, with no type of any engine in it. One world per run.

    - a virtual clock, from 0 s, that only waits, the statements executed and the events of the
      stimulus move on; nothing reads the host's clock, so a run is reproducible;
    - the I/O signals of the configuration, their values, and the timed changes of inputs
      (the stimulus) and of outputs (SetDO \SDelay, PulseDO);
    - the interrupt numbers, their sources (timers, signal edges), the queue of interrupts that
      occurred and wait for their trap, IDisable/IEnable, ISleep/IWatch (ch. 8, §4.15);
    - the clocks of ClkStart/ClkRead, and the wall clock of CDate/CTime/GetTime;
    - with several tasks, each task's RAPID Message Queue (ABB's RMQ), which the others send to.

    Times are seconds; inside, the clock counts whole microseconds, so that adding the time of
    a statement a million times gives exactly a million times it. *)

type t

(** What the world makes observable, each with its virtual time (seconds). *)
type observation = Rapid_observable.Controller_observation.t = 
  | Signal_changed of { time : float; signal : string; value : float }
  | Interrupt_occurred of { time : float; number : int }
  | Interrupt_discarded of { time : float; number : int; reason : string }

val default_statement_time : float
(** 0.0001 s of virtual time for each statement executed (and each new round of a loop). *)

val default_max_time : float
(** 3600 s: a run whose virtual time goes beyond it is stopped (resource exhaustion). *)

val default_epoch : float
(** The wall-clock time at virtual time 0, in seconds since 1970-01-01 00:00:00:
    2024-01-01 00:00:00, a Monday. *)

val default_poll_rate : float
(** WaitUntil's \PollRate when absent: 0.1 s (installed-facts.md section 4, UNCERTAIN). *)

val min_poll_rate : float
(** 0.04 s: a shorter WaitUntil \PollRate polls at this rate (installed-facts.md section 4,
    doc/rulings.md R-8-waits1). *)

val min_timer_single : float
val min_timer_cyclic : float
(** ITimer's minimum Time: 0.01 s with \Single or \SingleSafe, 0.1 s cyclic; a shorter time
    is raised to it (installed-facts.md section 6, doc/rulings.md R-8-waits1). *)

val max_interrupts : int
(** Interrupt numbers a task may hold at once: 100 (installed-facts.md section 6); one more
    CONNECT raises ERR_INOMAX. *)

val queue_capacity : int
(** Interrupts waiting for their trap at once: 30 (doc/rulings.md R-8-c). *)

val create :
  ?statement_time:float -> ?max_time:float -> ?epoch:float -> Io_config.t -> t

(** {1 Services (doc/services.md)} *)

val set_services : t -> Services.t -> unit
val services : t -> Services.t
(** The files, sockets and text resources of the run; without {!set_services}, the default
    sandbox ({!File_sandbox.default_root}), loopback sockets only. *)

(** {1 Time} *)

val now : t -> float
val max_time : t -> float
val epoch : t -> float

val collisions : t -> float list
(** The times of the stimulus's [at TIME collision] lines, for the motion model. *)

val system_input_active : t -> action:string -> bool
(** Whether a system input of this action (ABB's name, letter case aside: [LimitSpeed]) is 1 now,
    whatever mechanical unit it names (R-13-speedlim1: the task's robot stands for them). *)

val statement : t -> unit
(** The time of one statement passes (the events due meanwhile happen). *)

val statement_within : t -> bool
(** {!statement}, then whether the clock is still within {!max_time}: the same as
    [statement w; not (now w > max_time w)], without allocating (an engine's hot path). *)

val statements : t -> int -> unit
(** The time of this many statements passes at once (the events due meanwhile happen). *)

val statements_left : t -> int
(** How many more statements' time can pass with the clock still within {!max_time}; with
    nothing scheduled, an engine may count them itself and charge them later with
    {!statements}. *)

val next_event : t -> float option
(** When the next timed event (a stimulus, a delayed output, a timer) is due, if any. *)

val next_change : t -> float option
(** {!next_event}, leaving out the waits' own looks ({!wake_at}): when the next event that
    changes something is due (a socket wait holds the clock when there is none,
    doc/rulings.md R-13-sockwait1). *)

val advance_to : t -> float -> unit
(** The clock moves on to this time; the events due until then happen in order of time (and of
    scheduling for equal times). A time in the past changes nothing. *)

val wake_at : t -> float -> unit
(** A timed event that changes nothing, so that a wait whose end another model computes (a move
    until the robot's ready time, doc/motion.md) is looked at again at that time. Past, infinite and absurdly
    large (from 1e12 s) times are ignored. *)

val seconds : float -> int
(** Seconds to the clock's microseconds, rounded to nearest; from 10^12 s on (and NaN) the same
    count, 10^18, that no run reaches ("never"), so that a time as large as a num can hold
    neither overflows nor wraps to the past. *)

val at : t -> float -> (unit -> unit) -> unit
(** A timed event of a model beside the controller: [f] runs when the clock reaches the time
    (a past time: at the next move of the clock), among the events due then in the order they
    were scheduled; an infinite or absurdly large time never comes. A trigger on the robot's
    path (TriggIO, TriggInt; doc/motion.md) sets its output or makes its interrupt occur
    there, at its exact time, and looks again if the robot was held up meanwhile. *)

(** {1 Signals} *)

val signals : t -> (string * Io_config.signal_type * int) list
(** The configured signals, with the identity each has ([1], [2], ...; 0 is "not connected"). *)

val find_signal : t -> string -> int option
(** The identity of the signal of this name (letter case aside). *)

val signal_name : t -> int -> string
val signal_kind : t -> int -> Io_config.signal_type option
(** [None]: no such signal. *)

val read : t -> int -> float
val write : t -> int -> float -> unit
(** A change now: an observation, and the interrupts it triggers. *)

val write_later : t -> int -> float -> delay:float -> unit

(** {1 Waiting} *)

(** A wait of a waiting instruction, engine-neutral: the engine checks [satisfied] and the
    deadline at every step of the wait, lets interrupts in, and moves the clock on to the next
    event, the deadline or the next poll. *)
type wait = Rapid_observable.Wait.t = {
  what : string;
  satisfied : unit -> bool;
  deadline : float option;
  finish : timed_out:bool -> Rapid_observable.Wait.raised option;
  poll : float option;
}

(** {1 Interrupts} *)

val connect : t -> trap:int -> (int, string) result
(** A new interrupt number bound to the trap (the engine's identity of the routine), or
    ERR_INOMAX. *)

val connected : t -> int -> bool

val delete : t -> int -> unit
(** IDelete: the number is free again; its source is cancelled, and its occurrences still queued
    are dropped (an [Interrupt_discarded] each, R-8-x). *)

val interrupt : t -> int -> unit
(** The interrupt of this number occurs now, as its order would make it occur (TriggInt's, when
    the robot reaches its position): queued for its trap, or discarded if it sleeps or the
    queue is full; nothing for a number not connected. *)

val order_timer : t -> int -> period:float -> single:bool -> (unit, string) result
(** ITimer; ERR_UNKINO for a number that is not connected. A period below {!min_timer_single}
    or {!min_timer_cyclic} is raised to it. *)

type trigger = old:float -> now:float -> bool
(** May keep a state of its own (ISignalAI's reference value). *)

val order_signal : t -> int -> signal:int -> trigger:trigger -> single:bool -> (unit, string) result
(** ISignalDI/DO/AI/AO/GI/GO: an interrupt at each change of the signal that satisfies the
    trigger. *)

val order_watch : t -> int -> changed:(unit -> bool) -> single:bool -> (unit, string) result
(** IPers: [changed ()] says whether the persistent changed since it was last asked; it is asked
    wherever an interrupt may be served. *)

(** An entry of the event log that IError sees: its domain (errdomain), number and type
    (errtype), and its text lines. *)
type error_datum = { domain : int; id : int; error_type : int; strings : string list }

val order_error : t -> int -> domain:int -> id:int option -> error_type:int -> (unit, string) result
(** IError: COMMON_ERR (0) is every domain, [None] every number, TYPE_ALL (0) every type. *)

val post_error : t -> error_datum -> unit
(** An entry in the event log: the IError interrupts it matches occur, carrying it. *)

val trap_data : t -> int
(** GetTrapData: an identity for the event of the interrupt served last (0: it has none). *)

val error_datum : t -> int -> error_datum option
(** ReadErrData: the event a trapdata identity denotes. *)

val set_safe : t -> int -> safe:bool -> unit
(** Whether the number's interrupt is safe (ordered with \SingleSafe, R-8-w); every order sets it. *)

val sleep : t -> int -> (unit, string) result
(** ISleep: ERR_UNKINO for a number that is not connected, ERR_INOISSAFE for a safe one. *)

val watch : t -> int -> (unit, string) result
val disable : t -> unit
val enable : t -> unit
val enabled : t -> bool

val take : t -> (int * int) option
(** The first queued interrupt and its trap, when interrupts are enabled: it leaves the queue.
    Occurrences of a deleted number are dropped. *)

(** {1 Clocks (ClkReset, ClkStart, ClkStop, ClkRead)} *)

val new_clock : t -> int
val clock_reset : t -> int -> unit
val clock_start : t -> int -> unit
val clock_stop : t -> int -> unit
val clock_read : t -> int -> float
(** Seconds, to the microsecond. *)

(** {1 Observations} *)

val drain : t -> observation list
(** What happened since the last call, in order. *)

(** {1 Tasks (ch. 14)}

    The worlds of the tasks of one run share the virtual clock, the timed events, the signals
    and the services; each task has its own interrupt numbers and queue, IDisable, clocks and
    observations. {!create} makes the world of one task, T_ROB1, number 1, the motion task. *)

val task_name : t -> string
val task_number : t -> int
(** From 1, in the order the tasks were made. *)

val motion_task : t -> bool
val task_names : t -> string list
(** Every task of the run, in order of their numbers. *)

val name_task : t -> name:string -> motion:bool -> unit

val add_task : t -> name:string -> motion:bool -> t
(** The world of a new task of the same run: the next number, on the same clock. *)

val every_task_waits : t -> string list -> unit
(** The scheduler: every running task of the run, these, waits now (before the clock moves on). *)

val host_wait_begin : t -> unit
val host_wait_end : t -> unit
(** This task begins (ends) a wait that only the host can end: a socket's (R-13-sockwait2). *)

val only_host_waits : t -> bool
(** Whether only the host can end any task's wait: the run has one task, or every running task
    waited when the scheduler last said so, no statement has run since, and each of them still
    waits on the host (doc/rulings.md R-13-sockwait2). *)

val host_waiters : t -> int
(** How many tasks wait on the host. *)

val sync_arrive : t -> string -> int
(** WaitSyncTask: this task reaches the synchronisation point of this name once more; how many
    times it has now. *)

val sync_arrivals : t -> string -> task:string -> int
(** How many times the task of that name has reached the synchronisation point. *)

val sync_move : t -> string list option
(** SyncMoveOn (doc/rulings.md R-14-m): the task list this task is in synchronized movement
    with, or [None] (independent movement). *)

val set_sync_move : t -> string list option -> unit

(** {1 The RAPID Message Queue (ABB's RMQ; doc/controller.md, "The RAPID Message Queue")}

    Each task of the run has a queue of messages from the other tasks (and from itself), in the
    shared part of the worlds, so that a task's RMQSendMessage reaches another's queue. A slot
    is a task's number; its name is RMQ_ and the task's name. What a message carries is opaque
    here: the installed routines extend {!rmq_data} with their values. *)

type rmq_data = ..

type rmq_message = {
  sender : int;              (** the slot of the sending task *)
  datatype : string;         (** the name of the data's type: [num], [robtarget], a record's name *)
  dims : int list;           (** the sizes of its dimensions, [[]] for a scalar *)
  user_def : int;            (** \UserDef of the send *)
  data : rmq_data;
}

(** ABB's RMQ Mode of a task (Interrupt or Synchronous); a task of rapid-sem takes the mode of the
    first of IRMQMessage and RMQReadWait it executes (doc/rulings.md R-14-rmq2). *)
type rmq_mode = Rmq_unset | Rmq_interrupt | Rmq_synchronous

(** A task's queue: its messages, first in first out, its mode, and the answer RMQSendWait
    awaits (the slot it sent to and the answer's data type) once it has come. *)
type rmq = {
  messages : rmq_message Queue.t;
  mutable mode : rmq_mode;
  mutable awaiting : (int * string) option;
  mutable answer : rmq_message option;
}

val rmq_max_messages : int
val rmq_max_size : int
(** ABB's defaults of the task parameters RMQ Max No Of Messages (5) and RMQ Max Message Size
    (400 bytes of data), doc/rulings.md R-14-rmq1. *)

val rmq : t -> rmq
(** This task's queue. *)

val rmq_slot : t -> string -> int option
(** RMQFindSlot: the slot of this name (letter case aside). *)

val rmq_slot_name : t -> int -> string option
(** RMQGetSlotName: [None] for a number that is no task of the run. *)

val order_rmq : t -> int -> datatype:string -> (unit, string) result
(** IRMQMessage: an interrupt for each message of this data type (its name, letter case aside)
    that arrives; ERR_UNKINO for a number that is not connected. *)

val rmq_send : t -> slot:int -> rmq_message -> (unit, string) result
(** The message arrives at the slot's task: to the answer its RMQSendWait awaits, to its queue
    (with the interrupt IRMQMessage ordered, in interrupt mode) or discarded (interrupt mode,
    no order for its type); ERR_RMQ_INVALID for a slot that is no task, ERR_RMQ_FULL when the
    queue holds {!rmq_max_messages} already (R-14-rmq2). *)

val rmq_keep : t -> ?into:int -> rmq_message -> int
val rmq_kept : t -> int -> rmq_message option
(** The messages rmqmessage variables hold, each by a new identity: [into], the identity the
    variable held so far, is forgotten; of the others the last 1000 given out are kept
    (doc/rulings.md R-14-rmq3). *)
