(* Steps per second and peak memory of the machine on the programs of issue 4's benchmark: a
   loop of 1,000,000 iterations with two assignments, recursive fib(25), and recursion 10,
   5,000 and 100,000 deep (the call-depth limit raised). Each program runs in a fresh child
   process, whose peak resident set (VmHWM) is read at the end. *)

open Rapid_syntax
module M = Rapid_semantics.Machine

let programs = [
  ("loop 1,000,000 x 2 assignments",
   "MODULE b\n  PROC main()\n    VAR num i := 0;\n    VAR num s := 0;\n    WHILE i < 1000000 DO\n\
   \      i := i + 1;\n      s := s + 2;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n", 10_000);
  ("fib(25), recursive",
   "MODULE b\n  FUNC num fib(num n)\n    IF n < 2 RETURN n;\n    RETURN fib(n - 1) + fib(n - 2);\n\
   \  ENDFUNC\n  PROC main()\n    VAR num r;\n    r := fib(25);\n  ENDPROC\nENDMODULE\n", 10_000);
] @ List.map (fun depth ->
    (Printf.sprintf "recursion %d deep" depth,
     Printf.sprintf "MODULE b\n  FUNC num down(num n)\n    IF n = 0 RETURN 0;\n    RETURN down(n - 1) + 1;\n\
                     \  ENDFUNC\n  PROC main()\n    VAR num r;\n    VAR num k := 0;\n\
                     \    WHILE k < %d DO\n      r := down(%d);\n      k := k + 1;\n    ENDWHILE\n\
                     \  ENDPROC\nENDMODULE\n" (max 1 (1_000_000 / depth)) depth,
     depth + 10)) [ 10; 5_000; 100_000 ]

let peak_kb () =
  let ic = open_in "/proc/self/status" in
  let rec find () =
    match input_line ic with
    | line when String.length line > 6 && String.sub line 0 6 = "VmHWM:" ->
        Scanf.sscanf line "VmHWM: %d kB" (fun k -> k)
    | _ -> find ()
    | exception End_of_file -> 0
  in
  let k = find () in
  close_in ic; k

let child index =
  (* As rapid-sem run sets it (bin/main.ml). *)
  Gc.set { (Gc.get ()) with space_overhead = 400 };
  let _, text, depth = List.nth programs index in
  let m = match Parse.parse_string ~name:"bench.mod" text with Ok m -> m | Error d -> failwith (Diagnostic.to_string d) in
  match Rapid_load.Session.load_modules [ m ] with
  | Error _ -> failwith "the benchmark program does not check"
  | Ok loaded ->
      let limits = { Rapid_runtime.Limits.default with max_call_depth = max depth Rapid_runtime.Limits.default.max_call_depth } in
      let cfg = match M.start ~host:(Rapid_run.Run.setup ()).host ~limits loaded.program ~entry:"main" with Ok c -> c | Error m -> failwith m in
      let t0 = Unix.gettimeofday () in
      while M.outcome cfg = Running do ignore (M.step cfg) done;
      let t = Unix.gettimeofday () -. t0 in
      (match M.outcome cfg with Ended -> () | _ -> failwith "the benchmark program did not end");
      Printf.printf "%d %f %d\n" (M.steps cfg) t (peak_kb ())

let () =
  match Sys.argv with
  | [| _; "--child"; i |] -> child (int_of_string i)
  | _ ->
      Printf.printf "%-34s %12s %9s %12s %10s %11s\n" "program" "steps" "seconds" "steps/s" "ns/step" "peak RSS";
      List.iteri (fun i (name, _, _) ->
          let ic = Unix.open_process_args_in Sys.executable_name [| Sys.executable_name; "--child"; string_of_int i |] in
          let line = input_line ic in
          ignore (Unix.close_process_in ic);
          Scanf.sscanf line "%d %f %d" (fun steps t kb ->
              Printf.printf "%-34s %12d %9.3f %12.0f %10.1f %8d KB\n%!" name steps t
                (float_of_int steps /. t) (t *. 1e9 /. float_of_int steps) kb)) programs
