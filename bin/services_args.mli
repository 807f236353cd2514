(** The command-line options of the controller's services (doc/services.md): [--fs ROOT],
    [--net HOST:PORT,...], [--map-address FROM=TO,...]. *)

type t

val term : t Cmdliner.Term.t

val install : t -> Rapid_controller.World.t -> (unit, string) result
(** The run's services, or why an option is wrong. *)
