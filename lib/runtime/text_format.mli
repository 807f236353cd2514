(** Numbers and values as text, as the controller writes them: NumToStr, DnumToStr, ValToStr
    and the value that TPWrite appends to its text (installed-facts.md §1, "Number -> text
    conversion"). Every number is written from its exact binary value, and every rounding to a
    number of digits is to nearest with ties away from zero; a number that rounds to zero has
    no minus sign. The formats the facts mark UNCERTAIN are decided in doc/rulings.md
    R-13-a and R-13-b.

    Inside the library rapid_semantics this module hides [Stdlib.Format]. *)

val fixed : float -> decimals:int -> string
(** NumToStr and DnumToStr without [\Exp]: exactly [decimals] digits after the point, none and
    no point when [decimals = 0]. [fixed 0.38521 ~decimals:3 = "0.385"].
    Precondition: [decimals >= 0], the float finite. *)

val scientific : float -> decimals:int -> string
(** NumToStr and DnumToStr with [\Exp]: one digit before the point, [decimals] after it, then
    [E], a sign and at least two digits: [scientific 0.38521 ~decimals:2 = "3.85E-01"]. *)

val num_text : float -> string
(** A num as ValToStr and TPWrite [\Num] write it: a number within 0.000005 of an integer
    of the exact integer sub-domain (§2.13) is that integer; any other is written with 6
    significant digits, in positional notation when its decimal exponent is in -4..5 and
    otherwise as [d.dddddE+XX], trailing zeros removed. *)

val dnum_text : float -> string
(** A dnum as ValToStr and TPWrite [\Dnum] write it: an integer of the exact sub-domain in
    full, any other number with 15 significant digits, in the same notation as
    {!num_text} (positional for decimal exponents -4..14). *)

val string_literal : string -> string
(** A string as a RAPID string literal (§2.7): in double quotes, with [""] for a quote, [\\]
    for a backslash and [\hh] for control characters (codes below 32, and 127). *)

val display : string -> string
(** A line as the pendant shows it: a control character (codes below 32, and 127) as a
    backslash and its code in two upper-case hex digits, as RAPID writes character codes in
    string literals (§2.7): ["a\rb"] shows as [a\0Db]. Other bytes are unchanged. *)

val value_text : Value.t -> string
(** ValToStr without the length check: numbers as {!num_text} and {!dnum_text}, [TRUE],
    [FALSE], strings as {!string_literal}, records and arrays as [[a,b,c]] without spaces.
    Raises {!Value.Type_mismatch} on a handle, which has no value to write. *)

val tpwrite : string -> Value.t option -> string
(** The line TPWrite writes: the text followed by the value of [\Num], [\Bool], [\Pos],
    [\Orient] or [\Dnum] as {!value_text} writes it. *)

(** {1 Exact decimal arithmetic shared with {!Library}} *)

val round_half_away : Q.t -> Z.t
(** The integer nearest to the rational, ties away from zero. *)

val pow10 : int -> Q.t
(** [10^e] for any integer [e]. *)
