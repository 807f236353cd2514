(* The closure engine's direct path for calls (lib/semantics/closure_call.ml, doc/semantics.md
   "The second engine"): which calls take it, and that a run taking it is the run the general
   path makes. The general path is the one every call takes when the run is observed (schema
   rapid-sem/2), so the same program is run three ways: observed (general path), with every
   event and with output only (direct path); the outcome, the fuel used and the events other
   than the observations must be the same, at every point where a budget runs out. *)

open Rapid_syntax
open Rapid_runtime
open Rapid_load
open Rapid_semantics
module M = Machine
module C = Rapid_closure.Closure_engine

let load name text =
  match Parse.parse_string ~name:(name ^ ".mod") text with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Session.load_modules [ m ] with
      | Ok l -> l.program
      | Error _ -> Alcotest.failf "%s does not check" name)

let routine (p : Ir.program) name =
  match Array.find_opt (fun (r : Ir.routine) -> String.lowercase_ascii r.name = name) p.routines with
  | Some r -> r
  | None -> Alcotest.failf "no routine %s" name

(* One argument given by value for each parameter. *)
let values (r : Ir.routine) =
  Array.map (fun _ -> Ir.By_value { e = Literal (Value.Num 1.); at = r.at }) r.parameters

let decisions () =
  let p = load "kinds" {rapid|MODULE kinds
  FUNC num plain(num a, num b) RETURN a + b; ENDFUNC
  PROC p_none() ENDPROC
  PROC p_var(VAR num a) a := 1; ENDPROC
  PROC p_inout(INOUT num a) ENDPROC
  PROC p_optional(\num a) ENDPROC
  PROC p_switch(\switch s) ENDPROC
  PROC p_handler(num a)
  ERROR
    RETURN;
  ENDPROC
  PROC p_undo(num a)
  UNDO
    TPWrite "undo";
  ENDPROC
  PROC main() ENDPROC
ENDMODULE
|rapid} in
  let direct name = Rapid_closure.Closure_call.direct (routine p name) (values (routine p name)) <> None in
  Alcotest.(check bool) "in parameters" true (direct "plain");
  Alcotest.(check bool) "no parameters" true (direct "p_none");
  Alcotest.(check bool) "a VAR parameter" false (direct "p_var");
  Alcotest.(check bool) "an INOUT parameter" false (direct "p_inout");
  Alcotest.(check bool) "an optional parameter" false (direct "p_optional");
  Alcotest.(check bool) "a switch" false (direct "p_switch");
  Alcotest.(check bool) "an error handler" false (direct "p_handler");
  Alcotest.(check bool) "an UNDO handler" false (direct "p_undo");
  Alcotest.(check bool) "an installed routine" false (direct "abs");
  let plain = routine p "plain" in
  Alcotest.(check bool) "an absent argument" false
    (Rapid_closure.Closure_call.direct plain [| Ir.Absent; Ir.Absent |] <> None);
  Alcotest.(check bool) "a data reference for an in parameter" true
    (Rapid_closure.Closure_call.direct plain [| Ir.By_reference (Whole (Global 0), Ref_variable);
                                  Ir.By_reference (Whole (Global 0), Ref_variable) |] <> None)

let outcome_text = function
  | Rapid_runtime.Outcome.Running -> "fuel"
  | Ended -> "ended"
  | Stopped { name; at; _ } -> Printf.sprintf "stopped %s %s" name (Source.to_string at)
  | Resource_exhausted (m, _) -> "exhausted: " ^ m
  | Unsupported { reason; _ } -> "unsupported: " ^ reason
  | Deadlock m -> "deadlock: " ^ m
  | Stuck m -> "stuck: " ^ m

let unobserved = List.filter (function Rapid_runtime.Event.Observed _ -> false | _ -> true)

(* The three runs agree; the outcome of the direct path is returned. *)
let same ?limits ?fuel program entry =
  let run ~all_events ~observe =
    match C.events ~host:(Rapid_run.Run.setup ()).host ?limits ?fuel ~all_events ~observe program ~entry with
    | Error m -> Alcotest.fail m
    | Ok (events, r) -> (unobserved events, outcome_text r.outcome, r.fuel_used) in
  let g_events, g_outcome, g_fuel = run ~all_events:true ~observe:true in
  let d_events, d_outcome, d_fuel = run ~all_events:true ~observe:false in
  let o_events, o_outcome, o_fuel = run ~all_events:false ~observe:false in
  Alcotest.(check string) "outcome, every event" g_outcome d_outcome;
  Alcotest.(check string) "outcome, output only" g_outcome o_outcome;
  Alcotest.(check int) "fuel, every event" g_fuel d_fuel;
  Alcotest.(check int) "fuel, output only" g_fuel o_fuel;
  Alcotest.(check bool) "the events" true (g_events = d_events);
  let output = List.filter (function Rapid_runtime.Event.Output _ | Rapid_runtime.Event.Erase | Rapid_runtime.Event.Log _ -> true | _ -> false) in
  Alcotest.(check bool) "the output" true (output g_events = o_events);
  d_outcome

let program = {rapid|MODULE direct
  FUNC num fib(num n)
    IF n < 2 RETURN n;
    RETURN fib(n - 1) + fib(n - 2);
  ENDFUNC
  FUNC num down(num n, num by)
    VAR num here := 0;
    IF n <= 0 RETURN 0;
    here := n;
    RETURN down(n - by, by) + 1;
  ENDFUNC
  FUNC num pick(num n)
    VAR num twice := 0;
    IF n > 5 THEN
      RETURN 1;
    ENDIF
    twice := 2 * n;
    TEST n
    CASE 1:
      RETURN 10;
    ENDTEST
    IF n = 2 RETURN twice;
    RETURN n + pick(n + 3);
  ENDFUNC
  FUNC num hop(num n)
    VAR num k := 0;
    again:
    k := k + 1;
    IF k < n GOTO again;
    RETURN k;
  ENDFUNC
  FUNC num firstover(num n)
    VAR num i := 0;
    WHILE TRUE DO
      i := i + 1;
      IF i * i > n RETURN i;
    ENDWHILE
    RETURN -1;
  ENDFUNC
  FUNC num noreturn(num n)
    TPWrite "n=" \Num:=n;
  ENDFUNC
  PROC count(num n)
    TPWrite "count " \Num:=n;
    IF n > 0 count n - 1;
  ENDPROC
  PROC main()
    TPWrite "fib(12)=" \Num:=fib(12);
    count 3;
    TPWrite "pick=" \Num:=pick(1) + pick(2) + pick(4) + pick(6);
    TPWrite "hop=" \Num:=hop(3);
    TPWrite "firstover=" \Num:=firstover(10);
    TPWrite "down=" \Num:=down(100000, 1);
  ENDPROC
  PROC main2()
    TPWrite "x=" \Num:=noreturn(3);
  ENDPROC
  PROC main4()
    VAR num x;
    x := down(100000, 1);
  ENDPROC
  PROC main3()
    VAR num zero := 0;
    TPWrite "x=" \Num:=fib(1 / zero);
  ENDPROC
ENDMODULE
|rapid}

let contains s w =
  let n = String.length w in
  let rec go i = i + n <= String.length s && (String.sub s i n = w || go (i + 1)) in
  go 0

(* §1.4: the call depth, the memory budget (the argument's copy, then the activation), the fuel
   and the native stack run out at the same point on both paths, with the same message. *)
let budgets () =
  let p = load "direct" program in
  (* The default limits: the depth of down(100000) is beyond them. *)
  let o = same p "main" in
  Alcotest.(check bool) ("call depth: " ^ o) true (contains o "call depth beyond");
  let deep = { Rapid_runtime.Limits.default with max_call_depth = max_int } in
  let o = same ~limits:deep p "main" in
  Alcotest.(check bool) ("native stack: " ^ o) true (contains o "native stack");
  Alcotest.(check string) "an error in a directly called function" "stopped ERR_FNCNORET direct.mod:56:5"
    (same p "main2");
  Alcotest.(check string) "an error in an argument" "stopped ERR_DIVZERO direct.mod:64:5" (same p "main3");
  (* The memory budget: the smallest that lets down() reach the call depth of 40 is found (the
     installed data count too); below it, every budget down to one that does not hold the
     first activation, in steps that meet each place in a call. *)
  let shallow max_memory = { Rapid_runtime.Limits.default with max_memory; max_call_depth = 40 } in
  let deep_enough m = contains (same ~limits:(shallow m) p "main4") "call depth beyond" in
  let rec least lo hi = if lo >= hi then lo else let mid = (lo + hi) / 2 in
      if deep_enough mid then least lo mid else least (mid + 1) hi in
  let enough = least 0 10_000_000 in
  let copies = ref 0 and calls = ref 0 in
  let m = ref enough in
  while !m > enough - 40 * 400 do
    let o = same ~limits:(shallow !m) p "main4" in
    if contains o "the copy for the parameter" then incr copies;
    if contains o "the call of" then incr calls;
    m := !m - 13
  done;
  Alcotest.(check bool) (Printf.sprintf "both kinds of memory exhaustion met (%d, %d)" !copies !calls) true
    (!copies > 0 && !calls > 0);
  ignore (same ~limits:(shallow 10_000_000) p "main");
  for fuel = 1 to 400 do ignore (same ~fuel p "main") done

let suite =
  ( "closure_call",
    [ Alcotest.test_case "which calls take the direct path" `Quick decisions;
      Alcotest.test_case "the direct path runs out where the general path does" `Quick budgets ] )
