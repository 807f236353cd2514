(** --samples HZ (doc/motion.md, doc/trace-format.md): the TCP pose and the axis angles at
    k / HZ seconds of virtual time, each once, as the clock of a run passes them, and at the end
    of a run that ended until the robot stands still. A run's sampling, not its output: the
    command line writes each sample ({!Rapid_oracle.Event_json.sample}). *)

type sample = { time : float; pose : Rapid_observable.Pose.t; joints : float array option }

val max_samples : int
(** 200,000: the most samples one run writes (doc/motion.md, "Memory"): a step of the clock may
    pass many, and they are built before they are written. *)

val check : float option -> (unit, string) result
(** A rate above 0 and at most 10,000 Hz; the message is the whole line. *)

type t

val create : ?on_capped:(unit -> unit) -> float -> t
(** A sampler at this rate from time 0. [on_capped] is called once, when {!max_samples} are
    taken. *)

val until : t -> Rapid_installed.Motion_routines.state -> float -> sample list
(** The samples not yet taken up to this time (within a nanosecond), in order. *)

val final : t -> Rapid_runtime.Outcome.t -> Run.world -> sample list
(** At the end of a run: when it ended, the samples until the robot stands still, but not
    beyond --max-time (a move of 1E30 s is planned, not sampled); otherwise those until now. *)
