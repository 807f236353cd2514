(** Well-typed RAPID programs, generated type-directed (doc/oracle.md, "Fuzzing").

    A program is one module with module data of every kind (VAR, PERS, CONST; num, dnum, bool,
    string, an array and a record), routines with every parameter mode, optional, switch and
    mutually exclusive parameters, error handlers ending in RETRY, TRYNEXT, RAISE, RETURN or
    falling off their end, error recovery points, UNDO handlers, and a [main] procedure. Statements
    reach every form of chapter 4 that needs no controller (assignment, calls, late-bound calls,
    GOTO, BREAK, CONTINUE, RETURN, RAISE, EXIT, CONNECT, IF, compact IF, FOR, WHILE, TEST, labels),
    and expressions every operator row of §3.12 for num, dnum, bool and string. Every program
    terminates: routines call only routines generated before them, WHILE loops count, RETRY is
    bounded by the retry limit. Errors are welcome (division by zero, an index out of bounds, a
    string over 80 bytes, RAISE): they exercise the error rules.

    Late-bound calls with mismatching arguments are generated when [mismatching] is set: the
    call must then raise ERR_CALLPROC at run time (§4.6). *)

type stmt =
  | Line of string                             (** a simple statement, without indentation *)
  | Compound of (string * stmt list) list * string
      (** headers each with their statements (IF/ELSEIF/ELSE, TEST/CASE/DEFAULT ...), and the
          closing line *)

type routine = {
  header : string;                             (** "PROC main()", "FUNC num f1(...)" *)
  data : string list;                          (** routine data declarations *)
  body : stmt list;
  error : (string * stmt list) option;         (** "ERROR" or "ERROR (...)", its statements *)
  undo : stmt list option;
  footer : string;                             (** "ENDPROC", "ENDFUNC" *)
}

type program = { name : string; module_data : string list; routines : routine list }

type options = {
  mismatching : bool;                          (** late-bound calls with wrong arguments *)
  max_routines : int;
  max_statements : int;                        (** per statement list *)
  controller : bool;
      (** some programs (three in ten) use the controller: interrupts (CONNECT, ITimer,
          ISignalDI/DO, ISleep, IWatch, IDelete, IDisable, IEnable), waits (WaitTime, WaitUntil,
          WaitDI), signals (SetDO, Set, Reset, PulseDO, reading di1 and do1), moves (MoveJ, MoveL);
          they run with the signals of {!Fuzz_run.io} *)
  signal_stores : bool;
      (** assignments to signal variables ([do1 := 1]) too: on by default, since both engines run
          the controller (doc/fuzz-campaign.md); [--no-signal-stores] turns them off *)
}

val default_options : options
(** Mismatching late-bound calls and the controller on, five routines, five statements. *)

val generate : ?options:options -> Random.State.t -> program

val to_source : program -> string
(** The module as RAPID source text. *)

val shrink : program -> program Seq.t
(** Smaller programs, the largest steps first: a routine other than main removed, a module data
    declaration removed, an error or UNDO handler removed, one statement removed or a compound
    statement replaced by one of its statement lists anywhere, a routine data declaration
    removed. Many candidates no longer pass [check] (a name left without its declaration): the
    caller skips them, since they do not fail in the same way. *)

val size : program -> int
(** Statements, counted recursively. *)
