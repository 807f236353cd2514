module W = Rapid_controller.World
module V = Value
module MR = Motion_routines

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

let make w motion : Host.t =
  let registry = Registry.create w motion in
  let booked = ref 0 in
  {
    routine = Registry.find registry;
    book_error = (fun () -> incr booked; 2000 + !booked);
    booked = (fun n -> n > 2000 && n <= 2000 + !booked);
    now = (fun () -> W.now w);
    max_time = W.max_time w;
    reached = (fun t -> W.seconds (W.now w) >= W.seconds t);
    statement = (fun () -> W.statement w);
    statement_within = (fun () -> W.statement_within w);
    statements = (fun n -> W.statements w n);
    statements_left = (fun () -> W.statements_left w);
    next_event = (fun () -> W.next_event w);
    advance_to = (fun t -> W.advance_to w t);
    every_task_waits = W.every_task_waits w;
    collisions = W.collisions w <> [];
    read_signal = read_signal w;
    write_signal = write_signal w;
    connect = (fun ~trap -> W.connect w ~trap);
    connected = (fun n -> W.connected w n);
    take_interrupt = (fun () -> W.take w);
    observations = (fun () -> W.drain w);
    motion_events = (fun () -> MR.drain motion w);
    motion_finish = (fun () -> MR.finish motion);
    motion_error = (fun () ->
        Option.map (fun (error, move, handled) -> { Host.error; move; handled }) (MR.take_org_error motion));
    set_backward = MR.set_backward motion;
    wait_abandoned = (fun wait ->
        W.host_wait_end w; Rmq_routines.wait_abandoned w wait; Egm_routines.wait_abandoned motion wait;
        MR.wait_abandoned motion wait ~now:(W.now w));
    prepare = MR.robot_data motion;
  }
