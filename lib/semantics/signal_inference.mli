(** The signals a program uses without declaring them (doc/rulings.md R-13-aa): real programs
    name the I/O signals of their controller's EIO configuration, which is not part of the
    program. Under [run --allow-unknown --stub-unmodelled] without that configuration, a name
    that no module declares and that is passed where an installed routine takes a signal
    becomes a virtual signal of that routine's signal type, at 0. *)

open Rapid_syntax

val infer :
  installed:Ast.module_declaration list -> Ast.module_declaration list ->
  (string * Rapid_controller.Io_config.signal_type) list
(** The undeclared names the modules pass as signal arguments of installed routines, each
    once (the first use decides its type), in the order of their first use. Names declared in
    the modules (data, parameters, anywhere) or in the installed environment are left out. *)

val extend : Rapid_controller.Io_config.t -> (string * Rapid_controller.Io_config.signal_type) list ->
  Rapid_controller.Io_config.t
(** The configuration with the inferred signals added after its own, at 0; a name the
    configuration already has is left as it is. *)
