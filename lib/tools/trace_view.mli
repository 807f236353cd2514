(** What [rapid-sem trace] prints of a step: the redex as RAPID text with the values it works on,
    what it became, and the changes it made to what a program can observe (doc/trace-format.md).

    The views are computed from the machine's configuration before and after the step, only
    when tracing: running never calls this module. *)

val value : Value.t -> string
(** A value in RAPID's literal syntax: a num with the fewest significant digits that read back
    to the same single-precision number (a dnum to the same double), strings quoted as §2.7
    writes them, [TRUE] and [FALSE], records and arrays as [[a,b,c]]. An installed object
    (§2.16), which has no literal, is written [<kind #n>]. *)

type change =
  | Write of { place : string; value : string }
      (** a data object, or a part of it, written: the place as RAPID writes it ([a{2}.x]) *)
  | Output of string                    (** a line written by TPWrite *)
  | Erase
  | Log of string
  | Raised of { name : string; number : int; at : Rapid_syntax.Source.region }
  | Handled of { name : string; routine : string }
  | Retried
  | Next_tried
  | Undo_run of string
  | Routine_entered of string
  | Routine_left of string
  | Task_ended
  | Controller_event of Event.t
      (** what the controller around the program did (a signal changed, an interrupt occurred,
          a trap entered or left, a routine stubbed) and the motion: as [Machine.step] said it *)

type step = {
  number : int;
  rule : string;
  depth : int;                          (** active routines before the step *)
  at : Rapid_syntax.Source.region;      (** the redex's place in the source *)
  redex : string;
  result : string option;
  changes : change list;
  statement : Ir.stmt option;           (** the statement that begins with this step *)
  in_statement : Ir.stmt option;        (** the innermost statement in progress before it *)
  routine : Ir.routine;                 (** the routine the step runs in *)
  state : string option;
      (** after the step, the statement in progress as it stands: its text with the values
          computed so far in place of their expressions ([total := 0 + sq(1);]); [None] when
          nothing is computed yet *)
}

type t
(** The source text of the files a trace quotes, read once. *)

val create : ?read:(string -> string option) -> unit -> t
(** [read name]: the bytes of a source the trace cannot open as a file (standard input), when
    the caller has them. *)

type before
(** What the trace needs to know of the configuration before a step. *)

val before : t -> Machine.config -> before

val after : t -> before -> Machine.config -> string * Event.t list -> step
(** The step, from the view before it, the configuration after it and what [Machine.step]
    answered. *)

val source_text : t -> Rapid_syntax.Source.region -> string
(** The text of a region on one line (line breaks and runs of blanks as one space), cut at 72
    characters. *)

val statement_text : t -> Ir.stmt -> string
(** A compound statement (IF, WHILE, FOR, TEST) by its first line, another one whole. *)

val place_of_statement : t -> Ir.routine -> Ir.stmt -> string
(** A statement's place as a programmer names it on the FlexPendant: [MODULE:LINE]. *)
