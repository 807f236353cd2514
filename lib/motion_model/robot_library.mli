(** The library of ABB robot descriptions (doc/motion.md, "The robot library"): one file each in
    robots/, in the format of {!Robot}, compiled into the program. A robot is named by its library
    name, the file's name without [.robot] ([irb2400-10-1.5]: model, payload in kg, reach in m, as
    ABB names the product), or by the robot type a controller's MOC.cfg gives
    ([-use_robot_type "ROB1_2400_1.5_10"]: model, reach, payload). *)

val names : unit -> string list
(** The library names, in the order of their files. *)

val text : string -> string option
(** The description file of a library name. *)

val robot_type : string -> string option
(** The MOC.cfg robot type of a library name: [ROB1_MODEL_REACH_PAYLOAD]. *)

val find : string -> (Robot.t, string) result
(** The robot a name stands for: a library name, a model alone when the library has one variant of
    it ([irb2400] when only one IRB 2400 is known; [IRB 2400] and [2400] alike), or a MOC.cfg robot
    type (an [ROBn_] prefix, the model, the reach and the payload separated by [_]; a reach may be
    written [0_95] for 0.95; words such as [TypeB] or [LeanID] after the model are variants, and
    [ID] right after it is part of the model, [1660_ID] = [1660ID]). The error names what was
    asked and the robot types the library knows. *)

val load : string -> (Robot.t, string) result
(** What [--robot] and a spec case's [@robot] name: a description file when a file of that name
    exists (its errors those of {!Robot.load}), else {!find}. *)
