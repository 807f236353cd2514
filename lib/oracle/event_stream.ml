type event = Yojson.Safe.t
type t = { schema : string option; events : event list }

let kind = function
  | `Assoc fields -> (match List.assoc_opt "event" fields with Some (`String k) -> k | _ -> "")
  | _ -> ""

(* Two implementations may write an object's fields in any order: the comparison and the
   report see them sorted, so that only a difference of content counts. *)
let rec canonical : Yojson.Safe.t -> Yojson.Safe.t = function
  | `Assoc fields ->
      `Assoc (List.sort (fun (a, _) (b, _) -> compare a b) (List.map (fun (k, v) -> (k, canonical v)) fields))
  | `List items -> `List (List.map canonical items)
  | other -> other

let to_string e = Yojson.Safe.to_string (canonical e)

let parse text =
  let lines = String.split_on_char '\n' text in
  let rec read n acc = function
    | [] -> Ok (List.rev acc)
    | line :: rest when String.trim line = "" -> read (n + 1) acc rest
    | line :: rest -> (
        match Yojson.Safe.from_string line with
        | `Assoc _ as obj -> read (n + 1) (canonical obj :: acc) rest
        | _ -> Error (Printf.sprintf "line %d: not a JSON object" n)
        | exception Yojson.Json_error m ->
            let one_line = String.map (function '\n' -> ' ' | c -> c) m in
            Error (Printf.sprintf "line %d: not JSON (%s)" n one_line))
  in
  match read 1 [] lines with
  | Error m -> Error m
  | Ok (first :: rest) when kind first = "start" ->
      let schema = match first with
        | `Assoc f -> (match List.assoc_opt "schema" f with Some (`String s) -> Some s | _ -> None)
        | _ -> None in
      Ok { schema; events = rest }
  | Ok events -> Ok { schema = None; events }
