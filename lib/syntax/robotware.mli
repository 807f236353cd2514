(** The RobotWare release a module is written for (doc/dialect.md, doc/rulings.md R-2.4-rw6).

    The specification is the kernel manual of RobotWare 7.12, whose reserved words (§2.4) include
    BREAK and CONTINUE, the statements of §4.8 and §4.9. RobotWare 5 and 6 have neither statement:
    there BREAK and CONTINUE are names, and [Break] is an installed instruction that stops the
    program (ABB's RAPID Instructions of RobotWare 6). Real controller backups are mostly
    RobotWare 5 and 6, and their modules use [continue] as a variable and [Break;] to stop. *)

type t =
  | Rw7  (** the manual's release: BREAK and CONTINUE are reserved words *)
  | Rw6  (** RobotWare 5 and 6: BREAK and CONTINUE are identifiers *)

val default : t
(** [Rw7]: the manual's. *)

val of_string : string -> t option
(** ["7"], ["6"], ["5"] or a version as backinfo.txt writes it (["6.13.02.00"], ["5.15.9100.10"]):
    its major number; [None] for anything else. *)

val reserves_loop_words : t -> bool
(** Whether BREAK and CONTINUE are reserved words (§2.4). *)

val to_string : t -> string
