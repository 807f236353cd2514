(* The moves with triggers (TriggL, TriggJ, TriggC) and the instructions that define their
   triggers (TriggIO, TriggEquip, TriggInt, TriggSpeed): a trigger is kept in its triggdata
   variable, and each Trigg move that names it makes it a timed event on the virtual clock at
   the moment the planner gives for its position on the move's path (doc/motion.md, "M-trigg").
   The move itself is Motion_routines'. *)

module V = Value
module W = Rapid_controller.World
module P = Rapid_motion_model.Planner
module MR = Motion_routines
open Primitive

let same = Rapid_typing.Types.same_name

let arg = named_argument
let present = named_present
let num = named_num

(* ------------------------------------------------------------------ trigger data *)

(* What a trigger does when the robot gets to it. *)
type action =
  | Set_output of { signal : int; value : float }   (* TriggIO, TriggEquip *)
  | Occur of int                                   (* TriggInt: the interrupt number *)
  | Speed_output of { signal : int; scale : float; dip_lag : float }  (* TriggSpeed *)

type definition = {
  distance : float;                 (* mm; with [time], s before the end point *)
  from_start : bool;                (* \Start *)
  time : bool;                      (* \Time *)
  shift : float;                    (* s of path time: \DODelay later, EquipLag or ScaleLag earlier *)
  inhib : (V.t array * int) option; (* \Inhib: the persistent read when the robot gets there *)
  action : action;
}

(* A triggdata variable holds a handle of its own; its definition is found by the handle, and
   goes when no variable holds the handle any more (a local triggdata of a routine called in a
   loop leaves nothing behind). *)
module Handles = Ephemeron.K1.Make (struct
    type t = V.handle
    let equal = ( == )
    let hash h = V.handle_id h
  end)

(* A trigger of a move on its way: its moment on the path, what it does, and the time the world
   is asked to call it back at ([None]: the robot is stopped short of it, the next drain asks
   again). A callback of an older generation is stale. *)
type pending = { mark : P.mark; fire : W.t -> unit; mutable armed : bool; mutable generation : int }

type run = {
  defs : definition Handles.t;
  mutable next_id : int;            (* handles of the run, numbered from 1 as they are made *)
  mutable pending : pending list;
}

type MR.extension += Trigg of run

let finish_pending planner r pd =
  P.release planner pd.mark;
  r.pending <- List.filter (fun x -> x != pd) r.pending

(* The world calls the trigger back at the time the planner gives now; at that time the planner
   is asked again: a StopMove meanwhile has moved it later (it is called back then), a ClearPath
   has dropped it. *)
let rec arm planner r w pd =
  match P.mark_time planner pd.mark with
  | None -> finish_pending planner r pd
  | Some t when Float.is_finite t ->
      pd.generation <- pd.generation + 1;
      let g = pd.generation in
      pd.armed <- true;
      W.at w t (fun () -> if pd.generation = g then due planner r w pd)
  | Some _ -> pd.armed <- false

and due planner r w pd =
  match P.mark_time planner pd.mark with
  | Some t when W.seconds t <= W.seconds (W.now w) -> finish_pending planner r pd; pd.fire w
  | _ -> arm planner r w pd

let run_of st =
  match List.find_map (function Trigg r -> Some r | _ -> None) (MR.extensions st) with
  | Some r -> r
  | None ->
      let r = { defs = Handles.create 8; next_id = 0; pending = [] } in
      MR.add_extension st (Trigg r);
      (* A trigger the robot was stopped short of is called back once the path goes on. *)
      MR.on_drain st (fun w ->
          if r.pending <> [] then
            List.iter (fun pd -> if not pd.armed then arm (MR.planner st) r w pd) r.pending);
      r

(* ------------------------------------------------------------------ defining a trigger *)

let ( let* ) = Result.bind

(* Distances and times are not negative (ABB gives them as positive values; R-4.1-trigg4). *)
let not_negative = function
  | Some d when d >= 0. && Float.is_finite d -> Ok d
  | _ -> Error "ERR_ARGVALERR"

let finite = function Some d when Float.is_finite d -> Ok d | _ -> Error "ERR_ARGVALERR"

let not_modelled = "not modelled"

(* The output of TriggIO and TriggEquip, \DOp, \GOp or \AOp, and the value it is set to
   (SetValue, a num or a dnum): a digital value 0 or 1, a group value a whole number of 32
   bits at most (ERR_GO_LIM), an analog value a num (ERR_AO_LIM; R-4.1-trigg4). \ProcID is
   not for the user's programs (ABB) and is not modelled. *)
let output ctx args =
  let kind =
    if present ctx args "DOp" then Some "DOp" else if present ctx args "GOp" then Some "GOp"
    else if present ctx args "AOp" then Some "AOp" else None in
  match kind, num ctx args "SetValue" with
  | None, _ when present ctx args "ProcID" -> Error not_modelled
  | None, _ | _, None -> Error "ERR_ARGVALERR"
  | Some k, Some v ->
      let* id = Io_routines.signal ctx args k in
      match k with
      | "DOp" -> if v = 0. || v = 1. then Ok (id, v) else Error "ERR_ARGVALERR"
      | "GOp" -> if Float.is_integer v && v >= 0. && v < 4294967296. then Ok (id, v) else Error "ERR_GO_LIM"
      | _ -> let a = V.num_value (V.num v) in if Float.is_finite a then Ok (id, a) else Error "ERR_AO_LIM"

let inhib ctx args = match arg ctx args "Inhib" with Location (box, i, _) -> Some (box, i) | _ -> None

(* The definition goes into the triggdata variable: a handle of its own, kept when it is
   defined again (TriggIO in a loop). *)
let define ctx st args = function
  | Error e when e = not_modelled -> Not_modelled
  | Error e -> Failed e
  | Ok def -> (
      match arg ctx args "TriggData" with
      | Location (box, i, _) ->
          let r = run_of st in
          let h = match box.(i) with
            | V.Handle h when Handles.mem r.defs h -> h
            | _ ->
                r.next_id <- r.next_id + 1;
                let h = V.make_handle ~kind:"triggdata" r.next_id in
                box.(i) <- V.Handle h; h in
          Handles.replace r.defs h def;
          Returned None
      | _ -> Failed "ERR_ARGVALERR")

(* TriggIO (ABB): an output set at Distance mm from the end point (\Start: the start point),
   or Distance s before the end point (\Time), \DODelay s later (not with \Time). *)
let trigg_io ctx args =
  let* distance = not_negative (num ctx args "Distance") in
  let time = present ctx args "Time" in
  let* delay = match num ctx args "DODelay" with None -> Ok 0. | d -> not_negative d in
  let* signal, value = output ctx args in
  Ok { distance; from_start = present ctx args "Start"; time; shift = (if time then 0. else delay);
       inhib = None; action = Set_output { signal; value } }

(* TriggEquip (ABB): as TriggIO at a distance, EquipLag s earlier (negative: later), to make up
   for the equipment's lag; with \Inhib TRUE then, the output is set to 0. *)
let trigg_equip ctx args =
  let* distance = not_negative (num ctx args "Distance") in
  let* lag = finite (num ctx args "EquipLag") in
  let* signal, value = output ctx args in
  Ok { distance; from_start = present ctx args "Start"; time = false; shift = -. lag; inhib = inhib ctx args;
       action = Set_output { signal; value } }

(* TriggInt (ABB): the interrupt Interrupt occurs at the position; TriggInt activates it, as an
   order does (IWatch's rule): a number not connected is ERR_UNKINO (R-4.1-trigg3). *)
let trigg_int ctx args =
  let* distance = not_negative (num ctx args "Distance") in
  let* n = match num ctx args "Interrupt" with
    | Some n when Float.is_integer n -> Ok (int_of_float n) | _ -> Error "ERR_UNKINO" in
  let* () = W.watch ctx.world n in
  Ok { distance; from_start = present ctx args "Start"; time = present ctx args "Time"; shift = 0.;
       inhib = None; action = Occur n }

(* TriggSpeed (ABB): from the position, ScaleLag s earlier, the analog output AOp is ScaleValue
   times the TCP speed (mm/s); with \Inhib TRUE then, 0. The model sets the value at that
   moment only (R-4.1-trigg5). *)
let trigg_speed ctx args =
  let* distance = not_negative (num ctx args "Distance") in
  let* lag = finite (num ctx args "ScaleLag") in
  let* signal = Io_routines.signal ctx args "AOp" in
  let* scale = finite (num ctx args "ScaleValue") in
  let* dip_lag = match num ctx args "DipLag" with None -> Ok 0. | d -> not_negative d in
  let* () = match arg ctx args "ErrDO" with
    | Missing -> Ok ()
    | _ -> Result.map ignore (Io_routines.signal ctx args "ErrDO") in
  Ok { distance; from_start = present ctx args "Start"; time = false; shift = -. lag; inhib = inhib ctx args;
       action = Speed_output { signal; scale; dip_lag } }

(* ------------------------------------------------------------------ the moves *)

let no_effects = { MR.at_move = false; new_move = None; first_poll = None }

let triggers = [ "Trigg_1"; "T2"; "T3"; "T4"; "T5"; "T6"; "T7"; "T8" ]

(* The triggdata arguments' definitions, in their order; one no instruction defined sets
   nothing (R-4.1-trigg2). *)
let definitions ctx r args =
  List.filter_map (fun name ->
      match arg ctx args name with
      | Location (box, i, _) -> (match box.(i) with V.Handle h -> Handles.find_opt r.defs h | _ -> None)
      | _ -> None) triggers

(* TriggL (ABB): ERR_AO_LIM when a TriggSpeed's ScaleValue with the programmed speed is out of
   the analog output's limits, ERR_DIPLAG_LIM when its DipLag is beyond the Event Preset Time;
   both before the move is planned. The model's analog outputs have no limits but num's range,
   and its Event Preset Time is the look-ahead horizon (R-4.1-trigg5). *)
let check_speed ctx args planner defs =
  let v_tcp = match arg ctx args "Speed" with
    | Value v -> (try V.num_value (V.components v).(0) with _ -> 0.)
    | _ -> 0. in
  List.fold_left (fun acc d ->
      match acc, d.action with
      | Ok (), Speed_output { scale; dip_lag; _ } ->
          if not (Float.is_finite (V.num_value (V.num (scale *. v_tcp)))) then Error "ERR_AO_LIM"
          else if dip_lag > (P.settings planner).look_ahead +. 1e-9 then Error "ERR_DIPLAG_LIM"
          else Ok ()
      | _ -> acc) (Ok ()) defs

let fire planner id d =
  let speed = P.segment_speed planner id in
  let inhibited () = match d.inhib with Some (box, i) -> (try V.bool_value box.(i) with _ -> false) | None -> false in
  fun w ->
    match d.action with
    | Set_output { signal; value } -> W.write w signal (if inhibited () then 0. else value)
    | Occur n -> W.interrupt w n
    | Speed_output { signal; scale; _ } ->
        let v = if inhibited () then 0. else V.num_value (V.num (scale *. speed)) in
        if Float.is_finite v then W.write w signal v

(* Each trigger of the move just planned becomes a timed event at its position (law
   T-distance): Distance from the end point, or from the start point with \Start, or Distance
   s before the end point with \Time; a distance beyond the move's length is its start (end)
   point (R-4.1-trigg1). *)
let set_triggers ctx st r id defs =
  let planner = MR.planner st in
  List.iter (fun d ->
      let mark =
        if d.time then P.mark ~from_end:true ~shift:(d.shift -. d.distance) planner id 0.
        else P.mark ~from_end:(not d.from_start) ~shift:d.shift planner id d.distance in
      let pd = { mark; fire = fire planner id d; armed = false; generation = 0 } in
      r.pending <- r.pending @ [ pd ];
      arm planner r ctx.world pd) defs

let trigg_move ctx st name args =
  if not (W.motion_task ctx.world) then Some (Failed "ERR_NOT_MOVETASK", no_effects)
  else
    let r = run_of st in
    let defs = definitions ctx r args in
    match check_speed ctx args (MR.planner st) defs with
    | Error e -> Some (Failed e, no_effects)
    | Ok () ->
        let answer = MR.call ctx st name args in
        (match answer with
         | Some (_, { MR.new_move = Some id; _ }) when not (MR.retracing st) -> set_triggers ctx st r id defs
         | _ -> ());
        answer

(* ------------------------------------------------------------------ the routines *)

let moves = [ "TriggL"; "TriggJ"; "TriggC" ]
let names = moves @ [ "TriggIO"; "TriggEquip"; "TriggInt"; "TriggSpeed" ]

let modelled name = List.exists (same name) names
let claims _ name = modelled name
let reach name : Installed_routine.reach = if List.exists (same name) moves then Moves else World

let call ~standstill:_ ctx st name args =
  let setup f = Some (define ctx st args (f ctx args), no_effects) in
  match String.lowercase_ascii name with
  | "triggl" | "triggj" | "triggc" -> trigg_move ctx st name args
  | "triggio" -> setup trigg_io
  | "triggequip" -> setup trigg_equip
  | "triggint" -> setup trigg_int
  | "triggspeed" -> setup trigg_speed
  | _ -> None
