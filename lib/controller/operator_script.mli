(** The operator at the FlexPendant, scripted (`--operator FILE`, doc/controller.md "The
    operator"; doc/rulings.md R-13-ui2): the answers a person would give to the program's
    dialogues (TPReadFK, TPReadNum, UIMsgBox, UIMessageBox, UINumEntry, UINumTune, UIAlphaEntry,
    UIListView), one line each, taken in the order the program asks, whichever task asks.

    A line is [ROUTINE ANSWER...]: the routine's name (letter case aside) and its answer's
    tokens, a number, a name ([resYes], [timeout]) or a double-quoted string ([""] inside it is
    one quote); [#] begins a comment. What an answer means is the routine's
    (lib/installed/ui_routines.ml): this module reads the lines and hands them out. *)

type token =
  | Number of float * string       (** its value and its text as written *)
  | Name of string
  | Text of string

type answer = {
  line : int;                      (** in the script, from 1 *)
  routine : string;                (** as written *)
  tokens : token list;             (** at least one *)
}

type t

val of_text : file:string -> string -> (t, string) result
(** The script in this text, [file] naming it in messages; [Error "FILE:LINE: ..."] for a line
    that is not [ROUTINE ANSWER...]. *)

val of_file : string -> (t, string) result

val take : t -> routine:string -> (answer, string) result
(** The next answer, when it is for this routine: it is used up. [Error] says why there is none
    for it (the script is used up; its next line is for another dialogue), and leaves the script
    as it was. *)

val place : t -> answer -> string
(** [FILE:LINE] of an answer, for messages. *)

val remaining : t -> int
(** The answers not used yet. *)
