module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
module EJ = Rapid_oracle.Event_json
module Setup = Rapid_run.Run_setup
open Rapid_syntax

let exit_ok = 0
let exit_static_error = 2
let exit_spec_failed = 1
let exit_internal = 125
let version = "0.1.0"

(* Standard output closed (a pipe whose reader has gone) or not writable (a full disk): the run
   ends at once with this status, 128 + SIGPIPE as a shell reports a process that a closed pipe
   ended (doc/user-guide.md). *)
let exit_output_failed = 141

exception Output_failed of string

(* Each line leaves the process as it is written: a reader waiting for it (a client before the
   program's SocketAccept) would otherwise wait for the buffer to fill, and a run killed by a
   timeout (SIGKILL) would lose every line still in the buffer (doc/services.md). *)
let print_line s =
  try print_string s; print_char '\n'; flush stdout with Sys_error m -> raise (Output_failed m)

let flush_output () = try flush stdout with Sys_error m -> raise (Output_failed m)

let contains_sub s p =
  let n = String.length p and m = String.length s in
  let rec go i = if i + n > m then raise Not_found else if String.sub s i n = p then i else go (i + 1) in
  go 0

let contains_sub_bool s p = match contains_sub s p with _ -> true | exception Not_found -> false

(* No OCaml exception may reach a user as such: anything that escapes is a bug of rapid-sem,
   reported as one. *)
let stdout_broken m =
  contains_sub_bool m "Broken pipe" || (try flush stdout; false with Sys_error _ -> true)

let guard f =
  try
    try let status = f () in flush_output (); status
    with Sys_error m when stdout_broken m -> raise (Output_failed m)
  with
  | Output_failed m ->
      (* A closed pipe is the reader's choice: quiet. Anything else is said once. *)
      let broken_pipe = contains_sub_bool m "Broken pipe" in
      if not broken_pipe then (try Printf.eprintf "rapid-sem: cannot write the standard output: %s\n%!" m with _ -> ());
      (* What is left in the buffer cannot be written either: closing drops it, so that the
         flushes at exit have nothing to fail on. *)
      close_out_noerr stdout;
      exit_output_failed
  | Stack_overflow ->
      prerr_endline "rapid-sem: internal error: stack overflow (please report this input)";
      exit_internal
  | Out_of_memory ->
      (* The machine's memory, not a rule of rapid-sem: a resource exhausted (§1.4). The RAPID
         data of a run is bounded by --max-memory, so this means a budget beyond the memory the
         machine has. *)
      prerr_endline "rapid-sem: out of memory (resource exhaustion, §1.4): try a smaller --max-memory";
      3
  | e ->
      Printf.eprintf "rapid-sem: internal error: %s (please report this input)\n"
        (Printexc.to_string e);
      exit_internal

let exit_stopped = 1
let exit_exhausted = 3
let exit_unsupported = 4

let stopped_text at name about chain =
  Printf.sprintf "%s: execution error: %s%s: the system error handler stopped the task (%s)"
    (Source.to_string at) name (match about with Some a -> " (" ^ a ^ ")" | None -> "") (EJ.chain_text chain)

let finish (o : Rapid_runtime.Outcome.t) steps ~max_steps =
  match o with
  | Ended -> exit_ok
  | Stopped { name; at; chain; about; _ } -> prerr_endline (stopped_text at name about chain); exit_stopped
  | Resource_exhausted (m, _) -> Printf.eprintf "rapid-sem: %s\n" m; exit_exhausted
  | Deadlock m -> Printf.eprintf "rapid-sem: %s\n" m; exit_exhausted
  | Unsupported { reason; at; _ } ->
      Printf.eprintf "%s: %s\n" (Source.to_string at) (Rapid_runtime.Outcome.unsupported_text reason);
      exit_unsupported
  | Stuck m ->
      Printf.eprintf "rapid-sem: internal error: no rule applies (%s) after %d steps; please report this program\n"
        m steps;
      exit_internal
  | Running -> Printf.eprintf "rapid-sem: the step limit (%d) is exhausted\n" max_steps; exit_exhausted

(* With several tasks the run's end names one outcome (the exit status's); a task that an error
   stopped, or a routine not modelled, before another task's end decided the run (a deadlock, the
   --max-time limit, an error of its own) would otherwise leave no word on standard error. *)
let report_task_stops tasks (run : Rapid_runtime.Outcome.t) =
  let key (o : Rapid_runtime.Outcome.t) = match o with
    | Stopped { name; at; _ } | Unsupported { name; at; _ } -> Some (name, Source.to_string at)
    | _ -> None in
  List.iter (fun (task, (o : Rapid_runtime.Outcome.t)) ->
      if key o <> None && key o <> key run then
        match o with
        | Stopped { name; at; chain; about; _ } ->
            Printf.eprintf "task %s: %s\n%!" task (stopped_text at name about chain)
        | Unsupported { reason; at; _ } ->
            Printf.eprintf "task %s: %s: %s\n%!" task (Source.to_string at)
              (Rapid_runtime.Outcome.unsupported_text reason)
        | _ -> ())
    tasks

let report_load_failure ?(json = false) failure =
  (* With --json, a program refused before it runs still gives an event stream: the start line
     and an end object naming the first error (doc/oracle.md). *)
  if json then Option.iter (fun j -> List.iter (fun l -> print_endline (Json_text.to_string l)) j)
      (Verdict.stream_of_failure failure);
  match failure with
  | Rapid_load.Session.Front_end ds ->
      List.iter (fun d -> prerr_endline (Diagnostic.to_string d)) ds; exit_static_error
  | Static reports -> List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) reports; exit_static_error
  | Internal m -> Printf.eprintf "rapid-sem: internal error: %s\n" m; exit_internal

let notify : Setup.notice -> unit = function
  | Inferred_signal (s, at) ->
      let kind = Rapid_controller.Io_config.type_name s.kind in
      let io_kind = if String.length kind > 6 then String.sub kind 6 (String.length kind - 6) else kind in
      Printf.eprintf "%swarning: %s is not declared; --stub-unmodelled made it a virtual %s at 0 (R-13-aa)\n  \
                      hint: to model it, give it in a stimulus file: --io FILE with a line \"signal %s %s\" \
                      (doc/controller.md)\n%!"
        (if Rapid_syntax.Source.file_of at = None then "" else Rapid_syntax.Source.to_string at ^ ": ")
        s.name kind s.name io_kind
  | Warnings (reports, unknown_summary) ->
      List.iter (fun r -> prerr_endline (Rapid_typing.Report.to_string r)) reports;
      Option.iter prerr_endline unknown_summary
  | Stdin_not_saved ->
      prerr_endline "rapid-sem: --save: warning: the module read from standard input (-) is not saved: \
                     it has no file to write back to"
  | Samples_capped n ->
      Printf.eprintf "rapid-sem: --samples: %d samples written, the most a run writes; the rest are left out\n%!" n
  | Backup_warning w -> prerr_endline w

let failure ?(json = false) ?(files = []) : Setup.failure -> int = function
  | Usage m -> prerr_endline m; exit_static_error
  | Refused f -> report_load_failure ~json f
  | Task_refused (name, f) -> Printf.eprintf "rapid-sem: task %s is refused:\n%!" name; report_load_failure ~json f
  | Tasks_refused m -> prerr_endline ("rapid-sem: " ^ m); exit_static_error
  | Cannot_start { entry; reason } ->
      if json then print_endline (Json_text.to_string (EJ.refused_entry ~files ~entry));
      Printf.eprintf "rapid-sem: %s\n" reason; exit_static_error
  | Save_failed m -> Printf.eprintf "rapid-sem: --save: %s\n%!" m; exit_static_error

let report_stubbed events =
  List.iter (function
      | Rapid_runtime.Event.Stubbed { routine; at } ->
          Printf.eprintf "%s: warning: %s is not modelled; --stub-unmodelled ran it as a no-op\n%!"
            (Source.to_string at) routine
      | _ -> ()) events
