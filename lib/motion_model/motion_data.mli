(** The motion data types and the predefined data of the BASE module, as tables the machine can
    install (doc/motion.md, "Data"). Values from installed-facts.md §3 with their confidence. *)

type speeddata = { v_tcp : float; v_ori : float; v_leax : float; v_reax : float }
(** mm/s, deg/s, mm/s, deg/s (CONFIRMED). *)

type zonedata = {
  finep : bool; pzone_tcp : float; pzone_ori : float; pzone_eax : float;
  zone_ori : float; zone_leax : float; zone_reax : float;
}
(** mm, mm, mm, deg, mm, deg (CONFIRMED). *)

type stop_type = Inpos | Stoptime | Fllwtime

type stoppointdata = {
  stop_type : stop_type;
  progsynch : bool;
  inpos_position : float;  (** % of the fine-point zone *)
  inpos_speed : float;  (** % of the fine-point speed *)
  inpos_mintime : float;  (** s *)
  inpos_maxtime : float;  (** s *)
  stoptime : float;  (** s *)
  followtime : float;  (** s *)
}

type tooldata = { tool_robhold : bool; tframe : Geom.pose; tool_mass : float }
type wobjdata = { wobj_robhold : bool; ufprog : bool; ufmec : string; uframe : Geom.pose; oframe : Geom.pose }
type loaddata = { mass : float; cog : Geom.pos; aom : Geom.orient; ix : float; iy : float; iz : float }

val speeddata : (string * speeddata) list
(** v5 … v7000 = [N, 500, 5000, 1000] (CORROBORATED) and vmax (v_tcp = the default robot's
    maximum TCP speed, UNCERTAIN). *)

val vmax : Robot.t -> speeddata
(** vmax for a robot: its maximum TCP speed, and 500, 5000, 1000. *)

val zonedata : (string * zonedata) list
(** fine, z0 … z200 (CORROBORATED). *)

val stoppointdata : (string * stoppointdata) list
(** inpos20/50/100, stoptime0_5/1_0/1_5, fllwtime0_5/1_0/1_5 (names CONFIRMED; values
    UNCERTAIN: inposN = [inpos, TRUE, [N, N, 0, 20], 0, 0], stoptimeX = [stoptime, FALSE, …, X,
    0], fllwtimeX = [fllwtime, TRUE, …, 0, X]). *)

val tool0 : tooldata
val wobj0 : wobjdata
val load0 : loaddata
(** BASE's tool0, wobj0, load0 (CORROBORATED). *)

val find : (string * 'a) list -> string -> 'a option
(** Lookup by name, ignoring case as RAPID names do. *)
