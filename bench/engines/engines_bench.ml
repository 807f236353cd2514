(* The machine, the closure engine and CPython 3 on the two programs of the closure engine's
   target (bench/README.md): recursive fib(25) and a loop of 1,000,000 iterations with two
   assignments. Each engine runs the program already checked and lowered (loading is the same
   for both and is not timed); CPython runs the equivalent Python function, timed inside the
   interpreter (its start-up is not timed either). The closure engine runs twice: making every
   event (closure, as run --json needs them) and only the output (closure-o, as run needs it). Times are processor time (Sys.time,
   time.process_time), not wall-clock time: the machine this runs on is shared, and processor
   time is what the process itself spent. Best of three runs each. *)

open Rapid_syntax
module M = Rapid_semantics.Machine
module C = Rapid_closure.Closure_engine

let programs = [
  ("fib(25), recursive",
   "MODULE b\n  FUNC num fib(num n)\n    IF n < 2 RETURN n;\n    RETURN fib(n - 1) + fib(n - 2);\n\
   \  ENDFUNC\n  PROC main()\n    VAR num r;\n    r := fib(25);\n    TPWrite \"fib(25)=\" \\Num:=r;\n\
   \  ENDPROC\nENDMODULE\n",
   "def fib(n):\n    if n < 2:\n        return n\n    return fib(n - 1) + fib(n - 2)\n\
    def main():\n    r = fib(25)\n    return r\n");
  ("loop 1,000,000 x 2 assignments",
   "MODULE b\n  PROC main()\n    VAR num i := 0;\n    VAR num s := 0;\n    WHILE i < 1000000 DO\n\
   \      i := i + 1;\n      s := s + 2;\n    ENDWHILE\n    TPWrite \"s=\" \\Num:=s;\n  ENDPROC\nENDMODULE\n",
   "def main():\n    i = 0\n    s = 0\n    while i < 1000000:\n        i = i + 1\n        s = s + 2\n    return s\n");
]

let best_of n f =
  let best = ref infinity and result = ref None in
  for _ = 1 to n do
    let t0 = Sys.time () in
    let r = f () in
    let t = Sys.time () -. t0 in
    if t < !best then best := t;
    result := Some r
  done;
  (!best, Option.get !result)

let load text =
  let m = match Parse.parse_string ~name:"bench.mod" text with Ok m -> m | Error d -> failwith (Diagnostic.to_string d) in
  match Rapid_load.Session.load_modules [ m ] with
  | Ok l -> l.program
  | Error _ -> failwith "the benchmark program does not check"

let machine program =
  match M.start ~host:(Rapid_run.Run.setup ()).host program ~entry:"main" with
  | Error m -> failwith m
  | Ok cfg ->
      let out = ref [] in
      while M.outcome cfg = Running do
        List.iter (function Rapid_runtime.Event.Output s -> out := s :: !out | _ -> ()) (snd (M.step cfg))
      done;
      (String.concat "" !out, M.steps cfg)

let closure ?all_events program =
  let out = ref [] in
  match C.run ~host:(Rapid_run.Run.setup ()).host ?all_events ~on_event:(function Rapid_runtime.Event.Output s -> out := s :: !out | _ -> ()) program ~entry:"main" with
  | Error m -> failwith m
  | Ok r -> (String.concat "" !out, r.fuel_used)

(* CPython's time for main(), best of three, measured by the interpreter itself. *)
let python source =
  let script = source ^ "import time\nbest = None\nfor _ in range(3):\n    t0 = time.process_time()\n\
                        \    main()\n    t = time.process_time() - t0\n    best = t if best is None or t < best else best\n\
                        print(best)\n" in
  let file = Filename.temp_file "engines_bench" ".py" in
  let oc = open_out file in
  output_string oc script; close_out oc;
  let ic = Unix.open_process_in ("python3 " ^ Filename.quote file) in
  let line = try Some (input_line ic) with End_of_file -> None in
  ignore (Unix.close_process_in ic);
  Sys.remove file;
  Option.bind line float_of_string_opt

let () =
  Gc.set { (Gc.get ()) with space_overhead = 400 };
  Printf.printf "%-32s %10s %10s %10s %10s %8s %8s\n" "program" "machine" "closure" "closure-o" "CPython"
    "CPy/clo" "CPy/clo-o";
  List.iter (fun (name, rapid, py) ->
      let program = load rapid in
      let tm, (out_m, _) = best_of 3 (fun () -> machine program) in
      let tc, (out_c, _) = best_of 3 (fun () -> closure program) in
      let to_, (out_o, _) = best_of 3 (fun () -> closure ~all_events:false program) in
      if out_m <> out_c || out_c <> out_o then Printf.printf "  (the engines' outputs differ: %S, %S)\n" out_m out_c;
      match python py with
      | Some tp -> Printf.printf "%-32s %10.4f %10.4f %10.4f %10.4f %8.1f %8.1f\n%!" name tm tc to_ tp (tp /. tc) (tp /. to_)
      | None -> Printf.printf "%-32s %10.4f %10.4f %10.4f %10s\n%!" name tm tc to_ "(no python3)")
    programs
