(** The installed environment parsed, checked and lowered: what every task shares (ch. 13), as
    one value without functional values, so that the build marshals it once
    (lib/load/gen/gen_installed_image.ml) and every run of rapid-sem starts from it in one read
    (lib/load/installed_image.ml) instead of parsing, checking and lowering the installed
    modules again. *)

type t

val compute : unit -> (t * Rapid_syntax.Ast.module_declaration list, string) result
(** Parses, checks and lowers the installed modules now: the level and the modules with their
    declarations, which the level does not hold (they are marshalled apart). The ids of the files it registers and of
    the record types it makes are part of the result: a process uses it only where as many files
    were registered and record types made before as when it was computed ({!before}). *)

val before : t -> Rapid_syntax.Source.registry * int
(** The files registered and how many record types were made when [compute] started. *)

val files : t -> Rapid_syntax.Source.registry
(** The source files' table after [compute]: the installed modules' files. *)

val record_ids : t -> int
(** The record types' ids [compute] used. *)

val level : t -> Rapid_syntax.Ast.module_declaration list
(** The modules' headers (Rapid_typing.Installed_env.level), which the state is keyed by. *)

val install : t -> unit
(** The checker's, the lowering's and the initial values' shared state become this one's
    (Check.use_installed_state, Lower.use_installed_lowering, Initial_values.keep): the next
    tasks over [level t] start from it. The files and the record ids are restored apart
    (before anything else registers a file or makes a record type). *)
