(** An installed routine as an engine calls it (ch. 11, 13; lib/typing/installed): the entry the
    host's registry gives for its name, the context of a call and the outcome that says
    everything the call did. The bodies live in lib/installed; an engine knows only this. *)

(** What an engine tells a call. *)
type context = {
  parameters : string array;                   (** the routine's parameter names, in order *)
  argument_label : string -> string option;
      (** the name of the data object given for a parameter (by the parameter's name), for the
          motion's output: [p10], [z10]; for any other expression its line, [line 12]; for
          [P:type] the static type of an anytype parameter's argument ({!argument_label}) *)
  book_error : unit -> int;                    (** BookErrNo: the task's next error number *)
  error_number : string -> int;                (** the number of an ERR_ name (§7.1) *)
}

(** What the call does to the program. *)
type result =
  | Returned of Value.t option                 (** a function's value, or a procedure's end *)
  | Failed of { error : string; at_move : bool }
      (** an execution error, by its ERR_ name; [at_move]: a \SyncLastMoveInst error of the
          motion raised at the move instruction, asynchronous: TRYNEXT in its handler executes
          as RETRY (§7.4) *)
  | Call_by_name of string                     (** CallByVar: call this procedure (§4.6) *)
  | Stop_requested                             (** Stop: the task stops *)
  | Exit_cycle_requested
      (** ExitCycle: the cycle ends, every active routine is abandoned (UNDO handlers run) and
          the entry routine starts again (doc/rulings.md R-13-exitcycle1) *)
  | Not_modelled                               (** rapid-sem does not model this routine yet *)
  | Wait of { wait : Rapid_observable.Wait.t; first_poll : float option }
      (** a waiting instruction: the engine waits (doc/controller.md); [first_poll]: WaitUntil
          \InPos's first evaluation of its condition, when the robot moves *)
  | Retry_requested                            (** StartMoveRetry: RETRY, as the statement (§7.1) *)
  | History_exhausted of string
      (** the motion history beyond its budget (doc/motion.md): the run ends as a resource
          exhausted (§1.4) at the call *)
  | Assertion_failed of string
      (** an assertion of rapid-sem test failed (lib/typing/installed/unit_test.sys): the task
          stops at the call with ERR_ASSERT and this message as what the error is about; no
          error handler takes it (doc/rulings.md R-test-b) *)
  | Unanswered of string
      (** a dialogue of the FlexPendant the scripted operator has no answer for (--operator,
          doc/rulings.md R-13-ui2): the run ends at the call as for a routine not modelled, with
          this reason *)

type outcome = {
  result : result;
  events : Event.t list;
      (** what the call made observable, in order: its own events (TPWrite's line, ErrWrite's
          entry) and what the world observed meanwhile, each after its cause *)
  new_move : int option;
      (** the move it planned: the engine remembers which routine activation executed it, to
          raise the move's asynchronous errors there (§7.4, §7.6) *)
}

type reach =
  | Values                 (** a function of its arguments and the context only *)
  | World                  (** it reads or changes the controller (clock, signals, services) *)
  | Moves                  (** it reads or changes the motion too *)

(** A function of {!entry.values} by its number of arguments, every one required: the engine
    passes them without an array (the library's StrLen, StrPart, Abs...). *)
type fixed =
  | One of (Value.t -> (Value.t, string) Stdlib.result)
  | Two of (Value.t -> Value.t -> (Value.t, string) Stdlib.result)
  | Three of (Value.t -> Value.t -> Value.t -> (Value.t, string) Stdlib.result)
  | Length of (Value.t -> (Value.t, string) Stdlib.result)
      (** [One] of StrLen (ch. 11): of a string, the number of its characters as a num, never an
          error; an engine may compute it from the string without the call *)

type entry = {
  name : string;                               (** as declared *)
  reach : reach;
  condition : string option;
      (** the parameter whose expression the engine evaluates again at every poll of the wait
          the call returns (WaitUntil's [Cond]) *)
  call : context -> Argument.t array -> outcome;
  values : (Value.t option array -> (Value.t, string) Stdlib.result) option;
      (** a function of {!Values} reach that only computes (ch. 11, the library's functions):
          [call] on arguments that are all values (None for an absent one) is [Returned (Some v)]
          for [Ok v] and [Failed] (not at a move) for [Error name], without events or move; an
          engine with the values at hand may call it instead *)
  fixed : fixed option;
      (** [values] again when the function has one, two or three parameters, none optional:
          [values [|Some a; Some b|]] is [f a b] for [Two f] *)
}

val returned : Value.t option -> outcome
(** A call that returned, with no event and no move. *)

val parameter_names : Ir.routine -> string array
(** The names of the routine's parameters, in order: the same array for the same routine (of
    the last few asked), which {!context.parameters} should be. *)

val default_bytes : Ir.routine -> int array
(** [Value.shape_bytes] of each parameter's default, in order (an absent argument's bytes in
    the memory budget); the same array for the same routine, as {!parameter_names}. *)

val copy_bytes : Ir.routine -> int array
(** For each parameter (of an installed or a RAPID routine), the bytes of any value it takes
    when they are the same for all of them (a type without strings, neither anytype nor
    conformant: its default's), or -1; the same array for the same routine, as
    {!parameter_names}. *)

val argument_label : Ir.program -> Ir.routine -> Ir.argument array -> string -> string option
(** The data object the argument of a call gives for a parameter (by the parameter's name), for
    the motion's output ([p10], [z10]), the expression as written for another one
    ([Offs(pPick, 0, 0, 100)], a routine's local [pStart]: {!Ir.names}), or [line N] for a
    literal or an aggregate (an inline target): the [argument_label] of a call's context. Asked
    for [P:type] (a parameter name and [:type], which no parameter name holds), it gives the name
    of the static type of the data reference given for the anytype parameter P, as the lowering
    recorded it
    ({!Ir.Argument_types}: a call the checker bound; not a late-bound one): the RAPID Message
    Queue sends data with its type's name (ABB's RMQSendMessage, doc/rulings.md R-14-rmq4). *)

val condition_argument : entry -> Ir.routine -> Ir.argument array -> Ir.expr option
(** The expression given for the entry's [condition] parameter, when it has one. *)

val stub_value : Ir.routine -> Value.t
(** What a function rapid-sem does not model gives under --stub-unmodelled: the initial value of
    its result type (§2.22, doc/rulings.md R-13-i). *)
