(* The interface of the bodies of installed routines inside lib/installed: the context a body
   is given (the world of its task, where its events go) and what it returns. The registry
   turns it into the engines' {!Rapid_runtime.Installed_routine}. *)

module V = Rapid_runtime.Value

type argument = Rapid_runtime.Argument.t =
  | Value of V.t
  | Location of V.t array * int * Rapid_runtime.Ir.reference_kind
  | Switch
  | Missing

type log_entry = Rapid_runtime.Event.log_entry =
  | Err_log of { id : int; kind : string; arguments : string list }
  | Skip_warning

type context = {
  output : string -> unit;
  erase : unit -> unit;
  log : string -> unit;
  event_log : log_entry -> unit;
  mutable book_error : unit -> int;
  mutable error_number : string -> int;
  world : Rapid_controller.World.t;
  mutable parameters : string array;
  mutable argument_label : string -> string option;
}

type outcome =
  | Returned of V.t option
  | Failed of string
  | Call_by_name of string
  | Stop_requested
  | Exit_cycle_requested
  | Not_modelled
  | Wait of Rapid_controller.World.wait
  | Retry_requested
  | Assertion_failed of string
  | Unanswered of string

(* The argument of the parameter of this name (letter case aside, §2.3): installed routines
   whose behaviour lives outside this module find their arguments by name. *)
(* A move asks for a dozen arguments by name, each a literal of this library: the index found
   is kept by the parameters' array and the name, both physically (an engine gives one array per
   routine), so the next move finds it without comparing names. A miss only computes it again. *)
let index_slots = 128
let slot_parameters : string array array = Array.make index_slots [||]
let slot_names = Array.make index_slots ""
let slot_index = Array.make index_slots (-1)

(* Two ways: a name is kept in its slot or the next one, the newer in its own. *)
let parameter_index (parameters : string array) name =
  let n = String.length name in
  let code i = Char.code (String.unsafe_get name i) in
  let h = if n = 0 then 0
    else (n * 31 + 5 * code 0 + 3 * code (n - 1) + 17 * code (n / 2)) land (index_slots - 1) in
  let h' = (h + 1) land (index_slots - 1) in
  if Array.unsafe_get slot_parameters h == parameters && Array.unsafe_get slot_names h == name then
    Array.unsafe_get slot_index h
  else if Array.unsafe_get slot_parameters h' == parameters && Array.unsafe_get slot_names h' == name then
    Array.unsafe_get slot_index h'
  else begin
    let rec find i =
      if i >= Array.length parameters then -1
      else if Rapid_typing.Types.same_name parameters.(i) name then i
      else find (i + 1) in
    let i = find 0 in
    slot_parameters.(h') <- slot_parameters.(h); slot_names.(h') <- slot_names.(h); slot_index.(h') <- slot_index.(h);
    slot_parameters.(h) <- parameters; slot_names.(h) <- name; slot_index.(h) <- i;
    i
  end

let named_argument (ctx : context) args name =
  let i = parameter_index ctx.parameters name in
  if i < 0 || i >= Array.length args then Missing else args.(i)

let named_present ctx args name = match named_argument ctx args name with Missing -> false | _ -> true

(* The number an argument holds, given by value or by reference. *)
let named_num ctx args name =
  match named_argument ctx args name with
  | Value (V.Num f | V.Dnum f) -> Some f
  | Location (box, i, _) -> (match box.(i) with V.Num f | V.Dnum f -> Some f | _ -> None)
  | _ -> None

(* A VAR, INOUT or PERS argument written: nothing for an argument not passed by reference. *)
let named_store ctx args name v =
  match named_argument ctx args name with Location (box, i, _) -> box.(i) <- v | _ -> ()

