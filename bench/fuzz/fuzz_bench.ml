(* Where a generated program's processor time goes (bench/README.md, "Fuzzing throughput"): each phase of
   what [rapid-sem fuzz] does to a program, timed alone over the same programs, then the whole
   of Fuzz_run.check_program with both engines, in programs per second on one core. *)

open Rapid_syntax
module G = Rapid_fuzz.Program_gen
module F = Rapid_fuzz.Fuzz_run

let count = ref 1000
let seed = ref 1
let detail = ref false

let time name n f =
  Gc.compact ();
  let minor0 = (Gc.quick_stat ()).minor_words in
  let t0 = Sys.time () in
  let r = f () in
  let dt = Sys.time () -. t0 in
  let words = (Gc.quick_stat ()).minor_words -. minor0 in
  Printf.printf "  %-34s %8.3f ms/program  %9.0f programs/s  %8.0f kwords/program\n%!" name
    (1000. *. dt /. float n) (float n /. dt) (words /. 1000. /. float n);
  (r, dt)

let () =
  Arg.parse [ ("--count", Arg.Set_int count, "N programs (1000)"); ("--seed", Arg.Set_int seed, "S the seed (1)");
              ("--hostile-detail", Arg.Set detail, " the slowest hostile texts, each timed alone") ]
    (fun _ -> raise (Arg.Bad "no positional arguments")) "fuzz_bench [--count N] [--seed S] [--hostile-detail]";
  let n = !count in
  (* the garbage collector as rapid-sem fuzz sets it *)
  Rapid_fuzz.Campaign.tune_gc ();
  Printf.printf "Fuzzing throughput, %d programs, seed %d, one core\n" n !seed;
  (* The first load elaborates whatever is shared between programs: not a program's cost. *)
  ignore (F.check_program "MODULE m\n  PROC main()\n  ENDPROC\nENDMODULE\n");
  let programs, _ = time "generate" n (fun () ->
      List.init n (fun i -> G.generate (Rapid_fuzz.Campaign.program_seed ~seed:!seed i))) in
  let sources, _ = time "to_source" n (fun () -> List.map G.to_source programs) in
  let trees, _ = time "parse" n (fun () ->
      List.map (fun s -> match Parse.parse_string ~name:"fuzz.mod" s with Ok m -> m | Error _ -> failwith "parse") sources) in
  let _ = time "print + parse again + compare" n (fun () ->
      List.iter (fun m ->
          let printed = Printer.module_declaration m in
          match Parse.parse_string ~name:"fuzz.mod" printed with
          | Ok m' -> ignore (Ast_erase.equal m m')
          | Error _ -> failwith "round trip") trees) in
  (* the signals the generated programs use, in one installed list for every program, as
     Fuzz_run.load has it *)
  let io = F.io in
  let installed = match Rapid_load.Session.installed ~io () with Ok i -> i | Error _ -> failwith "installed" in
  let checked, _ = time "check" n (fun () ->
      List.map (fun m ->
          let r = Rapid_typing.Check.check_task ~installed [ m ] in
          if Rapid_typing.Check.errors r <> [] then failwith "a generated program does not check";
          (m, r)) trees) in
  let lowered, _ = time "lower" n (fun () ->
      List.map (fun (m, (r : Rapid_typing.Check.result)) ->
          Rapid_runtime.Lower.program ~installed ~modules:[ m ] r.elaboration) checked) in
  let _ = time "initial values" n (fun () -> List.iter (fun p -> ignore (Rapid_runtime.Initial_values.evaluate p)) lowered) in
  let loaded, _ = time "lower + initial values" n (fun () ->
      List.map (fun (m, r) -> match Rapid_load.Session.lower ~io ~installed ~modules:[ m ] r with
        | Ok p -> p | Error _ -> failwith "lower") checked) in
  let _ = time "machine run" n (fun () -> List.iter (fun p -> ignore (F.machine.run p ~max_steps:200_000)) loaded) in
  let _ = time "closure run" n (fun () -> List.iter (fun p -> ignore (F.closure.run p ~max_steps:200_000)) loaded) in
  let _, dt = time "whole: check_program, both engines" n (fun () ->
      List.iter (fun s -> match F.check_program ~engines:[ F.closure ] s with
        | Ok _ -> () | Error f -> failwith (F.failure_to_string f)) sources) in
  let _, dg = time "whole + generate + to_source" n (fun () ->
      for i = 0 to n - 1 do
        let s = G.to_source (G.generate (Rapid_fuzz.Campaign.program_seed ~seed:!seed i)) in
        ignore (F.check_program ~engines:[ F.closure ] s)
      done) in
  ignore dt;
  (* What the default configuration adds (one mutant a program, a hostile text every ten), made
     as Campaign.check_texts makes them, timed per program of the campaign. *)
  let module M = Rapid_fuzz.Mutant in
  let texts i = Random.State.make [| !seed; i; 7919 |] in
  let mutants = List.mapi (fun i s -> M.mutate (texts i) s) sources in
  let _ = time "mutants (one a program)" n (fun () -> List.iter (fun t -> ignore (M.check_text t)) mutants) in
  let hostiles = List.filteri (fun i _ -> i mod 10 = 0) sources
                 |> List.mapi (fun k s -> let rs = texts (10 * k) in ignore (M.mutate rs s); M.hostile rs) in
  (* A change for speed must leave the texts as they were: compare this line between builds. *)
  Printf.printf "  texts made: digest %s\n%!" (Digest.to_hex (Digest.string (String.concat "\000" (mutants @ hostiles))));
  let _ = time "hostile texts (one every ten)" n (fun () -> List.iter (fun t -> ignore (M.check_text t)) hostiles) in
  if !detail then begin
    (* each hostile text alone, the slowest first: which kinds the time goes to *)
    let timed = List.map (fun t ->
        let t0 = Sys.time () in ignore (M.check_text t); (Sys.time () -. t0, t)) hostiles in
    List.iter (fun (dt, t) ->
        Printf.printf "  %8.3f ms  %7d bytes  %S\n" (1000. *. dt) (String.length t)
          (String.sub t 0 (min 40 (String.length t))))
      (List.filteri (fun i _ -> i < 25) (List.sort (fun (a, _) (b, _) -> compare b a) timed))
  end;
  Printf.printf "throughput: %.0f programs/s/core (generated, checked and run by both engines)\n" (float n /. dg)
