module V = Value
module W = Rapid_controller.World
module C = Rapid_controller.Io_config
open Primitive

let same = Rapid_typing.Types.same_name  (* without lowered copies: every call site asks [modelled] *)

let arg = named_argument

let present = named_present

let num = named_num

let store = named_store

(* A signal argument: the identity of the configured signal its object denotes. A signal
   variable of the program that is connected to no signal of the configuration denotes none:
   ERR_NO_ALIASIO_DEF (doc/rulings.md R-8-a). *)
let signal ctx args name =
  match arg ctx args name with
  | Location (box, i, _) -> (
      match box.(i) with
      | V.Handle h when V.handle_id h > 0 && W.signal_kind ctx.world (V.handle_id h) <> None -> Ok (V.handle_id h)
      | _ -> Error "ERR_NO_ALIASIO_DEF")
  | _ -> Error "ERR_NO_ALIASIO_DEF"

let ( let* ) r f = match r with Ok v -> f v | Error name -> Failed name

(* dionum is 0 or 1 (installed-facts.md section 1). *)
let digital = function Some 0. -> Ok 0. | Some 1. -> Ok 1. | _ -> Error "ERR_ARGVALERR"

let duration = function
  | Some t when t >= 0. && Float.is_finite t -> Ok t
  | _ -> Error "ERR_ARGVALERR"

let done_ = Returned None

(* The end of a wait with \MaxTime: without \TimeFlag a timeout raises ERR_WAIT_MAXTIME, with it
   the flag tells (installed-facts.md section 4). *)
let timed_wait ctx args ~what ~satisfied =
  let w = ctx.world in
  let flag = present ctx args "TimeFlag" in
  let* deadline = match num ctx args "MaxTime" with
    | None -> Ok None
    | Some m -> Result.map (fun m -> Some (W.now w +. m)) (duration (Some m)) in
  let finish ~timed_out =
    if flag then (store ctx args "TimeFlag" (V.Bool timed_out); None)
    else if timed_out then Rapid_observable.Wait.error "ERR_WAIT_MAXTIME" else None in
  if satisfied () then (ignore (finish ~timed_out:false); done_)
  else Wait { W.what; satisfied; deadline; finish; poll = None }

(* WaitGI, WaitGO, WaitAI, WaitAO: equal by default, or \NOTEQ, \LT, \GT. *)
let comparison ctx args =
  if present ctx args "NOTEQ" then (( <> ), "not equal to")
  else if present ctx args "LT" then (( < ), "less than")
  else if present ctx args "GT" then (( > ), "greater than")
  else (( = ), "equal to")

let value_text f = if Float.is_integer f then Printf.sprintf "%.0f" f else Printf.sprintf "%g" f

let wait_signal ctx args ~compare_with =
  let* id = signal ctx args "Signal" in
  let w = ctx.world in
  let* target = match compare_with with
    | `Digital -> digital (num ctx args "Value")
    | `Number -> (match num ctx args "Value" with Some v -> Ok v | None -> Error "ERR_ARGVALERR") in
  let op, words = if compare_with = `Digital then (( = ), "equal to") else comparison ctx args in
  let satisfied () = op (W.read w id) target in
  let r =
    timed_wait ctx args ~what:(Printf.sprintf "%s %s %s" (W.signal_name w id) words (value_text target)) ~satisfied in
  (* \ValueAtTimeout: the signal's value when the time ran out. *)
  (match r with
   | Wait wt when present ctx args "ValueAtTimeout" ->
       Wait { wt with finish = (fun ~timed_out ->
           if timed_out then store ctx args "ValueAtTimeout" (V.num (W.read w id));
           wt.finish ~timed_out) }
   | r -> r)

let set_signal ctx id v = W.write ctx.world id v; done_

(* The wall clock: the epoch plus the virtual time. Days to a civil date (proleptic Gregorian). *)
let date_time seconds =
  let total = int_of_float (Float.floor seconds) in
  let days = if total >= 0 then total / 86400 else ((total + 1) / 86400) - 1 in
  let secs = total - (days * 86400) in
  let z = days + 719468 in
  let era = (if z >= 0 then z else z - 146096) / 146097 in
  let doe = z - (era * 146097) in
  let yoe = (doe - (doe / 1460) + (doe / 36524) - (doe / 146096)) / 365 in
  let doy = doe - ((365 * yoe) + (yoe / 4) - (yoe / 100)) in
  let mp = ((5 * doy) + 2) / 153 in
  let d = doy - (((153 * mp) + 2) / 5) + 1 in
  let m = if mp < 10 then mp + 3 else mp - 9 in
  let y = (yoe + (era * 400)) + (if m <= 2 then 1 else 0) in
  (* 1970-01-01 was a Thursday (4). *)
  let wday = ((((days mod 7) + 7) mod 7 + 3) mod 7) + 1 in
  (y, m, d, secs / 3600, secs mod 3600 / 60, secs mod 60, wday)

let wall ctx = date_time (W.epoch ctx.world +. W.now ctx.world)

(* The interrupt number of an intnum argument (VAR, or by value for IDelete). *)
let interrupt ctx args =
  match num ctx args "Interrupt" with
  | Some f when Float.is_integer f && f >= 1. -> Ok (int_of_float f)
  | _ -> Error "ERR_UNKINO"

let single ctx args = present ctx args "Single" || present ctx args "SingleSafe"

(* The end of an order: a new order makes the interrupt safe, or not, by its \SingleSafe
   (R-8-w). *)
let ordered ctx args n = function
  | Ok () -> W.set_safe ctx.world n ~safe:(present ctx args "SingleSafe"); done_
  | Error e -> Failed e

(* A clock object: the handle stored in the variable gets its identity at its first use. *)
let clock ctx args =
  match arg ctx args "Clock" with
  | Location (box, i, _) -> (
      match box.(i) with
      | V.Handle h when V.handle_id h > 0 -> V.handle_id h
      | _ ->
          let id = W.new_clock ctx.world in
          box.(i) <- V.Handle (V.make_handle ~kind:"clock" id); id)
  | _ -> 0

let digital_trigger t ~old ~now =
  match t with
  | 2. -> old <> now
  | t -> now = t && old <> now

(* ISignalAI/AO: the condition on the value (aiotrigg, io.sys), and DeltaValue: an interrupt at a
   change where the condition holds and either did not hold before, or the value moved more than
   DeltaValue (up with \DPos, down with \DNeg) from where it was at the last interrupt
   (R-8-k). *)
let analog_trigger ~condition ~high ~low ~delta ~direction =
  let holds v = match condition with
    | 1 -> v > high | 2 -> v < high | 3 -> v > low | 4 -> v < low
    | 5 -> v >= low && v <= high | 6 -> v < low || v > high | _ -> true in
  let reference = ref None in
  fun ~old ~now ->
    let moved = match !reference with
      | None -> true
      | Some r -> (match direction with
          | `Up -> now -. r > delta | `Down -> r -. now > delta | `Any -> Float.abs (now -. r) > delta) in
    let fire = holds now && (not (holds old) || moved) in
    if fire then reference := Some now;
    fire

(* The text lines of an ErrWrite entry: the header, the reason and up to three more lines. *)
let err_write_datum ctx args =
  let text name = match arg ctx args name with Value (V.String s) -> Some s | _ -> None in
  let error_type, id =
    if present ctx args "W" then (2, 2) else if present ctx args "I" then (1, 3) else (3, 1) in
  { W.domain = 8; id; error_type;
    strings = List.filter_map text [ "Header"; "Reason"; "RL2"; "RL3"; "RL4" ] }

let names = [
  "WaitTime"; "WaitUntil"; "WaitDI"; "WaitDO"; "WaitGI"; "WaitGO"; "WaitAI"; "WaitAO";
  "SetDO"; "Set"; "Reset"; "InvertDO"; "PulseDO"; "SetAO"; "SetGO";
  "DInput"; "DOutput"; "AInput"; "AOutput"; "GInput"; "GOutput"; "GInputDnum"; "GOutputDnum";
  "TestDI"; "TestAndSet"; "WaitTestAndSet"; "AliasIO";
  "IDelete"; "IDisable"; "IEnable"; "ISleep"; "IWatch"; "ITimer"; "ISignalDI"; "ISignalDO";
  "ISignalGI"; "ISignalGO"; "ISignalAI"; "ISignalAO"; "IPers"; "IError"; "GetTrapData"; "ReadErrData";
  "ClkReset"; "ClkStart"; "ClkStop"; "ClkRead"; "CDate"; "CTime"; "GetTime";
]

let modelled name = List.exists (same name) names

let call (ctx : context) name args =
  let w = ctx.world in
  let value f = Returned (Some (V.num f)) in
  match String.lowercase_ascii name with
  | "waittime" ->
      (* WaitTime \InPos is Motion_routines', which is called first (R-8-n). *)
      Some (let* t = duration (num ctx args "Time") in
            Wait { W.what = "time"; satisfied = (fun () -> false); deadline = Some (W.now w +. t);
                   finish = (fun ~timed_out:_ -> None); poll = None })
  | "waituntil" ->
      Some (match arg ctx args "Cond" with
          | Value (V.Bool true) -> ignore (timed_wait ctx args ~what:"" ~satisfied:(fun () -> true)); done_
          | _ -> (
              let rate = Option.value (num ctx args "PollRate") ~default:W.default_poll_rate in
              (* A shorter poll is the minimum (R-8-waits1): a wait polls at most 25 times a
                 virtual second. *)
              let rate = if rate > 0. then Float.max rate W.min_poll_rate else rate in
              if not (rate > 0.) || not (Float.is_finite rate) then Failed "ERR_ARGVALERR"
              else match timed_wait ctx args ~what:"a condition" ~satisfied:(fun () -> false) with
                | Wait wt -> Wait { wt with poll = Some rate }
                | r -> r))
  | "waitdi" | "waitdo" -> Some (wait_signal ctx args ~compare_with:`Digital)
  | "waitgi" | "waitgo" | "waitai" | "waitao" -> Some (wait_signal ctx args ~compare_with:`Number)
  | "setdo" ->
      Some (let* id = signal ctx args "Signal" in
            let* v = digital (num ctx args "Value") in
            match num ctx args "SDelay" with
            | Some d ->
                (* \SDelay: the change happens later; execution goes on at once. *)
                let* d = duration (Some d) in
                W.write_later w id v ~delay:d; done_
            | None -> set_signal ctx id v)
  | "set" -> Some (let* id = signal ctx args "Signal" in set_signal ctx id 1.)
  | "reset" -> Some (let* id = signal ctx args "Signal" in set_signal ctx id 0.)
  | "invertdo" -> Some (let* id = signal ctx args "Signal" in set_signal ctx id (if W.read w id = 0. then 1. else 0.))
  | "pulsedo" ->
      Some (let* id = signal ctx args "Signal" in
            let* length = match num ctx args "PLength" with
              | None -> Ok 0.2
              | Some l when l >= 0.001 && l <= 2000. -> Ok l
              | Some _ -> Error "ERR_ARGVALERR" in
            (* A pulse inverts the signal for PLength (a high signal gets a low pulse); with
               \High it is high for PLength and then low, whatever it was (R-8-d). *)
            let during, after =
              if present ctx args "High" then (1., 0.)
              else if W.read w id = 0. then (1., 0.) else (0., 1.) in
            W.write w id during; W.write_later w id after ~delay:length; done_)
  | "setao" ->
      Some (let* id = signal ctx args "Signal" in
            match num ctx args "Value" with
            | Some v -> set_signal ctx id (V.num_value (V.num v)) | None -> Failed "ERR_ARGVALERR")
  | "setgo" ->
      Some (let* id = signal ctx args "Signal" in
            match num ctx args "Value" with
            | Some v when Float.is_integer v && v >= 0. -> set_signal ctx id v
            | _ -> Failed "ERR_ARGVALERR")
  | "dinput" | "doutput" | "ainput" | "aoutput" | "ginput" | "goutput" ->
      Some (let* id = signal ctx args "Signal" in value (W.read w id))
  | "ginputdnum" | "goutputdnum" -> Some (let* id = signal ctx args "Signal" in Returned (Some (V.dnum (W.read w id))))
  | "testdi" -> Some (let* id = signal ctx args "Signal" in Returned (Some (V.Bool (W.read w id = 1.))))
  | "testandset" | "waittestandset" -> (
      (* Tasks take turns of whole statements: no other task comes between the test and the set. *)
      match arg ctx args "Object" with
      | Location (box, i, _) ->
          let was = box.(i) = V.Bool true in
          if was && same name "WaitTestAndSet" then
            Some (Wait { W.what = "a semaphore set by nobody else"; satisfied = (fun () -> box.(i) = V.Bool false);
                         deadline = None; poll = None;
                         finish = (fun ~timed_out:_ -> box.(i) <- V.Bool true; None) })
          else begin
            box.(i) <- V.Bool true;
            Some (if same name "TestAndSet" then Returned (Some (V.Bool (not was))) else done_)
          end
      | _ -> Some (Failed "ERR_ARGNOTVAR"))
  | "idelete" ->
      (* A number that is not connected has nothing to delete: programs guard a CONNECT with an
         IDelete (R-8-f). *)
      (match interrupt ctx args with Ok n -> W.delete w n | Error _ -> ());
      Some done_
  | "idisable" -> W.disable w; Some done_
  | "ienable" -> W.enable w; Some done_
  | "isleep" | "iwatch" ->
      let n = match num ctx args "ino" with Some f when Float.is_integer f -> int_of_float f | _ -> 0 in
      Some (match (if same name "ISleep" then W.sleep else W.watch) w n with Ok () -> done_ | Error e -> Failed e)
  | "itimer" ->
      Some (let* n = interrupt ctx args in
            let* t = match num ctx args "Time" with
              | Some t when t > 0. && Float.is_finite t -> Ok t | _ -> Error "ERR_ARGVALERR" in
            ordered ctx args n (W.order_timer w n ~period:t ~single:(single ctx args)))
  | "isignaldi" | "isignaldo" ->
      Some (let* n = interrupt ctx args in
            let* id = signal ctx args "Signal" in
            let* t = match num ctx args "TriggValue" with
              | Some (0. | 1. | 2. as t) -> Ok t | _ -> Error "ERR_ARGVALERR" in
            ordered ctx args n (W.order_signal w n ~signal:id ~trigger:(digital_trigger t) ~single:(single ctx args)))
  | "isignalgi" | "isignalgo" ->
      (* A group signal interrupts at every change of its value. *)
      Some (let* n = interrupt ctx args in
            let* id = signal ctx args "Signal" in
            ordered ctx args n
              (W.order_signal w n ~signal:id ~trigger:(fun ~old ~now -> old <> now) ~single:(single ctx args)))
  | "isignalai" | "isignalao" ->
      Some (let* n = interrupt ctx args in
            let* id = signal ctx args "Signal" in
            let get k = Option.value (num ctx args k) ~default:0. in
            let condition = int_of_float (get "Condition") in
            let* () = if condition >= 1 && condition <= 7 then Ok () else Error "ERR_ARGVALERR" in
            let direction = if present ctx args "DPos" then `Up else if present ctx args "DNeg" then `Down else `Any in
            let trigger = analog_trigger ~condition ~high:(get "HighValue") ~low:(get "LowValue")
                ~delta:(Float.abs (get "DeltaValue")) ~direction in
            ordered ctx args n (W.order_signal w n ~signal:id ~trigger ~single:(single ctx args)))
  | "ipers" -> (
      (* IPers: an interrupt each time the persistent gets a new value. *)
      match arg ctx args "Name" with
      | Location (box, i, _) ->
          let last = ref (V.copy box.(i)) in
          let changed () =
            if V.equal !last box.(i) then false else (last := V.copy box.(i); true) in
          Some (let* n = interrupt ctx args in
                ordered ctx args n (W.order_watch w n ~changed ~single:(single ctx args)))
      | _ -> Some (Failed "ERR_ARGNOTPER"))
  | "ierror" ->
      Some (let* n = interrupt ctx args in
            let int_of name = Option.map int_of_float (num ctx args name) in
            ordered ctx args n (W.order_error w n ~domain:(Option.value (int_of "ErrorDomain") ~default:0)
                    ~id:(int_of "ErrorId") ~error_type:(Option.value (int_of "ErrorType") ~default:0)))
  | "errwrite" ->
      (* The entry goes to the event log, where IError sees it (R-8-l): written first, so that
         the interrupts it makes occur come after it. *)
      let r = Basic_routines.call ctx name args in
      W.post_error w (err_write_datum ctx args); Some r
  | "gettrapdata" ->
      store ctx args "TrapEvent" (V.Handle (V.make_handle ~kind:"trapdata" (W.trap_data w)));
      Some done_
  | "readerrdata" -> (
      match arg ctx args "TrapEvent" with
      | Location (box, i, _) -> (
          let datum = match box.(i) with V.Handle h -> W.error_datum w (V.handle_id h) | _ -> None in
          match datum with
          | None -> Some (Failed "ERR_ARGVALERR")
          | Some d ->
              store ctx args "ErrorDomain" (V.num (float_of_int d.domain));
              store ctx args "ErrorId" (V.num (float_of_int d.id));
              store ctx args "ErrorType" (V.num (float_of_int d.error_type));
              (* \Title: the entry's title, which for ErrWrite is its header (R-8-y). *)
              (match d.strings with title :: _ -> store ctx args "Title" (V.String title) | [] -> ());
              List.iteri (fun k s -> store ctx args (Printf.sprintf "Str%d" (k + 1)) (V.String s)) d.strings;
              Some done_)
      | _ -> Some (Failed "ERR_ARGVALERR"))
  | "aliasio" -> (
      (* AliasIO: the program's signal variable denotes the configured signal named by a signal
         object or a string, of the same kind (ERR_ALIASIO_DEF, ERR_ALIASIO_TYPE). *)
      (* FromSignal is a value parameter (io.sys), so that a string literal names a signal too. *)
      let given = match arg ctx args "FromSignal" with
        | Value v -> Some v | Location (box, i, _) -> Some box.(i) | Switch | Missing -> None in
      let from = match given with
        | Some (V.String name) -> W.find_signal w name
        | Some (V.Handle h) when W.signal_kind w (V.handle_id h) <> None -> Some (V.handle_id h)
        | _ -> None in
      match from, arg ctx args "ToSignal" with
      | None, _ -> Some (Failed "ERR_ALIASIO_DEF")
      | Some id, Location (box, i, _) -> (
          match box.(i), W.signal_kind w id with
          | V.Handle h, Some kind when V.handle_kind h = C.type_name kind ->
              box.(i) <- V.Handle (V.make_handle ~kind:(V.handle_kind h) id); Some done_
          | _ -> Some (Failed "ERR_ALIASIO_TYPE"))
      | Some _, _ -> Some (Failed "ERR_ALIASIO_TYPE"))
  | "clkreset" -> W.clock_reset w (clock ctx args); Some done_
  | "clkstart" -> W.clock_start w (clock ctx args); Some done_
  | "clkstop" -> W.clock_stop w (clock ctx args); Some done_
  | "clkread" ->
      (* Milliseconds, or microseconds with \HighRes. *)
      let t = W.clock_read w (clock ctx args) in
      let t = if present ctx args "HighRes" then Float.round (t *. 1e6) /. 1e6 else Float.round (t *. 1e3) /. 1e3 in
      Some (value t)
  | "cdate" ->
      let y, m, d, _, _, _, _ = wall ctx in Some (Returned (Some (V.String (Printf.sprintf "%04d-%02d-%02d" y m d))))
  | "ctime" ->
      let _, _, _, h, mi, s, _ = wall ctx in Some (Returned (Some (V.String (Printf.sprintf "%02d:%02d:%02d" h mi s))))
  | "gettime" ->
      let _, _, _, h, mi, s, wd = wall ctx in
      Some (if present ctx args "WDay" then value (float_of_int wd)
            else if present ctx args "Hour" then value (float_of_int h)
            else if present ctx args "Min" then value (float_of_int mi)
            else if present ctx args "Sec" then value (float_of_int s)
            else Failed "ERR_ARGVALERR")
  | _ -> None
