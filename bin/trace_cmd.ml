(* rapid-sem trace: the reductions of a run by the machine one by one, or the statements it
   executes (doc/trace-format.md). The run is Machine_steps' (lib/run); what is here is how each
   step is written. *)

module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
module EJ = Rapid_oracle.Event_json
module M = Rapid_semantics.Machine
module TV = Rapid_tools.Trace_view
module Steps = Rapid_run.Machine_steps
open Cmdliner
open Rapid_syntax

let print_line = Cli.print_line
let display = Rapid_runtime.Text_format.display

let write_json (w : TV.change) =
  match w with
  | Write { place; value } -> Some (`Assoc [ ("place", EJ.text place); ("value", EJ.text value) ])
  | _ -> None

(* The changes other than writes, as the events of run --json, with two more kinds. *)
let change_json encoder (c : TV.change) : Yojson.Safe.t option =
  let ev (e : Rapid_runtime.Event.t) = Some (EJ.event encoder e) in
  match c with
  | Write _ -> None
  | Output s -> ev (Output s)
  | Erase -> ev Erase
  | Log s -> ev (Log s)
  | Raised { name; number; at } -> ev (Error_raised { name; number; at })
  | Handled { name; routine } -> ev (Error_handled { name; routine })
  | Undo_run r -> ev (Undo_run r)
  | Routine_entered r -> ev (Routine_entered r)
  | Routine_left r -> ev (Routine_left r)
  | Task_ended -> ev Task_ended
  | Retried -> Some (`Assoc [ ("event", `String "retry") ])
  | Next_tried -> Some (`Assoc [ ("event", `String "trynext") ])
  | Controller_event e -> ev e

(* What the controller and the motion did, as the human trace writes it after "~ ". *)
let controller_text (e : Rapid_runtime.Event.t) =
  match e with
  | Controller (Signal_changed { time; signal; value }) -> Some (Printf.sprintf "%.6f s: %s = %g" time signal value)
  | Controller (Interrupt_occurred { time; number }) ->
      Some (Printf.sprintf "%.6f s: interrupt %d occurred" time number)
  | Controller (Interrupt_discarded { time; number; reason }) ->
      Some (Printf.sprintf "%.6f s: interrupt %d discarded (%s)" time number reason)
  | Trap_entered { time; number; trap } ->
      Some (Printf.sprintf "%.6f s: trap %s serves interrupt %d" time trap number)
  | Trap_left { time; trap } -> Some (Printf.sprintf "%.6f s: trap %s left" time trap)
  | Motion m -> Some (Rapid_observable.Motion_event.to_string m)
  | _ -> None

(* An entry of the event log other than ErrWrite's (§7.5), as the debugger shows it. *)
let event_log_text : Rapid_runtime.Event.log_entry -> string = function
  | Err_log { id; kind; arguments } -> Printf.sprintf "%s %d: %s" kind id (String.concat " | " arguments)
  | Skip_warning -> "SkipWarn"

(* A change as the statement-level trace writes it after the statement. *)
let change_text (c : TV.change) =
  match c with
  | Controller_event (Event_log l) -> Some ("log: " ^ event_log_text l)
  | Write { place; value } -> Some (place ^ " := " ^ value)
  | Output s -> Some ("> " ^ s)
  | Erase -> Some "(erased)"
  | Log s -> Some ("log: " ^ s)
  | Raised { name; number; at } -> Some (Printf.sprintf "%s (%d) raised at %s" name number (Source.to_string at))
  | Handled { routine; _ } -> Some ("handled by " ^ routine)
  | Retried | Next_tried -> None  (* the statement says it *)
  | Undo_run r -> Some ("UNDO of " ^ r)
  | Controller_event (Observed (Propagated { name; number; routine; _ })) ->
      Some (Printf.sprintf "%s (%d) propagated from %s" name number routine)
  | Controller_event e -> Option.map (fun t -> "~ " ^ t) (controller_text e)
  | Routine_entered _ | Routine_left _ | Task_ended -> None

(* What a reduction line adds under it: output, errors and handlers, UNDO. *)
let change_line (c : TV.change) =
  match c with
  | Controller_event (Event_log l) -> Some ("log: " ^ event_log_text l)
  | Output s -> Some ("> " ^ s)
  | Erase -> Some "> (erased)"
  | Log s -> Some ("log: " ^ s)
  | Undo_run r -> Some ("! the UNDO handler of " ^ r ^ " runs")
  | Controller_event e -> Option.map (fun t -> "~ " ^ t) (controller_text e)
  | Raised _ | Handled _ (* the error's own step says it *) | Write _ | Retried | Next_tried
  | Routine_entered _ | Routine_left _ | Task_ended -> None

let contains s p =
  let n = String.length p and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = p || go (i + 1)) in
  n = 0 || go 0

(* The trace of a started run: [format], [level], the steps [from_] to [to_] whose rule contains
   [rules]; --samples of the run's robot (the one task's, or the motion task's). *)
let trace run ~format ~level ~from_ ~to_ ~rules ~samples ~max_steps =
  let robot = Steps.robot run in
  let sampler = match samples, robot with
    | Some hz, Some _ when format = `Jsonl ->
        Some (Rapid_run.Tcp_samples.create hz
                ~on_capped:(fun () -> Cli.notify (Samples_capped Rapid_run.Tcp_samples.max_samples)))
    | _ -> None in
  let sample_json (s : Rapid_run.Tcp_samples.sample) = EJ.sample s.time s.pose s.joints in
  let views = Hashtbl.create 4 in
  let view_of task =
    match Hashtbl.find_opt views task with
    | Some v -> v
    | None ->
        let read name = if name = Parse.stdin_name then Some (Parse.source_text "-") else None in
        let v = TV.create ~read () in
        Hashtbl.replace views task v; v in
  let view = view_of None in
  let json j = print_line (Json_text.to_string j) in
  let encoder = EJ.create () in
  if format = `Jsonl then
    json (`Assoc [ ("schema", `String EJ.schema); ("kind", `String "trace");
                   ("level", `String (match level with `Reduction -> "reduction" | `Statement -> "statement")) ]);
  (* Source text and values as JSON strings: valid UTF-8 whatever the file's encoding. *)
  let text_json = EJ.text in
  let writes (st : TV.step) = List.filter_map write_json st.changes in
  let events (st : TV.step) = List.filter_map (change_json encoder) st.changes in
  (* The statement level: one line per statement, its changes after it. A change made after a
     nested statement printed (the store of [x := f(y)] after f's statements) continues its
     statement on a line of its own. *)
  (* A line is a statement's, or, before a routine's first statement, its routine data's. *)
  let module Ir = Rapid_runtime.Ir in
  let line : (int * Ir.routine * Ir.stmt option * int * TV.change list) option ref = ref None in
  (* With several tasks: the task of the line being built; a step of another task ends it. *)
  let line_task : string option ref = ref None in
  let flush () =
    match !line with
    | None -> ()
    | Some (first, routine, s, depth, changes) ->
        line := None;
        if first >= from_ && first <= to_ then begin
          let changes = List.rev changes in
          let place, text, at = match s with
            | Some s -> (TV.place_of_statement view routine s, TV.statement_text view s, s.sat)
            | None ->
                (Printf.sprintf "%s:%d" routine.module_name (Source.start routine.at).line,
                 "(routine data of " ^ routine.name ^ ")", routine.at) in
          match format with
          | `Human ->
              let shown = List.filter_map change_text changes in
              let place = match !line_task with Some t -> t ^ " " ^ place | None -> place in
              print_line @@ Printf.sprintf "%s%s%s%s%s" place (String.make (max 2 (20 - String.length place)) ' ')
                (String.make (2 * min 10 (depth - 1)) ' ') (display text)
                (if shown = [] then "" else "   " ^ display (String.concat "; " shown))
          | `Jsonl ->
              json (`Assoc ((match !line_task with Some t -> [ ("task", `String t) ] | None -> []) @ [
                  ("statement", `String place);
                  ("step", `Int first); ("depth", `Int depth); ("routine", `String routine.name);
                  ("at", EJ.region at); ("text", text_json text);
                  ("writes", `List (List.filter_map write_json changes));
                  ("events", `List (List.filter_map (change_json encoder) changes)) ]))
        end
  in
  let statement_step (st : TV.step) =
    let owner = match st.statement with Some s -> Some s | None -> st.in_statement in
    let printable = List.exists (fun c -> change_text c <> None) st.changes in
    (match st.statement, !line, owner with
     | Some s, _, _ -> flush (); line := Some (st.number, st.routine, Some s, st.depth, [])
     | None, Some (_, _, Some s, _, _), Some o when s == o -> ()
     | None, _, Some o when printable -> flush (); line := Some (st.number, st.routine, Some o, st.depth, [])
     | None, Some (_, r, None, _, _), None when r == st.routine -> ()
     (* An interrupt served between statements, a trap left: what the controller did goes
        on the line printed last, in the order it happened. *)
     | None, Some _, None when List.for_all (function
         | TV.Controller_event _ | Routine_entered _ | Routine_left _ -> true | _ -> false) st.changes -> ()
     | None, _, None when printable -> flush (); line := Some (st.number, st.routine, None, st.depth, [])
     | _ -> ());
    match !line with
    | Some (first, r, s, d, changes) ->
        line := Some (first, r, s, d, List.rev_append st.changes changes)
    | None -> ()
  in
  let last_state = ref None in
  let reduction_step task (st : TV.step) region kind stack samples =
    if st.number >= from_ && st.number <= to_ && (match rules with None -> true | Some p -> contains st.rule p) then
      match format with
      | `Human ->
          let shown_writes = List.filter_map (function
              | TV.Write { place; value } ->
                  let w = place ^ " := " ^ value in if w = st.redex then None else Some w
              | _ -> None) st.changes in
          let results = (match st.result with Some r -> [ r ] | None -> []) @ shown_writes in
          let step = Printf.sprintf "%s%s%s" (String.make (2 * min 10 (st.depth - 1)) ' ') st.redex
              (if results = [] then "" else " -> " ^ String.concat "; " results) in
          (* The statement as it stands, when this step changed it. *)
          let state = match st.state with
            | Some s when Some s <> !last_state -> last_state := st.state; "   | " ^ s
            | Some _ -> ""
            | None -> last_state := None; "" in
          let step = display step and state = display state in
          let number = match task with
            | Some t -> Printf.sprintf "%s %d" t st.number
            | None -> Printf.sprintf "%6d" st.number in
          let at = Source.to_string st.at in
          if state = "" then print_line (Printf.sprintf "%s %-22s %-24s %s" number st.rule at step)
          else print_line (Printf.sprintf "%s %-22s %-24s %-44s%s" number st.rule at step state);
          List.iter (fun c -> match change_line c with
              | Some l -> print_line ("       " ^ display l) | None -> ()) st.changes
      | `Jsonl ->
          json (`Assoc ((match task with Some t -> [ ("task", `String t) ] | None -> []) @ [
              ("step", `Int st.number); ("rule", `String st.rule); ("depth", `Int st.depth);
              ("at", EJ.region st.at); ("redex", text_json st.redex);
              ("result", (match st.result with Some r -> text_json r | None -> `Null));
              ("writes", `List (writes st));
              ("state", (match st.state with Some s -> text_json s | None -> `Null));
              ("focus", `Assoc [ ("kind", `String kind); ("at", EJ.region region);
                                 ("text", text_json (TV.source_text view region)) ]);
              ("stack", `List (List.map (fun s -> `String s) stack));
              ("events", `List (events st @ samples ())) ]))
  in
  let rec loop () =
    match Steps.next run with
    | None -> ()
    | Some (task, cfg) ->
        let view = view_of task in
        let region = M.focus_region cfg and kind = M.focus_kind cfg and stack = M.stack_view cfg in
        let before = TV.before view cfg in
        let (_, events) as answer = Steps.step run in
        Cli.report_stubbed events;
        (* The error in flight, for error-handled, also from the steps --from and --to leave out. *)
        List.iter (EJ.note encoder) events;
        let st = TV.after view before cfg answer in
        (* The robot sampled: the one task's, or with several the motion task's. *)
        let samples () = match sampler, robot with
          | Some s, Some (_, (w : Rapid_run.Run.world)) ->
              List.map sample_json
                (Rapid_run.Tcp_samples.until s w.motion (Rapid_controller.World.now w.controller))
          | _ -> [] in
        (match level with
         | `Reduction -> reduction_step task st region kind stack samples
         | `Statement ->
             ignore (samples ());
             if task <> !line_task then (flush (); line_task := task);
             statement_step st);
        loop ()
  in
  loop ();
  flush ();
  Option.iter (fun s -> Option.iter (fun (cfg, w) ->
      List.iter (fun j -> print_line (Json_text.to_string (sample_json j)))
        (Rapid_run.Tcp_samples.final s (M.outcome cfg) w)) robot) sampler;
  let outcome = Steps.outcome run and steps = Steps.steps run in
  if format = `Jsonl then print_line (Json_text.to_string (EJ.outcome ?entry_at:(Steps.entry_at run) outcome steps))
  else print_line @@ Printf.sprintf "end: %s after %d steps" (match outcome with
      | Ended -> "the task ended" | Stopped { name; _ } -> "stopped by the system error handler (" ^ name ^ ")"
      | Resource_exhausted (m, _) | Unsupported { reason = m; _ } | Stuck m | Deadlock m -> m
      | Running -> "step limit") steps;
  Cli.finish outcome steps ~max_steps

let cmd =
  let _files, _entry, max_steps, allow_unknown, max_depth, retry_limit = Run_args.common_run_args in
  let format = Arg.(value & opt (enum [ ("human", `Human); ("jsonl", `Jsonl) ]) `Human & info [ "format" ]
                      ~docv:"FORMAT" ~doc:"$(b,human) or $(b,jsonl) (doc/trace-format.md).") in
  let level = Arg.(value & opt (enum [ ("reduction", `Reduction); ("statement", `Statement) ]) `Reduction
                   & info [ "level" ] ~docv:"LEVEL"
                       ~doc:"$(b,reduction): one line per reduction step (the default); $(b,statement): one line \
                             per statement executed, with the changes it made.") in
  let from_ = Arg.(value & opt (Run_args.count ~what:"--from") 1 & info [ "from" ] ~docv:"N"
                     ~doc:"First step printed.") in
  let to_ = Arg.(value & opt (Run_args.count ~what:"--to") max_int & info [ "to" ] ~docv:"N"
                   ~doc:"Last step printed.") in
  let rules = Arg.(value & opt (some string) None & info [ "rules" ] ~docv:"PATTERN"
                     ~doc:"Print only the steps whose rule name contains PATTERN (reduction level).") in
  let run tasks max_steps allow_unknown max_depth retry_limit format level from_ to_ rules controller
      (robot, base_frames) samples =
    Cli.guard @@ fun () ->
    match Rapid_run.Tcp_samples.check samples with
    | Error m -> prerr_endline m; Cli.exit_static_error
    | Ok () ->
        let options =
          Run_args.options ~base_frames ~max_steps ~allow_unknown ~max_depth ~retry_limit ~controller ~robot ()
        in
        match Steps.start ~history:(samples <> None && format = `Jsonl) ~notify:Cli.notify options tasks with
        | Error f -> Cli.failure f
        | Ok run -> trace run ~format ~level ~from_ ~to_ ~rules ~samples ~max_steps
  in
  let doc = "print the reductions of a run one by one, or the statements it executes" in
  let man = [
    `S Manpage.s_description;
    `P "Runs the task like $(b,rapid-sem run --engine machine) (the small-step machine) and prints each reduction: \
        the step number, the rule applied (doc/semantics.md), where in the source, the redex with the values it \
        works on and what it became (errors raised and where they went included), and the statement as it stands \
        after |; output and UNDO handlers follow on lines of their own. $(b,--level statement) prints one line per \
        statement executed, as a programmer steps through it on the FlexPendant: MODULE:LINE, the statement, and \
        the changes it made (store writes, output, errors). $(b,--format jsonl) writes one JSON object per line in \
        the schema of doc/trace-format.md.";
    `S Manpage.s_exit_status; `P "As $(b,rapid-sem run).";
  ] in
  Cmd.v (Cmd.info "trace" ~doc ~man)
    Term.(const run $ Run_args.tasks_args $ max_steps $ allow_unknown $ max_depth $ retry_limit $ format $ level
          $ from_ $ to_ $ rules $ Run_args.controller_args $ Run_args.robot_and_base_frames $ Run_args.samples_arg)
