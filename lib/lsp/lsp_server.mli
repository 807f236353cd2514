(** The language server: LSP 3.17 over a pair of channels (standard input and output for
    [rapid-sem lsp]). Requests are answered in the order they come; no request ever ends the
    server: a handler's exception becomes an InternalError response, an unknown method a
    MethodNotFound, a malformed message a ParseError (or InvalidRequest), and the next message
    is read. The server ends at the [exit] notification or at the end of its input. *)

type t

val create : Lsp_workspace.options -> t

val handle : t -> Yojson.Safe.t -> Yojson.Safe.t list
(** The messages one incoming message makes, in order: its response (for a request) and the
    notifications it causes (publishDiagnostics). Never raises. *)

val workspace : t -> Lsp_workspace.t
(** Its documents, for a test to compare with what the client sent. *)

val finished : t -> int option
(** After [exit]: the exit status (0 after [shutdown], 1 otherwise, as LSP 3.17 says). *)

val run : Lsp_workspace.options -> in_channel -> out_channel -> int
(** Serves until [exit] or the end of input; the exit status. *)
