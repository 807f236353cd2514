(** The exact value of a numeric literal (§2.5).

    A literal denotes a rational number exactly: its digits times a power of ten. Rounding it to
    num (single precision) or dnum (double precision) is for the phase that knows which of the
    two the context wants; the lexer only checks that the literal lies in the range of IEEE 754
    double precision (§2.5, ruling R-2.5 in doc/rulings.md). *)

type t = { mantissa : Z.t; exponent : int }
(** The value [mantissa * 10 ^ exponent]. Zero is [{ mantissa = 0; exponent = 0 }]. *)

val of_text : string -> (t, string) result
(** Reads a literal in any form of §2.5 ([38.], [.5], [2.5E-3], [0D17], [0XFF], [0o17],
    [0b101]). [Error message] when it is out of range, in the manual's words. The text must be
    lexically a numeric literal. *)

val value : string -> Q.t
(** The exact value of a literal that {!of_text} accepts. *)

val to_q : t -> Q.t
