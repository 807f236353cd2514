(* The diagnostics of `rapid-sem check` in the three formats of doc/user-guide.md: text (standard
   error, one headline per diagnostic and its hint on an indented line), JSON and SARIF 2.1.0
   (standard output, one document for the whole run). Front-end diagnostics and the reports of
   the static semantics are first made one kind of item, so that every format carries the same
   fields: file, region, class, rule, sections, message, hint. *)

module Json_text = Rapid_runtime.Json_text  (* every JSON written is valid UTF-8 *)
open Rapid_syntax
module Report = Rapid_typing.Report

type item = {
  region : Source.region;
  class_name : string;      (* lexical error, syntax error, semantic error, fatal error, file error, warning *)
  level : [ `Error | `Warning ];
  rule : string;            (* the rule of doc/typing.md, or the class for the front end *)
  sections : string list;
  message : string;         (* as the text format prints it, sections included *)
  hint : string option;
  text : string;            (* the text format's lines *)
}

let of_diagnostic (d : Diagnostic.t) =
  let class_name = Diagnostic.class_name d.error_class in
  { region = d.region; class_name; level = `Error;
    rule = String.map (fun c -> if c = ' ' then '-' else c) class_name;
    sections = Diagnostic.sections_of d.message; message = d.message; hint = d.hint;
    text = Diagnostic.to_string d }

let of_report (r : Report.t) =
  { region = r.region; class_name = Report.class_name r;
    level = (match r.severity with Report.Error -> `Error | Report.Warning -> `Warning);
    rule = r.rule; sections = r.sections;
    message = Printf.sprintf "%s (%s)" r.message
        (String.concat ", " (List.map (fun s -> "§" ^ s) r.sections));
    hint = r.hint; text = Report.to_string r }

let file_name r = match Source.file_of r with Some f -> Source.name f | None -> ""

let optional name = function None -> [] | Some s -> [ (name, `String s) ]

let json_item i : Yojson.Safe.t =
  let p = Source.start i.region and q = Source.stop i.region in
  `Assoc ([ ("file", `String (file_name i.region));
            ("region", `Assoc [ ("start_line", `Int p.line); ("start_column", `Int p.col);
                                ("end_line", `Int q.line); ("end_column", `Int q.col) ]);
            ("class", `String i.class_name);
            ("severity", `String (match i.level with `Error -> "error" | `Warning -> "warning"));
            ("rule", `String i.rule);
            ("sections", `List (List.map (fun s -> `String s) i.sections));
            ("message", `String i.message) ]
          @ optional "hint" i.hint)

let json items =
  let count l = List.length (List.filter (fun i -> i.level = l) items) in
  `Assoc [ ("schema", `String "rapid-sem/diagnostics/1");
           ("diagnostics", `List (List.map json_item items));
           ("errors", `Int (count `Error)); ("warnings", `Int (count `Warning)) ]

(* RFC 3986: a relative reference keeps unreserved characters and '/'; everything else is
   percent-encoded ("<stdin>" becomes "%3Cstdin%3E"). *)
let uri path =
  let b = Buffer.create (String.length path) in
  String.iter (fun c ->
      match c with
      | 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '-' | '.' | '_' | '~' | '/' -> Buffer.add_char b c
      | c -> Buffer.add_string b (Printf.sprintf "%%%02X" (Char.code c))) path;
  Buffer.contents b

let sarif_result i : Yojson.Safe.t =
  let p = Source.start i.region and q = Source.stop i.region in
  let text = match i.hint with None -> i.message | Some h -> i.message ^ "\nhint: " ^ h in
  `Assoc [
    ("ruleId", `String i.rule);
    ("level", `String (match i.level with `Error -> "error" | `Warning -> "warning"));
    ("message", `Assoc [ ("text", `String text) ]);
    ("locations", `List [
        `Assoc [ ("physicalLocation", `Assoc [
            ("artifactLocation", `Assoc [ ("uri", `String (uri (file_name i.region))) ]);
            ("region", `Assoc [ ("startLine", `Int (max 1 p.line)); ("startColumn", `Int (max 1 p.col));
                                ("endLine", `Int (max 1 q.line)); ("endColumn", `Int (max 1 q.col)) ]) ]) ] ]);
    ("properties", `Assoc ([ ("class", `String i.class_name);
                             ("sections", `List (List.map (fun s -> `String s) i.sections)) ]
                           @ optional "hint" i.hint)) ]

let sarif ~version items : Yojson.Safe.t =
  let rules = List.sort_uniq compare (List.map (fun i -> i.rule) items) in
  `Assoc [
    ("$schema", `String "https://json.schemastore.org/sarif-2.1.0.json");
    ("version", `String "2.1.0");
    ("runs", `List [
        `Assoc [
          ("tool", `Assoc [ ("driver", `Assoc [
              ("name", `String "rapid-sem");
              ("version", `String version);
              ("rules", `List (List.map (fun r -> `Assoc [ ("id", `String r) ]) rules)) ]) ]);
          (* Columns count characters (Unicode code points), not UTF-16 units. *)
          ("columnKind", `String "unicodeCodePoints");
          ("results", `List (List.map sarif_result items)) ] ]) ]

type format = Text | Json | Sarif

let print ~version format items =
  match format with
  | Text -> List.iter (fun i -> prerr_endline i.text) items
  | Json -> print_endline (Json_text.pretty_to_string (json items))
  | Sarif -> print_endline (Json_text.pretty_to_string (sarif ~version items))
