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
let named_argument (ctx : context) args name =
  (* Without lowered copies: a move asks for a dozen arguments by name. *)
  let rec find i =
    if i >= Array.length ctx.parameters || i >= Array.length args then Missing
    else if Rapid_typing.Types.same_name ctx.parameters.(i) name then args.(i)
    else find (i + 1) in
  find 0

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

