(** The first place where two streams of observable events differ (doc/oracle.md). *)

type divergence = {
  index : int;                                  (** 1-based, among the events compared *)
  expected : Event_stream.event option;         (** [None]: the reference had ended *)
  actual : Event_stream.event option;           (** [None]: the implementation had ended *)
  before : Event_stream.event list;             (** up to [context] events before, oldest first *)
  at : Yojson.Safe.t option;                    (** the nearest source region: the expected
                                                    event's ["at"], or the last one before *)
}

val implementation_specific : string list
(** Fields no other implementation is asked to reproduce: ["steps"], the reduction count of
    rapid-sem's machine. They are removed before comparing. *)

val strip : Event_stream.event -> Event_stream.event
(** The event without its {!implementation_specific} fields. *)

val compare :
  ?ignore:string list -> ?context:int -> expected:Event_stream.event list ->
  actual:Event_stream.event list -> unit -> divergence option
(** [None] when the streams agree, after the events whose kind is in [ignore] are taken out of
    both and the implementation-specific fields are removed. [context] defaults to 3. *)

val report : file:string -> divergence -> string
(** A report a person can act on: the program, the event's index, the source place, the events
    before, what rapid-sem expected and what the implementation wrote. *)
