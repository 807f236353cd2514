(* The system rapid-sem is, and the settings of the motion that its model has no place for
   (doc/rulings.md R-13-sys1 to R-13-sys5). *)

module V = Rapid_runtime.Value
open Primitive

type identity = {
  serial_no : string;
  sw_version : string;
  sw_version_name : string;
  ctrl_id : string;
  lan_ip : string;
  ctrl_lang : string;
  system_name : string;
}

(* R-13-sys1: a virtual controller of RobotWare 7.12, the release of the kernel manual
   (3HAC065039-010 rev. F); texts that say it is rapid-sem where ABB's would name a cabinet. *)
let virtual_controller = {
  serial_no = "rapid-sem-vc";
  sw_version = "7.12.0";
  sw_version_name = "RobotWare 7.12.0";
  ctrl_id = "rapid-sem";
  lan_ip = "127.0.0.1";
  ctrl_lang = "en";
  system_name = "rapid-sem";
}

let same = Rapid_typing.Types.same_name

let names = [
  "GetSysInfo"; "OpMode"; "RobOS"; "DecToHex"; "HexToDec"; "BitSet"; "BitClear"; "BitSetDnum"; "BitClearDnum";
  "MaxRobReorientSpeed"; "SoftAct"; "SoftDeact"; "PathAccLim"; "UIClientExist";
]

let modelled name = List.exists (same name) names

let returned v = Returned (Some v)
let result = function Ok v -> returned v | Error e -> Failed e

(* ------------------------------------------------------------------ the virtual controller *)

(* GetSysInfo: exactly one switch says what is asked (its page gives them as alternatives);
   without one nothing is asked, ERR_ARGVALERR (R-13-sys1). *)
let get_sys_info ctx motion args =
  let id = virtual_controller in
  let answers = [
    ("SerialNo", fun () -> id.serial_no);
    ("SWVersion", fun () -> id.sw_version);
    ("SWVersionName", fun () -> id.sw_version_name);
    ("RobotType", fun () -> (Motion_routines.robot motion).Rapid_motion_model.Robot.name);
    ("CtrlId", fun () -> id.ctrl_id);
    ("LanIp", fun () -> id.lan_ip);
    ("CtrlLang", fun () -> id.ctrl_lang);
    ("SystemName", fun () -> id.system_name);
  ] in
  match List.find_opt (fun (switch, _) -> named_present ctx args switch) answers with
  | Some (_, text) -> returned (V.String (text ()))
  | None -> Failed "ERR_ARGVALERR"

(* OpMode: OP_AUTO (system.sys: 1), the mode in which a program runs with nobody at the pendant;
   RobOS: FALSE, rapid-sem is no robot controller (R-13-sys2). *)
let op_auto = 1.

(* UIClientExist (ABB, RAPID Instructions: is a user device such as the FlexPendant connected):
   FALSE, a run has no FlexPendant and no answers from one (R-13-ui1). *)
let ui_client_exists = false

(* ------------------------------------------------------------------ DecToHex, HexToDec *)

(* R-13-sys3: the range of their pages, 0 .. 9223372036854775807 (7FFFFFFFFFFFFFFF). *)
let largest = Z.of_string "9223372036854775807"

let convert ~digit ~base ~print text =
  let n = String.length text in
  if n = 0 || n > 80 || not (String.for_all digit text) then Error "ERR_ARGVALERR"
  else
    let value = Z.of_string_base base text in
    if Z.gt value largest then Error "ERR_ARGVALERR" else Ok (print value)

let is_decimal = function '0' .. '9' -> true | _ -> false
let is_hex = function '0' .. '9' | 'A' .. 'F' | 'a' .. 'f' -> true | _ -> false

let dec_to_hex text = convert ~digit:is_decimal ~base:10 ~print:(Z.format "%X") text
let hex_to_dec text = convert ~digit:is_hex ~base:16 ~print:Z.to_string text

let string_argument ctx args name =
  match named_argument ctx args name with
  | Value (V.String s) -> Some s
  | Location (box, i, _) -> (match box.(i) with V.String s -> Some s | _ -> None)
  | _ -> None

let text_function f ctx args =
  match string_argument ctx args "Str" with
  | Some s -> result (Result.map (fun t -> V.String t) (f s))
  | None -> Failed "ERR_ARGVALERR"

(* ------------------------------------------------------------------ the bit instructions *)

(* BitSet and BitClear (ABB: "BitData | DnumData, BitPos"): a byte's bits 1..8, a dnum's 1..52,
   by the type of the value the argument holds (R-13-sys4; the errors are R-13-h's).
   BitSetDnum and BitClearDnum, rapid-sem's older names, take a dnum. *)
let bit_update ~set ctx args =
  let data = if Array.length args = 0 then Missing else args.(0) in
  match data, named_argument ctx args "BitPos" with
  | Location (box, i, _), Value position -> (
      let f = match box.(i), set with
        | V.Num _, true -> Some Library.bit_set
        | V.Num _, false -> Some Library.bit_clear
        | V.Dnum _, true -> Some Library.bit_set_dnum
        | V.Dnum _, false -> Some Library.bit_clear_dnum
        | _ -> None in
      match f with
      | None -> Failed "ERR_ARGVALERR"
      | Some f -> (
          match f box.(i) position with
          | Ok v -> box.(i) <- v; Returned None
          | Error e -> Failed e))
  | Location _, _ -> Failed "ERR_NOTPRES"
  | _ -> Failed "ERR_ARGNOTVAR"

(* ------------------------------------------------------------------ the motion's settings *)

(* R-13-sys5: checked as their pages give the ranges, and changing nothing of the motion. *)
let finite x = Float.is_finite x

(* An axis number: an integer (ERR_NOTINTVAL, as positions are, R-13-c) from 1 to 6. *)
let axis_number x =
  if not (finite x && Float.is_integer x) then Error "ERR_NOTINTVAL"
  else if x < 1. || x > 6. then Error "ERR_ARGVALERR"
  else Ok ()

(* \Ramp: a ramp factor in percent, at least 100. *)
let ramp ctx args =
  match named_argument ctx args "Ramp" with
  | Missing -> Ok ()
  | _ -> (
      match named_num ctx args "Ramp" with
      | Some r when finite r && r >= 100. -> Ok ()
      | _ -> Error "ERR_ARGVALERR")

let soft_act ctx args =
  let checked =
    match named_num ctx args "Axis", named_num ctx args "Softness" with
    | Some axis, Some softness -> (
        match axis_number axis with
        | Error e -> Error e
        | Ok () ->
            if finite softness && softness >= 0. && softness <= 100. then ramp ctx args else Error "ERR_ARGVALERR")
    | _ -> Error "ERR_ARGVALERR" in
  match checked with Ok () -> Returned None | Error e -> Failed e

let soft_deact ctx args = match ramp ctx args with Ok () -> Returned None | Error e -> Failed e

(* PathAccLim AccLim [\AccMax] DecelLim [\DecelMax]: a limit switched on needs its value, in
   m/s2, greater than 0; a value given with its limit off is not used. *)
let path_acc_lim ctx args =
  let limit switch value =
    match named_argument ctx args switch with
    | Value (V.Bool false) -> Ok ()
    | Value (V.Bool true) -> (
        match named_num ctx args value with
        | Some a when finite a && a > 0. -> Ok ()
        | _ -> Error "ERR_ARGVALERR")
    | _ -> Error "ERR_ARGVALERR" in
  match limit "AccLim" "AccMax", limit "DecelLim" "DecelMax" with
  | Ok (), Ok () -> Returned None
  | Error e, _ | _, Error e -> Failed e

(* ------------------------------------------------------------------ by name *)

let call ctx motion name args =
  match String.lowercase_ascii name with
  | "getsysinfo" -> Some (get_sys_info ctx motion args)
  | "opmode" -> Some (returned (V.num op_auto))
  | "robos" -> Some (returned (V.Bool false))
  | "uiclientexist" -> Some (returned (V.Bool ui_client_exists))
  | "dectohex" -> Some (text_function dec_to_hex ctx args)
  | "hextodec" -> Some (text_function hex_to_dec ctx args)
  | "bitset" | "bitsetdnum" -> Some (bit_update ~set:true ctx args)
  | "bitclear" | "bitcleardnum" -> Some (bit_update ~set:false ctx args)
  | "maxrobreorientspeed" ->
      let vmax = Rapid_motion_model.Motion_data.vmax (Motion_routines.robot motion) in
      Some (returned (V.num vmax.Rapid_motion_model.Motion_data.v_ori))
  | "softact" -> Some (soft_act ctx args)
  | "softdeact" -> Some (soft_deact ctx args)
  | "pathacclim" -> Some (path_acc_lim ctx args)
  | _ -> None
