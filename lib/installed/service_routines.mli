(** The behaviour of the installed routines of the controller's services (doc/services.md):
    files and directories in the sandbox (Open ... CloseDir), raw data (rawbytes), and sockets.
    They act on the run's {!Rapid_controller.Services}, reached through the world of the
    primitive context. *)

val call :
  ?standstill:(unit -> float) -> Primitive.context -> string -> Primitive.argument array ->
  Primitive.outcome option
(** [None]: not one of these routines. Arguments are found by parameter name. [standstill]: when
    the task's robot stands still (doc/motion.md); a socket wait follows the host's clock while
    the robot moves (doc/rulings.md R-13-sockwait1). Without it, the robot stands still. *)

val modelled : string -> bool

val encode_any : Value.t -> (string, string) result
(** WriteAnyBin's encoding of a value (doc/rulings.md R-13-t). *)

val decode_any : string -> int -> (Value.t * int, string) result
(** The value encoded at this offset and the offset after it; ERR_RANYBIN_EOF when the data
    end before it, ERR_RANYBIN_CHK when they are not an encoding. *)
