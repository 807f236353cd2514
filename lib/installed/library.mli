(** The pure functions of the installed library (ch. 13): string functions, number/text
    conversion, arithmetic, trigonometry, vectors, poses and bits. Their signatures are those
    of lib/typing/installed/*.sys; their behaviour is from installed-facts.md, whose confidence
    each entry repeats. Where the facts are uncertain or silent, doc/rulings.md R-13-a to
    R-13-h decide.

    Every function takes and returns {!Value.t}. An [Error] carries the name of the execution
    error (["ERR_..."]); {!Value.Type_mismatch} is raised on arguments of the wrong type, which
    the static semantics excludes. Every num result is rounded to single precision, and a num
    or dnum result beyond the finite range is ["ERR_OVERFLOW"] (R-3.12-c).

    Conventions shared by several functions (R-13-c, R-13-e):
    - a character position, length or number of decimals that is not an integer value is
      ["ERR_NOTINTVAL"];
    - a position outside the string is ["ERR_OUTOFBND"];
    - an argument outside the function's domain (Sqrt of a negative number, ASin of 2, a
      negative number of decimals, a byte of 300) is ["ERR_ARGVALERR"];
    - strings are sequences of bytes and positions count bytes from 1 (§2.13: 80 bytes). *)

type result = (Value.t, string) Stdlib.result

(** {1 Strings} installed-facts.md §1 "String functions": signatures CONFIRMED, results of the
    manual's examples CONFIRMED, the rest as marked. *)

val str_len : Value.t -> result
(** StrLen(Str): the number of bytes. [StrLen("Robotics") = 8]. CONFIRMED. *)

val str_part : Value.t -> Value.t -> Value.t -> result
(** StrPart(Str, ChPos, Len): the [Len] bytes from [ChPos]. [StrPart("Robotics",1,5) =
    "Robot"]. CONFIRMED. A part not inside the string (ChPos < 1, Len < 0, ChPos + Len - 1 >
    StrLen) is ERR_OUTOFBND: UNCERTAIN ("probably ERR_OUTOFBND"), R-13-c. *)

val str_find : not_in_set:bool -> Value.t -> Value.t -> Value.t -> result
(** StrFind(Str, ChPos, Set [\NotInSet]): the first position from ChPos whose byte is in Set
    (not in Set). [StrFind("Robotics",1,"aeiou") = 2], with [\NotInSet] 1. CONFIRMED. None:
    StrLen + 1 (UNCERTAIN, memory). ChPos may be 1 .. StrLen + 1 (R-13-c). *)

val str_match : Value.t -> Value.t -> Value.t -> result
(** StrMatch(Str, ChPos, Pattern): the first position from ChPos where Pattern starts.
    [StrMatch("Robotics",1,"bo") = 3]. CONFIRMED. None: StrLen + 1 (UNCERTAIN). *)

val str_map : Value.t -> Value.t -> Value.t -> result
(** StrMap(Str, FromMap, ToMap): each byte found in FromMap (its first occurrence) replaced by
    the byte at the same position of ToMap. [StrMap("Robotics","aeiou","AEIOU") =
    "RObOtIcs"]. CONFIRMED. A byte of FromMap past the end of ToMap maps to itself: R-13-c. *)

val str_memb : Value.t -> Value.t -> Value.t -> result
(** StrMemb(Str, ChPos, Set): whether the byte at ChPos (1 .. StrLen) is in Set.
    [StrMemb("Robotics",2,"aeiou") = TRUE]. CONFIRMED. *)

val str_order : Value.t -> Value.t -> Value.t -> result
(** StrOrder(Str1, Str2, Order): whether Str1 sorts strictly before Str2 when bytes are ranked
    by their first position in Order; a proper prefix sorts first. The manual's examples
    CONFIRMED; bytes not in Order (UNCERTAIN) rank after all of Order, among themselves by
    code: R-13-c. *)

(** {1 Numbers and text} installed-facts.md §1 "Number -> text conversion". *)

val num_to_str : Value.t -> Value.t -> exp:bool -> result
(** NumToStr(Val, Dec [\Exp]): [Dec] decimals. [NumToStr(0.38521,3) = "0.385"] CONFIRMED; the
    [\Exp] format ("3.85E-01") UNCERTAIN: R-13-a. Dec must be a non-negative integer;
    a result over 80 bytes is ERR_STRTOOLNG. *)

val dnum_to_str : Value.t -> Value.t -> exp:bool -> result
(** DnumToStr(Val, Dec [\Exp]): the same for a dnum. CONFIRMED (signature). *)

val val_to_str : Value.t -> result
(** ValToStr(Val): the value as RAPID writes it ({!Format.value_text}): "TRUE", "[x,y,z]", num
    with 6 significant digits ([ValToStr(1.234567890123456789) = "1.23457"]; UNCERTAIN),
    strings in quotes (R-13-b). Over 80 bytes: ERR_STRTOOLNG. *)

val str_to_val : Value.t -> Value.shape -> Value.t option
(** StrToVal(Str, Val): [Some v] (the function returns TRUE and Val becomes [v]) when Str is
    the text of a value of Val's shape as ValToStr writes it, read with the literal syntax of
    §2.5-§2.7 (a sign before a number, blanks between items allowed); [None] otherwise
    (FALSE, Val unchanged: UNCERTAIN), also for a number that the type cannot hold.
    Signature and bool result CONFIRMED; R-13-b. *)

(** {1 Arithmetic} installed-facts.md §1 "Math functions": signatures CONFIRMED. *)

val abs_num : Value.t -> result
(** Abs(Input); also AbsDnum on a dnum. *)

val sqrt_num : Value.t -> result
(** Sqrt(Value); SqrtDnum. A negative argument: ERR_ARGVALERR (UNCERTAIN, the facts' plausible
    candidate), R-13-e. *)

val exp_num : Value.t -> result
(** Exp(Exponent): e to the power Exponent. *)

val pow_num : Value.t -> Value.t -> result
(** Pow(Base, Exponent); PowDnum. An undefined power (a negative base and a non-integer
    exponent) is ERR_ARGVALERR; an infinite one (0 to a negative power) ERR_OVERFLOW: R-13-e. *)

val sin_num : Value.t -> result
(** Sin(Angle), the angle in degrees (CONFIRMED); SinDnum. Multiples of 90 degrees give 0, 1
    and -1 exactly: R-13-e. *)

val cos_num : Value.t -> result
val tan_num : Value.t -> result
(** Tan(Angle): at odd multiples of 90 degrees the result is infinite: ERR_OVERFLOW. *)

val asin_num : Value.t -> result
(** ASin(Value), Value in [-1, 1] (CONFIRMED, ERR_ARGVALERR outside: UNCERTAIN); result in
    degrees, -90..90 (UNCERTAIN): R-13-e. *)

val acos_num : Value.t -> result
(** ACos(Value): degrees, 0..180. *)

val atan_num : Value.t -> result
(** ATan(Value): degrees, -90..90. *)

val atan2_num : Value.t -> Value.t -> result
(** ATan2(Y, X): the angle of (X, Y) in degrees, -180..180 (UNCERTAIN); ATan2(0, 0) = 0. *)

val round_num : Value.t -> dec:Value.t option -> result
(** Round(Val [\Dec]): to [Dec] decimals, 0 when absent (CONFIRMED: [Round(0.3852138\Dec:=3) =
    0.385], [\Dec:=1] 0.4, no [\Dec] 0). Ties away from zero, from the exact value (UNCERTAIN):
    R-13-d. RoundDnum on a dnum. *)

val trunc_num : Value.t -> dec:Value.t option -> result
(** Trunc(Val [\Dec]): toward zero. [Trunc(0.3852138\Dec:=3) = 0.385] CONFIRMED. *)

val max_num : Value.t -> Value.t -> result
(** Max(Value1, Value2). *)

val min_num : Value.t -> Value.t -> result

val num_to_dnum : Value.t -> result
(** NumToDnum(Value): exact. CONFIRMED. *)

val dnum_to_num : Value.t -> integer:bool -> result
(** DnumToNum(Value [\Integer]): the dnum rounded to single precision (CONFIRMED: "converts if
    possible, otherwise a recoverable error"). Beyond the range of num: ERR_NUM_LIMIT; with
    [\Integer] a non-integer value is ERR_NOTINTVAL and an integer outside the exact integer
    sub-domain of num ERR_NUM_LIMIT (names UNCERTAIN): R-13-g. *)

(** {1 Vectors and poses} installed-facts.md §1 "Vector functions", §3 "Geometry types" and
    §4 "Position functions": signatures CONFIRMED, formulas R-13-f. *)

val distance : Value.t -> Value.t -> result
(** Distance(Point1, Point2): the Euclidean distance, in double precision then rounded. *)

val dot_prod : Value.t -> Value.t -> result
(** DotProd(Vector1, Vector2): computed exactly and rounded once. *)

val cross_prod : Value.t -> Value.t -> result
(** CrossProd(Vector1, Vector2): as pos * pos (§3.12). *)

val vect_magn : Value.t -> result
(** VectMagn(Vector): the length. *)

val pose_mult : Value.t -> Value.t -> result
(** PoseMult(Pose1, Pose2): [trans1 + R(rot1) trans2], [rot1 * rot2]. *)

val pose_inv : Value.t -> result
(** PoseInv(Pose): [-(R(rot)^T trans)], the conjugate of rot. *)

val pose_vect : Value.t -> Value.t -> result
(** PoseVect(Pose, Pos): [R(rot) pos + trans]. *)

val orient_zyx : Value.t -> Value.t -> Value.t -> result
(** OrientZYX(ZAngle, YAngle, XAngle): the rotation about z, then the new y, then the new x,
    angles in degrees (CONFIRMED: "Euler ZYX in degrees"). *)

val euler_zyx : [ `X | `Y | `Z ] option -> Value.t -> result
(** EulerZYX([\X]|[\Y]|[\Z] Rotation): one Euler ZYX angle of the rotation, in degrees, the
    inverse of OrientZYX for Y in -90..90. No switch: ERR_ARGVALERR (R-13-f). *)

val norient : Value.t -> result
(** NOrient(Rotation): the quaternion divided by its norm. The thresholds CONFIRMED: an error
    |q1²+q2²+q3²+q4² - 1| of 0.1 or more cannot be fixed: ERR_ILLQUAT (name UNCERTAIN). *)

(** {1 Bits} installed-facts.md §1 "Bit functions" (byte 0..255, bit positions 1..8; dnum bit
    positions 1..52): CONFIRMED; errors R-13-h. *)

val bit_and : Value.t -> Value.t -> result
val bit_or : Value.t -> Value.t -> result
val bit_xor : Value.t -> Value.t -> result
val bit_neg : Value.t -> result
val bit_lsh : Value.t -> Value.t -> result
val bit_rsh : Value.t -> Value.t -> result
val bit_check : Value.t -> Value.t -> result

val bit_set : Value.t -> Value.t -> result
(** The new value of BitSet's BitData (an INOUT procedure; the machine stores it). *)

val bit_clear : Value.t -> Value.t -> result

val bit_and_dnum : Value.t -> Value.t -> result
val bit_or_dnum : Value.t -> Value.t -> result
val bit_xor_dnum : Value.t -> Value.t -> result
val bit_neg_dnum : Value.t -> result
val bit_lsh_dnum : Value.t -> Value.t -> result
val bit_rsh_dnum : Value.t -> Value.t -> result
val bit_check_dnum : Value.t -> Value.t -> result
val bit_set_dnum : Value.t -> Value.t -> result
val bit_clear_dnum : Value.t -> Value.t -> result

(** {1 By name} *)

val functions : (string * int * (Value.t option array -> result)) list
(** Every installed function above except StrToVal (whose Val is INOUT and whose type the
    caller must give), by its name in the installed modules, with its number of parameters
    and its implementation. Arguments come one per parameter of the declaration, in order,
    each alternative of an optional parameter in its own place (EulerZYX has 4); [None] is an
    absent optional parameter, and a switch is present when it is [Some _]. Num or dnum
    variants share an implementation that follows the argument's type. *)

val find : string -> (Value.t option array -> result) option
(** {!functions} by name, without regard to letter case (§2.3). *)

val find_fixed : string -> Installed_routine.fixed option
(** The same function by its number of parameters, when none is optional and there are at most
    three: [find name] applied to [[|Some a; Some b|]] is [f a b] for [Two f]. *)
