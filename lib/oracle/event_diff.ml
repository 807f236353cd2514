type divergence = {
  index : int;
  expected : Event_stream.event option;
  actual : Event_stream.event option;
  before : Event_stream.event list;
  at : Yojson.Safe.t option;
}

let implementation_specific = [ "steps" ]

let strip : Event_stream.event -> Event_stream.event = function
  | `Assoc fields -> `Assoc (List.filter (fun (k, _) -> not (List.mem k implementation_specific)) fields)
  | other -> other

let region_of = function
  | `Assoc fields -> List.assoc_opt "at" fields
  | _ -> None

let last n l =
  let len = List.length l in
  List.filteri (fun i _ -> i >= len - n) l

let compare ?(ignore = []) ?(context = 3) ~expected ~actual () =
  let keep e = not (List.mem (Event_stream.kind e) ignore) in
  (* rev_map: List.map is not tail recursive, and a stream may hold a million events. *)
  let prepare l = List.rev (List.rev_map strip (List.filter keep l)) in
  let expected = prepare expected and actual = prepare actual in
  (* [seen] holds the agreed events, newest first. *)
  let rec go i seen es as_ =
    let divergence expected actual =
      let before = last context (List.rev seen) in
      let at =
        match Option.bind expected region_of with
        | Some r -> Some r
        | None -> List.find_map region_of seen
      in
      Some { index = i; expected; actual; before; at }
    in
    match es, as_ with
    | [], [] -> None
    | e :: es', a :: as' ->
        if Yojson.Safe.equal e a then go (i + 1) (e :: seen) es' as' else divergence (Some e) (Some a)
    | e :: _, [] -> divergence (Some e) None
    | [], a :: _ -> divergence None (Some a)
  in
  go 1 [] expected actual

let region_text = function
  | `Assoc f ->
      let str k = match List.assoc_opt k f with Some (`String s) -> s | _ -> "?" in
      let int k = match List.assoc_opt k f with Some (`Int n) -> string_of_int n | _ -> "?" in
      Printf.sprintf "%s:%s:%s" (str "file") (int "line") (int "col")
  | _ -> "?"

let report ~file d =
  let b = Buffer.create 256 in
  let line fmt = Printf.ksprintf (fun s -> Buffer.add_string b s; Buffer.add_char b '\n') fmt in
  line "%s: the implementation diverges at event %d%s" file d.index
    (match d.at with Some r -> " (near " ^ region_text r ^ ")" | None -> "");
  List.iter (fun e -> line "    agreed:   %s" (Event_stream.show e)) d.before;
  line "    expected: %s" (match d.expected with Some e -> Event_stream.show e | None -> "(no more events)");
  line "    actual:   %s" (match d.actual with Some e -> Event_stream.show e | None -> "(no more events)");
  Buffer.contents b
