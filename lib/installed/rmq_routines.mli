(** The RAPID Message Queue between the tasks of one run (ABB's "RAPID Message Queue" of the
    Multitasking option; its routines' pages in the Technical reference manual - RAPID
    Instructions, Functions and Data types): RMQFindSlot, RMQSendMessage, RMQSendWait,
    IRMQMessage, RMQGetMessage, RMQGetMsgHeader, RMQGetMsgData, RMQReadWait, RMQEmptyQueue and
    RMQGetSlotName, for both engines (doc/semantics.md, "Several tasks").

    Why here: the queues are shared by the tasks, so they live in the controller
    ({!Rapid_controller.World.rmq}), which knows no RAPID value; this module says what a message
    carries (a copy of the data, with the name of its static type and its dimensions) and checks
    it against the receiving variable, as ABB's RMQGetMsgData does (doc/rulings.md R-14-rmq1 to
    R-14-rmq5: the slots RMQ_ and the task's name, the defaults 5 messages and 400 bytes, the
    interrupt and synchronous modes, the errors ERR_RMQ_... and the waits on the virtual
    clock). *)

val call : Primitive.context -> string -> Primitive.argument array -> Primitive.outcome option
(** [None]: not one of these routines. RMQSendWait and RMQReadWait may answer a wait
    ({!Primitive.Wait}), which the engines carry out on the virtual clock, serving interrupts
    and letting the other tasks run. *)

val modelled : string -> bool

val wait_abandoned : Rapid_controller.World.t -> Rapid_observable.Wait.t -> unit
(** A wait an error or a long jump leaves (§7.2; the host's [wait_abandoned]): when it is
    RMQSendWait's, the task awaits no answer any more. *)
