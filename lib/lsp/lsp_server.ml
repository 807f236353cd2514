module W = Lsp_workspace
module F = Lsp_features
module R = Lsp_rpc

type state = Waiting | Running | Shut_down

type t = {
  workspace : W.t;
  mutable state : state;
  mutable snippets : bool;
  mutable exit_status : int option;
}

let create options = { workspace = W.create options; state = Waiting; snippets = false; exit_status = None }
let finished t = t.exit_status
let workspace t = t.workspace

exception Bad_params of string

let field name (j : Yojson.Safe.t) = match j with `Assoc l -> List.assoc_opt name l | _ -> None

let path names j = List.fold_left (fun j n -> Option.bind j (field n)) (Some j) names

let string_at names j = match path names j with Some (`String s) -> s
                                              | _ -> raise (Bad_params (String.concat "." names ^ " is not a string"))

let position_at j =
  match Option.bind (path [ "position" ] j) (fun p -> Lsp_text.position_of_json p) with
  | Some p -> p
  | None -> raise (Bad_params "position is not a Position")

let uri_of j = string_at [ "textDocument"; "uri" ] j

let capabilities : Yojson.Safe.t =
  `Assoc [
    ("positionEncoding", `String "utf-16");
    ("textDocumentSync", `Assoc [ ("openClose", `Bool true); ("change", `Int 2) ]);
    ("hoverProvider", `Bool true);
    ("definitionProvider", `Bool true);
    ("referencesProvider", `Bool true);
    ("documentSymbolProvider", `Bool true);
    ("workspaceSymbolProvider", `Bool true);
    ("completionProvider", `Assoc [ ("triggerCharacters", `List [ `String "."; `String "\\" ]) ]);
    ("signatureHelpProvider", `Assoc [ ("triggerCharacters", `List [ `String "("; `String "," ]) ]);
    ("codeActionProvider", `Assoc [ ("codeActionKinds", `List [ `String "quickfix" ]) ]);
    ("renameProvider", `Assoc [ ("prepareProvider", `Bool true) ]);
  ]

let publish t uri =
  List.map (fun (u, ds) ->
      R.notification "textDocument/publishDiagnostics" (`Assoc [ ("uri", `String u); ("diagnostics", `List ds) ]))
    (W.diagnostics t.workspace uri)

let initialize t params =
  let snippets = [ "capabilities"; "textDocument"; "completion"; "completionItem"; "snippetSupport" ] in
  t.snippets <- (match path snippets params with Some (`Bool b) -> b | _ -> false);
  let root = match path [ "workspaceFolders" ] params with
    | Some (`List (f :: _)) -> Option.bind (field "uri" f) (function `String u -> Lsp_uri.to_path u | _ -> None)
    | _ -> (match field "rootUri" params with
        | Some (`String u) -> Lsp_uri.to_path u
        | _ -> (match field "rootPath" params with Some (`String p) -> Some p | _ -> None)) in
  W.set_root t.workspace root;
  `Assoc [ ("capabilities", capabilities);
           ("serverInfo", `Assoc [ ("name", `String "rapid-sem"); ("version", `String "1") ]) ]

let change t params =
  let uri = uri_of params in
  let changes = match field "contentChanges" params with Some (`List l) -> l | _ -> [] in
  List.iter (fun c ->
      let text = match field "text" c with Some (`String s) -> s | _ -> raise (Bad_params "a change without text") in
      let range = match field "range" c with
        | Some r -> (
            match Option.bind (field "start" r) Lsp_text.position_of_json,
                  Option.bind (field "end" r) Lsp_text.position_of_json with
            | Some a, Some b -> Some (a, b)
            | _ -> raise (Bad_params "a change's range is not a Range"))
        | None -> None in
      W.change_document t.workspace uri range text) changes;
  publish t uri

(* A request's result; [None] for a method the server does not serve. *)
let request t meth params : Yojson.Safe.t option =
  let ws = t.workspace in
  let served f = Some (f ()) in
  match meth with
  | "textDocument/hover" -> served (fun () -> F.hover ws (uri_of params) (position_at params))
  | "textDocument/definition" -> served (fun () -> F.definition ws (uri_of params) (position_at params))
  | "textDocument/references" ->
      let include_declaration = match path [ "context"; "includeDeclaration" ] params with
        | Some (`Bool b) -> b | _ -> true in
      served (fun () -> F.references ws (uri_of params) (position_at params) ~include_declaration)
  | "textDocument/documentSymbol" -> served (fun () -> F.document_symbols ws (uri_of params))
  | "workspace/symbol" ->
      served (fun () -> F.workspace_symbols ws (match field "query" params with Some (`String q) -> q | _ -> ""))
  | "textDocument/completion" ->
      served (fun () -> F.completion ws (uri_of params) (position_at params) ~snippets:t.snippets)
  | "textDocument/signatureHelp" -> served (fun () -> F.signature_help ws (uri_of params) (position_at params))
  | "textDocument/codeAction" ->
      let diagnostics = match path [ "context"; "diagnostics" ] params with Some (`List l) -> l | _ -> [] in
      served (fun () -> F.code_actions ws (uri_of params) diagnostics)
  | "textDocument/prepareRename" -> served (fun () -> F.prepare_rename ws (uri_of params) (position_at params))
  | "textDocument/rename" ->
      served (fun () -> F.rename ws (uri_of params) (position_at params) (string_at [ "newName" ] params))
  | _ -> None

let notification t meth params =
  match meth with
  | "initialized" -> []
  | "textDocument/didOpen" ->
      let uri = uri_of params in
      W.open_document t.workspace uri (string_at [ "textDocument"; "text" ] params);
      publish t uri
  | "textDocument/didChange" -> change t params
  | "textDocument/didClose" ->
      let uri = uri_of params in
      W.close_document t.workspace uri;
      (* its diagnostics go with it; the others of its task are judged again without it *)
      R.notification "textDocument/publishDiagnostics" (`Assoc [ ("uri", `String uri); ("diagnostics", `List []) ])
      :: (if W.diagnostics t.workspace uri = [] then [] else publish t uri)
  | "textDocument/didSave" | "workspace/didChangeWatchedFiles" ->
      (* the modules on disk are read again, and every open task judged again *)
      W.files_changed t.workspace;
      let seen = Hashtbl.create 4 in
      List.concat_map (fun uri ->
          let k = W.task_key t.workspace uri in
          if Hashtbl.mem seen k then [] else (Hashtbl.replace seen k (); publish t uri)) (W.open_uris t.workspace)
  | _ -> []

let log message =
  R.notification "window/logMessage" (`Assoc [ ("type", `Int 1); ("message", `String message) ])

let describe_exn = function
  | Stack_overflow -> "the request nests too deeply (stack overflow)"
  | Out_of_memory -> "out of memory"
  | e -> Printexc.to_string e

let dispatch t (msg : Yojson.Safe.t) : Yojson.Safe.t list =
  let id = field "id" msg in
  let params = Option.value (field "params" msg) ~default:(`Assoc []) in
  let fail code m = match id with Some id -> [ R.error_response id code m ] | None -> [ log m ] in
  match field "method" msg with
  | None when id <> None && (field "result" msg <> None || field "error" msg <> None) -> []  (* a response to us *)
  | Some (`String meth) -> (
      match id with
      | Some (`Int _ | `String _ | `Intlit _) | None -> (
          try
            match meth, id, t.state with
            | "exit", _, _ ->
                t.exit_status <- Some (if t.state = Shut_down then 0 else 1); []
            | "initialize", Some id, Waiting -> t.state <- Running; [ R.response id (initialize t params) ]
            | "initialize", Some id, _ -> [ R.error_response id R.invalid_request "initialize is sent once" ]
            | _, Some id, Waiting ->
                [ R.error_response id R.server_not_initialized "the server is not initialized" ]
            | _, None, Waiting -> []
            | "shutdown", Some id, _ -> t.state <- Shut_down; [ R.response id `Null ]
            | _, Some id, Shut_down -> [ R.error_response id R.invalid_request "the server is shut down" ]
            | _, Some id, _ -> (
                match request t meth params with
                | Some result -> [ R.response id result ]
                | None -> [ R.error_response id R.method_not_found ("unknown method " ^ meth) ])
            | _, None, _ -> notification t meth params
          with
          | Bad_params m -> fail R.invalid_params m
          | F.Refused m -> fail R.request_failed m
          | e -> fail R.internal_error ("rapid-sem: internal error in " ^ meth ^ ": " ^ describe_exn e))
      | Some _ -> [ R.error_response `Null R.invalid_request "an id is a number or a string" ])
  | _ ->
      [ R.error_response (Option.value id ~default:`Null) R.invalid_request "a request or notification has a method" ]

let handle t msg =
  try
    match msg with
    | `Assoc _ -> dispatch t msg
    | _ -> [ R.error_response `Null R.invalid_request "a message is a JSON object" ]
  with e -> [ R.error_response `Null R.internal_error ("rapid-sem: internal error: " ^ describe_exn e) ]

let run options ic oc =
  set_binary_mode_in ic true;
  set_binary_mode_out oc true;
  (match Rapid_load.Session.installed ~io:options.W.io () with
   | Ok modules ->
       (* the index reads the installed declarations (hover, completion), not only the level *)
       Lsp_index.use_installed (Rapid_typing.Installed_env.full modules)
   | Error _ -> ());
  let t = create options in
  let rec loop () =
    match R.read ic with
    | R.End -> Option.value t.exit_status ~default:(if t.state = Shut_down then 0 else 1)
    | R.Malformed m -> R.write oc (R.error_response `Null R.parse_error m); loop ()
    | R.Message j ->
        List.iter (R.write oc) (handle t j);
        (match t.exit_status with Some s -> s | None -> loop ()) in
  loop ()
