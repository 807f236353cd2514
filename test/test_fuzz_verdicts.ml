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

(* A large hostile text is judged once per process (Campaign.judge_hostile): a campaign where
   it recurs counts the same rules and failures as one that judges every text afresh. *)
let hostile_kept () =
  let run ~count ~shard = C.run ~mutants:0 ~hostile_every:1 ~scenarios:0 ~seed:5 ~count ~shard () in
  let afresh = Hashtbl.create 64 and failed = ref 0 in
  for i = 0 to 59 do
    C.forget_texts ();
    let s = run ~count:(i + 1) ~shard:{ C.index = i + 1; count = i + 1 } in
    failed := !failed + List.length s.failures;
    List.iter (fun (r, n) -> Hashtbl.replace afresh r (n + Option.value (Hashtbl.find_opt afresh r) ~default:0)) s.rules
  done;
  let afresh = List.sort compare (List.filter (fun (_, n) -> n > 0) (Hashtbl.fold (fun k v a -> (k, v) :: a) afresh [])) in
  let kept = run ~count:60 ~shard:{ C.index = 1; count = 1 } in
  let kept_rules = List.filter (fun (_, n) -> n > 0) kept.rules in
  let show l = String.concat " " (List.map (fun (r, n) -> Printf.sprintf "%s=%d" r n) l) in
  (* the texts as Campaign.check_texts draws them (the hostile text first): some large one recurs *)
  let texts = List.init 60 (fun i -> Rapid_fuzz.Mutant.hostile (Random.State.make [| 5; i; 7919 |])) in
  let large = List.filter (fun t -> String.length t >= 4096) texts in
  Alcotest.(check bool) "a large text recurs" true (List.length (List.sort_uniq compare large) < List.length large);
  Alcotest.(check string) "rules" (show afresh) (show kept_rules);
  Alcotest.(check int) "failures" !failed (List.length kept.failures)

let suite = ("fuzz verdicts", [ Alcotest.test_case "seed 7: the first 200 programs' verdicts" `Quick seed_7;
                                Alcotest.test_case "hostile texts judged once, counted each time" `Quick hostile_kept ])
