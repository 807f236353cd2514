(* The controller as the closure engine sees it: the machine's rules for signals and waits
   (doc/controller.md), carried out in one call where the machine takes a step at a time. *)

module V = Value

let is_signal (v : V.t) =
  match v with
  | V.Handle h ->
      let k = V.handle_kind h in
      String.length k > 6 && String.sub k 0 6 = "signal"
  | _ -> false

type wait_end = Finished of Rapid_observable.Wait.raised option | Halted of Outcome.t

(* The machine's wait-* rules, in the same order at each turn: interrupts and asynchronous errors
   first; then the poll of a WaitUntil condition when its time has come, the wait's own test, the
   deadline; else the clock moves on (wait-advance), or nothing can end the wait
   (wait-deadlock). Each poll, each move of the clock and each yield is a step of the machine:
   [spend] charges it, so that --max-steps bounds a wait as it bounds the machine's (issue 21). *)
let wait ?yield (host : Host.t) (wt : Rapid_observable.Wait.t) ~first_poll ~condition ~serve ~observe ~spend =
  let now = host.now () in
  let next_poll = ref (Rapid_observable.Wait.first_poll wt ~now first_poll) in
  let finish timed_out = Finished (wt.finish ~timed_out) in
  (* ch. 14: whether this turn (of several tasks) began at this wait's yield and nothing
     happened since: then the turn was the yield alone, which wakes no other task. *)
  let fresh = ref false in
  let rec turn () =
    if serve () then (fresh := false; turn ())
    else
      let now = host.now () in
      let reached = host.reached in
      match condition with
      | Some holds when reached !next_poll ->
          spend ();
          fresh := false;
          if holds () then finish false
          else begin
            next_poll := !next_poll +. Option.value wt.poll ~default:Rapid_observable.Wait.default_poll_rate;
            turn ()
          end
      | None when wt.satisfied () -> finish false
      | _ when (match wt.deadline with Some d -> reached d | None -> false) -> finish true
      | _ -> (
          let candidates = List.filter_map Fun.id
              [ wt.deadline; host.next_event (); (if condition = None then None else Some !next_poll) ] in
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
              Halted (Outcome.Deadlock
                        (Printf.sprintf "deadlock at %g s: the task waits for %s, and nothing can end the wait \
                                         (no stimulus event left, no interrupt to come)"
                           now wt.what))
          | t :: _, None when t > host.max_time -> Halted (Outcome.time_limit host.max_time)
          | t :: _, None -> spend (); host.advance_to t; observe (); turn ())
  in
  turn ()
