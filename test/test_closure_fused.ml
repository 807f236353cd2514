(* The closure engine's fused forms for recursive functions (lib/semantics/closure_engine.ml,
   [valued_body] and [direct_call]; doc/semantics.md, "The second engine"): a guard [IF own < k
   RETURN e;] compared in its statement's closure, and an argument [own + k] or [own - k]
   computed in the call's closure. They take the direct path only: a run taking them must be
   the run the general path makes (observed, schema rapid-sem/2), at every unit of fuel, and
   the machine's run. The program is the conformance case that states what the manual
   requires of them (each comparison at its boundary, single-precision steps, ERR_OVERFLOW). *)

let case = "../spec/05-run/04-recursive-function-guards.mod"

(* A valued body of two statements, a guard and RETURN of +, - or * (guarded_return). *)
let steps = "../spec/05-run/04-recursive-function-steps.mod"

let text ?(case = case) () =
  let ic = open_in_bin case in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))

let with_machine ?case ?(lines = 12) () =
  let program = Test_engines.load_text "guards" (text ?case ()) in
  let events, outcome = Test_engines.agree program in
  Alcotest.(check string) "ended" "ended" (Test_engines.outcome_text outcome);
  let output = List.filter_map (function Rapid_runtime.Event.Output s -> Some s | _ -> None) events in
  Alcotest.(check int) "every line written" lines (List.length output)

let at_every_fuel ?case () =
  let program = Test_closure_call.load "guards" (text ?case ()) in
  Alcotest.(check string) "the whole run" "ended" (Test_closure_call.same program "main");
  let used = match Rapid_closure.Closure_engine.run ~host:(Rapid_run.Run.setup ()).host ~all_events:false program ~entry:"main" with
    | Ok r -> r.fuel_used
    | Error m -> Alcotest.fail m in
  for fuel = 1 to used do ignore (Test_closure_call.same ~fuel program "main") done

(* §1.4: the memory budget runs out at the copy of a fused argument, and at the activation it
   goes to, where the general path stops: budgets just below the least that lets the run end
   are tried, in steps that meet each place in a call. *)
let memory ?case () =
  let program = Test_closure_call.load "guards" (text ?case ()) in
  let limits max_memory = { Rapid_runtime.Limits.default with max_memory } in
  let ends m = Test_closure_call.same ~limits:(limits m) program "main" = "ended" in
  let rec least lo hi = if lo >= hi then lo else let mid = (lo + hi) / 2 in
      if ends mid then least lo mid else least (mid + 1) hi in
  let enough = least 0 100_000_000 in
  let contains s w =
    let n = String.length w in
    let rec go i = i + n <= String.length s && (String.sub s i n = w || go (i + 1)) in
    go 0 in
  let copies = ref 0 and calls = ref 0 in
  let m = ref (enough - 1) in
  while !m > enough - 4_000 do
    let o = Test_closure_call.same ~limits:(limits !m) program "main" in
    if contains o "the copy for the parameter" then incr copies;
    if contains o "the call of" then incr calls;
    m := !m - 7
  done;
  Alcotest.(check bool) (Printf.sprintf "both kinds of memory exhaustion met (%d, %d)" !copies !calls) true
    (!copies > 0 && !calls > 0)

(* ch. 8: with an interrupt connected every statement is a point of response, and traps are
   served inside the recursion: a call whose callee's first statement returns goes through the
   activation as any other (the world is observed), the run the general path's and the
   machine's. *)
let traps () =
  let text = {rapid|MODULE trapfib
  VAR intnum timer;
  VAR num ticks := 0;
  TRAP counted
    ticks := ticks + 1;
  ENDTRAP
  FUNC num fib(num n)
    IF n < 2 RETURN n;
    RETURN fib(n - 1) + fib(n - 2);
  ENDFUNC
  PROC main()
    CONNECT timer WITH counted;
    ITimer 0.01, timer;
    TPWrite "fib(16)=" \Num:=fib(16);
    IDelete timer;
    TPWrite "ticks>0=" \Bool:=ticks > 0;
  ENDPROC
ENDMODULE
|rapid} in
  let events, _ = Test_engines.agree (Test_engines.load_text "trapfib" text) in
  let output = List.filter_map (function Rapid_runtime.Event.Output s -> Some s | _ -> None) events in
  Alcotest.(check (list string)) "output" [ "fib(16)=987"; "ticks>0=TRUE" ] output;
  let program = Test_closure_call.load "trapfib" text in
  Alcotest.(check string) "the whole run" "ended" (Test_closure_call.same program "main");
  let used = match Rapid_closure.Closure_engine.run ~host:(Rapid_run.Run.setup ()).host ~all_events:false program ~entry:"main" with
    | Ok r -> r.fuel_used
    | Error m -> Alcotest.fail m in
  let fuel = ref 1 in
  while !fuel < used do ignore (Test_closure_call.same ~fuel:!fuel program "main"); fuel := !fuel + 37 done

let suite =
  ( "closure_fused",
    [ Alcotest.test_case "the fused forms against the machine" `Quick with_machine;
      Alcotest.test_case "the fused forms against the general path, at every unit of fuel" `Quick at_every_fuel;
      Alcotest.test_case "the fused forms within the memory budget" `Quick memory;
      Alcotest.test_case "two fused statements against the machine" `Quick (with_machine ~case:steps ~lines:5);
      Alcotest.test_case "two fused statements against the general path, at every unit of fuel" `Quick
        (at_every_fuel ~case:steps);
      Alcotest.test_case "two fused statements within the memory budget" `Quick (memory ~case:steps);
      Alcotest.test_case "traps served inside a fused recursion" `Quick traps ] )
