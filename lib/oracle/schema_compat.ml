let current = "rapid-sem/2"
let accepted = [ current; "rapid-sem/1" ]

let added_in_v2 = [ "store"; "arguments"; "returned"; "retry"; "trynext" ]

let field k = function `Assoc f -> List.assoc_opt k f | _ -> None
let without k = function `Assoc f -> `Assoc (List.filter (fun (k', _) -> k' <> k) f) | e -> e

let to_v1 events =
  let events = match events with
    | first :: rest when Event_stream.kind first = "routine-entered" -> rest
    | l -> l in
  (* [raised]: the place of the error last raised, which /1 repeated at each call point. *)
  let rec go raised acc = function
    | [] -> List.rev acc
    | e :: rest -> (
        match Event_stream.kind e with
        | k when List.mem k added_in_v2 || k = "task-ended" -> go raised acc rest
        | "error-raised" -> go (field "at" e) (e :: acc) rest
        | "error-propagated" ->
            let again = `Assoc ([ ("event", `String "error-raised") ]
                                @ List.filter_map (fun k -> Option.map (fun v -> (k, v)) (field k e))
                                    [ "name"; "number" ]
                                @ (match raised with Some at -> [ ("at", at) ] | None -> [])) in
            go raised (Event_stream.canonical again :: acc) rest
        | "end" -> go raised (without "at" e :: acc) rest
        | "error-handled" -> go raised (without "number" e :: acc) rest
        | _ -> go raised (e :: acc) rest)
  in
  go None [] events

let v1_actual events = List.filter (fun e -> Event_stream.kind e <> "task-ended") events
