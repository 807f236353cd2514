(** The events of a run of several tasks (rapid-sem run --task), compared stream by stream
    (doc/oracle.md, "Several tasks"; doc/rulings.md R-14-p): the manual does not say how tasks
    interleave, so the order between two tasks' events is not compared, only each task's own. *)

val world_kinds : string list
(** The kinds of the world's events (signals, interrupts occurred or discarded, motion): one
    stream of their own, in their order, as rapid-sem compares its two engines. *)

val streams : Event_stream.event list -> (string * (int * Event_stream.event) list) list
(** The events split into streams, each event with its 1-based index in the whole stream:
    ["task NAME"] for each task's events (its [task-end] included), in the order the tasks first
    appear; ["world"] for the kinds of {!world_kinds}; ["run"] for the events that name no task
    (the [end] object). Streams without events are left out. *)

type divergence = { stream : string; divergence : Event_diff.divergence }
(** [divergence.index] counts the events of that stream. *)

type verdict = Agree of int | Diverge of divergence | Broken of string

val compare :
  ?ignore:string list -> expected:Event_stream.t -> actual:Event_stream.t -> unit -> verdict
(** rapid-sem's stream against an implementation's, both of schema [rapid-sem/2] (another is
    [Broken]): every stream of either compared as {!Event_diff.compare} compares one task's, after
    the kinds in [ignore] are taken out. Of several streams that diverge, the one whose expected
    event comes first in rapid-sem's whole stream is reported. *)

val report : divergence -> string
(** [task T_B, event 3: expected {...}, got {...}]. *)
