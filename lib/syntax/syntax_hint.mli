(** Hints for syntax errors: the likely intent behind the most common mistakes (a comparison
    written [==], an assignment written [=], a procedure called with parentheses, an IF without
    THEN, a compound statement or routine left open), found from the tokens around the error. *)

val hint :
  Source.file -> Decode.t -> installed:bool -> robotware:Robotware.t -> error_start:int -> string option
(** [hint file decoded ~installed ~robotware ~error_start]: the hint for a syntax error at the token that
    starts at character offset [error_start], from the tokens of [decoded] read again from its
    start. [None] when no mistake is recognised. Never raises. *)

val lexical_hint : string -> string option
(** The hint for a lexical error's message: a string in single quotes, [&], [#]. *)
