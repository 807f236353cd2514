(* Which module gives a routine its body, in one place: a name may be claimed by several, the
   first that answers gives the outcome (WaitTime \InPos is the motion's, WaitTime the
   controller's; ErrWrite the controller's, which logs through Basic_routines). The order is
   that of the dispatch the engines once each wrote by hand. *)

module W = Rapid_controller.World
module IR = Installed_routine

(* A module of bodies: which names it claims (in a task's world), whether its routines reach
   the world or the motion, and its answer ([None]: not this module's after all; the next one
   in the order answers). *)
type body = {
  module_name : string;
  claims : W.t -> string -> bool;
  reach : string -> IR.reach;
  answer : standstill:(unit -> float) -> Primitive.context -> Motion_routines.state -> string ->
    Primitive.argument array -> (Primitive.outcome * Motion_routines.effects) option;
}

let no_effects = { Motion_routines.at_move = false; new_move = None; first_poll = None }

let plain f = fun ~standstill:_ ctx _ name args -> Option.map (fun r -> (r, no_effects)) (f ctx name args)

let same = Rapid_typing.Types.same_name

(* The order in which the modules answer: WaitTime and WaitUntil with \InPos are the motion's
   (R-8-n), without it the controller's; ErrWrite's entry goes to the controller's event log,
   then to Basic_routines' log line; a motion instruction in a task without the robot is
   Task_routines' refusal (R-14-e). One line per module. *)
let bodies = [
  { module_name = "ui"; reach = (fun _ -> World); claims = Ui_routines.claims; answer = plain Ui_routines.call };
  { module_name = "task"; reach = (fun _ -> World);
    claims = (fun w name -> Task_routines.modelled name
                            || ((not (W.motion_task w)) && List.exists (same name) Task_routines.motion_instructions));
    answer = (fun ~standstill ctx _ name args ->
        Option.map (fun r -> (r, no_effects)) (Task_routines.call ~standstill ctx name args)) };
  { module_name = "trigg"; reach = Trigg_routines.reach; claims = Trigg_routines.claims; answer = Trigg_routines.call };
  { module_name = "motion"; reach = (fun name -> if Motion_routines.modelled name then Moves else World);
    claims = (fun _ name -> Motion_routines.modelled name || same name "WaitTime" || same name "WaitUntil");
    answer = (fun ~standstill:_ ctx motion name args -> Motion_routines.call ctx motion name args) };
  { module_name = "io"; reach = (fun _ -> World);
    claims = (fun _ name -> Io_routines.modelled name || same name "ErrWrite");
    answer = plain Io_routines.call };
  { module_name = "service"; reach = (fun _ -> World); claims = (fun _ -> Service_routines.modelled);
    answer = (fun ~standstill ctx _ name args ->
        Option.map (fun r -> (r, no_effects)) (Service_routines.call ~standstill ctx name args)) };
  { module_name = "rmq"; reach = (fun _ -> World); claims = (fun _ -> Rmq_routines.modelled);
    answer = plain Rmq_routines.call };
  { module_name = "egm"; reach = Egm_routines.reach; claims = (fun _ -> Egm_routines.modelled);
    answer = (fun ~standstill:_ ctx motion name args ->
        Option.map (fun r -> (r, no_effects)) (Egm_routines.call ctx motion name args)) };
  { module_name = "system"; reach = (fun _ -> Values); claims = (fun _ -> System_routines.modelled);
    answer = (fun ~standstill:_ ctx motion name args ->
        Option.map (fun r -> (r, no_effects)) (System_routines.call ctx motion name args)) };
  { module_name = "assert"; reach = (fun _ -> Moves); claims = (fun _ -> Assert_routines.modelled);
    answer = (fun ~standstill:_ ctx motion name args ->
        Option.map (fun r -> (r, no_effects)) (Assert_routines.call ctx motion name args)) };
  { module_name = "basic"; reach = (fun _ -> Values); claims = (fun _ -> Basic_routines.modelled);
    answer = (fun ~standstill:_ ctx _ name args -> Some (Basic_routines.call ctx name args, no_effects)) };
]

type t = {
  world : W.t;
  motion : Motion_routines.state;
  entries : (string, IR.entry option) Hashtbl.t;  (* by lower-case name *)
  (* The last names asked, physically (an engine asks by the routine's own name, at every call
     site it compiles): their entries without a lower-case copy and a hash. *)
  last_names : string array;
  last_entries : IR.entry option array;
}

let create world motion =
  { world; motion; entries = Hashtbl.create 64; last_names = Array.make 4 ""; last_entries = Array.make 4 None }

let claimants world name = List.filter (fun b -> b.claims world name) bodies

(* The most any claimant reaches: the motion, the world (the clock, signals, interrupts,
   services, other tasks), or values only. ErrWrite's entry goes to the world's event log too
   (IError, R-8-l). *)
let reach_of claimants name : IR.reach =
  let reaches = List.map (fun b -> b.reach name) claimants in
  if List.mem IR.Moves reaches then Moves else if List.mem IR.World reaches then World else Values

let convert_result (r : Primitive.outcome) (effects : Motion_routines.effects) : IR.result =
  match r with
  | Returned v -> Returned v
  | Failed error -> Failed { error; at_move = effects.at_move }
  | Call_by_name n -> Call_by_name n
  | Stop_requested -> Stop_requested
  | Exit_cycle_requested -> Exit_cycle_requested
  | Not_modelled -> Not_modelled
  | Wait wait -> Wait { wait; first_poll = effects.first_poll }
  | Retry_requested -> Retry_requested
  | Assertion_failed m -> Assertion_failed m
  | Unanswered m -> Unanswered m

let make t name claimants : IR.entry =
  let reach = reach_of claimants name in
  let events = ref [] in
  (* What the world observed so far goes into the events before what the routine does next, so
     that an effect is never seen before its cause (ErrWrite's entry, then the IError interrupt
     it makes occur). A routine that does not reach the world leaves the world's observations
     to the engine. *)
  let drain () =
    if reach <> Values then
      List.iter (fun o -> events := Event.Controller o :: !events) (W.drain t.world) in
  let add e = drain (); events := e :: !events in
  (* One context per entry, its call's part set at each call: a call allocates nothing for it. *)
  let ctx : Primitive.context = {
    output = (fun line -> add (Output (Text_format.display line)));
    erase = (fun () -> add Erase);
    log = (fun line -> add (Log line));
    event_log = (fun entry -> add (Event_log entry));
    book_error = (fun () -> 0);
    error_number = (fun _ -> 0);
    world = t.world;
    parameters = [||];
    argument_label = (fun _ -> None);
  } in
  let standstill () = Rapid_motion_model.Planner.finished_by (Motion_routines.planner t.motion) in
  let pure = match claimants with [ { module_name = "basic"; _ } ] -> Basic_routines.pure name | _ -> None in
  let body args =
    match pure with
    | Some f -> Some (f args, no_effects)
    | None ->
    let rec first = function
      | [] -> None
      | b :: rest -> (match b.answer ~standstill ctx t.motion name args with Some a -> Some a | None -> first rest) in
    first claimants in
  let call (site : IR.context) args : IR.outcome =
    ctx.parameters <- site.parameters;
    ctx.argument_label <- site.argument_label;
    ctx.book_error <- site.book_error;
    ctx.error_number <- site.error_number;
    events := [];
    let result, new_move = match body args with
      | exception Motion_routines.History_exhausted m -> (IR.History_exhausted m, None)
      | None -> (IR.Not_modelled, None)
      | Some (r, effects) -> (convert_result r effects, effects.new_move) in
    drain ();
    let written = match !events with [] -> [] | e -> List.rev e in
    events := [];
    match result, written, new_move with
    | Returned v, [], None -> IR.returned v
    | _ -> { result; events = written; new_move } in
  let call = match pure with
    | Some f -> (fun _ args ->
        match f args with
        | Primitive.Returned v -> IR.returned v
        | r -> { IR.result = convert_result r no_effects; events = []; new_move = None })
    | None -> call in
  let condition = if same name "WaitUntil" then Some "Cond" else None in
  let values, fixed = match claimants with
    | [ { module_name = "basic"; _ } ] -> Basic_routines.pure_values name, Basic_routines.pure_fixed name
    | _ -> None, None in
  { name; reach; condition; call; values; fixed }

let find_key t name =
  let key = String.lowercase_ascii name in
  match Hashtbl.find_opt t.entries key with
  | Some e -> e
  | None ->
      let e = match claimants t.world name with
        | [] -> None
        | cs -> Some (make t name cs) in
      Hashtbl.replace t.entries key e;
      e

let find t name =
  let names = t.last_names in
  if names.(0) == name then t.last_entries.(0)
  else if names.(1) == name then t.last_entries.(1)
  else if names.(2) == name then t.last_entries.(2)
  else if names.(3) == name then t.last_entries.(3)
  else begin
    let e = find_key t name in
    (* an entry once made is the table's for good: the newest first, the oldest dropped *)
    Array.blit names 0 names 1 3; Array.blit t.last_entries 0 t.last_entries 1 3;
    names.(0) <- name; t.last_entries.(0) <- e;
    e
  end
