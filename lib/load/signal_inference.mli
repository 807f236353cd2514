(** The signals a program uses without declaring them (doc/rulings.md R-13-aa): real programs
    name the I/O signals of their controller's EIO configuration, which is not part of the
    program. Under [run --allow-unknown --stub-unmodelled] without that configuration, a name
    that no module declares and that is passed where a routine (installed or the program's)
    takes a signal becomes a virtual signal of that parameter's signal type, at 0. *)

open Rapid_syntax

val infer :
  installed:Ast.module_declaration list -> Ast.module_declaration list ->
  (string * Rapid_controller.Io_config.signal_type * Source.region) list
(** The undeclared names the modules pass as signal arguments of routines, each
    once (the first use decides its type, and is given: the argument's region), in the order of
    their first use. Names declared in
    the modules (data, parameters, anywhere) or in the installed environment are left out. *)

val extend : Rapid_controller.Io_config.t -> (string * Rapid_controller.Io_config.signal_type * Source.region) list ->
  Rapid_controller.Io_config.t
(** The configuration with the inferred signals added after its own, at 0; a name the
    configuration already has is left as it is. *)

val for_run :
  allow_unknown:bool -> stub_unmodelled:bool -> Ast.module_declaration list ->
  Rapid_controller.Io_config.t ->
  Rapid_controller.Io_config.t * (Rapid_controller.Io_config.signal * Source.region) list
(** The configuration a run uses: with both options, extended by {!infer} against the installed
    environment; otherwise unchanged. The second part is the signals added, each with its first
    use. *)
