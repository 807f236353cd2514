(* The table of [lower_distance], kept and grown: a module of thousands of routines asks the
   distance to each of their names (bench/README.md). Every cell read is written first. *)
let scratch = ref (Array.make 64 0)

(* Stdlib's [min] is polymorphic: a call to the runtime's comparison at every cell. *)
let min (a : int) b = if a <= b then a else b

(* The optimal string alignment distance (Damerau-Levenshtein without repeated edits of one
   substring): a swapped pair of letters (WObj, Wboj) is one slip of the fingers. *)
(* On names already in lower case; one flat table of (n+1)(m+1) cells, row i at i(m+1). Every
   index is within the table by construction: unchecked reads (a module of 10,000 routines asks
   the distance to each of their names).
   [within] cuts the rows short: every cell of row i is at least the least of row i-1 and of
   row i-2 plus one (each of its candidates is, and its first cell i is above row i-1's first),
   so once row i's least is above [within] and row i-1's at least [within], every later row's
   least is above it, and so is the distance: [within + 1] then stands for it. *)
let bounded_distance ~within a b =
  let n = String.length a and m = String.length b in
  let w = m + 1 in
  if Array.length !scratch < (n + 1) * w then scratch := Array.make ((n + 1) * w) 0;
  let d = !scratch in
  for i = 0 to n do Array.unsafe_set d (i * w) i done;
  for j = 0 to m do Array.unsafe_set d j j done;
  let rec row i previous =
    (* [previous]: the least cell of row i-1 *)
    if i > n then Array.unsafe_get d (n * w + m)
    else begin
      let ai = String.unsafe_get a (i - 1) and up = (i - 1) * w and here = i * w in
      let least = ref i in
      for j = 1 to m do
        let bj = String.unsafe_get b (j - 1) in
        let cost = if ai = bj then 0 else 1 in
        let best = min (min (Array.unsafe_get d (up + j) + 1) (Array.unsafe_get d (here + j - 1) + 1))
            (Array.unsafe_get d (up + j - 1) + cost) in
        let cell =
          if i > 1 && j > 1 && ai = String.unsafe_get b (j - 2) && String.unsafe_get a (i - 2) = bj
          then min best (Array.unsafe_get d ((i - 2) * w + j - 2) + 1) else best in
        Array.unsafe_set d (here + j) cell;
        if cell < !least then least := cell
      done;
      if !least > within && previous >= within then within + 1 else row (i + 1) !least
    end in
  row 1 0

let lower_distance a b = bounded_distance ~within:max_int a b

let distance a b = lower_distance (String.lowercase_ascii a) (String.lowercase_ascii b)

(* A third of the name: "tol0" finds tool0, "pHome" does not find pStart. Names of one or two
   characters are near every other short name, and get no suggestion. *)
let limit name = max 1 (min 3 (String.length name / 3))

let closest name candidates =
  if String.length name < 3 then [] else
  let seen = Hashtbl.create 16 in
  let lower = String.lowercase_ascii name and limit = limit name and length = String.length name in
  let scored =
    List.filter_map (fun c ->
        (* Names far longer or shorter cannot be near. Tested first: a later candidate of the
           same spelling has the same length, so leaving this one out of [seen] changes
           nothing. *)
        if abs (String.length c - length) > limit then None
        else
          let k = if String.exists (fun ch -> ch >= 'A' && ch <= 'Z') c then String.lowercase_ascii c else c in
          if k = lower then None
          else
            let d = bounded_distance ~within:limit lower k in
            (* Only near names need [seen]: a later candidate of the same spelling is as far. *)
            if d > limit || Hashtbl.mem seen k then None
            else begin Hashtbl.add seen k (); Some (d, c) end) candidates
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
