(* The parse benchmark: throughput, linearity and peak memory of the front end
   (Parse.parse_string: decode, lex, parse, and the nesting check) on generated CAD-style
   modules (gen.ml). bench/README.md explains the figures and records them.

   Each size is measured in a fresh child process (this executable run with --child), so that
   the peak resident set of one size is not the heap left over by another: the child reads its
   VmHWM before it reads the file and again after the first parse, with the tree still alive.

   Sizes are in MiB (2^20 bytes) and throughput in MiB/s. *)

open Rapid_syntax

let mib = 1048576.

(* Wall-clock and processor time of [f ()]. *)
let time f =
  let cpu () = let t = Unix.times () in t.tms_utime +. t.tms_stime in
  let w = Unix.gettimeofday () and c = cpu () in
  let r = f () in
  (r, Unix.gettimeofday () -. w, cpu () -. c)

(* ------------------------------------------------------------------ the child *)

(* Peak resident set of this process in bytes, from /proc/self/status. *)
let vm_hwm () =
  let ic = open_in "/proc/self/status" in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () ->
      let rec find () =
        match input_line ic with
        | l when String.length l > 6 && String.sub l 0 6 = "VmHWM:" ->
            Scanf.sscanf (String.sub l 6 (String.length l - 6)) " %d kB" (fun k -> k * 1024)
        | _ -> find ()
        | exception End_of_file -> failwith "no VmHWM in /proc/self/status"
      in
      find ())

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () ->
      really_input_string ic (in_channel_length ic))

(* Decode, then every token to the end of the file: the lexer's share of a parse. *)
let lex_only name contents =
  let d = Decode.decode contents in
  let file = Source.register ~name ~line_starts:d.line_starts in
  let lx = Lexer.create file d in
  let rec go n = match Lexer.next lx with
    | Parser.EOF, _, _ -> n + 1
    | _ -> go (n + 1)
  in
  go 0

let with_backend backend name contents =
  let d = Decode.decode contents in
  backend (Source.register ~name ~line_starts:d.line_starts) d

let best l = List.fold_left min infinity l

let median l =
  let a = Array.of_list l in
  Array.sort compare a;
  a.(Array.length a / 2)

let fail fmt = Printf.ksprintf (fun s -> prerr_endline ("bench: " ^ s); exit 1) fmt

(* [runs] timings of [f], as (wall, cpu) lists. Each run starts from a compacted heap, as the
   first parse of the child starts from a fresh one: it does not pay for collecting what the
   run before it left. *)
let timings runs f =
  List.split (List.init runs (fun _ ->
      Gc.compact ();
      let _, w, c = time (fun () -> Sys.opaque_identity (f ())) in
      (w, c)))

let child path runs =
  let baseline = vm_hwm () in
  let contents = read_file path in
  let result, first, first_cpu = time (fun () -> Parse.parse_string ~name:path contents) in
  let m = match result with
    | Ok m -> m
    | Error d -> fail "the generated module does not parse: %s" (Diagnostic.to_string d)
  in
  let peak = vm_hwm () - baseline in
  let top_heap = (Gc.quick_stat ()).top_heap_words * (Sys.word_size / 8) in
  let tree = Obj.reachable_words (Obj.repr m) * (Sys.word_size / 8) in
  (match List.filter (fun (_, n) -> n = 0) (Coverage.count m) with
   | [] -> ()
   | missing -> fail "the generated module lacks: %s" (String.concat ", " (List.map fst missing)));
  (* The experiment: both back ends must give the same tree. *)
  (match
     let d = Decode.decode contents in
     let file = Source.register ~name:path ~line_starts:d.line_starts in
     (Backends.table file d, Backends.code file d)
   with
   | (Backends.Tree _ as a), b when Backends.same a b -> ()
   | a, b -> fail "back ends disagree: table gives %s, code gives %s"
               (Backends.describe a) (Backends.describe b));
  let walls, cpus = timings (runs - 1) (fun () -> Parse.parse_string ~name:path contents) in
  let walls = first :: walls and cpus = first_cpu :: cpus in
  let decode, _ = timings runs (fun () -> Decode.decode contents) in
  let tokens = lex_only path contents in
  let lex, _ = timings runs (fun () -> lex_only path contents) in
  (* Parse raises the collector's space_overhead to 1000 for texts of 512 KiB and more
     (parse.ml); the two back ends are compared under that same setting. *)
  let as_parse f () =
    let old = Gc.get () in
    if String.length contents < 512 * 1024 || old.space_overhead >= 1000 then f ()
    else begin
      Gc.set { old with space_overhead = 1000 };
      Fun.protect f ~finally:(fun () -> Gc.set old)
    end
  in
  let table, _ = timings runs (as_parse (fun () -> with_backend Backends.table path contents)) in
  let code, _ = timings runs (as_parse (fun () -> with_backend Backends.code path contents)) in
  Printf.printf "RESULT bytes=%d tokens=%d first=%f best=%f median=%f cpu=%f decode=%f lex=%f \
                 table=%f code=%f peak=%d top_heap=%d tree=%d\n"
    (String.length contents) tokens first (best walls) (median walls)
    (best cpus) (best decode) (best lex) (best table) (best code)
    peak top_heap tree

(* For a profiler (perf record ... bench.exe --profile FILE): one phase alone, [runs] times. *)
let profile path runs phase =
  let contents = read_file path in
  for _ = 1 to runs do
    match phase with
    | "decode" -> ignore (Sys.opaque_identity (Decode.decode contents))
    | "lex" -> ignore (Sys.opaque_identity (lex_only path contents))
    | "table" -> ignore (Sys.opaque_identity (with_backend Backends.table path contents))
    | "code" -> ignore (Sys.opaque_identity (with_backend Backends.code path contents))
    | _ ->
        match Parse.parse_string ~name:path contents with
        | Ok m -> ignore (Sys.opaque_identity m)
        | Error d -> fail "%s" (Diagnostic.to_string d)
  done

(* ------------------------------------------------------------------ the parent *)

type result = {
  bytes : int; tokens : int; first : float; best : float; median : float; cpu : float;
  decode : float; lex : float; table : float; code : float; peak : int; top_heap : int;
  tree : int }

let run_child path runs =
  let ic = Unix.open_process_args_in Sys.executable_name
      [| Sys.executable_name; "--child"; path; "--runs"; string_of_int runs |] in
  let line = try Some (input_line ic) with End_of_file -> None in
  match Unix.close_process_in ic, line with
  | Unix.WEXITED 0, Some l ->
      Scanf.sscanf l "RESULT bytes=%d tokens=%d first=%f best=%f median=%f cpu=%f decode=%f \
                      lex=%f table=%f code=%f peak=%d top_heap=%d tree=%d"
        (fun bytes tokens first best median cpu decode lex table code peak top_heap tree ->
           { bytes; tokens; first; best; median; cpu; decode; lex; table; code; peak; top_heap;
             tree })
  | _ -> fail "measuring %s failed (see above)" path

let report results =
  let mb b = float_of_int b /. mib in
  let rate r t = mb r.bytes /. t in
  let ratio r b = float b /. float r.bytes in
  print_endline "\nThroughput of Parse.parse_string (decode + lex + parse + nesting check):";
  Printf.printf "%8s %8s %8s %8s %8s %8s %8s %8s %8s\n"
    "size" "tokens" "first" "best" "median" "MiB/s" "MiB/s" "MiB/s" "s/MiB";
  Printf.printf "%8s %8s %8s %8s %8s %8s %8s %8s %8s\n"
    "MiB" "" "s" "s" "s" "best" "median" "cpu" "median";
  List.iter (fun r ->
      Printf.printf "%8.2f %8d %8.3f %8.3f %8.3f %8.1f %8.1f %8.1f %8.4f\n"
        (mb r.bytes) r.tokens r.first r.best r.median (rate r r.best) (rate r r.median)
        (rate r r.cpu) (r.median /. mb r.bytes)) results;
  print_endline "\nPhases (best of the runs, MiB/s; each column from the start of the text) and \
                 the code back-end experiment:";
  Printf.printf "%8s %8s %8s %8s %8s %8s\n" "size" "decode" "+lex" "+table" "all" "+code";
  Printf.printf "%8s %8s %8s %8s %8s %8s\n" "MiB" "" "" "parse" "(Parse)" "parse";
  List.iter (fun r ->
      Printf.printf "%8.2f %8.0f %8.1f %8.1f %8.1f %8.1f\n" (mb r.bytes) (rate r r.decode)
        (rate r r.lex) (rate r r.table) (rate r r.best) (rate r r.code)) results;
  print_endline "\nMemory (after the first parse, with the tree alive):";
  Printf.printf "%8s %9s %6s %9s %6s %9s %6s\n" "size" "peak RSS" "x" "top heap" "x" "tree" "x";
  Printf.printf "%8s %9s %6s %9s %6s %9s %6s\n" "MiB" "MiB" "file" "MiB" "file" "MiB" "file";
  List.iter (fun r ->
      Printf.printf "%8.2f %9.1f %6.2f %9.1f %6.2f %9.1f %6.2f\n" (mb r.bytes) (mb r.peak)
        (ratio r r.peak) (mb r.top_heap) (ratio r r.top_heap) (mb r.tree) (ratio r r.tree))
    results;
  print_endline "\npeak RSS: VmHWM after the first parse less VmHWM before the file was read \
                 (the text itself is counted);";
  print_endline "top heap: Gc top_heap_words x 8; tree: Obj.reachable_words of the module's \
                 tree x 8.";
  (match results with
   | first :: _ :: _ ->
       let last = List.nth results (List.length results - 1) in
       let per r = r.median /. mb r.bytes in
       Printf.printf "linearity: s/MiB at %.1f MiB is %.2f x s/MiB at %.1f MiB (1.00 = linear)\n"
         (mb last.bytes) (per last /. per first) (mb first.bytes)
   | _ -> ());
  let slowest = List.fold_left (fun a r -> min a (rate r r.median)) infinity results in
  let worst = List.fold_left (fun a r -> max a (ratio r r.peak)) 0. results in
  Printf.printf "targets: >= 30 MiB/s: %s (slowest median %.1f MiB/s); peak < 10 x file: %s \
                 (worst %.2f x)\n"
    (if slowest >= 30. then "met" else "NOT met") slowest
    (if worst < 10. then "met" else "NOT met") worst

let parent sizes seed runs keep =
  (* Kept modules have stable names; the others are temporary files of their own, so that two
     benchmarks can run at once. *)
  let module_file size =
    let name = Printf.sprintf "cad_%g_MiB_seed%d" size seed in
    match keep with
    | Some d ->
        if not (Sys.file_exists d) then Sys.mkdir d 0o755;
        Filename.concat d (name ^ ".mod")
    | None -> Filename.temp_file name ".mod"
  in
  Printf.printf "rapid-sem parse benchmark: seed %d, %d run(s) per size, OCaml %s\n%!"
    seed runs Sys.ocaml_version;
  let results = List.map (fun size ->
      let text, gen, _ = time (fun () -> Gen.generate ~seed ~size:(int_of_float (size *. mib))) in
      let path = module_file size in
      let oc = open_out_bin path in
      output_string oc text;
      close_out oc;
      Printf.printf "  generated %s (%d bytes) in %.2f s\n%!" path (String.length text) gen;
      (* The memory the previous child gave back is still being reclaimed by the system for a
         moment; a child started at once measured its first phases up to twice slower. *)
      Unix.sleepf 5.;
      let r = Fun.protect ~finally:(fun () -> if keep = None then Sys.remove path)
          (fun () -> run_child path runs) in
      Printf.printf "  measured: %.1f MiB/s (median), peak %.2f x file\n%!"
        (float r.bytes /. mib /. r.median) (float r.peak /. float r.bytes);
      r) sizes
  in
  report results

let () =
  let sizes = ref "1,3,10,30" and seed = ref 1 and runs = ref 3 and keep = ref None
  and child_file = ref None and profile_file = ref None and phase = ref "parse" in
  Arg.parse
    [ ("--sizes", Arg.Set_string sizes,
       "LIST  sizes in MiB, comma-separated (default 1,3,10,30)");
      ("--seed", Arg.Set_int seed, "N  seed of the generator (default 1)");
      ("--runs", Arg.Set_int runs,
       "N  timed runs per size (default 3; the first also measures memory)");
      ("--keep", Arg.String (fun d -> keep := Some d),
       "DIR  write the generated modules to DIR and keep them");
      ("--profile", Arg.String (fun f -> profile_file := Some f),
       "FILE  run one phase on FILE --runs times and nothing else (to run under a profiler)");
      ("--phase", Arg.Set_string phase,
       "decode|lex|table|code|parse  the phase --profile runs (default parse)");
      ("--child", Arg.String (fun f -> child_file := Some f),
       "FILE  (internal) measure FILE in this process") ]
    (fun a -> raise (Arg.Bad ("unexpected argument " ^ a)))
    "bench.exe [--sizes 1,3,10,30] [--seed N] [--runs N] [--keep DIR]";
  let runs = max 1 !runs in
  match !child_file, !profile_file with
  | Some f, _ -> child f runs
  | None, Some f -> profile f runs !phase
  | None, None ->
      let sizes = List.map (fun s -> float_of_string (String.trim s))
          (String.split_on_char ',' !sizes) in
      parent sizes !seed runs !keep
