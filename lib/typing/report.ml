open Rapid_syntax

type severity = Error | Warning

type t = {
  severity : severity;
  rule : string;
  sections : string list;
  region : Source.region;
  message : string;
}

type collector = { mutable items : t list }

let create () = { items = [] }

let add c severity ~rule ~section region message =
  let sections = String.split_on_char ',' section |> List.map String.trim |> List.filter (( <> ) "") in
  c.items <- { severity; rule; sections; region; message } :: c.items

let error c = add c Error
let warning c = add c Warning

let file_name r = match Source.file_of r with Some f -> Source.name f | None -> ""

let all c =
  List.stable_sort (fun a b ->
      compare (file_name a.region, Source.start_offset a.region)
        (file_name b.region, Source.start_offset b.region))
    (List.rev c.items)

let cited d = String.concat ", " (List.map (fun s -> "§" ^ s) d.sections)

let to_string d =
  Printf.sprintf "%s: %s: %s (%s)" (Source.to_string d.region)
    (match d.severity with Error -> "semantic error" | Warning -> "warning")
    d.message (cited d)

let to_diagnostic d =
  Diagnostic.make Semantic_error d.region (Printf.sprintf "%s (%s)" d.message (cited d))
