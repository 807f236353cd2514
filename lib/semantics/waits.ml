(* Interrupts, time and waits (ch. 8, doc/controller.md): the interrupts served at the points of
   response, the statement time and the time limit, and the waiting instructions one step at a
   time. Why a module of its own: waits.mli. *)

open Configuration
open Store
open Event
open Outcome
module V = Value

(* ch. 8: an interrupt is served at the entry of the next statement, after the last statement
   of a statement list, and during waits; never at trap level, where it stays queued until the
   trap ends. The trap runs as a routine called from the point of interruption, with INTNO set
   to the interrupt's number (ch. 12). *)
let serve_interrupt cfg =
  if cfg.act.trap_level then None
  else
    let taken = match cfg.held with
      | Some _ as h -> cfg.held <- None; h   (* taken by settling, which stopped here *)
      | None -> cfg.host.take_interrupt () in
    match taken with
    | None -> None
    | Some (number, trap) ->
        let r = cfg.program.routines.(trap) in
        set cfg.globals.(cfg.program.intno) (V.num (float_of_int number));
        let slots = Array.init r.locals (fun _ -> fresh_loc (V.Bool false)) in
        let act = { (activation ~routine:r ~slots ~present:[||] ~kinds:[||] ~module_data:[||] ~caller:(Some cfg.act)
                       ~return_to:cfg.stack ~caller_mark:cfg.mark) with trap_level = true } in
        cfg.act <- act;
        cfg.stack <- [ K_local_init (act, r.local_inits); K_seq (r.body, 0); K_routine_end ];
        cfg.mark <- [];
        cfg.focus <- F_next;
        Some (Rule.Interrupt_serve, [ Trap_entered { number; trap = r.name; time = cfg.host.now () };
                                   Routine_entered r.name ])

(* Settling passes through a point of response where no interrupt is to be served; where one is,
   it is taken from the queue and held for the step (interrupt-serve, [serve_interrupt]). *)
let interrupt_taken cfg =
  (not cfg.act.trap_level)
  && (match cfg.host.take_interrupt () with Some i -> cfg.held <- Some i; true | None -> false)

(* Beyond --max-time the run ends (time-limit, wait-time-limit). *)
let time_exhausted cfg rule =
  cfg.focus <- F_done (Outcome.time_limit cfg.host.max_time);
  (rule, [])

(* A waiting instruction, one step at a time (doc/controller.md): interrupts come in; the wait
   ends when its condition holds or its deadline passes; otherwise the clock jumps to the next
   thing that can change anything: a timed event, the deadline, the next poll. With none, nothing
   can ever end the wait: a deadlock. *)
let wait_step cfg ws rest =
  match serve_interrupt cfg with
  | Some r -> r
  | None ->
  match Recovery.serve_async_error cfg with
  | Some r -> r
  | None -> (
      let host = cfg.host in
      let now = host.now () in
      let reached = host.reached in
      let finish timed_out rule =
        cfg.stack <- rest;
        match ws.wait.finish ~timed_out with
        | None -> cfg.focus <- F_next; (rule, [])
        | Some { error = name; at_move = true } ->
            (* §7.4: a \SyncLastMoveInst error at the move instruction the program pointer waits in. *)
            cfg.focus <- F_raise { (error cfg name (region_of_focus_stmt cfg)) with asynchronous = true };
            (rule, [])
        | Some { error = name; at_move = false } -> raise_ cfg name; (rule, [])
      in
      match ws.cond with
      | Some e when reached ws.next_poll ->
          cfg.stack <- K_poll ws :: cfg.stack; cfg.focus <- F_expr e; (Rule.Wait_poll, [])
      | _ when ws.cond = None && ws.wait.satisfied () -> finish false Rule.Wait_done
      | _ when (match ws.wait.deadline with Some d -> reached d | None -> false) -> finish true Rule.Wait_timeout
      | _ -> (
          let candidates = List.filter_map Fun.id
              [ ws.wait.deadline; host.next_event (); (if ws.cond = None then None else Some ws.next_poll) ] in
          match List.sort compare candidates with
          | l when cfg.cooperative ->
              (* ch. 14: another task may end the wait; the scheduler moves the clock when every
                 task waits (doc/semantics.md, "Several tasks"). *)
              cfg.wake <- (match l with t :: _ -> Some t | [] -> None); (Rule.Wait_yield, [])
          | [] ->
              cfg.focus <- F_done (Deadlock
                                     (Printf.sprintf ("deadlock at %g s: the task waits for %s, and nothing can end "
                                                      ^^ "the wait (no stimulus event left, no interrupt to come)")
                                        now ws.wait.what));
              (Rule.Wait_deadlock, [])
          | t :: _ when t > host.max_time -> time_exhausted cfg Rule.Wait_time_limit
          | t :: _ -> host.advance_to t; (Rule.Wait_advance, [])))

(* WaitUntil's condition has its value at a poll: the wait ends, or waits for the next poll. *)
let poll_value cfg (ws : wait_state) rest v =
  match bool_of v with
  | Some true ->
      cfg.stack <- rest;
      (match ws.wait.finish ~timed_out:false with
       | None -> cfg.focus <- F_next
       | Some { error; _ } -> raise_ cfg error);
      (Rule.Wait_poll_true, [])
  | _ ->
      ws.next_poll <- ws.next_poll +. Option.value ws.wait.poll ~default:Rapid_observable.Wait.default_poll_rate;
      cfg.stack <- K_wait ws :: rest; cfg.focus <- F_next; (Rule.Wait_poll_false, [])
