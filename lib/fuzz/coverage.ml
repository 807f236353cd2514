module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)

(* done and stuck are in the machine's list but are not rules (doc/semantics.md, "Not rules"):
   done is the answer after the end, stuck a bug. *)
let rule_names =
  (* computed at every start of rapid-sem: a table of those seen, not a scan of the list *)
  let seen = Hashtbl.create 512 in
  List.filter (fun r ->
      if Hashtbl.mem seen r || r = "done" || r = "stuck" then false else (Hashtbl.replace seen r (); true))
    Rapid_semantics.Machine.rule_names

type t = {
  programs : int;
  failures : int;
  outcomes : (string * int) list;
  rules : (string * int) list;
  cpu_seconds : float;
}

(* Every named rule, with 0 for those never applied; rules a run reports that are not named in
   the list (none today) are kept after them, so that nothing is lost in a merge. *)
let complete counts =
  List.map (fun r -> (r, Option.value (List.assoc_opt r counts) ~default:0)) rule_names
  @ List.filter (fun (r, _) -> not (List.mem r rule_names)) counts

let of_summary (s : Campaign.summary) =
  { programs = s.programs; failures = List.length s.failures; outcomes = s.outcomes;
    rules = complete s.rules; cpu_seconds = s.cpu_seconds }

let applied t = List.length (List.filter (fun (r, n) -> n > 0 && List.mem r rule_names) t.rules)

let add_counts a b =
  let keys = List.sort_uniq compare (List.map fst a @ List.map fst b) in
  List.map (fun k ->
      (k, Option.value (List.assoc_opt k a) ~default:0 + Option.value (List.assoc_opt k b) ~default:0)) keys

let merge ts =
  let zero = { programs = 0; failures = 0; outcomes = []; rules = []; cpu_seconds = 0. } in
  let m = List.fold_left (fun acc t ->
      { programs = acc.programs + t.programs; failures = acc.failures + t.failures;
        outcomes = add_counts acc.outcomes t.outcomes; rules = add_counts acc.rules t.rules;
        cpu_seconds = acc.cpu_seconds +. t.cpu_seconds }) zero ts in
  { m with rules = complete m.rules }

let to_json t : Yojson.Safe.t =
  let counts l = `Assoc (List.map (fun (k, n) -> (k, `Int n)) l) in
  `Assoc [ ("programs", `Int t.programs); ("failures", `Int t.failures);
           ("cpu_seconds", `Float t.cpu_seconds); ("outcomes", counts t.outcomes);
           ("rules_total", `Int (List.length rule_names)); ("rules_applied", `Int (applied t));
           ("rules", counts t.rules) ]

let of_json (j : Yojson.Safe.t) =
  let counts = function
    | `Assoc l -> List.filter_map (fun (k, v) -> match v with `Int n -> Some (k, n) | _ -> None) l
    | _ -> [] in
  match j with
  | `Assoc l -> (
      let field k = List.assoc_opt k l in
      match field "programs", field "failures", field "rules" with
      | Some (`Int programs), Some (`Int failures), Some rules ->
          let cpu_seconds = match field "cpu_seconds" with
            | Some (`Float f) -> f | Some (`Int n) -> float n | _ -> 0. in
          Ok { programs; failures; cpu_seconds;
               outcomes = (match field "outcomes" with Some o -> counts o | None -> []);
               rules = complete (counts rules) }
      | _ -> Error "not a coverage.json of rapid-sem fuzz: programs, failures and rules are missing")
  | _ -> Error "not a coverage.json of rapid-sem fuzz: not an object"

let to_markdown t =
  let b = Buffer.create 4096 in
  let total = List.length rule_names in
  Printf.bprintf b "%d programs, %d failures; %d of %d named rules of doc/semantics.md applied.\n\n"
    t.programs t.failures (applied t) total;
  Printf.bprintf b "Outcomes: %s.\n\n"
    (String.concat ", " (List.map (fun (k, n) -> Printf.sprintf "%s %d" k n) t.outcomes));
  Buffer.add_string b "| rule | applied |\n|---|---:|\n";
  List.iter (fun (r, n) -> Printf.bprintf b "| %s | %d |\n" r n) t.rules;
  let never = List.filter_map (fun (r, n) -> if n = 0 then Some r else None) t.rules in
  if never <> [] then
    Printf.bprintf b "\nNever applied (%d): %s.\n" (List.length never) (String.concat ", " never);
  Buffer.contents b

let write_file path text =
  let oc = open_out_bin path in
  Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text)

let write ~dir t =
  if not (Sys.file_exists dir) then Sys.mkdir dir 0o755;
  write_file (Filename.concat dir "coverage.json") (Json_text.pretty_to_string (to_json t) ^ "\n");
  write_file (Filename.concat dir "coverage.md") (to_markdown t)

let read path =
  match Yojson.Safe.from_file path with
  | j -> Result.map_error (fun m -> path ^ ": " ^ m) (of_json j)
  | exception Yojson.Json_error m -> Error (path ^ ": " ^ m)
  | exception Sys_error m -> Error m
