(* The FlexPendant's dialogues answered by a scripted operator (--operator, doc/rulings.md
   R-13-ui2). Without a script no body here claims them: they are not modelled (R-13-i). The
   answers come at once, in no virtual time; a dialogue the operator does not answer ("timeout")
   ends as ABB's pages say: at \MaxTime with ERR_TP_MAXTIME, at a break signal with its error,
   or, with \BreakFlag, with the error in the flag and the program going on. *)

module V = Rapid_runtime.Value
module W = Rapid_controller.World
module S = Rapid_controller.Services
module O = Rapid_controller.Operator_script
open Primitive

let same = Rapid_typing.Types.same_name
let arg = named_argument
let present = named_present
let num = named_num
let store = named_store

let names = [
  "TPReadFK"; "TPReadNum"; "UIMsgBox"; "UIMessageBox"; "UINumEntry"; "UINumTune"; "UIAlphaEntry"; "UIListView";
  "UIClientExist";
]

let operator w = S.operator (W.services w)

let claims w name = List.exists (same name) names && operator w <> None

(* The btnres constants and the buttons of each buttondata (lib/typing/installed/ui.sys). *)
let results = [ ("resUnkwn", 0.); ("resOK", 1.); ("resAbort", 2.); ("resRetry", 3.); ("resIgnore", 4.);
                ("resCancel", 5.); ("resYes", 6.); ("resNo", 7.) ]

let res_unknown = 0.

let buttons_of = function
  | 0. -> [ 1. ] | 1. -> [ 2.; 3.; 4. ] | 2. -> [ 1.; 5. ] | 3. -> [ 3.; 5. ] | 4. -> [ 6.; 7. ]
  | 5. -> [ 6.; 7.; 5. ] | _ -> []

let result_name r = match List.find_opt (fun (_, v) -> v = r) results with Some (n, _) -> n | None -> "?"

(* What the operator can choose among: the predefined buttons (\Buttons, default [default]) by
   their btnres, or the texts of \BtnArray by their index. *)
type choice = Results of float list | Labels of string list

let string_elements = function
  | Value (V.Array a) -> Array.to_list (Array.map (function V.String s -> s | _ -> "") a)
  | _ -> []

let choice ctx args ~default =
  if present ctx args "BtnArray" then Labels (string_elements (arg ctx args "BtnArray"))
  else Results (buttons_of (Option.value (num ctx args "Buttons") ~default))

let choice_text = function
  | Results [] -> "no button"
  | Results l -> String.concat ", " (List.map result_name l)
  | Labels l -> String.concat ", " (List.map (Printf.sprintf "%S") (List.filter (( <> ) "") l))

let lower = String.lowercase_ascii

(* The place, from 1, of a text that is not empty in a list of texts. *)
let index_of t l =
  let rec index i = function
    | [] -> None
    | x :: r -> if x <> "" && x = t then Some (float_of_int i) else index (i + 1) r in
  index 1 l

(* The button a token names: a btnres by its name (resYes, or Yes) or number, or a \BtnArray
   label by its index or its text. *)
let button choice (token : O.token) =
  match choice, token with
  | Results l, Name n -> (
      let n = lower n in
      match List.find_opt (fun (name, _) -> lower name = n || lower name = "res" ^ n) results with
      | Some (_, v) when List.mem v l -> Some v
      | _ -> None)
  | Results l, Number (v, _) when List.mem v l -> Some v
  | Labels l, Number (v, _) when Float.is_integer v && v >= 1. && v <= float_of_int (List.length l)
                                 && List.nth l (int_of_float v - 1) <> "" -> Some v
  | Labels l, Text t -> index_of t l
  | _ -> None

(* ------------------------------------------------------------------ breaks *)

(* A break of the dialogue (ABB's pages of the dialogues): \DIBreak or \DOBreak at 1, or
   \PersBoolBreak TRUE, "or already" so when the dialogue begins; with \DIPassive, \DOPassive or
   \PersBoolPassive at 0 or FALSE instead. An unconnected signal is ERR_NO_ALIASIO_DEF. *)
let break_now ctx args : (string option, string) result =
  let signal name passive error =
    match arg ctx args name with
    | Missing -> Ok None
    | Location (box, i, _) -> (
        match box.(i) with
        | V.Handle h when V.handle_id h > 0 && W.signal_kind ctx.world (V.handle_id h) <> None ->
            let on = W.read ctx.world (V.handle_id h) <> 0. in
            Ok (if on <> present ctx args passive then Some error else None)
        | _ -> Error "ERR_NO_ALIASIO_DEF")
    | _ -> Error "ERR_NO_ALIASIO_DEF" in
  let pers () = match arg ctx args "PersBoolBreak" with
    | Location (box, i, _) -> (
        match box.(i) with
        | V.Bool b when b <> present ctx args "PersBoolPassive" -> Some "ERR_TP_PERSBOOLBREAK"
        | _ -> None)
    | _ -> None in
  match signal "DIBreak" "DIPassive" "ERR_TP_DIBREAK" with
  | Error _ as e -> e
  | Ok (Some _ as b) -> Ok b
  | Ok None -> (
      match signal "DOBreak" "DOPassive" "ERR_TP_DOBREAK" with
      | Error _ as e -> e
      | Ok (Some _ as b) -> Ok b
      | Ok None -> Ok (pers ()))

(* The dialogue ends with an error: in \BreakFlag when it is given (the program goes on with
   [value]), else raised. *)
let broken ctx args error ~value =
  if present ctx args "BreakFlag" then begin
    store ctx args "BreakFlag" (V.num (float_of_int (ctx.error_number error)));
    Returned value
  end
  else Failed error

(* \UIActiveSignal: 1 while the dialogue is shown. *)
let active ctx args v =
  match arg ctx args "UIActiveSignal" with
  | Location (box, i, _) -> (
      match box.(i) with
      | V.Handle h when V.handle_id h > 0 && W.signal_kind ctx.world (V.handle_id h) <> None ->
          W.write ctx.world (V.handle_id h) v
      | _ -> ())
  | _ -> ()

(* ------------------------------------------------------------------ a dialogue *)

type reply = Answer of O.answer | No_answer

(* A dialogue: its checks of the arguments first, then the break signals, then the operator's
   answer. [answer] makes the dialogue's outcome of the answer's tokens, or [Error why] when the
   script's answer is not one the dialogue can take; [value] is what a function gives when it
   ends with \BreakFlag; [waits]: a procedure, whose unanswered dialogue waits for \MaxTime or a
   break in virtual time. *)
let dialogue ctx args name ~checks ~value ~waits ~on_end answer =
  let op = Option.get (operator ctx.world) in
  let ( let* ) r f = match r with Ok v -> f v | Error e -> e in
  let* () = Result.map_error (fun e -> Failed e) checks in
  let* deadline = match num ctx args "MaxTime" with
    | None -> Ok None
    | Some t when t >= 0. && Float.is_finite t -> Ok (Some t)
    | Some _ -> Error (Failed "ERR_ARGVALERR") in
  store ctx args "BreakFlag" (V.num 0.);
  let finish_with error = on_end (); broken ctx args error ~value in
  let* first_break = Result.map_error (fun e -> Failed e) (break_now ctx args) in
  match first_break with
  | Some error -> finish_with error
  | None -> (
      let reply = match O.take op ~routine:name with
        | Error why -> Error why
        | Ok { O.tokens = [ Name n ]; _ } when lower n = "timeout" -> Ok No_answer
        | Ok a -> Ok (Answer a) in
      match reply with
      | Error why -> Unanswered why
      | Ok (Answer a) -> (
          match answer a.O.tokens with
          | Ok outcome -> outcome
          | Error why -> Unanswered (Printf.sprintf "%s: the operator's answer %s" (O.place op a) why))
      | Ok No_answer when waits ->
          active ctx args 1.;
          let w = ctx.world in
          let deadline = Option.map (fun t -> W.now w +. t) deadline in
          let last_break = ref None in
          let satisfied () =
            match break_now ctx args with Ok (Some e) -> last_break := Some e; true | _ -> false in
          Wait { W.what = Printf.sprintf "the operator, who does not answer %s" name; satisfied; deadline; poll = None;
                 finish = (fun ~timed_out ->
                     active ctx args 0.;
                     let error = if timed_out then "ERR_TP_MAXTIME" else Option.value !last_break ~default:"" in
                     match finish_with error with
                     | Failed e -> Rapid_observable.Wait.error e
                     | _ -> None) }
      | Ok No_answer -> (
          match deadline with
          | Some _ -> finish_with "ERR_TP_MAXTIME"
          | None ->
              Unanswered
                (Printf.sprintf "the operator does not answer %s, which has no \\MaxTime: it waits for ever" name)))

let number = function [ O.Number (v, _) ] -> Some v | _ -> None

let token_text = function O.Number (_, t) -> t | Name n -> n | Text t -> Printf.sprintf "%S" t

let tokens_text l = String.concat " " (List.map token_text l)

(* A number the pendant's keypad gives for a num: finite once rounded to single precision. *)
let num_answer v = let s = V.to_single v in if Float.is_finite s then Some s else None

(* UINumEntry's and UINumTune's limits (ABB's pages): \MinValue above \MaxValue is ERR_UI_MAXMIN,
   an initial value outside them ERR_UI_INITVALUE, a non-integer one with \AsInteger ERR_UI_NOTINT. *)
let limits ctx args ~init =
  let lo = num ctx args "MinValue" and hi = num ctx args "MaxValue" in
  let outside v = (match lo with Some l -> v < l | None -> false) || (match hi with Some h -> v > h | None -> false) in
  match lo, hi, init with
  | Some l, Some h, _ when l > h -> Error "ERR_UI_MAXMIN"
  | _, _, Some v when outside v -> Error "ERR_UI_INITVALUE"
  | _, _, Some v when present ctx args "AsInteger" && not (Float.is_integer v) -> Error "ERR_UI_NOTINT"
  | _ -> Ok outside

let entered ctx args ~outside tokens =
  match Option.bind (number tokens) num_answer with
  | None -> Error (Printf.sprintf "%s is not a number" (tokens_text tokens))
  | Some v when outside v -> Error (Printf.sprintf "%s is outside \\MinValue..\\MaxValue" (tokens_text tokens))
  | Some v when present ctx args "AsInteger" && not (Float.is_integer v) ->
      Error (Printf.sprintf "%s is not an integer (\\AsInteger)" (tokens_text tokens))
  | Some v -> Ok v

let func v = Returned (Some v)

let not_a_button tokens buttons =
  Error (Printf.sprintf "%s is not a button of the box (%s)" (tokens_text tokens) (choice_text buttons))

let call ctx name args : outcome option =
  let dialogue = dialogue ctx args name in
  let nothing () = () in
  match lower name with
  | "uiclientexist" -> Some (func (V.Bool true))
  | "tpreadfk" | "tpreadnum" ->
      (* The text is written on the operator window, as TPWrite's line (ABB's TPReadFK, TPReadNum). *)
      (match arg ctx args "TPText" with Value (V.String s) -> ctx.output s | _ -> ());
      let answer tokens =
        if lower name = "tpreadnum" then
          Result.map (fun v -> store ctx args "TPAnswer" (V.num v); Returned None)
            (Option.to_result ~none:(Printf.sprintf "%s is not a number" (tokens_text tokens))
               (Option.bind (number tokens) num_answer))
        else
          let keys = List.map (fun k -> match arg ctx args k with Value (V.String s) -> s | _ -> "")
              [ "FK1"; "FK2"; "FK3"; "FK4"; "FK5" ] in
          match button (Labels keys) (List.hd tokens), tokens with
          | Some k, [ _ ] -> store ctx args "TPAnswer" (V.num k); Ok (Returned None)
          | _ -> Error (Printf.sprintf "%s is not one of the function keys (%s)" (tokens_text tokens)
                          (choice_text (Labels keys))) in
      Some (dialogue ~checks:(Ok ()) ~value:None ~waits:true ~on_end:nothing answer)
  | "uimsgbox" ->
      let buttons = choice ctx args ~default:0. in
      let on_end () = store ctx args "Result" (V.num res_unknown) in
      Some (dialogue ~checks:(Ok ()) ~value:None ~waits:true ~on_end (fun tokens ->
          match tokens with
          | [ t ] when button buttons t <> None ->
              store ctx args "Result" (V.num (Option.get (button buttons t))); Ok (Returned None)
          | _ -> not_a_button tokens buttons))
  | "uimessagebox" ->
      let buttons = choice ctx args ~default:0. in
      Some (dialogue ~checks:(Ok ()) ~value:(Some (V.num res_unknown)) ~waits:false ~on_end:nothing (fun tokens ->
          match tokens with
          | [ t ] when button buttons t <> None -> Ok (func (V.num (Option.get (button buttons t))))
          | _ -> not_a_button tokens buttons))
  | "uinumentry" | "uinumtune" ->
      let init = num ctx args "InitValue" in
      let checks = Result.map (fun _ -> ()) (limits ctx args ~init) in
      let outside = Result.value (limits ctx args ~init) ~default:(fun _ -> false) in
      let value = Some (V.num (Option.value init ~default:0.)) in
      Some (dialogue ~checks ~value ~waits:false ~on_end:nothing (fun tokens ->
          Result.map (fun v -> func (V.num v)) (entered ctx args ~outside tokens)))
  | "uialphaentry" ->
      let init = match arg ctx args "InitString" with Value (V.String s) -> s | _ -> "" in
      Some (dialogue ~checks:(Ok ()) ~value:(Some (V.String init)) ~waits:false ~on_end:nothing (fun tokens ->
          match tokens with
          | [ Text s ] when String.length s <= 80 -> Ok (func (V.String s))
          | [ Text _ ] -> Error "is longer than a string's 80 characters (§2.13)"
          | _ -> Error (Printf.sprintf "%s is not a string in double quotes" (tokens_text tokens))))
  | "uilistview" ->
      let items = match arg ctx args "ListItems" with
        | Value (V.Array a) ->
            Array.to_list (Array.map (function V.Record [| _; V.String t |] -> t | _ -> "") a)
        | _ -> [] in
      let buttons = choice ctx args ~default:(-1.) in
      let on_end () = store ctx args "Result" (V.num res_unknown) in
      let item (t : O.token) = match t with
        | Number (v, _) when Float.is_integer v && v >= 1. && v <= float_of_int (List.length items) -> Some v
        | Text s -> index_of s items
        | _ -> None in
      Some (dialogue ~checks:(Ok ()) ~value:(Some (V.num 0.)) ~waits:false ~on_end (fun tokens ->
          let chosen = match tokens with
            | [ t ] -> Option.map (fun i -> (i, match buttons with
                | Results (r :: _) -> r | Labels _ -> 1. | Results [] -> res_unknown)) (item t)
            | [ t; b ] -> (match item t, button buttons b with Some i, Some r -> Some (i, r) | _ -> None)
            | _ -> None in
          match chosen with
          | Some (i, r) -> store ctx args "Result" (V.num r); Ok (func (V.num i))
          | None ->
              Error (Printf.sprintf "%s is not an item of the list (1 to %d) and a button (%s)" (tokens_text tokens)
                       (List.length items) (choice_text buttons))))
  | _ -> None
