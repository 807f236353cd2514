(* The two engines against each other (doc/semantics.md, "The second engine"): every format 3
   run case of spec/ runs under the small-step machine and under the closure engine, and both
   must make the same observable events, in the same order, and end the same way: the same kind
   of outcome and, when the system error handler stops the task, the same error, number, place
   and call chain. Step counts are each engine's own and are not compared. *)

open Rapid_syntax
module M = Rapid_semantics.Machine
module C = Rapid_semantics.Closure_engine

let folders = [ "04-run"; "05-run"; "07-errors"; "11-installed"; "13-rulings-run" ]

let event_text (e : M.event) =
  let region r = Source.to_string r ^ "-" ^ (let q = Source.stop r in Printf.sprintf "%d:%d" q.line q.col) in
  match e with
  | Output s -> "output " ^ s
  | Erase -> "erase"
  | Log s -> "log " ^ s
  | Routine_entered r -> "entered " ^ r
  | Routine_left r -> "left " ^ r
  | Error_raised { name; number; at } -> Printf.sprintf "raised %s %d %s" name number (region at)
  | Error_handled { name; routine } -> Printf.sprintf "handled %s in %s" name routine
  | Undo_run r -> "undo " ^ r
  | Task_ended -> "task ended"

(* The outcome as the two engines must agree on it. A run cut short by the machine's step limit
   and one cut short by the closure engine's fuel are both "exhausted": what a step and a unit
   of fuel are differs. *)
let outcome_text (o : M.outcome) =
  match o with
  | Ended -> "ended"
  | Stopped { name; number; at; chain } ->
      Printf.sprintf "stopped %s %d %s (%s)" name number (Source.to_string at) (String.concat " <- " chain)
  | Running | Resource_exhausted _ -> "exhausted"
  | Unsupported _ -> "unsupported"
  | Stuck m -> "stuck " ^ m

let load (case : Rapid_conformance.Spec_case.t) =
  let modules = List.filter_map (fun f -> Result.to_option (Parse.parse_file f)) case.files in
  match Rapid_semantics.Session.load_modules ~allow_unknown:case.allow_unknown modules with
  | Ok loaded -> Some loaded.program
  | Error _ -> None

let machine_run limits program ~entry ~max_steps =
  match M.start ~limits program ~entry with
  | Error m -> Alcotest.failf "machine: %s" m
  | Ok cfg ->
      let events = ref [] in
      while M.outcome cfg = Running && M.steps cfg < max_steps do
        events := List.rev_append (snd (M.step cfg)) !events
      done;
      (List.rev !events, M.outcome cfg)

let closure_run limits program ~entry ~fuel =
  match C.events ~limits ~fuel program ~entry with
  | Error m -> Alcotest.failf "closure engine: %s" m
  | Ok (events, r) -> (events, r.outcome)

let rec is_prefix a b = match a, b with [], _ -> true | x :: a, y :: b -> x = y && is_prefix a b | _ :: _, [] -> false

(* The first difference, with a little context. *)
let difference machine closure =
  let rec go i m c =
    match m, c with
    | [], [] -> None
    | x :: m, y :: c when x = y -> go (i + 1) m c
    | _ ->
        let show = function [] -> "(nothing)" | e :: _ -> event_text e in
        Some (Printf.sprintf "event %d: machine %s, closure %s" i (show m) (show c))
  in
  go 0 machine closure

let compare_case path () =
  let case = Rapid_conformance.Spec_case.read path in
  match case.run, load case with
  | Some run, Some program ->
      let limits = { M.default_limits with
                     retry_limit = Option.value run.retry_limit ~default:M.default_limits.retry_limit } in
      let budget = Option.value run.max_steps ~default:10_000_000 in
      let m_events, m_outcome = machine_run limits program ~entry:run.entry ~max_steps:budget in
      let c_events, c_outcome = closure_run limits program ~entry:run.entry ~fuel:budget in
      Alcotest.(check string) "outcome" (outcome_text m_outcome) (outcome_text c_outcome);
      let cut_short = (m_outcome = Running || c_outcome = Running) in
      if cut_short then begin
        (* Cut short at different points: one event list must begin the other. *)
        if not (is_prefix m_events c_events || is_prefix c_events m_events) then
          Alcotest.failf "events differ before the limit: %s"
            (Option.value (difference m_events c_events) ~default:"")
      end
      else begin
        match difference m_events c_events with
        | None -> ()
        | Some d -> Alcotest.failf "%s" d
      end
  | Some _, None -> Alcotest.failf "%s does not check" path
  | None, _ -> ()

let run_cases () =
  List.concat_map (fun folder ->
      Rapid_conformance.Spec_runner.find_cases (Filename.concat "../spec" folder)
      |> List.filter (fun path -> (Rapid_conformance.Spec_case.read path).run <> None))
    folders

(* The conformance suite's run cases under the closure engine, through the spec runner. *)
let spec_under_closure () =
  let failures = List.concat_map (fun folder ->
      Rapid_conformance.Spec_runner.find_cases (Filename.concat "../spec" folder)
      |> List.filter_map (fun path ->
          let o = Rapid_conformance.Spec_runner.run_case ~engine:Closure (Rapid_conformance.Spec_case.read path) in
          if o.verdict = Failed then Some (path ^ ": " ^ o.detail) else None)) folders in
  Alcotest.(check (list string)) "spec/ run cases failing under --engine closure" [] failures

let suite =
  ( "engines",
    Alcotest.test_case "the spec/ run cases pass under the closure engine" `Quick spec_under_closure
    :: List.map (fun path ->
        let name = String.concat "/" (List.rev (List.filteri (fun i _ -> i < 2)
                                                  (List.rev (String.split_on_char '/' path)))) in
        Alcotest.test_case ("machine = closure: " ^ name) `Quick (compare_case path)) (run_cases ()) )
