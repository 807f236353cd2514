module I = Lsp_index
module W = Lsp_workspace

exception Refused of string

let key = String.lowercase_ascii

(* The occurrence under the cursor, with the task's index. *)
let at ws uri pos =
  let index = W.index ws uri in
  match W.text ws uri with
  | None -> (index, None)
  | Some text -> (index, I.occurrence_at index uri (Lsp_text.offset_of_position text pos))

let source_text index uri = Option.map (fun (s : I.source) -> s.text) (I.source index uri)

let range index uri a b =
  match source_text index uri with
  | Some text -> Lsp_text.json_range text a b
  | None -> Lsp_text.json_range (Lsp_text.of_bytes "") 0 0

let location index uri a b : Yojson.Safe.t = `Assoc [ ("uri", `String uri); ("range", range index uri a b) ]

(* Where a declaration stands, in words: "module Cell, line 12" or "installed (motion.sys)". *)
let where index (d : I.decl) =
  match d.uri with
  | None -> (
      let of_routine = match d.routine with Some r -> Printf.sprintf "of %s, " r | None -> "" in
      match d.installed_file with
      | Some "built-in" | None ->
          of_routine ^ (match d.kind with
              | Record _ | Component _ -> "built in (§2.14)"
              | Alias _ -> "built in (§2.15)"
              | Atomic when List.mem (key d.name) [ "num"; "dnum"; "bool"; "string" ] -> "built in (§2.13)"
              | _ -> "installed (ch. 13)")
      | Some f -> Printf.sprintf "%sinstalled (%s, ch. 13)" of_routine (Filename.basename f))
  | Some uri ->
      let line = match source_text index uri with
        | Some t -> Printf.sprintf ", line %d" ((Lsp_text.position_of_offset t d.name_start).line + 1)
        | None -> "" in
      Printf.sprintf "module %s%s%s" d.module_name
        (match d.routine with Some r -> ", routine " ^ r | None -> "") line

(* The declaration as written, on one line, when it is short enough to show. *)
let written index (d : I.decl) =
  match d.uri, d.kind with
  | _, Data { parameter = true; _ } | _, Data { storage = "FOR"; _ } -> None
  | Some uri, (Data _ | Alias _) -> (
      match source_text index uri with
      | Some t ->
          let s = String.trim (Lsp_text.slice t d.decl_start d.decl_stop) in
          let s = String.concat " " (List.filter (( <> ) "") (String.split_on_char '\n'
                                                              (String.map (function '\r' | '\t' -> ' ' | c -> c) s))) in
          if s = "" || String.length s > 240 then None else Some s
      | None -> None)
  | _ -> None

let hover_markdown index (d : I.decl) =
  let code s = "```rapid\n" ^ s ^ "\n```" in
  let lines = ref [ code (I.signature d) ] in
  let add s = lines := !lines @ [ s ] in
  (match written index d with
   | Some w when w <> I.signature d ^ ";" -> add (code w)
   | _ -> ());
  add (Printf.sprintf "%s `%s`: %s" (String.capitalize_ascii (I.kind_name d)) d.name (where index d));
  (match d.kind with
   | Routine _ when d.uri = None -> Option.iter add (Lsp_routine_docs.find d.name)
   | _ -> ());
  (* A data object's type: its definition, when it is a record. *)
  (match I.type_of_decl d, d.kind with
   | Some ty, (Data _ | Component _) -> (
       let uri = Option.value d.uri ~default:"" in
       match I.lookup_type index uri d.name_start ty with
       | Some ({ kind = Record cs; _ } as td) ->
           add (Printf.sprintf "Type `%s`, a record (%s): %s" td.name (where index td)
                  (String.concat ", " (List.map (fun (t, c) -> c ^ " " ^ t) cs)))
       | Some ({ kind = Alias b; _ } as td) ->
           add (Printf.sprintf "Type `%s`, an alias of %s (%s)" td.name b (where index td))
       | _ -> ())
   | _ -> ());
  String.concat "\n\n" !lines

let hover ws uri pos : Yojson.Safe.t =
  match at ws uri pos with
  | _, None -> `Null
  | index, Some o ->
      `Assoc [ ("contents", `Assoc [ ("kind", `String "markdown"); ("value", `String (hover_markdown index o.decl)) ]);
               ("range", range index uri o.o_start o.o_stop) ]

let definition ws uri pos : Yojson.Safe.t =
  match at ws uri pos with
  | index, Some { decl = { uri = Some u; name_start; name_stop; _ }; _ } ->
      `List [ location index u name_start name_stop ]
  | _ -> `List []

(* Only modules that parse now have uses at places the editor shows. *)
let fresh index uri = match I.source index uri with Some s -> s.fresh | None -> false

let references ws uri pos ~include_declaration : Yojson.Safe.t =
  match at ws uri pos with
  | _, None -> `List []
  | index, Some o ->
      let d = o.decl in
      `List (List.filter_map (fun (u, (x : I.occurrence)) ->
          let is_decl = d.uri = Some u && x.o_start = d.name_start in
          if (is_decl && not include_declaration) || not (fresh index u) then None
          else Some (location index u x.o_start x.o_stop)) (I.occurrences_of index d))

(* {1 Symbols} *)

(* LSP 3.17's SymbolKind. *)
let symbol_kind (d : I.decl) =
  match d.kind with
  | Module -> 2
  | Record _ -> 23
  | Alias _ | Atomic -> 26
  | Data { storage = "CONST"; _ } -> 14
  | Data _ -> 13
  | Routine { routine = Trap_routine; _ } -> 24
  | Routine _ -> 12
  | Component _ -> 8
  | Label -> 20

let document_symbol index uri (d : I.decl) children : Yojson.Safe.t =
  `Assoc [ ("name", `String d.name); ("detail", `String (I.signature d)); ("kind", `Int (symbol_kind d));
           ("range", range index uri d.decl_start d.decl_stop);
           ("selectionRange", range index uri d.name_start d.name_stop);
           ("children", `List children) ]

let document_symbols ws uri : Yojson.Safe.t =
  let index = W.index ws uri in
  if not (fresh index uri) then `List []
  else
    let all = I.decls index uri in
    let inside (r : I.decl) (d : I.decl) =
      d.routine = Some r.name && d.decl_start >= r.decl_start && d.decl_stop <= r.decl_stop in
    let routines = List.filter (fun (d : I.decl) -> d.routine = None && d.kind <> Module) all in
    let child (d : I.decl) =
      let kids = match d.kind with
        | Routine _ -> I.members index d @ List.filter (inside d) all
        | Record _ -> I.members index d
        | _ -> [] in
      document_symbol index uri d (List.map (fun k -> document_symbol index uri k []) kids) in
    match List.find_opt (fun (d : I.decl) -> d.kind = Module) all with
    | Some m -> `List [ document_symbol index uri m (List.map child routines) ]
    | None -> `List (List.map child routines)

let contains ~sub s =
  let sub = key sub and s = key s in
  let n = String.length sub and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = sub || go (i + 1)) in
  n = 0 || go 0

let workspace_symbols ws query : Yojson.Safe.t =
  let seen = Hashtbl.create 64 in
  `List (List.concat_map (fun index ->
      List.concat_map (fun (s : I.source) ->
          if Hashtbl.mem seen s.uri || not s.fresh then []
          else begin
            Hashtbl.replace seen s.uri ();
            List.filter_map (fun (d : I.decl) ->
                if d.routine <> None || not (contains ~sub:query d.name) then None
                else Some (`Assoc [ ("name", `String d.name); ("kind", `Int (symbol_kind d));
                                    ("location", location index s.uri d.name_start d.name_stop);
                                    ("containerName", `String d.module_name) ])) (I.decls index s.uri)
          end) (I.sources index)) (W.workspace_indexes ws))

(* {1 Completion} *)

let is_ident_char c = match c with 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_' -> true | _ -> false

(* LSP 3.17's CompletionItemKind. *)
let item_kind (d : I.decl) =
  match d.kind with
  | Module -> 9
  | Record _ -> 22
  | Alias _ | Atomic -> 25
  | Data { storage = "CONST"; _ } -> 21
  | Data _ -> 6
  | Routine { routine = Func _; _ } -> 3
  | Routine { routine = Proc; _ } -> 2
  | Routine { routine = Trap_routine; _ } -> 23
  | Component _ -> 5
  | Label -> 18

let snippet (d : I.decl) =
  match d.kind with
  | Routine { routine; slots } ->
      let required = List.filter_map (function I.Required q -> Some q.I.p_name | Optional _ -> None) slots in
      let holes = List.mapi (fun i n -> Printf.sprintf "${%d:%s}" (i + 1) n) required in
      Some (match routine with
          | Func _ -> d.name ^ "(" ^ String.concat ", " holes ^ ")"
          | Proc -> if holes = [] then d.name else d.name ^ " " ^ String.concat ", " holes
          | Trap_routine -> d.name)
  | _ -> None

let item ~snippets (d : I.decl) : Yojson.Safe.t =
  let doc = match d.kind, d.uri with
    | Routine _, None -> Lsp_routine_docs.find d.name
    | _ -> None in
  let insert = match snippets, snippet d with
    | true, Some s when s <> d.name -> [ ("insertText", `String s); ("insertTextFormat", `Int 2) ]
    | _ -> [] in
  (* LSP 3.17's labelDetails: the parameters beside the name, as ABB's syntax lists them *)
  let label_details = match d.kind with
    | Routine { slots; routine = Proc | Func _ } ->
        let slot = function
          | I.Required q -> q.I.p_name
          | Optional qs -> "[\\" ^ String.concat "|\\" (List.map (fun (q : I.param) -> q.p_name) qs) ^ "]" in
        [ ("labelDetails", `Assoc [ ("detail", `String (" (" ^ String.concat ", " (List.map slot slots) ^ ")")) ]) ]
    | _ -> [] in
  `Assoc ([ ("label", `String d.name); ("kind", `Int (item_kind d)); ("detail", `String (I.signature d)) ]
          @ label_details
          @ (match doc with Some s -> [ ("documentation", `String s) ] | None -> [])
          @ insert)

(* The chain of names before a '.' that ends at [stop] (exclusive): [p.trans] in [p.trans.], the
   indices of an element skipped ([a{i}.trans]). *)
let reference_before text stop =
  let rec names stop acc =
    let i = ref (stop - 1) in
    (* an element's indices *)
    if !i >= 0 && text.[!i] = '}' then begin
      let depth = ref 0 in
      let continue = ref true in
      while !continue && !i >= 0 do
        (match text.[!i] with '}' -> incr depth | '{' -> decr depth | _ -> ());
        if !depth = 0 then continue := false else decr i
      done;
      decr i
    end;
    let e = !i + 1 in
    while !i >= 0 && is_ident_char text.[!i] do decr i done;
    let s = !i + 1 in
    if s >= e then acc
    else
      let acc = String.sub text s (e - s) :: acc in
      if !i >= 0 && text.[!i] = '.' then names !i acc else acc in
  names stop []

let component_items index uri offset chain =
  match chain with
  | [] -> []
  | first :: rest ->
      let start = Option.bind (I.lookup_at index uri offset first) I.type_of_decl in
      let ty = List.fold_left (fun ty n ->
          Option.bind ty (fun ty ->
              let comps = I.components_of_type index uri offset ty in
              match List.find_opt (fun (c : I.decl) -> key c.name = key n) comps with
              | Some c -> I.type_of_decl c
              | None -> None)) start rest in
      match ty with Some ty -> I.components_of_type index uri offset ty | None -> []

(* The routine whose optional parameters a '\' asks for: the name before the innermost open '('
   on the line, else the line's first word. *)
let callee_before text line_start stop =
  let depth = ref 0 and i = ref (stop - 1) and found = ref None in
  while !found = None && !i >= line_start do
    (match text.[!i] with
     | ')' -> incr depth
     | '(' -> if !depth = 0 then found := Some !i else decr depth
     | _ -> ());
    decr i
  done;
  let word_before j =
    let e = ref j in
    while !e > line_start && text.[!e - 1] = ' ' do decr e done;
    let s = ref !e in
    while !s > line_start && is_ident_char text.[!s - 1] do decr s done;
    if !s < !e then Some (String.sub text !s (!e - !s)) else None in
  match !found with
  | Some p -> word_before p
  | None ->
      let s = ref line_start in
      while !s < stop && (text.[!s] = ' ' || text.[!s] = '\t') do incr s done;
      let e = ref !s in
      while !e < stop && is_ident_char text.[!e] do incr e done;
      if !e > !s then Some (String.sub text !s (!e - !s)) else None

let completion ws uri pos ~snippets : Yojson.Safe.t =
  let index = W.index ws uri in
  match W.text ws uri with
  | None -> `List []
  | Some t ->
      let offset = Lsp_text.offset_of_position t pos in
      let text = Lsp_text.text t in
      let b = Lsp_text.byte_of_offset t offset in
      let s = ref b in
      while !s > 0 && is_ident_char text.[!s - 1] do decr s done;
      let line_start = Lsp_text.byte_of_offset t (Lsp_text.offset_of_position t { pos with character = 0 }) in
      let items =
        if !s > 0 && text.[!s - 1] = '.' then
          List.map (item ~snippets) (component_items index uri offset (reference_before text (!s - 1)))
        else if !s > 0 && text.[!s - 1] = '\\' then
          match callee_before text line_start (!s - 1) with
          | None -> []
          | Some name -> (
              match I.lookup_at index uri offset name with
              | Some ({ kind = Routine { slots; _ }; _ } as r) ->
                  let optional = List.concat_map (function I.Optional qs -> qs | I.Required _ -> []) slots in
                  let params = I.members index r in
                  List.filter_map (fun (q : I.param) ->
                      Option.map (fun (p : I.decl) ->
                          let insert = if q.p_type = None then q.p_name else q.p_name ^ ":=" in
                          `Assoc [ ("label", `String q.p_name); ("kind", `Int 6);
                                   ("detail", `String (I.signature p)); ("insertText", `String insert) ])
                        (List.find_opt (fun (p : I.decl) -> key p.name = key q.p_name) params)) optional
              | _ -> [])
        else List.map (item ~snippets) (I.visible_at index uri offset) in
      `Assoc [ ("isIncomplete", `Bool false); ("items", `List items) ]

(* {1 Signature help} *)

(* The separators of required arguments (§4.6: a comma; an optional argument may have one
   before it too) between [start] and [stop], outside parentheses, brackets, braces and strings. *)
let commas text start stop =
  let depth = ref 0 and quoted = ref false and n = ref 0 in
  for i = start to stop - 1 do
    match text.[i] with
    | '"' -> quoted := not !quoted
    | ('(' | '[' | '{') when not !quoted -> incr depth
    | (')' | ']' | '}') when not !quoted -> decr depth
    | ',' when not !quoted && !depth = 0 -> incr n
    | _ -> ()
  done;
  !n

let signature_help ws uri pos : Yojson.Safe.t =
  let index = W.index ws uri in
  match W.text ws uri with
  | None -> `Null
  | Some t ->
      let offset = Lsp_text.offset_of_position t pos in
      let text = Lsp_text.text t in
      let b = Lsp_text.byte_of_offset t offset in
      let line_start = Lsp_text.byte_of_offset t (Lsp_text.offset_of_position t { pos with character = 0 }) in
      match callee_before text line_start b with
      | None -> `Null
      | Some name -> (
          match I.lookup_at index uri offset name with
          | Some ({ kind = Routine { slots; routine }; _ } as r) when routine <> I.Trap_routine ->
              (* the arguments begin after the name's last use before the cursor (and after the
                 '(' of a function call) *)
              let n = String.length name in
              let rec last i best =
                if i + n > b then best
                else if key (String.sub text i n) = key name && (i = 0 || not (is_ident_char text.[i - 1]))
                        && (i + n >= String.length text || not (is_ident_char text.[i + n])) then last (i + 1) (i + n)
                else last (i + 1) best in
              let after = last line_start line_start in
              let rec skip i = if i < b && (text.[i] = ' ' || text.[i] = '\t') then skip (i + 1) else i in
              let after = let i = skip after in if i < b && text.[i] = '(' then i + 1 else after in
              let k = commas text after b in
              let required = List.filteri (fun _ s -> match s with I.Required _ -> true | _ -> false) slots in
              let active = match List.nth_opt required (min k (List.length required - 1)) with
                | Some s -> let rec pos i = function [] -> 0 | x :: rest -> if x == s then i else pos (i + 1) rest in
                    pos 0 slots
                | None -> 0 in
              let prefix = match routine with
                | Func ret -> Printf.sprintf "FUNC %s %s (" ret r.name
                | _ -> Printf.sprintf "PROC %s (" r.name in
              let label = Buffer.create 80 in
              Buffer.add_string label prefix;
              let params = List.mapi (fun i s ->
                  if i > 0 then Buffer.add_string label ", ";
                  let a = Buffer.length label in
                  Buffer.add_string label (I.slot_text s);
                  `Assoc [ ("label", `List [ `Int a; `Int (Buffer.length label) ]) ]) slots in
              Buffer.add_string label ")";
              let doc = if r.uri = None then Lsp_routine_docs.find r.name else None in
              `Assoc [ ("signatures", `List [ `Assoc ([ ("label", `String (Buffer.contents label));
                                                        ("parameters", `List params) ]
                                                      @ (match doc with Some d -> [ ("documentation", `String d) ]
                                                                      | None -> [])) ]);
                       ("activeSignature", `Int 0); ("activeParameter", `Int active) ]
          | _ -> `Null)

(* {1 Rename} *)

let valid_identifier s =
  let n = String.length s in
  if n = 0 then Error "an identifier is not empty (§2.3)"
  else if not (match s.[0] with 'A' .. 'Z' | 'a' .. 'z' -> true | _ -> false) then
    Error (Printf.sprintf "%s is not an identifier: it begins with a letter (§2.3)" s)
  else if not (String.for_all is_ident_char s) then
    Error (Printf.sprintf "%s is not an identifier: letters, digits and underscores only (§2.3)" s)
  else if n > Rapid_syntax.Lexer.max_identifier_length then
    Error (Printf.sprintf "%s is not an identifier: at most %d characters (§2.3)" s
             Rapid_syntax.Lexer.max_identifier_length)
  else if Hashtbl.mem Rapid_syntax.Lexer.reserved_words (String.uppercase_ascii s) then
    Error (Printf.sprintf "%s is a reserved word (§2.4)" s)
  else Ok ()

let describe index (d : I.decl) = Printf.sprintf "the %s %s (%s)" (I.kind_name d) d.name (where index d)

let renamed ws uri pos =
  match at ws uri pos with
  | _, None -> raise (Refused "there is no name here to rename")
  | index, Some o ->
      if o.decl.uri = None then
        raise (Refused (Printf.sprintf "%s is installed (ch. 13): it is not declared in the program" o.decl.name));
      (match W.unparsed ws uri with
       | [] -> ()
       | u :: _ -> raise (Refused (Printf.sprintf "%s does not parse: its uses of the name cannot be seen" u)));
      (index, o)

let prepare_rename ws uri pos : Yojson.Safe.t =
  let index, o = renamed ws uri pos in
  `Assoc [ ("range", range index uri o.o_start o.o_stop); ("placeholder", `String o.decl.name) ]

let rename ws uri pos new_name : Yojson.Safe.t =
  let index, o = renamed ws uri pos in
  let d = o.decl in
  (match valid_identifier new_name with Ok () -> () | Error m -> raise (Refused m));
  let uses = I.occurrences_of index d in
  let member_of_other = match d.kind with Component _ -> true | Data { parameter = true; _ } -> true | _ -> false in
  if key new_name <> key d.name then begin
    (* Siblings: another component of the record, another parameter of the routine. *)
    (match d.kind with
     | Component { record; _ } ->
         List.iter (fun (c : I.decl) ->
             if key c.name = key new_name && not (I.same_decl c d) then
               raise (Refused (Printf.sprintf "%s already has a component %s" record c.name)))
           (I.components_of_type index (Option.value d.uri ~default:"") d.name_start record)
     | _ -> ());
    (* Already declared where a use stands: the new name would denote another object there.
       A parameter's named arguments stand in other routines: only its uses inside its own
       routine count. *)
    let routine_of (d : I.decl) =
      match d.uri with
      | None -> None
      | Some u -> List.find_opt (fun (r : I.decl) ->
          r.routine = None && (match r.kind with Routine _ -> true | _ -> false)
          && r.decl_start <= d.decl_start && d.decl_stop <= r.decl_stop) (I.decls index u) in
    let counts (u, (x : I.occurrence)) =
      match d.kind with
      | Component _ -> false
      | Data { parameter = true; _ } -> (
          match routine_of d with
          | Some r -> Some u = d.uri && r.decl_start <= x.o_start && x.o_stop <= r.decl_stop
          | None -> false)
      | _ -> true in
    List.iter (fun ((u, (x : I.occurrence)) as use) ->
        if counts use then
          match I.lookup_any index u x.o_start new_name with
          | Some other when not (I.same_decl other d) ->
              raise (Refused (Printf.sprintf "%s is already declared: %s" new_name (describe index other)))
          | _ -> ()) uses;
    (* A use of another object of the new name where the renamed one is visible too: the rename
       would make it ambiguous or change what it denotes. *)
    if not member_of_other then
      List.iter (fun (other : I.decl) ->
          if key other.name = key new_name && not (I.same_decl other d) then
            List.iter (fun (u, (x : I.occurrence)) ->
                match I.lookup_any index u x.o_start d.name with
                | Some p when I.same_decl p d ->
                    let line = match source_text index u with
                      | Some t -> (Lsp_text.position_of_offset t x.o_start).line + 1 | None -> 0 in
                    raise (Refused (Printf.sprintf "%s would then hide %s, used at line %d of %s" new_name
                                      (describe index other) line u))
                | _ -> ()) (I.occurrences_of index other)) (I.all_decls index @ I.installed_decls ())
  end;
  let by_uri = Hashtbl.create 4 in
  List.iter (fun (u, (x : I.occurrence)) ->
      let edit = `Assoc [ ("range", range index u x.o_start x.o_stop); ("newText", `String new_name) ] in
      Hashtbl.replace by_uri u (edit :: Option.value (Hashtbl.find_opt by_uri u) ~default:[])) uses;
  `Assoc [ ("changes", `Assoc (Hashtbl.fold (fun u edits acc -> (u, `List (List.rev edits)) :: acc) by_uri []
                               |> List.sort compare)) ]

(* {1 Quick fixes} *)

(* The names of a hint "did you mean a, b or c?" (Rapid_syntax.Suggest), when it is one. *)
let suggested hint =
  let prefix = "did you mean " in
  let n = String.length prefix and m = String.length hint in
  if m > n + 1 && String.sub hint 0 n = prefix && hint.[m - 1] = '?' then
    let names = String.sub hint n (m - n - 1) in
    let words = List.concat_map (String.split_on_char ',')
        (String.split_on_char ' ' names) |> List.filter (fun w -> w <> "" && w <> "or") in
    if words <> [] && List.for_all (fun w -> valid_identifier w = Ok ()) words then words else []
  else []

let code_actions ws uri (diagnostics : Yojson.Safe.t list) : Yojson.Safe.t =
  match W.text ws uri with
  | None -> `List []
  | Some t ->
      `List (List.concat_map (fun (d : Yojson.Safe.t) ->
          let field k (j : Yojson.Safe.t) = match j with `Assoc l -> List.assoc_opt k l | _ -> None in
          let message = match field "message" d with Some (`String m) -> m | _ -> "" in
          let hint = match String.split_on_char '\n' message with
            | _ :: rest -> List.find_map (fun l ->
                let p = "hint: " in
                if String.length l > String.length p && String.sub l 0 (String.length p) = p
                then Some (String.sub l (String.length p) (String.length l - String.length p)) else None) rest
            | [] -> None in
          let range = field "range" d in
          let ends = Option.bind range (fun r ->
              match Option.bind (field "start" r) Lsp_text.position_of_json,
                    Option.bind (field "end" r) Lsp_text.position_of_json with
              | Some a, Some b -> Some (a, b)
              | _ -> None) in
          match hint, ends, range with
          | Some h, Some (a, b), Some range ->
              (* only where the range holds one name, the one the hint corrects *)
              let written = Lsp_text.slice t (Lsp_text.offset_of_position t a) (Lsp_text.offset_of_position t b) in
              if valid_identifier written <> Ok () then []
              else
                List.map (fun name ->
                    `Assoc [ ("title", `String (Printf.sprintf "Change %s to %s" written name));
                             ("kind", `String "quickfix");
                             ("diagnostics", `List [ d ]);
                             ("edit", `Assoc [ ("changes", `Assoc [
                                  (uri, `List [ `Assoc [ ("range", range); ("newText", `String name) ] ]) ]) ]) ])
                  (suggested h)
          | _ -> []) diagnostics)
