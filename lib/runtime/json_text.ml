(* Yojson writes a string's bytes as they are: a byte that is not UTF-8 would make the whole
   document invalid JSON (RFC 8259 §8.1), which a strict reader refuses. The conversion is done
   once, on the tree about to be written, rather than at each place a string is built. *)

let text = Utf8_text.of_bytes

let rec valid (j : Yojson.Safe.t) : Yojson.Safe.t =
  match j with
  | `String s -> `String (text s)
  | `Assoc fields -> `Assoc (List.map (fun (k, v) -> (text k, valid v)) fields)
  | `List l -> `List (List.map valid l)
  | `Tuple l -> `Tuple (List.map valid l)
  | `Variant (k, v) -> `Variant (text k, Option.map valid v)
  | `Null | `Bool _ | `Int _ | `Intlit _ | `Float _ -> j

let to_string j = Yojson.Safe.to_string (valid j)

let pretty_to_string j = Yojson.Safe.pretty_to_string (valid j)
