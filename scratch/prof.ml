open Rapid_syntax
let t = Hashtbl.create 8
let time k f = let s = Unix.gettimeofday () in let r = f () in
  Hashtbl.replace t k ((try Hashtbl.find t k with Not_found -> 0.) +. Unix.gettimeofday () -. s); r
let () =
  for i = 0 to 299 do
    let p = time "gen" (fun () -> Rapid_fuzz.Program_gen.generate (Rapid_fuzz.Campaign.program_seed ~seed:1 i)) in
    let src = time "print" (fun () -> Rapid_fuzz.Program_gen.to_source p) in
    let m = match time "parse" (fun () -> Parse.parse_string ~name:"f.mod" src) with Ok m -> m | Error _ -> assert false in
    let pr = time "printer" (fun () -> Printer.module_declaration m) in
    let m' = match time "parse2" (fun () -> Parse.parse_string ~name:"f.mod" pr) with Ok m -> m | Error _ -> assert false in
    ignore (time "dump" (fun () -> Ast_dump.module_declaration m = Ast_dump.module_declaration m'));
    let installed = match Rapid_typing.Installed_env.modules () with Ok i -> i | Error _ -> assert false in
    let r = time "check" (fun () -> Rapid_typing.Check.check_task ~options:{ allow_unknown = false } ~installed [ m ]) in
    let prog = time "lower" (fun () -> Rapid_semantics.Lower.program ~installed ~modules:[ m ] r.elaboration) in
    ignore (time "run" (fun () -> Rapid_fuzz.Fuzz_run.machine.run prog ~max_steps:200000))
  done;
  Hashtbl.iter (fun k v -> Printf.printf "%-8s %.3f s\n" k v) t
