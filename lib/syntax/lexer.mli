(** The lexical elements of chapter 2 (§2.1-§2.10), read by sedlex. *)

exception Error of Source.region * string
(** A lexical error (§1.4): where, and what, in the manual's words. *)

type t

val create : ?installed:bool -> ?robotware:Robotware.t -> Source.file -> Decode.t -> t
(** [~installed:true] reads the installed environment, where REF is an access mode (ch. 11).
    [robotware] (default {!Robotware.default}): the release whose reserved words apply. *)

val next : t -> Parser.token * Lexing.position * Lexing.position
(** The next token and the character offsets ([pos_cnum]) where it starts and stops.
    Raises {!Error}. *)

val next_into : t -> Lexing.lexbuf -> Parser.token
(** The next token, where it starts and stops written to the lexbuf's [lex_start_p] and
    [lex_curr_p] (where Menhir's parser reads them); a start equal to the previous
    [lex_curr_p] is that very record. The lexbuf's [lex_curr_p] starts at an offset no token
    stops at ([-1]). One [t] is read with [next] or with [next_into], not both. Raises
    {!Error}. *)

val reserved_words : (string, Parser.token) Hashtbl.t
(** §2.4, keyed by the upper-case spelling. *)

val max_identifier_length : int

val is_ascii_name : string -> bool
(** An identifier of §2.3 in ASCII (a letter, then letters, digits and underscores, at most
    {!max_identifier_length} characters), reserved or not: how the names of rapid-sem's
    configuration files (EIO.cfg's signals, MOC.cfg's units) must be spelled. *)
val max_string_bytes : int
