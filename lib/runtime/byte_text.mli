(** StrToByte and ByteToStr (doc/rulings.md R-13-ab): a byte (0..255) as text, in decimal
    (no switch), hexadecimal (\Hex, two digits), octal (\Okt, three digits), binary (\Bin,
    eight digits) or as the one character of that code (\Char). *)

type base = Dec | Hex | Okt | Bin | Char

val base_of_switches : hex:bool -> okt:bool -> bin:bool -> char:bool -> base

val byte_to_str : base -> Value.t -> (Value.t, string) result
(** ERR_NOTINTVAL for a value that is not an integer, ERR_ARGVALERR outside 0..255 (as the bit
    functions, R-13-h). *)

val str_to_byte : base -> Value.t -> (Value.t, string) result
(** ERR_ARGVALERR for text that is not a byte in that base: empty, a wrong digit, more digits
    than the base writes, a value above 255, or for \Char not exactly one byte. *)
