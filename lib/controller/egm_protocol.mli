(** The messages of Externally Guided Motion (ABB's EGM application manual) between the robot
    controller and a sensor over UDP, in Google's protocol buffer wire format, for the fields
    rapid-sem uses (doc/services.md, "Externally Guided Motion"). No protocol buffer library is
    packaged for OCaml in Debian bookworm, so the wire format is written here: varints, 64-bit
    doubles, length-delimited submessages, repeated doubles packed or not; a field of another
    number or wire type is skipped, so that a sensor built on a newer schema is understood.

    The schema, in our words (field numbers are those ABB publishes with RobotWare):
    - a header (1 in both messages): sequence number (1, varint), the sender's time stamp in ms
      (2, varint), the message type (3, varint: 2 the robot's data, 3 a sensor's correction);
    - a joint set: the axis angles in degrees (1, repeated double); a pose: a position in mm
      (1: x 1, y 2, z 3), an orientation as a quaternion (2: u0 1 ... u3 4), Euler angles in
      degrees (3: x 1, y 2, z 3);
    - the robot's message: header, feedback (2: joints 1, pose 2, external joints 3), planned
      (3: the same three), motor state (4: state 1, 1 on, 2 off), the motion control state (5:
      state 1, 2 stopped, 3 running), whether the convergence criteria are met (6, varint bool),
      the RAPID execution state (8: state 1, 1 stopped, 2 running), the utilization rate (10,
      double, percent);
    - the sensor's message: header, planned set points (2: joints 1, pose 2, external joints 3),
      speed references (3: joints 1, Cartesian speeds 2 as repeated doubles 1). *)

type header = { seqno : int option; tm : int option; mtype : int option }

val mtype_data : int
(** 2: the robot controller's message. *)

val mtype_correction : int
(** 3: a sensor's position guidance. *)

type pose = {
  pos : (float * float * float) option;
  orient : (float * float * float * float) option;
  euler : (float * float * float) option;
}

type robot = {
  r_header : header;
  feedback_joints : float list option;
  feedback_pose : pose option;
  planned_joints : float list option;
  planned_pose : pose option;
  motor_on : bool option;
  mci_running : bool option;       (** the motion control state: running (3) or stopped (2) *)
  convergence_met : bool option;
  rapid_running : bool option;
  utilization : float option;
}

type sensor = {
  s_header : header;
  set_joints : float list option;   (** planned joints, degrees *)
  set_pose : pose option;
  set_external : float list option;
  speed_joints : float list option; (** degrees per second *)
}

val empty_header : header
val empty_robot : robot
val empty_sensor : sensor

val encode_robot : robot -> string
val encode_sensor : sensor -> string

val decode_robot : string -> (robot, string) result
val decode_sensor : string -> (sensor, string) result
(** Any bytes: a message, or why they are not one (a truncated varint or field, a varint beyond
    64 bits, a wire type protocol buffers do not have, a length beyond the bytes); never an
    exception. Of a field given twice the last counts (repeated doubles add up), as protocol
    buffers merge them. *)
