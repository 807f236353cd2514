(** The installed routines that ask about the system rapid-sem is, or set up what its motion model
    has no place for (ch. 13; ABB's "Technical reference manual - RAPID Instructions, Functions
    and Data types", 3HAC050917, one page per routine): GetSysInfo, OpMode and RobOS answer as a
    virtual controller (doc/rulings.md R-13-sys1, R-13-sys2); DecToHex and HexToDec convert whole
    numbers between base 10 and base 16 (R-13-sys3); BitSet and BitClear change one bit of a byte
    or of a dnum, as their pages say (R-13-sys4); MaxRobReorientSpeed, SoftAct, SoftDeact and
    PathAccLim are the motion's (R-13-sys5). The kernel manual knows none of them: installed
    routines are the system's (ch. 13). ExitCycle is the motion's (it drops the robot's path,
    Motion_routines) and the engines' (the next cycle, R-13-exitcycle1).

    The bodies find their arguments by the names of the routine's parameters
    ([Primitive.context.parameters], lib/typing/installed), so that a parameter added to a
    declaration later does not move them. *)

(** What GetSysInfo says of the controller, one text a switch. RobotType is not here: it is the
    name of the run's robot description (doc/motion.md), which [--robot] chooses. *)
type identity = {
  serial_no : string;        (** \SerialNo *)
  sw_version : string;       (** \SWVersion: the RobotWare of the kernel manual rapid-sem follows *)
  sw_version_name : string;  (** \SWVersionName *)
  ctrl_id : string;          (** \CtrlId *)
  lan_ip : string;           (** \LanIp: the loopback, where rapid-sem's sockets serve (doc/services.md) *)
  ctrl_lang : string;        (** \CtrlLang *)
  system_name : string;      (** \SystemName *)
}

val virtual_controller : identity
(** The identity of every run (doc/controller.md, "The virtual controller"); a later option may
    give another. *)

val modelled : string -> bool
(** Whether this module gives the installed routine of this name a body. *)

val call :
  Primitive.context -> Motion_routines.state -> string -> Primitive.argument array -> Primitive.outcome option
(** The routine's outcome; [None]: not one of these routines. The motion state gives the robot
    (GetSysInfo \RobotType, MaxRobReorientSpeed); nothing here changes the motion or the world. *)

val dec_to_hex : string -> (string, string) result
(** DecToHex's text: the digits 0-9 of a number from 0 to 2{^63}-1 written with 0-9 and A-F,
    without leading zeros; [Error "ERR_ARGVALERR"] for any other text. *)

val hex_to_dec : string -> (string, string) result
(** HexToDec's text: hexadecimal digits in either case, back to base 10. *)
