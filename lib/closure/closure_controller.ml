(* The controller as the closure engine sees it: the machine's rules for signals and waits
   (doc/controller.md), carried out in one call where the machine takes a step at a time. *)

module W = Rapid_controller.World
module V = Value

let time_limit w =
  Machine.Resource_exhausted (Printf.sprintf "virtual time beyond %g s (the --max-time limit)" (W.max_time w), None)

let is_signal (v : V.t) =
  match v with
  | V.Handle h ->
      let k = V.handle_kind h in
      String.length k > 6 && String.sub k 0 6 = "signal"
  | _ -> false

(* §2.16 *)
let read_signal w (v : V.t) =
  match v with
  | V.Handle h when W.signal_kind w (V.handle_id h) <> None -> Ok (V.num (W.read w (V.handle_id h)))
  | _ -> Error "ERR_NO_ALIASIO_DEF"

let write_signal w (target : V.t) (v : V.t) =
  match target with
  | V.Handle h -> (
      let id = V.handle_id h in
      match W.signal_kind w id, v with
      | None, _ -> Error "ERR_NO_ALIASIO_DEF"
      | Some (DO | DI), V.Num f when f <> 0. && f <> 1. -> Error "ERR_ARGVALERR"
      | Some _, V.Num f -> W.write w id f; Ok ()
      | _ -> Error "")
  | _ -> Error "ERR_NO_ALIASIO_DEF"

let argument_label (program : Ir.program) (callee : Ir.routine) (arguments : Ir.argument array) name =
  let found = ref None in
  Array.iteri (fun i (p : Ir.parameter) ->
      if String.lowercase_ascii p.p_name = String.lowercase_ascii name && i < Array.length arguments then
        match arguments.(i) with
        | Ir.By_value { e = Read (Whole (Global g)); _ } | By_reference (Whole (Global g), _) ->
            found := Some program.globals.(g).g_name
        | By_value { at; _ } -> found := Some (Printf.sprintf "line %d" (Rapid_syntax.Source.start at).line)
        | _ -> ()) callee.parameters;
  !found

type wait_end = Finished of string option | Halted of Machine.outcome

(* The machine's wait-* rules, in the same order at each turn: interrupts and asynchronous errors
   first; then the poll of a WaitUntil condition when its time has come, the wait's own test, the
   deadline; else the clock moves on (wait-advance), or nothing can end the wait
   (wait-deadlock). Each poll, each move of the clock and each yield is a step of the machine:
   [spend] charges it, so that --max-steps bounds a wait as it bounds the machine's (issue 21). *)
let wait ?yield w (wt : W.wait) ~first_poll ~condition ~serve ~observe ~spend =
  let now = W.now w in
  let period = Option.value wt.poll ~default:0. in
  let next_poll = ref (match first_poll with Some t -> Float.max t (now +. period) | None -> now +. period) in
  let finish timed_out = Finished (wt.finish ~timed_out) in
  (* ch. 14: whether this turn (of several tasks) began at this wait's yield and nothing
     happened since: then the turn was the yield alone, which wakes no other task. *)
  let fresh = ref false in
  let rec turn () =
    if serve () then (fresh := false; turn ())
    else
      let now = W.now w in
      let reached t = W.seconds now >= W.seconds t in
      match condition with
      | Some holds when reached !next_poll ->
          spend ();
          fresh := false;
          if holds () then finish false
          else begin
            next_poll := !next_poll +. Option.value wt.poll ~default:W.default_poll_rate;
            turn ()
          end
      | None when wt.satisfied () -> finish false
      | _ when (match wt.deadline with Some d -> reached d | None -> false) -> finish true
      | _ -> (
          let candidates = List.filter_map Fun.id
              [ wt.deadline; W.next_event w; (if condition = None then None else Some !next_poll) ] in
          match List.sort compare candidates, yield with
          | l, Some yield ->
              (* ch. 14: another task may end the wait; the scheduler moves the clock when every
                 task waits (the machine's wait-yield). *)
              spend ();
              yield ~wake:(match l with t :: _ -> Some t | [] -> None) ~what:wt.what ~pure:!fresh;
              fresh := true;
              observe ();
              turn ()
          | [], None ->
              Halted (Machine.Deadlock
                        (Printf.sprintf "deadlock at %g s: the task waits for %s, and nothing can end the wait (no stimulus event left, no interrupt to come)"
                           now wt.what))
          | t :: _, None when t > W.max_time w -> Halted (time_limit w)
          | t :: _, None -> spend (); W.advance_to w t; observe (); turn ())
  in
  turn ()
