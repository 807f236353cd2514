(* The language server (doc/editor.md) driven by a scripted client of ours: every request of
   LSP 3.17 it serves, on the task of test/lsp/cell (Cell.mod, Tools.mod in Latin-1, Wrong.mod
   with three semantic errors, one after a character beyond U+FFFF on its line), the base
   protocol's framing, and a fuzz of random edits and requests that must all be answered. The
   end-to-end session with a real client (Neovim) is test/lsp/nvim_session.lua, run below when
   nvim is installed. *)

open Rapid_lsp
module J = Yojson.Safe

let dir = Filename.concat (Sys.getcwd ()) "lsp/cell"
let uri f = Lsp_uri.of_path (Filename.concat dir f)
let read path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

let write path text =
  let oc = open_out_bin path in
  Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text)

let contains s sub =
  let n = String.length sub and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = sub || go (i + 1)) in
  go 0

let member k (j : J.t) = match j with `Assoc l -> (match List.assoc_opt k l with Some v -> v | None -> `Null) | _ -> `Null
let rec get path j = match path with [] -> j | k :: rest -> get rest (member k j)
let to_list = function `List l -> l | _ -> []
let str = function `String s -> s | j -> J.to_string j
let int = function `Int i -> i | _ -> -1

(* A session: the server and what it said since the last look. *)
type session = { server : Lsp_server.t; mutable out : J.t list; mutable next : int }

let send s msg = s.out <- s.out @ Lsp_server.handle s.server msg

let notify s meth params = send s (Lsp_rpc.notification meth params)

(* A request's response (the notifications it made stay in [s.out]). *)
let request s meth params =
  s.next <- s.next + 1;
  let id = s.next in
  send s (Lsp_rpc.request (`Int id) meth params);
  match List.partition (fun m -> member "id" m = `Int id) s.out with
  | [ r ], rest -> s.out <- rest; r
  | _ -> Alcotest.failf "%s: no single response with id %d" meth id

let diagnostics_of s u =
  let mine = List.filter (fun m -> member "method" m = `String "textDocument/publishDiagnostics"
                                   && get [ "params"; "uri" ] m = `String u) s.out in
  match List.rev mine with
  | last :: _ -> to_list (get [ "params"; "diagnostics" ] last)
  | [] -> Alcotest.failf "no diagnostics published for %s" u

let text_doc u = ("textDocument", `Assoc [ ("uri", `String u) ])
let pos line character = ("position", `Assoc [ ("line", `Int line); ("character", `Int character) ])

let open_doc s f =
  notify s "textDocument/didOpen"
    (`Assoc [ ("textDocument", `Assoc [ ("uri", `String (uri f)); ("languageId", `String "rapid");
                                        ("version", `Int 1); ("text", `String (read (Filename.concat dir f))) ]) ])

let start ?(allow_unknown = false) ?(snippets = true) () =
  let s = { server = Lsp_server.create { allow_unknown; io = Rapid_controller.Io_config.empty }; out = []; next = 0 } in
  let caps = `Assoc [ ("textDocument", `Assoc [ ("completion", `Assoc [
      ("completionItem", `Assoc [ ("snippetSupport", `Bool snippets) ]) ]) ]) ] in
  let r = request s "initialize" (`Assoc [ ("rootUri", `String (Lsp_uri.of_path dir)); ("capabilities", caps) ]) in
  Alcotest.(check int) "full or incremental sync: incremental advertised" 2
    (int (get [ "result"; "capabilities"; "textDocumentSync"; "change" ] r));
  notify s "initialized" (`Assoc []);
  s

let range_of (j : J.t) =
  let p k = (int (get [ k; "line" ] j), int (get [ k; "character" ] j)) in
  (p "start", p "end")

let range = Alcotest.(pair (pair int int) (pair int int))

(* {1 Diagnostics} *)

let diagnostics () =
  let s = start () in
  List.iter (open_doc s) [ "Cell.mod"; "Tools.mod"; "Wrong.mod" ];
  Alcotest.(check int) "Cell.mod has none" 0 (List.length (diagnostics_of s (uri "Cell.mod")));
  Alcotest.(check int) "Tools.mod (Latin-1) has none" 0 (List.length (diagnostics_of s (uri "Tools.mod")));
  let ds = diagnostics_of s (uri "Wrong.mod") in
  Alcotest.(check (list range)) "the three errors of Wrong.mod at their ranges (UTF-16: the emoji counts two)"
    [ ((3, 9), (3, 15)); ((4, 29), (4, 33)); ((5, 9), (5, 10)) ] (List.map (fun d -> range_of (member "range" d)) ds);
  let first = List.hd ds in
  Alcotest.(check int) "an error" 1 (int (member "severity" first));
  Alcotest.(check bool) "the manual's section in the message" true
    (contains (str (member "message" first)) "(§4.5, §2.17)");
  Alcotest.(check bool) "the rule as the code" true (str (member "code" first) <> "");
  (* A syntax error, by an incremental edit: only it is reported for the module. *)
  notify s "textDocument/didChange"
    (`Assoc [ ("textDocument", `Assoc [ ("uri", `String (uri "Wrong.mod")); ("version", `Int 2) ]);
              ("contentChanges", `List [ `Assoc [ ("range", `Assoc [ ("start", `Assoc [ ("line", `Int 3); ("character", `Int 6) ]);
                                                                     ("end", `Assoc [ ("line", `Int 3); ("character", `Int 8) ]) ]);
                                                  ("text", `String "= =") ] ]) ]);
  let ds = diagnostics_of s (uri "Wrong.mod") in
  Alcotest.(check int) "one syntax error" 1 (List.length ds);
  Alcotest.(check string) "its code" "syntax-error" (str (member "code" (List.hd ds)));
  Alcotest.(check bool) "with a section" true (contains (str (member "message" (List.hd ds))) "§");
  Alcotest.(check (pair int int)) "at the first =, where := was expected" (3, 6) (fst (range_of (member "range" (List.hd ds))));
  (* A full-text change puts the module right. *)
  notify s "textDocument/didChange"
    (`Assoc [ ("textDocument", `Assoc [ ("uri", `String (uri "Wrong.mod")); ("version", `Int 3) ]);
              ("contentChanges", `List [ `Assoc [ ("text", `String "MODULE Wrong\nENDMODULE\n") ] ]) ]);
  Alcotest.(check int) "full sync: no diagnostics left" 0 (List.length (diagnostics_of s (uri "Wrong.mod")));
  (* Warnings: an unknown name under --allow-unknown. *)
  let s = start ~allow_unknown:true () in
  notify s "textDocument/didOpen"
    (`Assoc [ ("textDocument", `Assoc [ ("uri", `String "untitled:w"); ("languageId", `String "rapid"); ("version", `Int 1);
                                        ("text", `String "MODULE W\n  PROC p()\n    Frobnicate;\n  ENDPROC\nENDMODULE\n") ]) ]);
  match diagnostics_of s "untitled:w" with
  | [ w ] ->
      Alcotest.(check int) "a warning" 2 (int (member "severity" w));
      Alcotest.(check (pair int int)) "at the name" (2, 4) (fst (range_of (member "range" w)))
  | l -> Alcotest.failf "expected one warning, got %d" (List.length l)

(* {1 Positions} *)

let positions () =
  let t = Lsp_text.of_bytes "a\xc3\xa9\xf0\x9f\x98\x80b\r\nx\ry\n" in
  let p o = let q = Lsp_text.position_of_offset t o in (q.line, q.character) in
  Alcotest.(check (list (pair int int))) "code points to UTF-16 units, CRLF and CR lines"
    [ (0, 0); (0, 1); (0, 2); (0, 4); (0, 5); (1, 0); (2, 0) ] (List.map p [ 0; 1; 2; 3; 4; 6; 8 ]);
  Alcotest.(check int) "back" 3 (Lsp_text.offset_of_position t { line = 0; character = 4 });
  Alcotest.(check int) "past the line's end: its end" 4 (Lsp_text.offset_of_position t { line = 0; character = 99 });
  let latin1 = Lsp_text.of_bytes "Z\xe4hler x" and utf8 = Lsp_text.of_bytes "Z\xc3\xa4hler x" in
  Alcotest.(check (pair int int)) "Latin-1 and UTF-8 give the same position"
    (let q = Lsp_text.position_of_offset utf8 7 in (q.line, q.character))
    (let q = Lsp_text.position_of_offset latin1 7 in (q.line, q.character));
  let t = Lsp_text.apply_change t (Some ({ line = 0; character = 2 }, { line = 0; character = 4 })) "--" in
  Alcotest.(check string) "an incremental change replaces the surrogate pair" "a\xc3\xa9--b\r\nx\ry\n" (Lsp_text.text t)

(* {1 Hover, definition, references, symbols} *)

let hover_value s f line ch =
  str (get [ "result"; "contents"; "value" ] (request s "textDocument/hover" (`Assoc [ text_doc (uri f); pos line ch ])))

let hover () =
  let s = start () in
  List.iter (open_doc s) [ "Cell.mod"; "Tools.mod" ];
  let h = hover_value s "Cell.mod" 13 12 in
  Alcotest.(check bool) "a data object's declaration" true (contains h "CONST robtarget pHome");
  Alcotest.(check bool) "its initial value as written" true (contains h "[[300, 0, 400]");
  Alcotest.(check bool) "its type" true (contains h "Type `robtarget`, a record");
  let h = hover_value s "Cell.mod" 13 5 in
  Alcotest.(check bool) "an installed routine's signature" true (contains h "PROC MoveL (\\switch Conc, robtarget ToPoint");
  Alcotest.(check bool) "and what it does" true (contains h "straight line");
  let h = hover_value s "Tools.mod" 6 10 in
  Alcotest.(check bool) "a global of another module" true (contains h "VAR num nCount" && contains h "module Cell");
  let h = hover_value s "Cell.mod" 17 44 in
  Alcotest.(check bool) "a component of a kernel record (§2.14)" true (contains h "num x (component of pos)");
  Alcotest.(check bool) "where it is declared: the kernel (§2.14)" true (contains h "built in (§2.14)");
  let h = hover_value s "Tools.mod" 2 22 in
  Alcotest.(check bool) "a parameter: its declaration and routine" true
    (contains h "robtarget pAt" && contains h "routine Pick");
  Alcotest.(check bool) "off a name: null" true
    (member "result" (request s "textDocument/hover" (`Assoc [ text_doc (uri "Cell.mod"); pos 0 0 ])) = `Null)

let locations r = List.map (fun l -> (Filename.basename (str (member "uri" l)), range_of (member "range" l))) (to_list (member "result" r))
let located = Alcotest.(list (pair string range))

let definition_references () =
  let s = start () in
  open_doc s "Cell.mod";
  let def f l c = locations (request s "textDocument/definition" (`Assoc [ text_doc (uri f); pos l c ])) in
  Alcotest.(check located) "Pick is declared in Tools.mod (not open)" [ ("Tools.mod", ((2, 7), (2, 11))) ]
    (def "Cell.mod" 15 5);
  Alcotest.(check located) "a record component" [ ("Cell.mod", ((4, 14), (4, 18))) ] (def "Cell.mod" 14 10);
  Alcotest.(check located) "an installed name has no location here" [] (def "Cell.mod" 13 5);
  let refs include_declaration =
    locations (request s "textDocument/references"
                 (`Assoc [ text_doc (uri "Cell.mod"); pos 9 12;
                           ("context", `Assoc [ ("includeDeclaration", `Bool include_declaration) ]) ])) in
  Alcotest.(check located) "nCount in both modules (Latin-1 columns as characters)"
    [ ("Cell.mod", ((9, 10), (9, 16))); ("Cell.mod", ((16, 4), (16, 10))); ("Cell.mod", ((16, 14), (16, 20)));
      ("Tools.mod", ((5, 29), (5, 35))); ("Tools.mod", ((6, 9), (6, 15))) ] (refs true);
  Alcotest.(check int) "without the declaration" 4 (List.length (refs false));
  (* A named argument is a use of the parameter. *)
  let params = locations (request s "textDocument/references"
                            (`Assoc [ text_doc (uri "Tools.mod"); pos 2 22; ("context", `Assoc [ ("includeDeclaration", `Bool true) ]) ])) in
  Alcotest.(check int) "pAt: its declaration and its use" 2 (List.length params)

let symbols () =
  let s = start () in
  open_doc s "Cell.mod";
  let r = request s "textDocument/documentSymbol" (`Assoc [ text_doc (uri "Cell.mod") ]) in
  let names j = List.map (fun c -> str (member "name" c)) (to_list j) in
  (match to_list (member "result" r) with
   | [ m ] ->
       Alcotest.(check string) "the module" "Cell" (str (member "name" m));
       Alcotest.(check (list string)) "its declarations" [ "partdata"; "tGripper"; "pHome"; "nCount"; "part"; "main" ]
         (names (member "children" m));
       let partdata = List.hd (to_list (member "children" m)) in
       Alcotest.(check (list string)) "a record's components" [ "name"; "grip" ] (names (member "children" partdata))
   | _ -> Alcotest.fail "one module symbol");
  let r = request s "workspace/symbol" (`Assoc [ ("query", `String "pick") ]) in
  Alcotest.(check (list string)) "workspace/symbol finds Pick in the folder" [ "Pick" ] (names (member "result" r));
  Alcotest.(check string) "in Tools.mod" "Tools.mod"
    (Filename.basename (str (get [ "location"; "uri" ] (List.hd (to_list (member "result" r))))))

(* A backup's task is its RAPID/TASKn folder with PROGMOD and SYSMOD below it; another task of
   the same backup is not part of it. *)
let backup () =
  let root = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "rapid-sem-backup-%d" (Unix.getpid ())) in
  let file rel text =
    let p = List.fold_left Filename.concat root rel in
    let rec mkdir_p d = if not (Sys.file_exists d) then (mkdir_p (Filename.dirname d); Unix.mkdir d 0o755) in
    mkdir_p (Filename.dirname p);
    write p text; p in
  let main = file [ "RAPID"; "TASK1"; "PROGMOD"; "Main.mod" ]
      "MODULE Cycle\n  PROC main()\n    nCycles := nCycles + 1;\n  ENDPROC\nENDMODULE\n" in
  ignore (file [ "RAPID"; "TASK1"; "SYSMOD"; "user.sys" ] "MODULE user (SYSMODULE)\n  PERS num nCycles := 0;\nENDMODULE\n");
  ignore (file [ "RAPID"; "TASK2"; "PROGMOD"; "Other.mod" ] "MODULE Other\n  VAR num nCycles;\nENDMODULE\n");
  let s = { server = Lsp_server.create { allow_unknown = false; io = Rapid_controller.Io_config.empty }; out = []; next = 0 } in
  ignore (request s "initialize" (`Assoc [ ("rootUri", `String (Lsp_uri.of_path root)); ("capabilities", `Assoc []) ]));
  let u = Lsp_uri.of_path main in
  notify s "textDocument/didOpen"
    (`Assoc [ ("textDocument", `Assoc [ ("uri", `String u); ("languageId", `String "rapid"); ("version", `Int 1);
                                        ("text", `String (read main)) ]) ]);
  Alcotest.(check int) "no error: SYSMOD's user.sys is in the task" 0 (List.length (diagnostics_of s u));
  let r = request s "textDocument/definition" (`Assoc [ text_doc u; pos 2 6 ]) in
  Alcotest.(check (list string)) "the definition is in SYSMOD, not in TASK2" [ "user.sys" ]
    (List.map (fun l -> Filename.basename (str (member "uri" l))) (to_list (member "result" r)));
  let r = request s "workspace/symbol" (`Assoc [ ("query", `String "ncycles") ]) in
  Alcotest.(check int) "workspace/symbol sees both tasks" 2 (List.length (to_list (member "result" r)));
  (* A module of the task changed on disk: after didSave the task is judged again. *)
  ignore (file [ "RAPID"; "TASK1"; "SYSMOD"; "user.sys" ] "MODULE user (SYSMODULE)\n  PERS num nLoops := 0;\nENDMODULE\n");
  s.out <- [];
  notify s "textDocument/didSave" (`Assoc [ text_doc u ]);
  Alcotest.(check int) "nCycles is now unknown" 1 (List.length (diagnostics_of s u));
  (* R-2.4-rw6: the backup's backinfo.txt names RobotWare 6, where CONTINUE is a name. *)
  let rw6 = file [ "RAPID"; "TASK3"; "PROGMOD"; "Rw6.mod" ]
      "MODULE Rw6\n  VAR bool continue := TRUE;\n  PROC main()\n    Break;\n  ENDPROC\nENDMODULE\n" in
  let open_rw6 () =
    s.out <- [];
    notify s "textDocument/didOpen"
      (`Assoc [ ("textDocument", `Assoc [ ("uri", `String (Lsp_uri.of_path rw6)); ("languageId", `String "rapid");
                                          ("version", `Int 1); ("text", `String (read rw6)) ]) ]);
    List.length (diagnostics_of s (Lsp_uri.of_path rw6)) in
  Alcotest.(check int) "without backinfo.txt: RobotWare 7, CONTINUE reserved" 1 (open_rw6 ());
  ignore (file [ "BACKINFO"; "backinfo.txt" ] ">>PRODUCTS_ID:\nRobotWare Version: 6.13.02.00\n");
  notify s "textDocument/didClose" (`Assoc [ text_doc (Lsp_uri.of_path rw6) ]);
  Alcotest.(check int) "backinfo.txt's RobotWare 6: no error" 0 (open_rw6 ());
  ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote root)))

(* A module of rapid-sem test's tests is checked with the assertions installed, as that command
   checks it (R-test-a); a module without tests is not. *)
let test_module () =
  let root = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "rapid-sem-lsp-test-%d" (Unix.getpid ())) in
  Unix.mkdir root 0o755;
  let file name text = let p = Filename.concat root name in write p text; p in
  let tests = file "Cell_test.mod"
      "MODULE Cell_test\n  PROC test_sum()\n    AssertEqual 1 + 1, 2;\n  ENDPROC\nENDMODULE\n" in
  let plain = file "Plain.mod" "MODULE Plain\n  PROC main()\n    AssertEqual 1 + 1, 2;\n  ENDPROC\nENDMODULE\n" in
  let diagnostics_in path =
    let s = { server = Lsp_server.create { allow_unknown = false; io = Rapid_controller.Io_config.empty }; out = [];
              next = 0 } in
    ignore (request s "initialize" (`Assoc [ ("rootUri", `String (Lsp_uri.of_path root)); ("capabilities", `Assoc []) ]));
    let u = Lsp_uri.of_path path in
    notify s "textDocument/didOpen"
      (`Assoc [ ("textDocument", `Assoc [ ("uri", `String u); ("languageId", `String "rapid"); ("version", `Int 1);
                                          ("text", `String (read path)) ]) ]);
    List.map (fun d -> str (member "message" d)) (diagnostics_of s u) in
  Sys.remove plain;
  Alcotest.(check (list string)) "the assertions are installed for a test module" [] (diagnostics_in tests);
  Sys.remove tests;
  ignore (file "Plain.mod" "MODULE Plain\n  PROC main()\n    AssertEqual 1 + 1, 2;\n  ENDPROC\nENDMODULE\n");
  Alcotest.(check bool) "and not for a module without tests" true
    (List.exists (fun m -> contains m "AssertEqual") (diagnostics_in plain));
  ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote root)))

(* {1 Completion} *)

let labels r = List.map (fun i -> str (member "label" i)) (to_list (get [ "result"; "items" ] r))

let complete s f l c = request s "textDocument/completion" (`Assoc [ text_doc (uri f); pos l c ])

let change s f (l1, c1) (l2, c2) text =
  let p l c = `Assoc [ ("line", `Int l); ("character", `Int c) ] in
  notify s "textDocument/didChange"
    (`Assoc [ ("textDocument", `Assoc [ ("uri", `String (uri f)); ("version", `Int 9) ]);
              ("contentChanges", `List [ `Assoc [ ("range", `Assoc [ ("start", p l1 c1); ("end", p l2 c2) ]); ("text", `String text) ] ]) ])

let completion () =
  let s = start () in
  List.iter (open_doc s) [ "Cell.mod"; "Tools.mod" ];
  let inside = labels (complete s "Tools.mod" 6 4) in
  Alcotest.(check bool) "a routine's own data in scope" true (List.mem "k" inside && List.mem "pAt" inside);
  Alcotest.(check bool) "a global of another module" true (List.mem "nCount" inside);
  Alcotest.(check bool) "installed routines" true (List.mem "MoveL" inside && List.mem "Offs" inside);
  Alcotest.(check bool) "not another routine's data" false (List.mem "k" (labels (complete s "Cell.mod" 14 4)));
  let item name r = List.find (fun i -> member "label" i = `String name) (to_list (get [ "result"; "items" ] r)) in
  let movel = item "MoveL" (complete s "Tools.mod" 6 4) in
  Alcotest.(check string) "MoveL's required parameters as a snippet"
    "MoveL ${1:ToPoint}, ${2:Speed}, ${3:Zone}, ${4:Tool}" (str (member "insertText" movel));
  Alcotest.(check bool) "its signature as detail" true (contains (str (member "detail" movel)) "PERS tooldata Tool");
  Alcotest.(check string) "its parameters beside the label (labelDetails)"
    " ([\\Conc], ToPoint, [\\ID], Speed, [\\V|\\T], Zone, [\\Z], [\\Inpos], Tool, [\\WObj], [\\Corr], [\\TLoad])"
    (str (get [ "labelDetails"; "detail" ] movel));
  let s2 = start ~snippets:false () in
  open_doc s2 "Tools.mod";
  Alcotest.(check bool) "no snippet for a client without them" true
    (member "insertText" (item "MoveL" (complete s2 "Tools.mod" 6 4)) = `Null);
  (* After '.': the components of the record, even while the module does not parse. *)
  change s "Cell.mod" (17, 32) (17, 45) "pHome.trans.";
  Alcotest.(check (list string)) "pHome.trans." [ "x"; "y"; "z" ] (labels (complete s "Cell.mod" 17 44));
  change s "Cell.mod" (17, 32) (17, 44) "part.";
  Alcotest.(check (list string)) "a user record" [ "name"; "grip" ] (labels (complete s "Cell.mod" 17 37));
  (* After '\': the optional parameters of the routine called. *)
  change s "Cell.mod" (13, 37) (13, 37) " \\";
  Alcotest.(check bool) "MoveL's optional parameters" true
    (let l = labels (complete s "Cell.mod" 13 39) in List.mem "WObj" l && List.mem "Conc" l && not (List.mem "Tool" l))

(* {1 Signature help} *)

let signature_help () =
  let s = start () in
  open_doc s "Tools.mod";
  let help l c = member "result" (request s "textDocument/signatureHelp" (`Assoc [ text_doc (uri "Tools.mod"); pos l c ])) in
  let active h =
    let label = str (get [ "signatures" ] h |> to_list |> List.hd |> member "label") in
    let p = List.nth (to_list (get [ "parameters" ] (List.hd (to_list (member "signatures" h))))) (int (member "activeParameter" h)) in
    match to_list (member "label" p) with
    | [ `Int a; `Int b ] -> String.sub label a (b - a)
    | _ -> "?" in
  (* line 4: "    MoveL Offs(pAt, 0, 0, 50), v100, z10, tGripper \WObj:=wobj0;" *)
  Alcotest.(check string) "inside Offs( after one comma: its second parameter" "num XOffset" (active (help 4 20));
  Alcotest.(check string) "MoveL after the point and the speed: Zone" "zonedata Zone" (active (help 4 37));
  Alcotest.(check string) "MoveL's first required parameter at the start" "robtarget ToPoint" (active (help 4 10));
  Alcotest.(check bool) "the installed routine's line" true
    (contains (str (member "documentation" (List.hd (to_list (member "signatures" (help 4 37)))))) "straight line");
  Alcotest.(check bool) "nothing on a line without a call" true (help 0 3 = `Null)

(* {1 Quick fixes} *)

let quick_fix () =
  let s = start () in
  let u = "untitled:fix" in
  notify s "textDocument/didOpen"
    (`Assoc [ ("textDocument", `Assoc [ ("uri", `String u); ("languageId", `String "rapid"); ("version", `Int 1);
                                        ("text", `String "MODULE W\n  PROC p()\n    TPWrite \"\" \\Num:=ERRNUM + tol0.tload.mass;\n  ENDPROC\nENDMODULE\n") ]) ]);
  let ds = diagnostics_of s u in
  let with_hint = List.filter (fun d -> contains (str (member "message" d)) "hint: did you mean") ds in
  Alcotest.(check bool) "a diagnostic with a hint" true (with_hint <> []);
  let r = request s "textDocument/codeAction"
      (`Assoc [ text_doc u; ("range", `Assoc [ ("start", `Assoc [ ("line", `Int 2); ("character", `Int 0) ]);
                                                 ("end", `Assoc [ ("line", `Int 2); ("character", `Int 40) ]) ]);
                ("context", `Assoc [ ("diagnostics", `List ds) ]) ]) in
  let titles = List.map (fun a -> str (member "title" a)) (to_list (member "result" r)) in
  Alcotest.(check bool) "Change tol0 to tool0 offered" true (List.mem "Change tol0 to tool0" titles);
  let fix = List.find (fun a -> member "title" a = `String "Change tol0 to tool0") (to_list (member "result" r)) in
  let edit = List.hd (to_list (get [ "edit"; "changes"; u ] fix)) in
  Alcotest.(check string) "the edit writes the name" "tool0" (str (member "newText" edit));
  Alcotest.(check range) "over the misspelt name" ((2, 30), (2, 34)) (range_of (member "range" edit));
  Alcotest.(check (list string)) "the hint's names" [ "a"; "bb"; "c" ] (Lsp_features.suggested "did you mean a, bb or c?");
  Alcotest.(check (list string)) "no other hint" [] (Lsp_features.suggested "write \\Num:=x (§4.6)")

(* {1 Rename} *)

let rename () =
  let s = start () in
  List.iter (open_doc s) [ "Cell.mod"; "Tools.mod" ];
  let rename f l c name = request s "textDocument/rename" (`Assoc [ text_doc (uri f); pos l c; ("newName", `String name) ]) in
  let r = rename "Tools.mod" 6 10 "nPicks" in
  let changes = match get [ "result"; "changes" ] r with `Assoc l -> l | _ -> [] in
  Alcotest.(check (list (pair string int))) "edits in both modules"
    [ (uri "Cell.mod", 3); (uri "Tools.mod", 2) ] (List.map (fun (u, e) -> (u, List.length (to_list e))) changes);
  Alcotest.(check bool) "each edit writes the new name" true
    (List.for_all (fun (_, e) -> List.for_all (fun x -> member "newText" x = `String "nPicks") (to_list e)) changes);
  let refused name why =
    let r = rename "Cell.mod" 9 12 name in
    Alcotest.(check int) (name ^ ": refused") Lsp_rpc.request_failed (int (get [ "error"; "code" ] r));
    Alcotest.(check bool) (name ^ ": " ^ why) true (contains (str (get [ "error"; "message" ] r)) why) in
  refused "pHome" "already declared";
  refused "IF" "reserved word";
  refused "2x" "begins with a letter";
  refused "tool0" "already declared: the persistent tool0";
  refused (String.make 33 'a') "at most 32";
  (* A routine's local renamed to a global the routine uses: that use would be captured. *)
  let r = request s "textDocument/rename" (`Assoc [ text_doc (uri "Tools.mod"); pos 3 12; ("newName", `String "nCount") ]) in
  Alcotest.(check bool) "a capture is refused" true (get [ "error"; "code" ] r = `Int Lsp_rpc.request_failed);
  let r = request s "textDocument/rename" (`Assoc [ text_doc (uri "Cell.mod"); pos 13 5; ("newName", `String "Go") ]) in
  Alcotest.(check bool) "an installed routine is refused" true (contains (str (get [ "error"; "message" ] r)) "installed");
  let r = request s "textDocument/prepareRename" (`Assoc [ text_doc (uri "Cell.mod"); pos 9 12 ]) in
  Alcotest.(check range) "prepareRename gives the name's range" ((9, 10), (9, 16)) (range_of (get [ "result"; "range" ] r))

(* Every installed routine has its line of what it does, and every line is an installed routine's. *)
let routine_docs () =
  let installed = List.filter_map (fun (d : Lsp_index.decl) ->
      match d.kind with Routine _ -> Some d.name | _ -> None) (Lsp_index.installed_decls ()) in
  Alcotest.(check bool) "the installed routines are read" true (List.length installed > 300);
  Alcotest.(check (list string)) "installed routines without a line" []
    (List.filter (fun n -> Lsp_routine_docs.find n = None) installed);
  Alcotest.(check (list string)) "lines of no installed routine" []
    (List.filter (fun n -> not (List.exists (fun i -> String.lowercase_ascii i = String.lowercase_ascii n) installed))
       Lsp_routine_docs.names)

(* {1 Robustness} *)

let protocol () =
  let s = { server = Lsp_server.create { allow_unknown = false; io = Rapid_controller.Io_config.empty }; out = []; next = 0 } in
  let code r = int (get [ "error"; "code" ] r) in
  Alcotest.(check int) "before initialize" Lsp_rpc.server_not_initialized (code (request s "textDocument/hover" (`Assoc [])));
  ignore (request s "initialize" (`Assoc [ ("capabilities", `Assoc []) ]));
  Alcotest.(check int) "an unknown method" Lsp_rpc.method_not_found (code (request s "textDocument/frobnicate" (`Assoc [])));
  Alcotest.(check int) "bad params" Lsp_rpc.invalid_params (code (request s "textDocument/hover" (`Assoc [ ("x", `Int 1) ])));
  Alcotest.(check bool) "a document never opened: an answer, not a crash" true
    (member "result" (request s "textDocument/hover" (`Assoc [ text_doc "file:///nowhere/x.mod"; pos 0 0 ])) = `Null);
  send s (`List [ `Int 1 ]);
  Alcotest.(check int) "not an object" Lsp_rpc.invalid_request (code (List.hd s.out));
  s.out <- [];
  Alcotest.(check bool) "shutdown" true (member "result" (request s "shutdown" `Null) = `Null);
  Alcotest.(check int) "after shutdown" Lsp_rpc.invalid_request (code (request s "textDocument/hover" (`Assoc [])));
  send s (Lsp_rpc.notification "exit" `Null);
  Alcotest.(check (option int)) "exit after shutdown: 0" (Some 0) (Lsp_server.finished s.server)

let with_input text f =
  let path = Filename.temp_file "lsp" ".in" in
  write path text;
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in ic; Sys.remove path) (fun () -> f ic)

let framing () =
  let ok = Lsp_rpc.frame (`Assoc [ ("a", `Int 1) ]) in
  with_input ("\r\n" ^ ok ^ "X-Other: 1\r\n\r\n" ^ "Content-Length: 3\r\n\r\n{x}" ^ ok
              ^ "X-Other: 2\r\n\r\n{\"b\":2}" ^ ok ^ Printf.sprintf "Content-Length: %d\r\n\r\n" (Lsp_rpc.max_body + 1)
              ^ String.make (Lsp_rpc.max_body + 1) ' ' ^ ok) (fun ic ->
      let kind = function Lsp_rpc.Message _ -> "message" | Malformed _ -> "malformed" | End -> "end" in
      let seq = List.init 9 (fun _ -> kind (Lsp_rpc.read ic)) in
      Alcotest.(check (list string))
        "a message, a header without length, bad JSON, a message, a body without a header (the next message found \
         again), a body too long (read past), the end"
        [ "message"; "malformed"; "malformed"; "message"; "malformed"; "message"; "malformed"; "message"; "end" ] seq)

(* A seeded fuzz: random edits (insertions, deletions, replacements of random text at random
   places, full replacements) of the task's modules, each followed by requests at random
   places. Every request is answered with its id, the server's text stays the one the edits
   make (checked against a model of our own), and nothing raises. *)
let fuzz () =
  let s = start () in
  let files = [ "Cell.mod"; "Tools.mod"; "Wrong.mod" ] in
  List.iter (open_doc s) files;
  let model = Hashtbl.create 3 in
  List.iter (fun f -> Hashtbl.replace model f (Lsp_text.of_bytes (read (Filename.concat dir f)))) files;
  let rng = Random.State.make [| 22 |] in
  let pieces = [| "MODULE"; "ENDPROC"; "."; "\\"; "("; ")"; ";"; ":="; "{"; "}"; "\n"; "pHome"; "nCount"; "Pick ";
                  "\"\xc3\xa4"; "\xf0\x9f\x98\x80"; "IF x THEN"; "!"; "%"; "1E99"; "part.grip."; "VAR num"; " " |] in
  let random_pos t =
    let o = Random.State.int rng (Lsp_text.length t + 1) in
    let p = Lsp_text.position_of_offset t o in
    (* now and then a position beyond the line or the text *)
    if Random.State.int rng 10 = 0 then { p with Lsp_text.character = p.character + 50 } else p in
  let methods = [| "textDocument/hover"; "textDocument/definition"; "textDocument/references"; "textDocument/completion";
                   "textDocument/rename"; "textDocument/documentSymbol"; "textDocument/prepareRename"; "workspace/symbol" |] in
  for _ = 1 to 300 do
    let f = List.nth files (Random.State.int rng 3) in
    let t = Hashtbl.find model f in
    let a = random_pos t and b = random_pos t in
    let text = String.concat "" (List.init (Random.State.int rng 4) (fun _ -> pieces.(Random.State.int rng (Array.length pieces)))) in
    let jp (p : Lsp_text.position) = `Assoc [ ("line", `Int p.line); ("character", `Int p.character) ] in
    let full = Random.State.int rng 40 = 0 in
    let change = if full then `Assoc [ ("text", `String text) ]
      else `Assoc [ ("range", `Assoc [ ("start", jp a); ("end", jp b) ]); ("text", `String text) ] in
    notify s "textDocument/didChange" (`Assoc [ ("textDocument", `Assoc [ ("uri", `String (uri f)); ("version", `Int 0) ]);
                                                ("contentChanges", `List [ change ]) ]);
    Hashtbl.replace model f (Lsp_text.apply_change t (if full then None else Some (a, b)) text);
    s.out <- [];
    for _ = 1 to 2 do
      let g = List.nth files (Random.State.int rng 3) in
      let p = random_pos (Hashtbl.find model g) in
      let r = request s methods.(Random.State.int rng (Array.length methods))
          (`Assoc [ text_doc (uri g); ("position", jp p); ("newName", `String "zz9"); ("query", `String "p");
                    ("context", `Assoc [ ("includeDeclaration", `Bool true) ]) ]) in
      match member "error" r with
      | `Null -> ()
      | e -> Alcotest.(check bool) ("only a refused rename is an error: " ^ J.to_string e) true
               (int (member "code" e) = Lsp_rpc.request_failed)
    done
  done;
  List.iter (fun f ->
      Alcotest.(check (option string)) (f ^ ": the server's text is the one the edits make")
        (Some (Lsp_text.text (Hashtbl.find model f)))
        (Option.map Lsp_text.text (Lsp_workspace.text (Lsp_server.workspace s.server) (uri f)))) files;
  let r = request s "shutdown" `Null in
  Alcotest.(check bool) "still answering after the fuzz" true (member "result" r = `Null)

(* {1 The command: framing over real pipes} *)

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

let command_session () =
  let input = String.concat "" (List.map Lsp_rpc.frame [
      Lsp_rpc.request (`Int 1) "initialize" (`Assoc [ ("capabilities", `Assoc []) ]);
      Lsp_rpc.notification "textDocument/didOpen"
        (`Assoc [ ("textDocument", `Assoc [ ("uri", `String (uri "Wrong.mod")); ("languageId", `String "rapid");
                                            ("version", `Int 1); ("text", `String (read (Filename.concat dir "Wrong.mod"))) ]) ]);
      Lsp_rpc.request (`Int 2) "textDocument/hover" (`Assoc [ text_doc (uri "Wrong.mod"); pos 5 5 ]) ])
              ^ "Content-Length: 2\r\n\r\n{]" ^ String.concat "" (List.map Lsp_rpc.frame [
      Lsp_rpc.request (`Int 3) "nothing/here" `Null;
      Lsp_rpc.request (`Int 4) "shutdown" `Null; Lsp_rpc.notification "exit" `Null ]) in
  let inf = Filename.temp_file "lsp" ".in" and outf = Filename.temp_file "lsp" ".out" in
  write inf input;
  let status = Sys.command (Printf.sprintf "%s lsp < %s > %s" (Filename.quote binary) (Filename.quote inf) (Filename.quote outf)) in
  let ic = open_in_bin outf in
  let rec all acc = match Lsp_rpc.read ic with Lsp_rpc.Message m -> all (m :: acc) | Malformed m -> Alcotest.fail m
                                              | End -> List.rev acc in
  let msgs = all [] in
  close_in ic; Sys.remove inf; Sys.remove outf;
  Alcotest.(check int) "exit status 0 after shutdown and exit" 0 status;
  let by_id i = List.find_opt (fun m -> member "id" m = `Int i) msgs in
  Alcotest.(check bool) "initialize answered" true (by_id 1 <> None);
  Alcotest.(check bool) "the hover of Pick" true
    (match by_id 2 with Some r -> contains (str (get [ "result"; "contents"; "value" ] r)) "PROC Pick" | None -> false);
  Alcotest.(check bool) "a ParseError for the malformed body" true
    (List.exists (fun m -> get [ "error"; "code" ] m = `Int Lsp_rpc.parse_error) msgs);
  Alcotest.(check bool) "MethodNotFound" true
    (match by_id 3 with Some r -> get [ "error"; "code" ] r = `Int Lsp_rpc.method_not_found | None -> false);
  Alcotest.(check bool) "the diagnostics of Wrong.mod" true
    (List.exists (fun m -> member "method" m = `String "textDocument/publishDiagnostics"
                           && List.length (to_list (get [ "params"; "diagnostics" ] m)) = 3) msgs)

(* {1 A real client: Neovim's, headless} *)

let nvim_session () =
  if Sys.command "command -v nvim > /dev/null 2>&1" <> 0 then
    (* CI runs `make deps`, which installs neovim: the session runs there. *)
    print_endline "SKIP: nvim is not installed (scripts/install-deps.sh installs it): the Neovim session did not run"
  else begin
    let work = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "rapid-sem-nvim-%d" (Unix.getpid ())) in
    ignore (Sys.command (Printf.sprintf "rm -rf %s && mkdir -p %s && cp %s/*.mod %s" (Filename.quote work) (Filename.quote work)
                           (Filename.quote dir) (Filename.quote work)));
    let result = Filename.concat work "result.txt" in
    let script = Filename.concat (Sys.getcwd ()) "lsp/nvim_session.lua" in
    let cmd = Printf.sprintf "cd %s && RAPID_SEM=%s RESULT=%s HOME=%s timeout 120 nvim --headless --clean -c %s > %s/nvim.log 2>&1"
        (Filename.quote work) (Filename.quote binary) (Filename.quote result) (Filename.quote work)
        (Filename.quote ("luafile " ^ script)) (Filename.quote work) in
    let status = Sys.command cmd in
    let lines = if Sys.file_exists result then String.split_on_char '\n' (String.trim (read result)) else [] in
    if status <> 0 || lines = [] then
      Alcotest.failf "nvim exited %d; its log: %s" status
        (if Sys.file_exists (Filename.concat work "nvim.log") then read (Filename.concat work "nvim.log") else "");
    let expected = [
      "diagnostics 3";
      "diagnostic 3:9-3:15 1 expected a value of type num, found string (§4.5, §2.17)";
      "diagtext \"text\"";
      "diagnostic 4:29-4:33 1 expected a value of type num, found bool";
      "diagtext TRUE";
      "diagnostic 5:9-5:10 1 expected a value of type robtarget for the parameter pAt, found num";
      "diagtext 5";
      "hover pHome CONST robtarget pHome";
      "hover MoveL PROC MoveL (\\switch Conc, robtarget ToPoint";
      "definition Pick Tools.mod 2:7";
      "references nCount 5";
      "completion MoveL yes";
      "signature MoveL zonedata Zone";
      "completion components x,y,z";
      "rename nCount nPicks 5";
      "renamed Cell.mod nPicks := nPicks + 1;";
      "done" ] in
    List.iter (fun e ->
        Alcotest.(check bool) ("nvim: " ^ e) true
          (List.exists (fun l -> String.length l >= String.length e && String.sub l 0 (String.length e) = e) lines))
      expected;
    ignore (Sys.command (Printf.sprintf "rm -rf %s" (Filename.quote work)))
  end

let suite =
  ("lsp",
   [ Alcotest.test_case "diagnostics: syntax, static, warnings, at UTF-16 ranges" `Quick diagnostics;
     Alcotest.test_case "positions: UTF-16, Latin-1, incremental changes" `Quick positions;
     Alcotest.test_case "hover" `Quick hover;
     Alcotest.test_case "definition and references across the task" `Quick definition_references;
     Alcotest.test_case "document and workspace symbols" `Quick symbols;
     Alcotest.test_case "a backup's RAPID/TASKn is a task" `Quick backup;
     Alcotest.test_case "a module of tests has the assertions" `Quick test_module;
     Alcotest.test_case "completion" `Quick completion;
     Alcotest.test_case "signature help" `Quick signature_help;
     Alcotest.test_case "quick fixes from the hints" `Quick quick_fix;
     Alcotest.test_case "rename and its refusals" `Quick rename;
     Alcotest.test_case "a line of what each installed routine does" `Quick routine_docs;
     Alcotest.test_case "protocol errors never end the server" `Quick protocol;
     Alcotest.test_case "framing: malformed messages are skipped" `Quick framing;
     Alcotest.test_case "a fuzz of random edits keeps it answering" `Quick fuzz;
     Alcotest.test_case "rapid-sem lsp over pipes" `Quick command_session;
     Alcotest.test_case "an end-to-end session with Neovim's client" `Quick nvim_session ])
