(** The UdpUc devices of Externally Guided Motion (ABB's EGM application manual: a transmission
    protocol of type UDPUC names the sensor's remote address and port) and the UDP channel of
    one EGM process to its sensor, on the host's loopback (doc/services.md, "Externally Guided
    Motion"). The run's devices come from the command line (--egm-device NAME=HOST:PORT). *)

type device = { name : string; host : string; port : int }

val parse_devices : string -> (device list, string) result
(** ["NAME=HOST:PORT,..."]: HOST a loopback address (127.x.y.z) or "localhost", PORT 1..65535;
    a message naming the item otherwise. *)

val find : device list -> string -> device option
(** The device of a RAPID UCDevice argument: letter case aside, a trailing ':' ignored
    ("EGMSensor:" is "EGMSensor"). *)

type t

val open_channel : device -> (t, string) result
(** A UDP socket of the host sending to the device; [Error] with the host's reason. *)

val send : t -> string -> unit
(** One datagram; a sensor not listening is no error of the sender (UDP). *)

val receive : t -> within:float -> string option
(** The newest datagram waiting, waiting at most [within] host seconds for one: older ones
    waiting are dropped, as a set point is replaced by a newer one. *)

val close : t -> unit
