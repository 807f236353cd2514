type table = { name : string; language : string; texts : (int * string) list }

exception Bad of string

(* §15: <Resource Language=.. Name=..> <Text Name="n"> <Value>..</Value> <Comment>..</Comment>
   </Text> ... </Resource>. *)
let parse contents =
  let input = Xmlm.make_input ~strip:false (`String (0, contents)) in
  let attr name attrs =
    List.find_map (fun (((_, n), v) : Xmlm.attribute) -> if n = name then Some v else None) attrs in
  (* The text of an element whose start tag was just read, to its end tag. *)
  let rec text_of acc =
    match Xmlm.input input with
    | `Data d -> text_of (acc ^ d)
    | `El_end -> acc
    | `El_start _ -> raise (Bad "an element inside a text value")
    | `Dtd _ -> text_of acc in
  let rec skip depth =
    match Xmlm.input input with
    | `El_start _ -> skip (depth + 1)
    | `El_end -> if depth > 0 then skip (depth - 1)
    | _ -> skip depth in
  let text_element attrs =
    let index = match attr "Name" attrs with
      | Some n -> (match int_of_string_opt (String.trim n) with
          | Some i when i >= 1 -> i
          | _ -> raise (Bad (Printf.sprintf "Text Name=%S is not a positive index" n)))
      | None -> raise (Bad "a Text element without Name") in
    let value = ref None in
    let rec children () =
      match Xmlm.input input with
      | `El_start ((_, "Value"), _) -> value := Some (text_of ""); children ()
      | `El_start _ -> skip 0; children ()
      | `El_end -> ()
      | `Data _ | `Dtd _ -> children () in
    children ();
    match !value with
    | Some v -> (index, v)
    | None -> raise (Bad (Printf.sprintf "Text %d has no Value" index)) in
  try
    let rec root () =
      match Xmlm.input input with
      | `Dtd _ | `Data _ -> root ()
      | `El_start ((_, "Resource"), attrs) ->
          let name = match attr "Name" attrs with Some n -> n | None -> raise (Bad "a Resource without Name") in
          let language = Option.value (attr "Language" attrs) ~default:"" in
          let rec texts acc =
            match Xmlm.input input with
            | `El_start ((_, "Text"), attrs) ->
                let i, v = text_element attrs in
                if List.mem_assoc i acc then raise (Bad (Printf.sprintf "Text %d twice" i));
                texts ((i, v) :: acc)
            | `El_start _ -> skip 0; texts acc
            | `El_end -> List.rev acc
            | `Data _ | `Dtd _ -> texts acc in
          { name; language; texts = texts [] }
      | `El_start ((_, other), _) -> raise (Bad (Printf.sprintf "the root element is %s, not Resource" other))
      | `El_end -> raise (Bad "no Resource element") in
    Ok (root ())
  with
  | Bad m -> Error m
  | Xmlm.Error ((line, col), e) -> Error (Printf.sprintf "%d:%d: %s" line col (Xmlm.error_message e))

type t = { mutable tables : table list (* in order of installation *) }

let create () = { tables = [] }

let find t name =
  let rec go i = function
    | [] -> None
    | tb :: rest -> if tb.name = name then Some i else go (i + 1) rest in
  go 1 t.tables

let free_to_use t name = find t name = None

let install t table = if free_to_use t table.name then t.tables <- t.tables @ [ table ]

let text t number index =
  match List.nth_opt t.tables (number - 1) with
  | Some tb when number >= 1 -> List.assoc_opt index tb.texts
  | _ -> None
