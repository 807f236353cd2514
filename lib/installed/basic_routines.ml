module V = Rapid_runtime.Value
module Arith = Rapid_runtime.Arith
open Primitive

(* The shape of a value, for StrToVal, whose target's type is only known by its value. *)
let rec shape_of_value : V.t -> V.shape = function
  | V.Num _ -> S_num
  | V.Dnum _ -> S_dnum
  | V.Bool _ -> S_bool
  | V.String _ -> S_string
  | V.Record cs -> S_record (Array.map shape_of_value cs)
  | V.Array es -> S_array (Array.length es, if Array.length es = 0 then S_num else shape_of_value es.(0))
  | V.Handle _ -> S_handle "handle"

let value_of = function
  | Value v -> Some v
  | Location (box, i, _) -> Some box.(i)
  | Switch -> Some (V.Bool true)
  | Missing -> None

let first_present args from =
  let rec go i = if i >= Array.length args then None
    else match value_of args.(i) with Some v -> Some v | None -> go (i + 1) in
  go from

let string_arg a = match value_of a with Some (V.String s) -> s | _ -> ""

let result = function Ok v -> Returned (Some v) | Error name -> Failed name

(* Incr, Decr, Add, Clear: num or dnum (their parameters are anytype, doc/rulings.md R-13). *)
let update args f =
  match args.(0) with
  | Location (box, i, _) -> (
      match f box.(i) with
      | Ok v -> box.(i) <- v; Returned None
      | Error name -> Failed name)
  | _ -> Failed "ERR_ARGNOTVAR"

let add_number a b =
  match a, b with
  | V.Num x, (V.Num y | V.Dnum y) -> Arith.check_num (x +. y)
  | V.Dnum x, (V.Num y | V.Dnum y) -> Arith.check_dnum (x +. y)
  | _ -> Error "ERR_ARGVALERR"

let zero_like = function V.Num _ -> Ok (V.num 0.) | V.Dnum _ -> Ok (V.dnum 0.) | _ -> Error "ERR_ARGVALERR"

(* Dim (ch. 11): the number of elements of dimension dimno (1, 2 or 3) of an array. *)
let dim args =
  match value_of args.(0), value_of args.(1) with
  | Some (V.Array elems), Some (V.Num d) ->
      let rec nth a k = match a with
        | V.Array e when k = 1 -> Ok (V.num (float_of_int (Array.length e)))
        | V.Array e when Array.length e > 0 -> nth e.(0) (k - 1)
        | V.Array _ -> Ok (V.num 0.)
        | _ -> Error "ERR_ILLDIM" in
      if Float.is_integer d && d >= 1. && d <= 3. then nth (V.Array elems) (int_of_float d)
      else Error "ERR_ILLDIM"
  | Some _, _ -> Error "ERR_NOTARR"
  | None, _ -> Error "ERR_NOTPRES"

let specials = [
  "TPWrite"; "TPErase"; "ErrWrite"; "Present"; "Dim"; "IsVar"; "IsPers"; "Incr"; "Decr"; "Add";
  "Clear"; "BookErrNo"; "SkipWarn"; "ErrLog"; "Stop"; "Break"; "CallByVar"; "StrToVal";
]

let modelled name =
  List.exists (fun s -> Rapid_typing.Types.same_name s name) specials
  || Library.find name <> None

let call ctx name args =
  match String.lowercase_ascii name with
  | "tpwrite" ->
      (* TPWrite TPText [\Num]|[\Bool]|[\Pos]|[\Orient]|[\Dnum]: the value follows the text. *)
      ctx.output (Text_format.tpwrite (string_arg args.(0)) (first_present args 1));
      Returned None
  | "tperase" -> ctx.erase (); Returned None
  | "errwrite" ->
      let line = String.concat " " (List.filter (( <> ) "") (List.map string_arg
                   (List.filteri (fun i _ -> i >= 2) (Array.to_list args)))) in
      ctx.log line; Returned None
  | "present" -> Returned (Some (V.Bool (args.(0) <> Missing)))
  | "dim" -> result (dim args)
  | "isvar" -> (
      match args.(0) with
      | Location (_, _, Ref_variable) -> Returned (Some (V.Bool true))
      | _ -> Returned (Some (V.Bool false)))
  | "ispers" -> (
      match args.(0) with
      | Location (_, _, Ref_persistent) -> Returned (Some (V.Bool true))
      | _ -> Returned (Some (V.Bool false)))
  | "incr" -> update args (fun v -> add_number v (V.num 1.))
  | "decr" -> update args (fun v -> add_number v (V.num (-1.)))
  | "add" -> (
      match value_of args.(1) with
      | Some d -> update args (fun v -> add_number v d)
      | None -> Failed "ERR_NOTPRES")
  | "clear" -> update args zero_like
  | "bookerrno" -> (
      match args.(0) with
      | Location (box, i, _) -> box.(i) <- V.num (float_of_int (ctx.book_error ())); Returned None
      | _ -> Failed "ERR_ARGNOTVAR")
  | "skipwarn" -> ctx.event_log Skip_warning; Returned None
  | "errlog" -> (
      (* ErrLog ErrorId [\W] | [\I] Argument1 .. Argument5 (§7.5; ABB's RAPID Instructions): an
         entry of the event log with its number and its five texts. *)
      let kind = match args.(1), args.(2) with
        | Switch, _ -> "warning" | _, Switch -> "information" | _ -> "error" in
      match value_of args.(0) with
      | Some (V.Num id) when Float.is_integer id ->
          ctx.event_log (Err_log { id = int_of_float id; kind;
                                   arguments =
                                     List.map string_arg (List.filteri (fun i _ -> i >= 3) (Array.to_list args)) });
          Returned None
      | _ -> Failed "ERR_ARGVALERR")
  | "stop" -> Stop_requested
  (* RobotWare 6's Break (R-2.4-rw6): the program stops at once, as Stop stops it; the
     virtual controller has no path to regain. *)
  | "break" -> Stop_requested
  | "callbyvar" -> (
      match value_of args.(0), value_of args.(1) with
      | Some (V.String n), Some (V.Num k) when Float.is_integer k && k >= 0. ->
          Call_by_name (n ^ string_of_int (int_of_float k))
      | _ -> Failed "ERR_ARGVALERR")
  | "strtoval" -> (
      match value_of args.(0), args.(1) with
      | Some str, Location (box, i, _) -> (
          match Library.str_to_val str (shape_of_value box.(i)) with
          | Some v -> box.(i) <- v; Returned (Some (V.Bool true))
          | None -> Returned (Some (V.Bool false)))
      | _ -> Failed "ERR_ARGVALERR")
  | _ -> (
      match Library.find name with
      | Some f -> result (f (Array.map value_of args))
      | None -> Not_modelled)

(* A function of the library that no special case above takes: its body is the library's, on
   the arguments' values, and a registry entry may call it without the name dispatch. *)
let special name = List.exists (fun s -> Rapid_typing.Types.same_name s name) specials

let pure_values name = if special name then None else Library.find name
let pure_fixed name = if special name then None else Library.find_fixed name

let pure name = Option.map (fun f args -> result (f (Array.map value_of args))) (pure_values name)
