module Source = Rapid_syntax.Source

type t =
  | Running
  | Ended
  | Stopped of { name : string; number : int; at : Source.region; chain : string list;
                 about : string option }
  | Resource_exhausted of string * Source.region option
  | Unsupported of { name : string; reason : string; at : Source.region }
  | Deadlock of string
  | Stuck of string

let index_outside index dimension =
  (* An integer as a programmer writes it: 1E+20 beyond the digits a num holds exactly. *)
  let text = if Float.abs index < 1e15 then Printf.sprintf "%.0f" index
    else String.uppercase_ascii (Printf.sprintf "%g" index) in
  Printf.sprintf "index %s outside the dimension 1 to %d" text dimension

let retries_beyond limit =
  Printf.sprintf "more than %d RETRY in one handler, the retry limit: --retry-limit N sets it" limit

let not_modelled name at =
  Unsupported
    { name; at;
      reason = Printf.sprintf "%s is an installed routine whose behaviour rapid-sem does not model yet" name }

(* The reason of a dialogue without an answer begins with this, so that it is not offered
   --stub-unmodelled, which does not answer dialogues the script leaves open. *)
let operator_prefix = "no answer from the operator: "

let unanswered name reason at = Unsupported { name; at; reason = operator_prefix ^ reason }

let unanswered_reason reason =
  let n = String.length operator_prefix in
  String.length reason >= n && String.sub reason 0 n = operator_prefix

let unsupported_what reason = if unanswered_reason reason then reason else "not modelled: " ^ reason

let unsupported_text reason =
  if unanswered_reason reason then reason
  else Printf.sprintf "not modelled: %s (run with --stub-unmodelled to run it as a no-op)" reason

let time_limit max_time =
  Resource_exhausted (Printf.sprintf "virtual time beyond %g s (the --max-time limit)" max_time, None)

let motion_history_exhausted reason at = Resource_exhausted (Source.to_string at ^ ": " ^ reason, Some at)
