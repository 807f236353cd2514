(** The Socket Messaging of the controller on real TCP and UDP sockets of the host (doc/services.md).

    Only loopback addresses (127.0.0.0/8, and "localhost") are reachable unless the run allows
    more ([--net HOST:PORT,...]); a RAPID address can be mapped to another before that check
    ([--map-address 192.168.125.1=127.0.0.1]), so that a module written for the controller's
    service port serves unmodified. Errors are the ERR_ names of the socket routines. Blocking
    calls wait on the host for at most their timeout and say how long they waited. *)

type t

type status = Created | Bound | Listening | Connected | Closed

val status_number : status -> int
(** SOCKET_CREATED 1, SOCKET_CONNECTED 2, SOCKET_BOUND 3, SOCKET_LISTENING 4, SOCKET_CLOSED 5. *)

val max_sockets : int
(** Sockets open at once in a run: 32 (doc/rulings.md R-13-u). *)

val create : ?allowed:(string * int option) list -> ?mapping:(string * string) list -> unit -> t
(** [allowed]: hosts (and ports, [None] any) reachable beyond the loopback. *)

val parse_allowed : string -> ((string * int option) list, string) result
(** ["HOST:PORT,HOST:*,..."]. *)

val parse_mapping : string -> ((string * string) list, string) result
(** ["FROM=TO,..."]. *)

val socket : t -> udp:bool -> (int, string) result
(** A new socket (SocketCreate): its identity (from 1). *)

val status : t -> int -> status
(** Of an identity no socket has: [Closed]. *)

val bind : t -> int -> string -> int -> (unit, string) result

val listen_backlog : int
(** The length of a listening socket's queue of connections not yet accepted: 4096, SOMAXCONN of
    current Linux, capped by the host's net.core.somaxconn (doc/rulings.md R-13-cli1). *)

val listen : t -> int -> (unit, string) result

val accept : t -> int -> timeout:float -> (int * string, string) result * float
(** The client socket and its address; with the host seconds waited. *)

val connect : t -> int -> string -> int -> timeout:float -> (unit, string) result * float
val send : t -> int -> string -> (unit, string) result
val send_to : t -> int -> string -> int -> string -> (unit, string) result

val receive : t -> int -> max:int -> exact:bool -> timeout:float -> (string, string) result * float
(** At most [max] bytes, at least one; with [exact], exactly [max] (\ReadNoOfBytes). *)

val receive_from : t -> int -> max:int -> timeout:float -> (string * string * int, string) result * float
val readable : t -> int -> within:float -> bool
(** Whether SocketAccept, SocketReceive or SocketReceiveFrom on this socket would go on at once
    (a connection or data waits, or the peer closed), looking for at most [within] host seconds;
    [true] too for a socket no call can wait on, whose call reports the error. *)

val peek : t -> int -> (int, string) result
val close : t -> int -> unit
val close_all : t -> unit
