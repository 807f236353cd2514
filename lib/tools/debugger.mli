(** A stepping session over the machine, as a programmer steps a program on the FlexPendant
    (doc/debugger.md): the program pointer moves statement by statement, forward or backward
    (ch. 6), and the data of the current routine can be read and written between statements.
    Every line it prints is deterministic. *)

type t

val create :
  ?max_steps:int -> ?hidden:(string -> bool) -> ?routine_data:(Ir.routine -> string list) ->
  ?type_of:(Ir.routine -> string -> (Rapid_typing.Types.object_type * bool) option) ->
  ?files:string list -> ?events:(string * string list) list -> out:(string -> unit) -> Machine.config -> t
(** A session on a machine just started: it runs to the first statement of the entry routine
    and prints where the program pointer is. [max_steps] bounds the reduction steps of the whole
    session (default 100,000,000). [hidden] tells the modules the program pointer does not stop
    in, by name: the NOSTEPIN and NOVIEW modules (§9.2, §9.4); their routines run as one step.
    [routine_data] names a routine's data declarations in order (the lowered program keeps no
    names for them), for print and set. [type_of] gives a name's declared type in a routine's
    scope and whether it may be written (not a constant, loop variable or system variable), for
    components and for set. [files] are the task's files, as named on the command line, where
    [break] may set a breakpoint (default: every file of the program's routines). [events]: a
    controller backup's event routines by event, START, RESTART, STEP and STOP, which the
    commands make happen (doc/rulings.md R-bk-11): the first continue START's, a later one
    RESTART's, each step, next, finish and back STEP's, a continue that stops at a breakpoint
    STOP's; each runs where the program pointer is, which stays there. The machine's own
    event routines before the entry routine (POWER_ON, RESET) run before the session begins. *)

val command : t -> string -> [ `Go_on | `Quit ]
(** Runs one command line (doc/debugger.md) and prints what it does. An unknown or malformed
    command prints an error line and changes nothing. *)

val config : t -> Machine.config

val rules : t -> string list
(** The rules of every reduction the session has applied, each once, in the order first
    applied (the backward rules included). *)
