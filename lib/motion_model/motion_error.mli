(** The errors of the motion model, each under the name the engines raise (ABB's event
    names where ABB has one; doc/motion.md, "Errors"). *)

type t =
  | Out_of_reach  (** "position outside reach"; CalcJointT's ERR_ROBLIMIT *)
  | Joint_out_of_range of int  (** "joint N out of range" *)
  | Configuration_error  (** no solution with the programmed confdata, or a linear move that
                             would have to change the arm configuration (ConfL \On) *)
  | Close_to_singularity  (** a linear or circular move to a wrist singularity, SingArea \Off *)
  | Circle_uncertain  (** MoveC: CirPoint too close to the start or end point, or on their line *)
  | Invalid_speed of string  (** a speed or \T that cannot give the move a duration *)
  | Robhold_conflict  (** tool and work object both held, or both not held, by the robot *)
  | Path_level of string  (** StorePath on level 2, RestoPath on level 1 *)
  | External_out_of_range of string
      (** "external axis eax_a out of range": a move's or CalcRobT's external axis beyond the
          range of the robot description (law X-target) *)

val name : t -> string
(** A one-line message, e.g. ["joint 4 out of range"]. *)

val errnum : t -> string option
(** The predefined errnum a function with \ErrorNumber (CalcJointT) stores: ERR_ROBLIMIT for a
    position the robot cannot take (installed-facts.md §2, CONFIRMED); [None] for the rest. *)
