(** The static rule across the task buffers of several tasks (ch. 14; `rapid-sem check --task`):
    a system-global persistent has one type in every task that declares it (doc/rulings.md
    R-14-c). Each buffer is judged on its own first ({!Rapid_typing.Check.check_task}); this
    judges them together. *)

open Rapid_syntax

type task = {
  name : string;
  modules : Ast.module_declaration list;
  elaboration : Rapid_typing.Elaboration.t;   (** of the buffer's check, which had no error *)
}

val shared_persistents : task list -> Rapid_typing.Report.t list
(** In the order of the tasks: a system-global persistent (PERS declared neither TASK nor LOCAL)
    declared with another type than in an earlier task, reported at the later declaration
    (rule pers-one-type, ch. 14). Types are compared as R-14-c says: the type's name as written,
    letter case aside, and for an array the size of each dimension as evaluated. *)
