(* Tarjan's strongly connected components, with an explicit stack instead of recursion: a node
   lies on a cycle when its component has more than one node, or it has an edge to itself. *)

let on_cycle ~id ~successors nodes =
  let succ = Hashtbl.create 64 in
  List.iter (fun n -> Hashtbl.replace succ (id n) (successors n)) nodes;
  let successors_of v =
    List.filter (Hashtbl.mem succ) (Option.value (Hashtbl.find_opt succ v) ~default:[]) in
  let index = Hashtbl.create 64 and low = Hashtbl.create 64 in
  let on_stack = Hashtbl.create 64 in
  let stack = ref [] in
  let counter = ref 0 in
  let cyclic = Hashtbl.create 16 in
  let visit root =
    (* Each frame: a node and the successors still to look at. *)
    let enter v =
      Hashtbl.replace index v !counter;
      Hashtbl.replace low v !counter;
      incr counter;
      stack := v :: !stack;
      Hashtbl.replace on_stack v ();
      (v, ref (successors_of v))
    in
    let frames = ref [ enter root ] in
    while !frames <> [] do
      match !frames with
      | [] -> ()
      | (v, rest) :: outer -> (
          match !rest with
          | w :: more ->
              rest := more;
              if not (Hashtbl.mem index w) then frames := enter w :: !frames
              else if Hashtbl.mem on_stack w then
                Hashtbl.replace low v (min (Hashtbl.find low v) (Hashtbl.find index w))
          | [] ->
              frames := outer;
              (match outer with
               | (u, _) :: _ -> Hashtbl.replace low u (min (Hashtbl.find low u) (Hashtbl.find low v))
               | [] -> ());
              if Hashtbl.find low v = Hashtbl.find index v then begin
                (* v is the root of a component: pop it. *)
                let rec pop acc =
                  match !stack with
                  | w :: tail ->
                      stack := tail;
                      Hashtbl.remove on_stack w;
                      if w = v then w :: acc else pop (w :: acc)
                  | [] -> acc
                in
                match pop [] with
                | [ single ] ->
                    if List.mem single (successors_of single) then Hashtbl.replace cyclic single ()
                | members -> List.iter (fun w -> Hashtbl.replace cyclic w ()) members
              end)
    done
  in
  List.iter (fun n -> if not (Hashtbl.mem index (id n)) then visit (id n)) nodes;
  fun v -> Hashtbl.mem cyclic v
