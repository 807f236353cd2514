(* The campaign's programs and verdicts do not change with a change for speed (issue 20): the
   first 200 programs of seed 7 in the default configuration of rapid-sem fuzz (a mutant each,
   a hostile text every ten, a scenario in ten, both engines), each one's outcome, the rules
   the machine applied to it and its mutant (how often each) and whether it passed, against
   the list rapid-sem fuzz gave before the work on speed (test/golden/fuzz-verdicts-seed7.txt,
   one line per program as `rapid-sem fuzz --count I+1 --shard I+1/I+1 --seed 7 --coverage`
   reports program I alone). *)

module C = Rapid_fuzz.Campaign

let verdict ~seed i =
  (* shard I+1 of I+1 of a campaign of I+1 programs is program I alone *)
  let shard = { C.index = i + 1; count = i + 1 } in
  let s = C.run ~engines:[ Rapid_fuzz.Fuzz_run.closure ] ~seed ~count:(i + 1) ~shard () in
  let outcomes = String.concat ", " (List.map (fun (k, n) -> Printf.sprintf "%s %d" k n) s.outcomes) in
  let applied (r, n) = if n = 0 then None else Some (r ^ "=" ^ string_of_int n) in
  let rules = List.sort compare (List.filter_map applied s.rules) in
  Printf.sprintf "%d: %s | %s | %d passed, %d failed" i outcomes
    (String.concat "" (List.map (fun r -> r ^ ",") rules))
    (s.programs - List.length s.failures) (List.length s.failures)

let read_lines file =
  let ic = open_in_bin file in
  let rec go acc = match input_line ic with l -> go (l :: acc) | exception End_of_file -> close_in ic; List.rev acc in
  go []

let seed_7 () =
  let expected = read_lines "golden/fuzz-verdicts-seed7.txt" in
  Alcotest.(check int) "programs pinned" 200 (List.length expected);
  List.iteri (fun i line -> Alcotest.(check string) (Printf.sprintf "program %d" i) line (verdict ~seed:7 i)) expected

let suite = ("fuzz verdicts", [ Alcotest.test_case "seed 7: the first 200 programs' verdicts" `Quick seed_7 ])
