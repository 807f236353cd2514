(** JSON-RPC 2.0 messages in the base protocol of LSP 3.17: a header of [Content-Length: N]
    (other header fields are read and ignored), an empty line, then N bytes of JSON. No Debian
    package of bookworm offers this framing for OCaml (only an XML-RPC library), so it is
    written here, over yojson. *)

type incoming =
  | Message of Yojson.Safe.t
  | Malformed of string   (** a header without Content-Length, or a body that is not JSON: answered
                              with a ParseError by the server, then the next message is read *)
  | End                   (** the input ended *)

val max_body : int
(** A body longer than this is refused as malformed and read past, not held in memory. *)

val read : in_channel -> incoming

val write : out_channel -> Yojson.Safe.t -> unit
(** Frames and flushes one message. *)

val frame : Yojson.Safe.t -> string
(** The bytes [write] sends: the header and the body. *)

(** Error codes of JSON-RPC 2.0 and LSP 3.17. *)

val parse_error : int
val invalid_request : int
val method_not_found : int
val invalid_params : int
val internal_error : int
val server_not_initialized : int
val request_failed : int

val response : Yojson.Safe.t -> Yojson.Safe.t -> Yojson.Safe.t
(** [response id result] *)

val error_response : Yojson.Safe.t -> int -> string -> Yojson.Safe.t
(** [error_response id code message] *)

val notification : string -> Yojson.Safe.t -> Yojson.Safe.t
(** [notification method params] *)

val request : Yojson.Safe.t -> string -> Yojson.Safe.t -> Yojson.Safe.t
(** [request id method params], for the scripted client of the tests. *)
