(** The atomic types of the installed system (ch. 13 "installed objects"): the types whose
    values the system holds and RAPID source cannot declare, since a type definition is a
    RECORD or an ALIAS (§2.11). Everything else the installed environment provides is RAPID
    source in [lib/typing/installed/], read by the same judgement as user code.

    Not here, because they are aliases of num and declared in that source: intnum and errnum
    (built in, §2.15), byte, dionum, identno, errdomain, errtype, socketstatus, inttypes,
    stoppoint, opnum, aiotrigg. *)

val atomic_types : (string * Types.value_class * Types.data_type option) list
(** Name, value class (§2.16) and, for a semi-value type, its associated value type. *)

val find : string -> Types.data_type option
(** The installed atomic type of that name, compared without regard to letter case (§2.3). *)

val refuses_update : string list
(** Semi-value types whose objects refuse an update by value (§2.16: "sig1 represents an input
    device and refuses the assignment sig1 := 1"): the input signals. *)
