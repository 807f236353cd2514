(* The optimal string alignment distance (Damerau-Levenshtein without repeated edits of one
   substring): a swapped pair of letters (WObj, Wboj) is one slip of the fingers. *)
let distance a b =
  let a = String.lowercase_ascii a and b = String.lowercase_ascii b in
  let n = String.length a and m = String.length b in
  let d = Array.make_matrix (n + 1) (m + 1) 0 in
  for i = 0 to n do d.(i).(0) <- i done;
  for j = 0 to m do d.(0).(j) <- j done;
  for i = 1 to n do
    for j = 1 to m do
      let cost = if a.[i - 1] = b.[j - 1] then 0 else 1 in
      let best = min (min (d.(i - 1).(j) + 1) (d.(i).(j - 1) + 1)) (d.(i - 1).(j - 1) + cost) in
      d.(i).(j) <-
        (if i > 1 && j > 1 && a.[i - 1] = b.[j - 2] && a.[i - 2] = b.[j - 1]
         then min best (d.(i - 2).(j - 2) + 1) else best)
    done
  done;
  d.(n).(m)

(* A third of the name: "tol0" finds tool0, "pHome" does not find pStart. Names of one or two
   characters are near every other short name, and get no suggestion. *)
let limit name = max 1 (min 3 (String.length name / 3))

let closest name candidates =
  if String.length name < 3 then [] else
  let seen = Hashtbl.create 16 in
  let scored =
    List.filter_map (fun c ->
        let k = String.lowercase_ascii c in
        if Hashtbl.mem seen k || k = String.lowercase_ascii name then None
        else begin
          Hashtbl.add seen k ();
          (* names far longer or shorter cannot be near: skip the table *)
          if abs (String.length c - String.length name) > limit name then None
          else
            let d = distance name c in
            if d <= limit name then Some (d, c) else None
        end) candidates
  in
  match List.sort (fun (d, _) (e, _) -> compare d e) scored with
  | [] -> []
  | (best, _) :: _ ->
      List.filter_map (fun (d, c) -> if d = best then Some c else None) scored
      |> List.filteri (fun i _ -> i < 3)

let hint name candidates =
  match closest name candidates with
  | [] -> None
  | [ c ] -> Some (Printf.sprintf "did you mean %s?" c)
  | cs ->
      let rec join = function
        | [] -> "" | [ c ] -> c | [ c; d ] -> c ^ " or " ^ d | c :: rest -> c ^ ", " ^ join rest in
      Some (Printf.sprintf "did you mean %s?" (join cs))
