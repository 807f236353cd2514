(* rapid-sem mem: program memory by chapter 16 (doc/memory.md). *)

module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
open Cmdliner
open Rapid_syntax
module P = Rapid_memory.Program_memory

let rec print_item indent (i : P.item) =
  Printf.printf "%s%-*s %8d\n" (String.make indent ' ') (48 - indent) i.label i.bytes;
  List.iter (print_item (indent + 2)) i.parts

let rec item_json (i : P.item) : Yojson.Safe.t =
  `Assoc ([ ("label", `String i.label); ("bytes", `Int i.bytes) ]
          @ if i.parts = [] then [] else [ ("parts", `List (List.map item_json i.parts)) ])

let cmd =
  let files = Arg.(non_empty & pos_all string [] & info [] ~docv:"FILE" ~doc:"RAPID module files: one task buffer.") in
  let json = Arg.(value & flag & info [ "json" ] ~doc:"One JSON object per module instead of the table.") in
  let run files json =
    let parsed = List.map (fun f -> Parse.parse_file f) files in
    match List.filter_map (function Error d -> Some d | Ok _ -> None) parsed with
    | (_ :: _) as errors -> List.iter (fun d -> prerr_endline (Diagnostic.to_string d)) errors; 2
    | [] ->
        let modules = List.filter_map Result.to_option parsed in
        let installed = match Rapid_typing.Installed_env.modules () with Ok l -> l | Error _ -> [] in
        let total = ref 0 in
        List.iter (fun m ->
            let item = P.module_memory ~records:(modules @ installed) m in
            total := !total + item.bytes;
            if json then print_endline (Json_text.to_string (item_json item)) else print_item 0 item) modules;
        if not json && List.length modules > 1 then Printf.printf "%-48s %8d\n" "task buffer" !total;
        0
  in
  let doc = "the program memory each module, declaration, routine and statement takes (ch. 16)" in
  let man = [
    `S Manpage.s_description;
    `P "Prints, for each module, the bytes of program memory (internal format) it takes by the \
        model of doc/memory.md: the figures of chapter 16 of the RAPID kernel manual for the \
        constructs it lists, and an additive model fitted to them for the rest. Each line is a \
        module, a declaration, a routine or a statement (by its line), indented under what \
        holds it.";
    `S Manpage.s_exit_status; `P "0; 2 when a module does not parse.";
  ] in
  Cmd.v (Cmd.info "mem" ~doc ~man) Term.(const run $ files $ json)
