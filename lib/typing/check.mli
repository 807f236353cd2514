(** The typing judgement of RAPID (chapters 2-5 and 9 of the kernel manual): a task buffer of
    modules is checked against the installed environment, and every static semantic error
    (§1.4) is reported with the rule of doc/typing.md it breaks. *)

open Rapid_syntax

type options = {
  allow_unknown : bool;
      (** a name that is neither declared nor installed is a warning, not an error: real code
          calls installed routines beyond rapid-sem's environment *)
}

val default_options : options

(** A name neither declared nor installed, allowed by [allow_unknown]. *)
type unknown_name = {
  what : string;                    (** "data object", "procedure", "function", "data type", "trap" *)
  name : string;                    (** as written at its first use *)
  first : Rapid_syntax.Source.region; (** its first use in source order *)
  uses : int;
}

type result = {
  reports : Report.t list;          (** errors and warnings, in source order; under
                                        [allow_unknown] one warning per unknown name *)
  elaboration : Elaboration.t;      (** what the dynamic semantics needs to know (no errors) *)
  unknown : unknown_name list;      (** under [allow_unknown], by name *)
}

val check_task :
  ?options:options ->
  installed:Ast.module_declaration list ->
  Ast.module_declaration list ->
  result
(** [check_task ~installed modules] checks [modules] as one task buffer (§9.1) whose installed
    level (ch. 13) holds the predefined types and objects of the kernel and the declarations of
    [installed]. *)

val errors : result -> Report.t list

val unknown_summary : result -> string option
(** Under [allow_unknown], when a name was unknown: ["N names unknown (M uses); they are
    warnings under --allow-unknown"]. *)

type installed_state
(** The installed level checked (the first half of every task's check), as the next
    {!check_task} over the same (physically) installed modules reuses it. It holds no functional
    value: lib/load/installed_image.ml marshals it at build time. *)

val installed_state : Ast.module_declaration list -> (installed_state, Report.t list) Stdlib.result
(** The installed level of these installed modules, checked under {!default_options}; [Error]:
    the reports of a check that reported something. *)

val installed_state_of : installed_state -> Ast.module_declaration list -> installed_state
(** The same state for the same modules given by their headers alone (Installed_env.level): the
    state the image holds, without the declarations' trees. *)

val use_installed_state : installed_state -> unit
(** The next tasks over its installed modules start from this state. *)
