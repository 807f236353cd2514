(** A RobotWare system parameter file (SYSPAR/SYS.cfg, MOC.cfg, EIO.cfg and the others of a
    controller backup), read as the controller's configuration reader takes it: a first line
    naming the domain ([SYS:CFG_1.0:5:0::]); sections that begin with a line [NAME:] (or
    [NAME = TYPE:]) and end at a line starting with [#]; in a section, instances, each a list of
    attributes [-Name value] on one line or over several joined by a final backslash. A value is
    a quoted string or a bare word (a number, a list such as [30,82]); an attribute with no
    value ([-MotionTask]) is a flag. Nothing here knows what a section means: {!Backup} does. *)

type value = Flag | Text of string    (** a flag, or the text of the value (without its quotes) *)

type attribute = { key : string; value : value; line : int; col : int }
(** [key] as written, without its dash; where the attribute's key is. *)

type instance = { attributes : attribute list; at_line : int }

type section = { name : string; instances : instance list; line : int }

type t = { file : string; domain : string; sections : section list }

val parse : file:string -> string -> (t, string) result
(** The text of a file. An error is one line, [FILE:LINE:COL: cfg error: MESSAGE]: a first line
    that is not a domain header, an attribute outside a section, a line in a section that is not
    an attribute, an unterminated quoted value, a value with no key before it. A UTF-8 byte
    order mark and carriage returns are skipped. *)

val read_file : string -> (t, string) result

val section : t -> string -> section option
(** The section of this name, letter case aside (the first, if written twice). *)

val find : instance -> string -> attribute option
(** The attribute of this key, letter case aside (the first). *)

val text : instance -> string -> string option
(** The value of the attribute as text, [None] when it is absent or a flag. *)

val flag : instance -> string -> bool
(** Whether the attribute is given (as a flag or with a value). *)

val place : t -> int -> string
(** [FILE:LINE]. *)
