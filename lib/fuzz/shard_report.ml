type failure_entry = {
  program : int;
  kind : string;
  message : string;
  original_size : int;
  minimal_size : int;
  reproducer : string;
  source : string;
}

type t = {
  settings : (string * string) list;
  shard : Campaign.shard;
  host : string;
  programs : int;
  failures : failure_entry list;
  outcomes : (string * int) list;
  rules : (string * int) list;
  seconds : float;
  cpu_seconds : float;
}

let format = "rapid-sem fuzz shard 1"
let merged_format = "rapid-sem fuzz campaign 1"

let kind : Fuzz_run.failure -> string = function
  | Refused _ -> "refused" | Exception _ -> "exception" | Stuck _ -> "stuck"
  | Nondeterministic _ -> "nondeterministic" | Engines_differ _ -> "engines-differ"
  | Round_trip _ -> "round-trip" | Checker_crashed _ -> "checker-crashed"

let of_summary ~settings ~shard ~host ~reproducer (s : Campaign.summary) =
  let cov = Coverage.of_summary s in
  { settings; shard; host; programs = s.programs; outcomes = cov.outcomes; rules = cov.rules;
    seconds = s.seconds; cpu_seconds = s.cpu_seconds;
    failures = List.map (fun (f : Campaign.failure_found) ->
        { program = f.program_index; kind = kind f.failure; message = Fuzz_run.failure_to_string f.failure;
          original_size = f.original_size; minimal_size = f.minimal_size; reproducer = reproducer f;
          source = f.source }) s.failures }

let counts l : Yojson.Safe.t = `Assoc (List.map (fun (k, n) -> (k, `Int n)) l)
let strings l : Yojson.Safe.t = `Assoc (List.map (fun (k, v) -> (k, `String v)) l)

let failure_json f : Yojson.Safe.t =
  `Assoc [ ("program", `Int f.program); ("kind", `String f.kind); ("message", `String f.message);
           ("original_size", `Int f.original_size); ("minimal_size", `Int f.minimal_size);
           ("reproducer", `String f.reproducer); ("source", `String f.source) ]

let applied rules = List.length (List.filter (fun (r, n) -> n > 0 && List.mem r Coverage.rule_names) rules)

let to_json t : Yojson.Safe.t =
  `Assoc [ ("format", `String format); ("settings", strings t.settings);
           ("shard", `Assoc [ ("index", `Int t.shard.index); ("count", `Int t.shard.count) ]);
           ("host", `String t.host); ("programs", `Int t.programs);
           ("failures", `List (List.map failure_json t.failures)); ("outcomes", counts t.outcomes);
           ("rules_total", `Int (List.length Coverage.rule_names)); ("rules_applied", `Int (applied t.rules));
           ("rules", counts t.rules); ("seconds", `Float t.seconds); ("cpu_seconds", `Float t.cpu_seconds) ]

(* Reading: every field checked, an error naming the first one missing or of the wrong type. *)
exception Bad of string

let field l k = match List.assoc_opt k l with Some v -> v | None -> raise (Bad ("the field " ^ k ^ " is missing"))
let int_of l k = match field l k with `Int n -> n | _ -> raise (Bad (k ^ " is not a whole number"))
let string_of l k = match field l k with `String s -> s | _ -> raise (Bad (k ^ " is not a string"))
let float_of l k = match field l k with
  | `Float f -> f | `Int n -> float n | _ -> raise (Bad (k ^ " is not a number"))
let obj what = function `Assoc l -> l | _ -> raise (Bad (what ^ " is not an object"))
let counts_of l k = List.map (fun (r, v) -> match v with
    | `Int n -> (r, n) | _ -> raise (Bad (Printf.sprintf "%s.%s is not a whole number" k r))) (obj k (field l k))

let failure_of j =
  let l = obj "a failure" j in
  { program = int_of l "program"; kind = string_of l "kind"; message = string_of l "message";
    original_size = int_of l "original_size"; minimal_size = int_of l "minimal_size";
    reproducer = string_of l "reproducer"; source = string_of l "source" }

let of_json j =
  try
    let l = obj "the report" j in
    if string_of l "format" <> format then
      raise (Bad (Printf.sprintf "format %S, not %S (rapid-sem fuzz --json)" (string_of l "format") format));
    let shard = obj "shard" (field l "shard") in
    let settings = List.map (fun (k, v) -> match v with
        | `String s -> (k, s) | _ -> raise (Bad ("settings." ^ k ^ " is not a string")))
        (obj "settings" (field l "settings")) in
    let failures = match field l "failures" with
      | `List fs -> List.map failure_of fs | _ -> raise (Bad "failures is not a list") in
    let index = int_of shard "index" and count = int_of shard "count" in
    if count < 1 || index < 1 || index > count then raise (Bad (Printf.sprintf "shard %d/%d" index count));
    Ok { settings; shard = { index; count }; host = string_of l "host"; programs = int_of l "programs"; failures;
         outcomes = counts_of l "outcomes"; rules = counts_of l "rules"; seconds = float_of l "seconds";
         cpu_seconds = float_of l "cpu_seconds" }
  with Bad m -> Error ("not a shard report of rapid-sem fuzz --json: " ^ m)

let read path =
  match Yojson.Safe.from_file path with
  | j -> Result.map_error (fun m -> path ^ ": " ^ m) (of_json j)
  | exception Yojson.Json_error m -> Error (path ^ ": " ^ String.escaped m)
  | exception Sys_error m -> Error (if String.length m >= String.length path
                                       && String.sub m 0 (String.length path) = path then m else path ^ ": " ^ m)

type merged = {
  m_settings : (string * string) list;
  shards : t list;
  m_programs : int;
  m_failures : failure_entry list;
  m_outcomes : (string * int) list;
  m_rules : (string * int) list;
}

let add_counts a b =
  let keys = List.sort_uniq compare (List.map fst a @ List.map fst b) in
  List.map (fun k -> (k, Option.value (List.assoc_opt k a) ~default:0 + Option.value (List.assoc_opt k b) ~default:0))
    keys

(* Coverage.merge keeps the rules in the order of doc/semantics.md. *)
let as_coverage (t : t) : Coverage.t =
  { programs = t.programs; failures = List.length t.failures; outcomes = t.outcomes; rules = t.rules;
    cpu_seconds = t.cpu_seconds }

let merge = function
  | [] -> Error "no shard report to merge"
  | first :: _ as ts ->
      let n = first.shard.count in
      let differ = List.find_opt (fun t -> t.settings <> first.settings || t.shard.count <> n) ts in
      match differ with
      | Some t ->
          let show s = String.concat ", " (List.map (fun (k, v) -> k ^ "=" ^ v) s) in
          Error (Printf.sprintf "shard %d/%d is not of the same campaign as shard %d/%d: %s against %s" t.shard.index
                   t.shard.count first.shard.index n (show t.settings) (show first.settings))
      | None ->
          let indexes = List.map (fun t -> t.shard.index) ts in
          let missing = List.filter (fun k -> not (List.mem k indexes)) (List.init n (fun k -> k + 1)) in
          let twice = List.filter (fun k -> List.length (List.filter (( = ) k) indexes) > 1)
              (List.sort_uniq compare indexes) in
          let show l = String.concat ", " (List.map string_of_int l) in
          if missing <> [] then Error (Printf.sprintf "shard%s %s of %d missing"
                                         (if List.length missing > 1 then "s" else "") (show missing) n)
          else if twice <> [] then Error (Printf.sprintf "shard %s of %d given more than once" (show twice) n)
          else
            let shards = List.sort (fun a b -> compare a.shard.index b.shard.index) ts in
            let cov = Coverage.merge (List.map as_coverage shards) in
            (* each program is in one shard, and a shard keeps its programs' failures in order:
               a stable sort by program gives the unsharded order *)
            let failures = List.stable_sort (fun a b -> compare a.program b.program)
                (List.concat_map (fun t -> t.failures) shards) in
            Ok { m_settings = first.settings; shards; m_programs = cov.programs; m_failures = failures;
                 m_outcomes = List.fold_left (fun acc t -> add_counts acc t.outcomes) [] shards;
                 m_rules = cov.rules }

let coverage m = Coverage.merge (List.map as_coverage m.shards)

let per_second n s = if s > 0. then float n /. s else 0.

let merged_to_json m : Yojson.Safe.t =
  let shard t : Yojson.Safe.t =
    `Assoc [ ("index", `Int t.shard.index); ("host", `String t.host); ("programs", `Int t.programs);
             ("failures", `Int (List.length t.failures)); ("rules_applied", `Int (applied t.rules));
             ("seconds", `Float t.seconds); ("cpu_seconds", `Float t.cpu_seconds);
             ("programs_per_cpu_second", `Float (per_second t.programs t.cpu_seconds)) ] in
  let cpu = List.fold_left (fun s t -> s +. t.cpu_seconds) 0. m.shards in
  let slowest = List.fold_left (fun s t -> Float.max s t.seconds) 0. m.shards in
  `Assoc [ ("format", `String merged_format); ("settings", strings m.m_settings);
           ("totals", `Assoc [ ("programs", `Int m.m_programs); ("failures", `Int (List.length m.m_failures));
                               ("outcomes", counts m.m_outcomes);
                               ("rules_total", `Int (List.length Coverage.rule_names));
                               ("rules_applied", `Int (applied m.m_rules)); ("rules", counts m.m_rules) ]);
           ("failures", `List (List.map failure_json m.m_failures));
           ("shards", `Assoc [ ("count", `Int (List.length m.shards)); ("cpu_seconds", `Float cpu);
                               ("slowest_seconds", `Float slowest);
                               ("programs_per_cpu_second", `Float (per_second m.m_programs cpu));
                               ("each", `List (List.map shard m.shards)) ]) ]

let first_line s = match String.index_opt s '\n' with Some i -> String.sub s 0 i | None -> s
let cell s =
  let s = first_line s in
  let s = if String.length s > 160 then String.sub s 0 157 ^ "..." else s in
  String.concat "\\|" (String.split_on_char '|' (String.escaped s))

let merged_to_markdown m =
  let b = Buffer.create 4096 in
  let n = List.length m.shards in
  let setting k = Option.value (List.assoc_opt k m.m_settings) ~default:"?" in
  let cpu = List.fold_left (fun s t -> s +. t.cpu_seconds) 0. m.shards in
  let slowest = List.fold_left (fun s t -> Float.max s t.seconds) 0. m.shards in
  Printf.bprintf b "# Fuzz campaign: %d programs, seed %s, %d shard%s\n\n" m.m_programs (setting "seed") n
    (if n = 1 then "" else "s");
  Printf.bprintf b "%d programs, %d failures; %d of %d named rules applied.\n\n" m.m_programs
    (List.length m.m_failures) (applied m.m_rules) (List.length Coverage.rule_names);
  Printf.bprintf b "Outcomes: %s.\n\n"
    (String.concat ", " (List.map (fun (k, n) -> Printf.sprintf "%s %d" k n) m.m_outcomes));
  Printf.bprintf b "Settings: %s.\n\n" (String.concat ", " (List.map (fun (k, v) -> k ^ " " ^ v) m.m_settings));
  Printf.bprintf b "Processor time %.1f s in all (%.0f programs per second of processor time); the slowest shard \
                    took %.1f s.\n\n" cpu (per_second m.m_programs cpu) slowest;
  if m.m_failures = [] then Buffer.add_string b "## Failures\n\nNone.\n\n"
  else begin
    Printf.bprintf b "## Failures (%d)\n\n| program | kind | statements (from) | reproducer | what |\n\
                      |---:|---|---:|---|---|\n" (List.length m.m_failures);
    List.iter (fun f ->
        (* an unsharded run's failures are in its --out itself *)
        let where = if n = 1 then f.reproducer else Printf.sprintf "shard-%d/%s" ((f.program mod n) + 1) f.reproducer in
        Printf.bprintf b "| %d | %s | %d (%d) | %s | %s |\n" f.program f.kind f.minimal_size f.original_size where
          (cell f.message)) m.m_failures;
    Buffer.add_char b '\n'
  end;
  Buffer.add_string b "## Shards\n\n| shard | host | programs | failures | rules applied | wall s | cpu s | \
                       programs/cpu s |\n|---:|---|---:|---:|---:|---:|---:|---:|\n";
  List.iter (fun t ->
      Printf.bprintf b "| %d/%d | %s | %d | %d | %d | %.1f | %.1f | %.0f |\n" t.shard.index n t.host t.programs
        (List.length t.failures) (applied t.rules) t.seconds t.cpu_seconds (per_second t.programs t.cpu_seconds))
    m.shards;
  Buffer.contents b
