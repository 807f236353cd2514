(** The decimal numbers of rapid-sem's own input files (the stimulus file, EIO.cfg, the robot
    description): [[+-]DIGITS[.DIGITS][(e|E)[+-]DIGITS]], at least one digit before the
    exponent. [float_of_string] alone would also take hexadecimal ([0x10]), underscores
    ([1_0]), [nan] and [inf], which these formats do not have. *)

val is_decimal : string -> bool

val num_max : float
(** The largest finite num, 3.40282347E+38: num is IEEE 754 single precision (§2.13). *)

val read : string -> (float, [ `Not_decimal | `Beyond_num ]) result
(** A decimal within num's range ([-0] is 0); [`Beyond_num] for one that does not round to a
    finite num, as a RAPID literal (§2.5, §2.13): above {!num_max} by half a unit of its last
    place or more. A value above {!num_max} that rounds to it (3.4028235E+38) is {!num_max}. *)

val shown : string -> string
(** A word as an error message quotes it: at most 40 bytes, then "...", so that a number of a
    million digits does not make a message of a million characters. *)
