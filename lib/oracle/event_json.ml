module Source = Rapid_syntax.Source
module Event = Rapid_runtime.Event

let schema = Schema_compat.current

let text s = `String (Rapid_runtime.Utf8_text.of_bytes s)

let region r =
  let p = Source.start r and q = Source.stop r in
  `Assoc [ ("file", text (match Source.file_of r with Some f -> Source.name f | None -> ""));
           ("line", `Int p.line); ("col", `Int p.col); ("end_line", `Int q.line); ("end_col", `Int q.col) ]

let time t = `Intlit (Printf.sprintf "%.6f" t)

(* ------------------------------------------------------------------ motion *)

(* Virtual times to the microsecond, lengths to the micrometre, angles to the microdegree; -0 is
   written 0. *)
let fixed digits x =
  if Float.is_finite x then
    let text = Printf.sprintf "%.*f" digits x in
    if Float.abs x < 0.5 *. (10. ** float_of_int (- digits)) then
      let sign = if x < 0. then 1 else 0 in
      `Intlit (String.sub text sign (String.length text - sign))
    else `Intlit text
  else `Null

let motion_time = fixed 6

let pose (p : Rapid_observable.Pose.t) =
  `Assoc [ ("trans", `List [ fixed 3 p.trans.x; fixed 3 p.trans.y; fixed 3 p.trans.z ]);
           ("rot", `List [ fixed 6 p.rot.q1; fixed 6 p.rot.q2; fixed 6 p.rot.q3; fixed 6 p.rot.q4 ]) ]

let joints q = `List (Array.to_list (Array.map (fixed 4) q))

let motion (e : Rapid_observable.Motion_event.t) : Yojson.Safe.t =
  let time = motion_time in
  match e with
  | Segment_planned { time = t; id; instruction; label; zone; target; joints = q; ready_time; start_time; end_time } ->
      `Assoc [ ("event", `String "move-planned"); ("time", time t); ("move", `Int id);
               ("instruction", `String instruction); ("target", `String label); ("zone", `String zone);
               ("pose", pose target); ("joints", joints q);
               ("start", time start_time); ("end", time end_time); ("ready", time ready_time) ]
  | Segment_started { time = t; id; label } ->
      `Assoc [ ("event", `String "move-started"); ("time", time t); ("move", `Int id); ("target", `String label) ]
  | Segment_ended { time = t; id; label } ->
      `Assoc [ ("event", `String "move-ended"); ("time", time t); ("move", `Int id); ("target", `String label) ]
  | Segment_dropped { time = t; id; label } ->
      `Assoc [ ("event", `String "move-dropped"); ("time", time t); ("move", `Int id); ("target", `String label) ]
  | Path_command { time = t; command } ->
      `Assoc [ ("event", `String "path-command"); ("time", time t); ("command", `String command) ]
  | Motion_warning { time = t; text } ->
      `Assoc [ ("event", `String "motion-warning"); ("time", time t); ("text", `String text) ]

let sample t p q : Yojson.Safe.t =
  `Assoc ([ ("event", `String "tcp-sample"); ("time", motion_time t); ("pose", pose p) ]
          @ (match q with Some q -> [ ("joints", joints q) ] | None -> []))

(* ------------------------------------------------------------------ observations *)

let observation (o : Rapid_runtime.Observation.t) : Yojson.Safe.t =
  let obj kind fields = `Assoc (("event", `String kind) :: fields) in
  match o with
  | Stored { place; value } -> obj "store" [ ("place", text place); ("value", text value) ]
  | Called { routine; arguments } ->
      let argument (p, v) =
        `Assoc (("parameter", text p) :: (match v with Some v -> [ ("value", text v) ] | None -> [])) in
      obj "arguments" [ ("routine", text routine); ("arguments", `List (List.map argument arguments)) ]
  | Returned { routine; value } -> obj "returned" [ ("routine", text routine); ("value", text value) ]
  | Propagated { name; number; routine; caller } ->
      obj "error-propagated"
        [ ("name", text name); ("number", `Int number); ("routine", text routine); ("caller", text caller) ]
  | Retried r -> obj "retry" [ ("routine", text r) ]
  | Tried_next r -> obj "trynext" [ ("routine", text r) ]

(* ------------------------------------------------------------------ events *)

type t = { mutable error_in_flight : int }

let create () = { error_in_flight = 0 }

let note enc (e : Event.t) =
  match e with
  | Error_raised { number; _ } | Observed (Propagated { number; _ }) -> enc.error_in_flight <- number
  | _ -> ()

let event enc (e : Event.t) : Yojson.Safe.t =
  match e with
  | Output s -> `Assoc [ ("event", `String "output"); ("text", text s) ]
  | Erase -> `Assoc [ ("event", `String "erase") ]
  | Log s -> `Assoc [ ("event", `String "log"); ("text", text s) ]
  | Event_log (Err_log { id; kind; arguments }) ->
      `Assoc [ ("event", `String "errlog"); ("id", `Int id); ("kind", `String kind);
               ("arguments", `List (List.map text arguments)) ]
  | Event_log Skip_warning -> `Assoc [ ("event", `String "skipwarn") ]
  | Routine_entered r -> `Assoc [ ("event", `String "routine-entered"); ("routine", text r) ]
  | Routine_left r -> `Assoc [ ("event", `String "routine-left"); ("routine", text r) ]
  | Error_raised { name; number; at } ->
      enc.error_in_flight <- number;
      `Assoc [ ("event", `String "error-raised"); ("name", text name); ("number", `Int number);
               ("at", region at) ]
  | Error_handled { name; routine } ->
      `Assoc [ ("event", `String "error-handled"); ("name", text name); ("number", `Int enc.error_in_flight);
               ("routine", text routine) ]
  | Undo_run r -> `Assoc [ ("event", `String "undo-run"); ("routine", text r) ]
  | Task_ended -> `Assoc [ ("event", `String "task-ended") ]
  | Controller (Signal_changed { time = t; signal; value }) ->
      `Assoc [ ("event", `String "signal-changed"); ("time", time t); ("signal", `String signal);
               ("value", `Float value) ]
  | Controller (Interrupt_occurred { time = t; number }) ->
      `Assoc [ ("event", `String "interrupt-occurred"); ("time", time t); ("number", `Int number) ]
  | Controller (Interrupt_discarded { time = t; number; reason }) ->
      `Assoc [ ("event", `String "interrupt-discarded"); ("time", time t); ("number", `Int number);
               ("reason", `String reason) ]
  | Trap_entered { number; trap; time = t } ->
      `Assoc [ ("event", `String "trap-entered"); ("time", time t); ("number", `Int number);
               ("trap", `String trap) ]
  | Trap_left { trap; time = t } ->
      `Assoc [ ("event", `String "trap-left"); ("time", time t); ("trap", `String trap) ]
  | Stubbed { routine; at } ->
      `Assoc [ ("event", `String "stubbed"); ("routine", `String routine); ("at", region at) ]
  | Motion m -> motion m
  | Observed (Propagated { number; _ } as o) -> enc.error_in_flight <- number; observation o
  | Observed o -> observation o

let with_task name = function
  | `Assoc fields -> `Assoc (List.hd fields :: ("task", `String name) :: List.tl fields)
  | j -> j

(* ------------------------------------------------------------------ call chains *)

let chain_shown = 20

let more_marker k = Printf.sprintf "... %d more ..." k

(* [items] as (text, calls it stands for). *)
let bound_items items =
  let n = List.length items and keep = chain_shown / 2 in
  if n <= chain_shown then List.map fst items
  else
    let part p = List.filteri (fun i _ -> p i) items in
    let left_out = List.fold_left (fun s (_, k) -> s + k) 0 (part (fun i -> i >= keep && i < n - keep)) in
    List.map fst (part (fun i -> i < keep)) @ (more_marker left_out :: List.map fst (part (fun i -> i >= n - keep)))

let chain routines = bound_items (List.map (fun r -> (r, 1)) routines)

let chain_text routines =
  if List.length routines <= chain_shown then String.concat " <- " routines
  else
    let runs = List.fold_left (fun acc name -> match acc with
        | (n, k) :: rest when n = name -> (n, k + 1) :: rest
        | _ -> (name, 1) :: acc) [] routines |> List.rev in
    let item (n, k) = ((if k = 1 then n else Printf.sprintf "%s x%d" n k), k) in
    String.concat " <- " (bound_items (List.map item runs))

(* ------------------------------------------------------------------ start and end *)

let start ?tasks () =
  `Assoc ([ ("event", `String "start"); ("schema", `String schema) ]
          @ match tasks with Some names -> [ ("tasks", `List (List.map (fun n -> `String n) names)) ] | None -> [])

let outcome ?entry_at (o : Rapid_runtime.Outcome.t) steps : Yojson.Safe.t =
  let nowhere = ("at", `Null) in
  let base kind extra =
    let extra = if List.mem_assoc "at" extra then extra else extra @ [ nowhere ] in
    `Assoc ([ ("event", `String "end"); ("outcome", `String kind); ("steps", `Int steps) ] @ extra) in
  match o with
  | Running -> base "running" []
  | Ended -> base "ended" (match entry_at with Some r -> [ ("at", region r) ] | None -> [])
  | Stopped { name; number; at; chain = routines; about } ->
      base "stopped" ([ ("name", text name); ("number", `Int number); ("at", region at);
                        ("chain", `List (List.map text (chain routines))) ]
                      @ (match about with Some a -> [ ("about", text a) ] | None -> []))
  | Resource_exhausted (m, at) ->
      (* At the declaration or the move beyond the memory budget; no place explains a limit of
         depth or time (R-1.4-small2). *)
      base "exhausted" ([ ("reason", text m) ] @ (match at with Some r -> [ ("at", region r) ] | None -> []))
  | Unsupported { name; reason; at } ->
      base "unsupported" [ ("name", text name); ("reason", text reason); ("at", region at) ]
  | Stuck m -> base "stuck" [ ("reason", text m) ]
  | Deadlock m -> base "deadlock" [ ("reason", text m) ]

let task_end name o steps =
  match outcome o steps with
  | `Assoc (_ :: rest) -> `Assoc (("event", `String "task-end") :: ("task", `String name) :: rest)
  | j -> j

type cell_task = {
  name : string; kind : string; entry : string; motion : bool; robot : string option; robot_type : string option;
  stand_in : string option; reads : string option; modules : int; event_routines : (string * string) list;
}

let cell ~backup ~io ~signals ~warnings tasks : Yojson.Safe.t =
  let opt = function Some s -> text s | None -> `Null in
  `Assoc [ ("event", `String "cell"); ("backup", text backup);
           ("tasks", `List (List.map (fun t ->
                `Assoc [ ("task", text t.name); ("type", `String t.kind); ("entry", text t.entry);
                         ("motion", `Bool t.motion); ("robot", opt t.robot); ("robot_type", opt t.robot_type);
                         ("stand_in", opt t.stand_in);
                         ("reads", opt t.reads); ("modules", `Int t.modules);
                         ("event_routines", `List (List.map (fun (r, e) ->
                              `Assoc [ ("routine", text r); ("event", `String e) ]) t.event_routines)) ]) tasks));
           ("io", opt io); ("signals", `Int signals); ("warnings", `Int warnings) ]

let refused_entry ~files ~entry : Yojson.Safe.t =
  let file = match files with f :: _ -> f | [] -> "" in
  let message =
    Printf.sprintf "there is no procedure %s without parameters to run: the task's entry routine (§9.1)" entry in
  `Assoc [ ("event", `String "end"); ("outcome", `String "refused"); ("class", `String "semantic-error");
           ("at", `Assoc [ ("file", text file); ("line", `Int 1); ("col", `Int 1); ("end_line", `Int 1);
                           ("end_col", `Int 1) ]);
           ("message", text message) ]
