open Rapid_syntax

type severity = Error | Warning

type t = {
  severity : severity;
  rule : string;
  sections : string list;
  region : Source.region;
  message : string;
  hint : string option;
}

type collector = { mutable items : t list }

let create () = { items = [] }

let add c ?hint severity ~rule ~section region message =
  let sections = String.split_on_char ',' section |> List.map String.trim |> List.filter (( <> ) "") in
  c.items <- { severity; rule; sections; region; message; hint } :: c.items

let error c ?hint ~rule ~section region message = add c ?hint Error ~rule ~section region message
let warning c ?hint ~rule ~section region message =
  add c ?hint Warning ~rule ~section region message

let file_name r = match Source.file_of r with Some f -> Source.name f | None -> ""

let all c =
  List.stable_sort (fun a b ->
      compare (file_name a.region, Source.start_offset a.region)
        (file_name b.region, Source.start_offset b.region))
    (List.rev c.items)

let cited d = String.concat ", " (List.map (fun s -> "§" ^ s) d.sections)

let class_name d = match d.severity with Error -> "semantic error" | Warning -> "warning"

let headline d =
  Printf.sprintf "%s: %s: %s (%s)" (Source.to_string d.region) (class_name d) d.message (cited d)

let to_string d =
  match d.hint with
  | None -> headline d
  | Some h -> headline d ^ "\n" ^ Diagnostic.hint_line h

let to_diagnostic d =
  Diagnostic.make ?hint:d.hint Semantic_error d.region (Printf.sprintf "%s (%s)" d.message (cited d))
