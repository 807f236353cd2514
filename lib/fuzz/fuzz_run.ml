open Rapid_syntax
module M = Rapid_semantics.Machine

type observed = { events : string list; outcome : string; finished : bool }

type failure =
  | Refused of string
  | Exception of string
  | Stuck of string
  | Nondeterministic of string
  | Engines_differ of string
  | Round_trip of string
  | Checker_crashed of string

let failure_to_string = function
  | Checker_crashed m -> "the checker does not answer properly on a mutant or hostile text: " ^ m
  | Refused m -> "the generated program does not check: " ^ m
  | Exception m -> "an OCaml exception escaped: " ^ m
  | Stuck m -> "no rule applies (exit 125): " ^ m
  | Nondeterministic m -> "two runs differ: " ^ m
  | Engines_differ m -> "the engines differ: " ^ m
  | Round_trip m -> "the printer's round trip fails: " ^ m

type engine = { engine_name : string; run : Rapid_runtime.Ir.program -> max_steps:int -> observed }

let place at = Source.to_string at

let event_text (e : Rapid_runtime.Event.t) =
  match e with
  | Output s -> "output " ^ String.escaped s
  | Erase -> "erase"
  | Log s -> "log " ^ String.escaped s
  | Event_log (Err_log { id; kind; arguments }) ->
      Printf.sprintf "errlog %d %s %s" id kind (String.concat " " (List.map String.escaped arguments))
  | Event_log Skip_warning -> "skipwarn"
  | Routine_entered r -> "routine-entered " ^ r
  | Routine_left r -> "routine-left " ^ r
  | Error_raised { name; number; at } -> Printf.sprintf "error-raised %s %d %s" name number (place at)
  | Error_handled { name; routine } -> Printf.sprintf "error-handled %s %s" name routine
  | Undo_run r -> "undo-run " ^ r
  | Task_ended -> "task-ended"
  | Controller (Signal_changed { time; signal; value }) -> Printf.sprintf "signal %s %g at %g" signal value time
  | Controller (Interrupt_occurred { time; number }) -> Printf.sprintf "interrupt %d at %g" number time
  | Controller (Interrupt_discarded { time; number; reason }) ->
      Printf.sprintf "interrupt-discarded %d at %g (%s)" number time reason
  | Trap_entered { number; trap; time } -> Printf.sprintf "trap-entered %s %d at %g" trap number time
  | Trap_left { trap; time } -> Printf.sprintf "trap-left %s at %g" trap time
  | Stubbed { routine; at } -> Printf.sprintf "stubbed %s %s" routine (place at)
  | Motion m -> Rapid_observable.Motion_event.to_string m
  | Observed o -> Rapid_runtime.Observation.to_string o

let outcome_text (o : Rapid_runtime.Outcome.t) =
  match o with
  | Running -> "running"
  | Ended -> "ended"
  | Stopped { name; number; at; chain; about } ->
      Printf.sprintf "stopped %s %d %s [%s]%s" name number (place at) (String.concat " " chain)
        (match about with Some a -> " about " ^ a | None -> "")
  | Resource_exhausted (m, _) -> "exhausted " ^ m
  | Unsupported { name; at; _ } -> Printf.sprintf "unsupported %s %s" name (place at)
  | Deadlock m -> "deadlock " ^ m
  | Stuck m -> "stuck " ^ m

(* Every step of every run counts its rule here: a counter per rule, found once, rather than a
   find and a replace (two hashes of the name) per step. *)
let rule_table : (string, int ref) Hashtbl.t = Hashtbl.create 200
let counter t rule =
  match Hashtbl.find_opt t rule with
  | Some c -> c
  | None -> let c = ref 0 in Hashtbl.add t rule c; c
let bump t rule n = let c = counter t rule in c := !c + n

(* The tables of the calls of [recording_rules] under way, innermost first. *)
let recording : (string, int ref) Hashtbl.t list ref = ref []

let note_rule rule =
  incr (counter rule_table rule);
  match !recording with [] -> () | ts -> List.iter (fun t -> bump t rule 1) ts

let counts t = List.sort compare (Hashtbl.fold (fun k v acc -> (k, !v) :: acc) t [])

let recording_rules f =
  let t = Hashtbl.create 16 in
  let saved = !recording in
  recording := t :: saved;
  let r = Fun.protect ~finally:(fun () -> recording := saved) f in
  (r, counts t)

let note_rules l = List.iter (fun (rule, n) -> bump rule_table rule n; List.iter (fun t -> bump t rule n) !recording) l
let reset_rule_counts () = Hashtbl.reset rule_table
let rule_counts () = counts rule_table

(* The outside world of every generated program (doc/oracle.md, "Fuzzing"): two digital signals
   the generator uses, and an input that changes at fixed times so that waits and interrupts on
   it are taken. *)
let io_text = "signal di1 di\nsignal do1 do\nat 0.25 di1 1\nat 0.75 di1 0\nat 1.5 di1 1\n"

let io =
  match Rapid_controller.Io_config.parse ~file:"fuzz.io" io_text with
  | Ok io -> io
  | Error m -> failwith ("the fuzzer's I/O configuration: " ^ m)

(* The installed environment with the signals, made once: the checker and the lowering share
   what they compute for it between programs as long as it is this very list. *)
let world_io = ref io

let mentions word text =
  let n = String.length word and m = String.length text in
  let rec go i = i + n <= m && (String.sub text i n = word || go (i + 1)) in
  go 0

let installed = lazy (Rapid_load.Session.installed ~io ())

(* What a scenario runs with (Fuzz_case): its stimulus, limits and options; the engines read it,
   so that their type stays that of one program. *)
type setting = { s_io : Rapid_controller.Io_config.t; s_options : Fuzz_case.options }

let setting = ref { s_io = io; s_options = Fuzz_case.default_options }

let with_run_options ~io options f =
  let saved = !setting in
  setting := { s_io = io; s_options = options };
  Fun.protect ~finally:(fun () -> setting := saved) f

let new_world () =
  let s = !setting in
  if s.s_options = Fuzz_case.default_options && s.s_io == io then Rapid_controller.World.create !world_io
  else Rapid_controller.World.create ?max_time:s.s_options.max_time s.s_io

(* The events of a run as two streams, each in its order: the program's, then the world's
   (signal changes, interrupts, motion). The engines may interleave the two differently within
   a step (doc/semantics.md, "What is compared"); each stream must be the same. *)
let streams () =
  let program = ref [] and world = ref [] in
  let add e =
    if Rapid_runtime.Event.world_event e then world := event_text e :: !world
    else program := event_text e :: !program in
  let result () = List.rev_append !program ("-- the world's events --" :: List.rev !world) in
  (add, result)

let machine =
  let run program ~max_steps =
    let world = new_world () and o = !setting.s_options in
    let host = (Rapid_run.Run.setup ~controller:world ()).host in
    match M.start ~limits:(Fuzz_case.limits o) ~stub_unmodelled:o.stub_unmodelled ~host ~observe:true
            program ~entry:"main" with
    | Error m -> { events = []; outcome = "cannot start: " ^ m; finished = true }
    | Ok cfg ->
        let add, events = streams () in
        while M.outcome cfg = Running && M.steps cfg < max_steps do
          let rule, evs = M.step cfg in
          note_rule rule;
          List.iter add evs
        done;
        let o = M.outcome cfg in
        let finished = match o with Running | Resource_exhausted _ | Deadlock _ -> false | _ -> true in
        { events = events (); outcome = outcome_text o; finished }
  in
  { engine_name = "machine"; run }

(* The second engine (doc/semantics.md, "The second engine"). A run that exhausts its fuel or a
   resource is not finished: it is not compared. *)
let closure =
  let run program ~max_steps =
    let add, events = streams () in
    let world = new_world () and o = !setting.s_options in
    match Rapid_closure.Closure_engine.run ~limits:(Fuzz_case.limits o) ~stub_unmodelled:o.stub_unmodelled
            ~fuel:max_steps ~observe:true ~host:(Rapid_run.Run.setup ~controller:world ()).host ~on_event:add
            program ~entry:"main" with
    | Error m -> { events = []; outcome = "cannot start: " ^ m; finished = true }
    | Ok r ->
        let finished = match r.outcome with
          | Running | Resource_exhausted _ | Deadlock _ -> false
          | _ -> true in
        { events = events (); outcome = outcome_text r.outcome; finished }
  in
  { engine_name = "closure"; run }

let first_difference a b =
  let rec go i a b =
    match a, b with
    | [], [] -> "equal"
    | x :: a', y :: b' -> if x = y then go (i + 1) a' b' else Printf.sprintf "event %d: %s / %s" i x y
    | x :: _, [] -> Printf.sprintf "event %d: %s / (none)" i x
    | [], y :: _ -> Printf.sprintf "event %d: (none) / %s" i y
  in
  go 1 a b

let compare_observed name (a : observed) (b : observed) =
  if a.events <> b.events then Some (Printf.sprintf "%s: %s" name (first_difference a.events b.events))
  else if a.outcome <> b.outcome then Some (Printf.sprintf "%s: outcome %s / %s" name a.outcome b.outcome)
  else None

(* As Session.load_modules, over the fuzzer's installed environment (a scenario's stimulus
   declares the same signals, so the same environment serves it). *)
let load_modules ?(allow_unknown = false) ?(io = io) modules
  : (Rapid_load.Session.loaded, Rapid_load.Session.failure) result =
  match Lazy.force installed with
  | Error d -> Error (Internal ("the installed environment does not parse: " ^ Diagnostic.to_string d))
  | Ok installed ->
      let result = Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
      if Rapid_typing.Check.errors result <> [] then Error (Static result.reports)
      else
        match Rapid_load.Session.lower ~io ~installed ~modules result with
        | Ok program -> Ok { program; warnings = result.reports; unknown_summary = None }
        | Error reports -> Error (Static (result.reports @ reports))

let load m = load_modules [ m ]

(* The printer's round trip: the printed module reads back to the same tree, locations aside
   (Ast_dump's equality, without writing the two dumps). *)
let round_trip ~name m =
  match Parse.parse_string ~name (Printer.module_declaration m) with
  | Error d -> Error (Round_trip (Diagnostic.to_string d))
  | Ok m' when not (Ast_erase.equal m m') -> Error (Round_trip (name ^ ": the printed module parses to another tree"))
  | Ok _ -> Ok ()

let refused : Rapid_load.Session.failure -> failure = function
  | Front_end ds -> Refused (String.concat "; " (List.map Diagnostic.to_string ds))
  | Static rs ->
      Refused (String.concat "; " (List.map Rapid_typing.Report.to_string
                                     (List.filter (fun (r : Rapid_typing.Report.t) -> r.severity = Error) rs)))
  | Internal m -> Exception m

let is_stuck (o : observed) = String.length o.outcome >= 5 && String.sub o.outcome 0 5 = "stuck"

(* Progress, determinism (the machine twice) and the engines' agreement on one loaded program. *)
let judge_runs ~engines ~max_steps program =
  let first = machine.run program ~max_steps in
  if is_stuck first then Error (Stuck first.outcome)
  else
    let again = machine.run program ~max_steps in
    match compare_observed "machine twice" first again with
    | Some d -> Error (Nondeterministic d)
    | None ->
        let differ = List.find_map (fun e ->
            let other = e.run program ~max_steps in
            (* An engine counts its own fuel: a run that exhausts it is compared only when both
               finished. *)
            if not (first.finished && other.finished) then None
            else compare_observed ("machine / " ^ e.engine_name) first other) engines in
        match differ with
        | Some d -> Error (Engines_differ d)
        | None -> Ok first

let check_program ?(engines = []) ?(max_steps = 200_000) source =
  try
    match Parse.parse_string ~name:"fuzz.mod" source with
    | Error d -> Error (Refused (Diagnostic.to_string d))
    | Ok m ->
        Result.bind (round_trip ~name:"fuzz.mod" m) (fun () ->
            match load m with
            | Error f -> Error (refused f)
            | Ok loaded -> judge_runs ~engines ~max_steps loaded.program)
  with
  | Stack_overflow -> Error (Exception "stack overflow")
  | Out_of_memory -> Error (Exception "out of memory")
  | e -> Error (Exception (Printexc.to_string e))

let io_text_for (_ : string) = io_text

let observe ?(max_steps = 200_000) source =
  match Parse.parse_string ~name:"fuzz.mod" source with
  | Error d -> Error (Diagnostic.to_string d)
  | Ok m -> (
      match load m with
      | Ok loaded -> Ok (machine.run loaded.program ~max_steps)
      | Error _ -> Error "the program does not check")
