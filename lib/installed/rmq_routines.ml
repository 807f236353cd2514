(* The RAPID Message Queue between the tasks of a run (ABB's RMQ routines; doc/rulings.md
   R-14-rmq1 to R-14-rmq5). The queues, the slots and the interrupts are the controller's
   (World); here is what a message carries, with which type, and how a task receives it. *)

module V = Value
module W = Rapid_controller.World
open Primitive

let same = Rapid_typing.Types.same_name

(* What a message carries: a copy of the data sent. *)
type W.rmq_data += Data of V.t

let names = [
  "RMQFindSlot"; "RMQSendMessage"; "RMQSendWait"; "IRMQMessage"; "RMQGetMessage"; "RMQGetMsgHeader";
  "RMQGetMsgData"; "RMQReadWait"; "RMQEmptyQueue"; "RMQGetSlotName";
]

let modelled name = List.exists (same name) names

let ( let* ) r f = match r with Ok v -> f v | Error name -> Failed name

let done_ = Returned None

(* WAIT_MAX (io.sys): ABB's time-out that never comes. *)
let wait_max = 8388608.

(* \TimeOut of RMQSendWait and RMQReadWait (R-14-rmq5): seconds, 60 when absent, 0 for no wait
   at all, WAIT_MAX (or more) for no end; a negative time is ERR_ARGVALERR. *)
let timeout ctx args =
  match named_num ctx args "TimeOut" with
  | None -> Ok (Some 60.)
  | Some t when t >= wait_max -> Ok None
  | Some t when t >= 0. && Float.is_finite t -> Ok (Some t)
  | Some _ -> Error "ERR_ARGVALERR"

(* The value a parameter's argument denotes: the data given by reference, or by value. *)
let value_of ctx args name =
  match named_argument ctx args name with
  | Location (box, i, _) -> Some box.(i)
  | Value v -> Some v
  | Switch | Missing -> None

(* The slot an rmqslot variable holds; its initial value (identity 0) holds none. *)
let slot ctx args name =
  match named_argument ctx args name with
  | Location (box, i, _) -> (
      match box.(i) with V.Handle h when V.handle_id h > 0 -> Some (V.handle_id h) | _ -> None)
  | _ -> None

let slot_value n = V.Handle (V.make_handle ~kind:"rmqslot" n)

(* The sizes of the dimensions of an array, [] for anything else (rmqheader's ndim, dim1..). *)
let rec dims = function
  | V.Array es when Array.length es > 0 -> Array.length es :: dims es.(0)
  | _ -> []

(* ABB's IRMQMessage and RMQSendMessage: data of a non-value or a semi-value type (an object of
   an installed type, a signal) can be neither sent nor waited for. *)
let rec holds_object = function
  | V.Handle _ -> true
  | V.Record cs | V.Array cs -> Array.exists holds_object cs
  | V.Num _ | V.Dnum _ | V.Bool _ | V.String _ -> false

let rec atomic_name = function
  | V.Num _ -> "num"
  | V.Dnum _ -> "dnum"
  | V.Bool _ -> "bool"
  | V.String _ -> "string"
  | V.Array es when Array.length es > 0 -> atomic_name es.(0)
  | V.Array _ | V.Record _ | V.Handle _ -> ""

(* The name of the type of the data given for an anytype parameter (R-14-rmq4): the static type
   the lowering recorded; for a call it did not see (a late-bound one) the value's atomic type,
   and "" for a record. *)
let type_name ctx param v =
  match ctx.argument_label (param ^ ":type") with Some t -> t | None -> atomic_name v

(* The size of a message's data (R-14-rmq1): its bytes written as ValToStr writes them. *)
let size v = String.length (Text_format.value_text v)

(* RMQSendMessage, and the send of RMQSendWait: the message goes to the slot's task at once
   (R-14-rmq2). The slot it went to. *)
let send ctx args =
  let w = ctx.world in
  let user_def = match named_num ctx args "UserDef" with
    | None -> Ok 0
    | Some u when Float.is_integer u && u >= 0. && u <= 32767. -> Ok (int_of_float u)
    | Some _ -> Error "ERR_ARGVALERR" in
  match slot ctx args "Slot", value_of ctx args "SendData", user_def with
  | None, _, _ -> Error "ERR_RMQ_INVALID"
  | _, _, Error e -> Error e
  | _, None, _ -> Error "ERR_RMQ_VALUE"
  | Some _, Some v, _ when holds_object v -> Error "ERR_RMQ_VALUE"
  | Some _, Some v, _ when size v > W.rmq_max_size -> Error "ERR_RMQ_MSGSIZE"
  | Some target, Some v, Ok user_def ->
      let m = { W.sender = W.task_number w; datatype = type_name ctx "SendData" v; dims = dims v; user_def;
                data = Data (V.copy v) } in
      Result.map (fun () -> target) (W.rmq_send w ~slot:target m)

(* A message into an rmqmessage variable, which gives back the one it held (R-14-rmq3). *)
let store_message ctx args name m =
  match named_argument ctx args name with
  | Location (box, i, _) ->
      let into = match box.(i) with V.Handle h when V.handle_id h > 0 -> Some (V.handle_id h) | _ -> None in
      let k = W.rmq_keep ctx.world ?into m in
      box.(i) <- V.Handle (V.make_handle ~kind:"rmqmessage" k)
  | _ -> ()

(* The message an rmqmessage variable holds: none before a message was put in it. *)
let message ctx args =
  match named_argument ctx args "Message" with
  | Location (box, i, _) -> (
      match box.(i) with V.Handle h when V.handle_id h > 0 -> W.rmq_kept ctx.world (V.handle_id h) | _ -> None)
  | _ -> None

(* R-14-rmq2: the first IRMQMessage of a task puts it in interrupt mode, its first RMQReadWait in
   synchronous mode. The messages queued until then are discarded in interrupt mode (which,
   ordering no interrupt for them, would have discarded them as they came) and kept in
   synchronous mode. The routine of the other mode is ERR_RMQ_INVALID (ABB: a fatal error). *)
let enter ctx mode =
  let q = W.rmq ctx.world in
  match q.mode with
  | W.Rmq_unset ->
      q.mode <- mode;
      if mode = W.Rmq_interrupt then Queue.clear q.messages;
      Ok ()
  | m when m = mode -> Ok ()
  | _ -> Error "ERR_RMQ_INVALID"

(* The data of a message fits the receiving variable: the same structure, scalar by scalar (two
   tasks may declare a record of one name differently). *)
let rec fits a b =
  match a, b with
  | V.Num _, V.Num _ | V.Dnum _, V.Dnum _ | V.Bool _, V.Bool _ | V.String _, V.String _ -> true
  | V.Record xs, V.Record ys | V.Array xs, V.Array ys -> Array.length xs = Array.length ys && Array.for_all2 fits xs ys
  | _ -> false

let number ctx args name =
  match named_num ctx args name with Some f when Float.is_integer f && f >= 1. -> Some (int_of_float f) | _ -> None

(* The wait of RMQSendWait, told by its text: left by an error or a long jump (§7.2), it awaits
   no answer any more, so that a later message of that type from that slot is not taken for
   one. *)
let send_wait = "(RMQSendWait)"

let wait_abandoned w (wait : Rapid_observable.Wait.t) =
  let n = String.length wait.what and k = String.length send_wait in
  if n >= k && String.sub wait.what (n - k) k = send_wait then begin
    let q = W.rmq w in
    q.awaiting <- None;
    q.answer <- None
  end

let call ctx name args =
  let w = ctx.world in
  match String.lowercase_ascii name with
  | "rmqfindslot" ->
      (* ABB's RMQFindSlot: ERR_RMQ_NAME for a name that is no slot. *)
      Some (match named_argument ctx args "Name" with
          | Value (V.String s) -> (
              match W.rmq_slot w s with
              | Some n -> named_store ctx args "Slot" (slot_value n); done_
              | None -> Failed "ERR_RMQ_NAME")
          | _ -> Failed "ERR_RMQ_NAME")
  | "rmqsendmessage" -> Some (let* _ = send ctx args in done_)
  | "rmqsendwait" ->
      (* ABB's RMQSendWait: the message is sent as RMQSendMessage sends it, then the task waits for
         the answer of ReceiveDataType's type from the slot it sent to (R-14-rmq5). *)
      Some (let* t = timeout ctx args in
            match value_of ctx args "ReceiveDataType" with
            | Some v when holds_object v -> Failed "ERR_RMQ_VALUE"
            | None -> Failed "ERR_RMQ_VALUE"
            | Some v ->
                let expected = type_name ctx "ReceiveDataType" v in
                let* target = send ctx args in
                let q = W.rmq w in
                q.awaiting <- Some (target, expected);
                q.answer <- None;
                let finish ~timed_out =
                  let answer = q.answer in
                  q.awaiting <- None;
                  q.answer <- None;
                  match answer with
                  | Some m when not timed_out -> store_message ctx args "Message" m; None
                  | _ -> Rapid_observable.Wait.error "ERR_RMQ_TIMEOUT" in
                if t = Some 0. then (q.awaiting <- None; Failed "ERR_RMQ_TIMEOUT")
                else
                  let from = Option.value (W.rmq_slot_name w target) ~default:"?" in
                  Wait { W.what = Printf.sprintf "an answer of type %s from %s %s" expected from send_wait;
                         satisfied = (fun () -> q.answer <> None);
                         deadline = Option.map (fun t -> W.now w +. t) t; poll = None; finish })
  | "irmqmessage" ->
      (* ABB's IRMQMessage: an interrupt for each message of InterruptDataType's type. *)
      Some (match number ctx args "Interrupt", value_of ctx args "InterruptDataType" with
          | None, _ -> Failed "ERR_UNKINO"
          | Some n, _ when not (W.connected w n) -> Failed "ERR_UNKINO"
          | _, None -> Failed "ERR_RMQ_VALUE"
          | _, Some v when holds_object v -> Failed "ERR_RMQ_VALUE"
          | Some n, Some v ->
              let* () = enter ctx W.Rmq_interrupt in
              let* () = W.order_rmq w n ~datatype:(type_name ctx "InterruptDataType" v) in
              W.set_safe w n ~safe:false;
              done_)
  | "rmqgetmessage" ->
      (* ABB's RMQGetMessage: the first message of the task's queue; ERR_RMQ_NOMSG when it has
         none. *)
      Some (match Queue.take_opt (W.rmq w).messages with
          | Some m -> store_message ctx args "Message" m; done_
          | None -> Failed "ERR_RMQ_NOMSG")
  | "rmqreadwait" ->
      (* ABB's RMQReadWait: the first message of the queue, waiting for one (R-14-rmq5). *)
      Some (let* () = enter ctx W.Rmq_synchronous in
            let* t = timeout ctx args in
            let q = W.rmq w in
            let take () = match Queue.take_opt q.messages with
              | Some m -> store_message ctx args "Message" m; None
              | None -> Rapid_observable.Wait.error "ERR_RMQ_TIMEOUT" in
            if not (Queue.is_empty q.messages) then (ignore (take ()); done_)
            else if t = Some 0. then Failed "ERR_RMQ_TIMEOUT"
            else
              Wait { W.what = "a message in its RAPID Message Queue (RMQReadWait)";
                     satisfied = (fun () -> not (Queue.is_empty q.messages));
                     deadline = Option.map (fun t -> W.now w +. t) t; poll = None;
                     finish = (fun ~timed_out ->
                         if timed_out then Rapid_observable.Wait.error "ERR_RMQ_TIMEOUT" else take ()) })
  | "rmqgetmsgheader" ->
      (* ABB's RMQGetMsgHeader: the data type's name, its dimensions (0 for those it has not), the
         sender's slot and \UserDef of the message. *)
      Some (match message ctx args with
          | None -> Failed "ERR_RMQ_INVMSG"
          | Some m ->
              let dim k = V.num (float_of_int (Option.value (List.nth_opt m.dims k) ~default:0)) in
              named_store ctx args "Header"
                (V.Record [| V.String m.datatype; V.num (float_of_int (List.length m.dims));
                             dim 0; dim 1; dim 2; dim 3; dim 4 |]);
              named_store ctx args "SenderId" (slot_value m.sender);
              named_store ctx args "UserDef" (V.num (float_of_int m.user_def));
              done_)
  | "rmqgetmsgdata" ->
      (* ABB's RMQGetMsgData (R-14-rmq4): the data, into a variable of its type: another type is
         ERR_RMQ_VALUE, the same type with other dimensions ERR_RMQ_DIM. *)
      Some (match message ctx args, named_argument ctx args "Data" with
          | Some m, Location (box, i, _) -> (
              let target = box.(i) in
              if not (same (type_name ctx "Data" target) m.datatype) then Failed "ERR_RMQ_VALUE"
              else if dims target <> m.dims then Failed "ERR_RMQ_DIM"
              else match m.data with
                | Data v when fits v target -> box.(i) <- V.copy v; done_
                | _ -> Failed "ERR_RMQ_INVMSG")
          | _ -> Failed "ERR_RMQ_INVMSG")
  | "rmqemptyqueue" -> Queue.clear (W.rmq w).messages; Some done_
  | "rmqgetslotname" ->
      Some (match Option.bind (slot ctx args "Slot") (W.rmq_slot_name w) with
          | Some name -> Returned (Some (V.String name))
          | None -> Failed "ERR_RMQ_INVALID")
  | _ -> None
