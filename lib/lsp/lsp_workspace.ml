open Rapid_syntax

type options = { allow_unknown : bool; io : Rapid_controller.Io_config.t }

type doc = {
  uri : string;
  path : string option;
  mutable text : Lsp_text.t;
  mutable last_good : string option;   (* the last text that parsed *)
}

type analysis = {
  index : Lsp_index.t;
  diagnostics : (string * Yojson.Safe.t list) list;
  unparsed : string list;   (* the modules that do not parse now *)
}

type t = {
  options : options;
  docs : (string, doc) Hashtbl.t;
  cache : (string, analysis) Hashtbl.t;   (* by task key *)
  mutable root : string option;
}

let create options = { options; docs = Hashtbl.create 16; cache = Hashtbl.create 8; root = None }

let uri_of_file = Lsp_uri.of_path

let is_module_file f =
  List.exists (fun e -> Filename.check_suffix (String.lowercase_ascii f) e) [ ".mod"; ".sys"; ".modx"; ".sysx" ]

let readdir d = try Array.to_list (Sys.readdir d) |> List.sort compare with Sys_error _ -> []
let is_dir p = try Sys.is_directory p with Sys_error _ -> false

(* The folder of a backup's task: the nearest ancestor TASKn whose parent is RAPID. *)
let backup_task path =
  let rec up d =
    let parent = Filename.dirname d in
    if parent = d then None
    else
      let base = String.uppercase_ascii (Filename.basename d) in
      if String.length base > 4 && String.sub base 0 4 = "TASK"
         && String.uppercase_ascii (Filename.basename parent) = "RAPID" then Some d
      else up parent in
  up (Filename.dirname path)

(* At most this many files are read for a task or a workspace: a folder of thousands of CAD
   modules is not one an editor should re-read at every key. *)
let max_files = 2000

let rec files_below depth d =
  if depth > 6 then []
  else List.concat_map (fun f ->
      let p = Filename.concat d f in
      if is_dir p then (if f <> "" && f.[0] = '.' then [] else files_below (depth + 1) p)
      else if is_module_file f then [ p ] else []) (readdir d)

let take n l = List.filteri (fun i _ -> i < n) l

(* A task: its key and its module files on disk. *)
let task_of_path path =
  match backup_task path with
  | Some d -> (d, take max_files (files_below 0 d))
  | None ->
      let d = Filename.dirname path in
      (d, take max_files (List.filter_map (fun f ->
           let p = Filename.concat d f in
           if is_module_file f && not (is_dir p) then Some p else None) (readdir d)))

let doc_path uri = Lsp_uri.to_path uri

let task_key t uri =
  match Hashtbl.find_opt t.docs uri with
  | Some { path = Some p; _ } -> fst (task_of_path p)
  | Some { path = None; _ } -> "untitled:" ^ uri
  | None -> (match doc_path uri with Some p -> fst (task_of_path p) | None -> "untitled:" ^ uri)

let invalidate t uri = Hashtbl.remove t.cache (task_key t uri)

(* R-2.4-rw6: a backup's task (RAPID/TASKn) is read with the release of the backup's
   BACKINFO/backinfo.txt; any other folder as the manual's release. *)
let robotware_of_key key =
  let rapid = Filename.dirname key in
  let backinfo = Filename.concat (Filename.concat (Filename.dirname rapid) "BACKINFO") "backinfo.txt" in
  if String.uppercase_ascii (Filename.basename rapid) = "RAPID" && Sys.file_exists backinfo then
    Option.value (Rapid_load.Backup.robotware_of_backinfo backinfo) ~default:Robotware.default
  else Robotware.default

let parse_options key = { Parse.default_options with robotware = robotware_of_key key }

let parses ~key raw =
  match Parse.parse_string ~options:(parse_options key) ~name:"check" raw with Ok _ -> true | Error _ -> false

let set_root t root = t.root <- root

let open_document t uri raw =
  invalidate t uri;
  let text = Lsp_text.of_bytes raw in
  let d = { uri; path = doc_path uri; text; last_good = None } in
  if parses ~key:(match d.path with Some p -> fst (task_of_path p) | None -> "") raw then d.last_good <- Some raw;
  Hashtbl.replace t.docs uri d;
  invalidate t uri

let change_document t uri range new_text =
  match Hashtbl.find_opt t.docs uri with
  | None -> ()
  | Some d ->
      d.text <- Lsp_text.apply_change d.text range new_text;
      invalidate t uri

let close_document t uri =
  invalidate t uri;
  Hashtbl.remove t.docs uri;
  invalidate t uri

let is_open t uri = Hashtbl.mem t.docs uri

let files_changed t = Hashtbl.reset t.cache

let open_uris t = List.sort compare (Hashtbl.fold (fun uri _ acc -> uri :: acc) t.docs [])

let read_file p =
  match open_in_bin p with
  | exception Sys_error _ -> None
  | ic ->
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
          try Some (really_input_string ic (in_channel_length ic)) with Sys_error _ | End_of_file -> None)

(* The modules of a task: (uri, raw text, the open document if it is one). *)
let task_modules t key =
  let open_docs = Hashtbl.fold (fun _ d acc -> if task_key t d.uri = key then d :: acc else acc) t.docs []
                  |> List.sort (fun a b -> compare a.uri b.uri) in
  let open_paths = List.filter_map (fun d -> d.path) open_docs in
  let disk =
    if String.length key >= 9 && String.sub key 0 9 = "untitled:" then []
    else
      let files = match open_docs with
        | { path = Some p; _ } :: _ -> snd (task_of_path p)
        | _ -> snd (task_of_path (Filename.concat key "x.mod")) in
      List.filter_map (fun p ->
          if List.mem p open_paths then None
          else Option.map (fun raw -> (uri_of_file p, raw, None)) (read_file p)) files in
  List.map (fun d -> (d.uri, Lsp_text.text d.text, Some d)) open_docs @ disk

(* {1 Diagnostics} *)

let severity_error = 1
let severity_warning = 2

let diagnostic text ~severity ~code ~start ~stop message : Yojson.Safe.t =
  `Assoc [ ("range", Lsp_text.json_range text start stop); ("severity", `Int severity);
           ("code", `String code); ("source", `String "rapid-sem"); ("message", `String message) ]

let with_hint message = function None -> message | Some h -> message ^ "\nhint: " ^ h

let of_front_end text (d : Diagnostic.t) =
  let class_name = Diagnostic.class_name d.error_class in
  diagnostic text ~severity:severity_error ~code:(String.map (fun c -> if c = ' ' then '-' else c) class_name)
    ~start:(Source.start_offset d.region) ~stop:(Source.stop_offset d.region)
    (with_hint (class_name ^ ": " ^ d.message) d.hint)

let of_report text (r : Rapid_typing.Report.t) =
  let sections = String.concat ", " (List.map (fun s -> "§" ^ s) r.sections) in
  diagnostic text ~severity:(match r.severity with Error -> severity_error | Warning -> severity_warning)
    ~code:r.rule ~start:(Source.start_offset r.region) ~stop:(Source.stop_offset r.region)
    (with_hint (Printf.sprintf "%s: %s (%s)" (Rapid_typing.Report.class_name r) r.message sections) r.hint)

let file_name (r : Source.region) = match Source.file_of r with Some f -> Source.name f | None -> ""

let analyse t key =
  let modules = task_modules t key in
  let options = parse_options key in
  (* Each module is registered under a name of its own in this analysis, so that a report is
     told to belong to it by the name of its region's file. *)
  let parsed = List.mapi (fun i (uri, raw, doc) ->
      let name = Printf.sprintf "%d:%s" i uri in
      let text = match doc with Some d -> d.text | None -> Lsp_text.of_bytes raw in
      match Parse.parse_string ~options ~name raw with
      | Ok ast ->
          Option.iter (fun d -> d.last_good <- Some raw) doc;
          (uri, name, text, doc, Some { Lsp_index.uri; text; ast; fresh = true }, None)
      | Error e ->
          (* The last text that parsed stands in, for the names it declares. *)
          let stale = match doc with
            | Some { last_good = Some good; _ } -> (
                match Parse.parse_string ~options ~name:(name ^ " (stale)") good with
                | Ok ast -> Some { Lsp_index.uri; text = Lsp_text.of_bytes good; ast; fresh = false }
                | Error _ -> None)
            | _ -> None in
          (uri, name, text, doc, stale, Some e)) modules in
  let sources = List.filter_map (fun (_, _, _, _, s, _) -> s) parsed in
  let index = Lsp_index.build sources in
  let reports =
    (* diagnostics are for open documents: a task none of whose modules is open is only indexed *)
    if List.exists (fun (_, _, _, _, s, _) -> s = None) parsed
    || not (List.exists (fun (_, _, _, doc, _, _) -> doc <> None) parsed) then []
    else
      let modules = List.map (fun (s : Lsp_index.source) -> s.ast) sources in
      let buffer = { Rapid_load.Buffer_check.name = ""; modules } in
      (* a task of rapid-sem test's tests is checked as that command checks it, assertions installed *)
      let testing = List.exists Rapid_load.Session.declares_tests modules in
      match Rapid_load.Buffer_check.check ~testing ~allow_unknown:t.options.allow_unknown ~io:t.options.io
              ~several:false [ buffer ] with
      | Ok c -> c.reports
      | Error _ -> [] in
  let diagnostics = List.filter_map (fun (uri, name, text, doc, _, error) ->
      match doc with
      | None -> None
      | Some _ ->
          let front = match error with Some e -> [ of_front_end text e ] | None -> [] in
          let mine = if error <> None then [] else
              List.filter_map (fun (r : Rapid_typing.Report.t) ->
                  if file_name r.region = name then Some (of_report text r) else None) reports in
          Some (uri, front @ mine)) parsed in
  let unparsed = List.filter_map (fun (uri, _, _, _, _, e) -> if e <> None then Some uri else None) parsed in
  { index; diagnostics; unparsed }

let analysis t uri =
  let key = task_key t uri in
  match Hashtbl.find_opt t.cache key with
  | Some a -> a
  | None ->
      let a = analyse t key in
      Hashtbl.replace t.cache key a;
      a

let index t uri = (analysis t uri).index
let diagnostics t uri = (analysis t uri).diagnostics
let unparsed t uri = (analysis t uri).unparsed

let text t uri =
  match Hashtbl.find_opt t.docs uri with
  | Some d -> Some d.text
  | None -> Option.map (fun (s : Lsp_index.source) -> s.text) (Lsp_index.source (index t uri) uri)

let workspace_indexes t =
  let open_keys = Hashtbl.fold (fun uri _ acc -> let k = task_key t uri in if List.mem k acc then acc else k :: acc)
      t.docs [] in
  let keys = match t.root with
    | None -> open_keys
    | Some root ->
        let files = take max_files (files_below 0 root) in
        List.fold_left (fun acc f -> let k = fst (task_of_path f) in if List.mem k acc then acc else acc @ [ k ])
          open_keys files in
  List.map (fun key ->
      match Hashtbl.find_opt t.cache key with
      | Some a -> a.index
      | None ->
          (* a task none of whose documents is open *)
          let a = analyse t key in
          Hashtbl.replace t.cache key a;
          a.index) keys
