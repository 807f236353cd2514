type options = { strict : bool; installed : bool; robotware : Robotware.t }

let default_options = { strict = false; installed = false; robotware = Robotware.default }

(* §1.4 names "program too complex (nested)" as a fatal static error without giving a bound;
   ruling R-1.4 in doc/rulings.md fixes it. Every later phase may then recurse on the tree. *)
let max_nesting = 1000

exception Refused of Diagnostic.t

let refuse error_class region message = raise (Refused (Diagnostic.make error_class region message))

let describe_token (token : Parser.token) =
  match token with
  | IDENT s | TASK s -> Printf.sprintf "the identifier %s" s
  | REF -> "REF"
  | NUM s -> Printf.sprintf "the numeric literal %s" s
  | STRING s -> Printf.sprintf "the string literal \"%s\"" s.raw
  | COMMENT _ -> "a comment"
  | HEADER _ -> "a %%% header block"
  | EOF -> "the end of the file"
  | TRUE -> "TRUE" | FALSE -> "FALSE"
  | TDN_PH -> "<TDN>" | DDN_PH -> "<DDN>" | RDN_PH -> "<RDN>" | PAR_PH -> "<PAR>"
  | ALT_PH -> "<ALT>" | DIM_PH -> "<DIM>" | SMT_PH -> "<SMT>" | VAR_PH -> "<VAR>"
  | EIT_PH -> "<EIT>" | CSE_PH -> "<CSE>" | EXP_PH -> "<EXP>" | ARG_PH -> "<ARG>"
  | ID_PH -> "<ID>"
  | LBRACE -> "'{'" | RBRACE -> "'}'" | LPAREN -> "'('" | RPAREN -> "')'"
  | LBRACKET -> "'['" | RBRACKET -> "']'" | COMMA -> "','" | DOT -> "'.'" | EQ -> "'='"
  | LT -> "'<'" | GT -> "'>'" | PLUS -> "'+'" | MINUS -> "'-'" | STAR -> "'*'"
  | SLASH -> "'/'" | COLON -> "':'" | SEMICOLON -> "';'" | BACKSLASH -> "'\\'"
  | QUESTION -> "'?'" | ASSIGN -> "':='" | NE -> "'<>'" | GE -> "'>='" | LE -> "'<='"
  | PERCENT -> "'%'" | BAR -> "'|'"
  | t ->
      (* A reserved word: its spelling in the table of §2.4. *)
      let found = ref "a reserved word" in
      Hashtbl.iter (fun word tok -> if tok = t then found := word) Lexer.reserved_words;
      !found

let syntax_message state =
  match Parser_messages.message state with
  | message -> String.trim message
  | exception Not_found -> "this is not allowed here"

(* The grammar accepts any depth; the tree is checked here, within bounded recursion, so that
   no later phase meets a tree deeper than [max_nesting]. *)
(* The walk is written with direct recursion over lists and options: [List.iter (expression d)]
   would build a closure at every node, and this walk visits every node of the tree. *)
module Nesting = struct
  open Ast

  exception Too_deep of Source.region

  let enter depth at = if depth > max_nesting then raise (Too_deep at); depth + 1

  let rec expression d (e : expression) = expression_at d e.at e.it

  (* Aggregate members come as contents and regions (ast.ml): walked without rebuilding them. *)
  and expression_at d at (e : expression_desc) =
    let d = enter d at in
    match e with
    | Num_literal _ | String_literal _ | Bool_literal _ | EXP_placeholder -> ()
    | Data_reference r -> reference d at r
    | Function_call f -> arguments d f.arguments f.argument_regions
    | Aggregate (es, rs) -> Array.iteri (fun i m -> expression_at d rs.(i) m) es
    | Unary (_, e, at) -> expression_at d at e
    | Binary (_, l, r) -> expression d l; expression d r

  and expressions d = function
    | [] -> ()
    | e :: rest -> expression d e; expressions d rest

  and optional_expression d = function
    | None -> ()
    | Some e -> expression d e

  and data_reference d (r : data_reference) = reference d r.at r.it

  (* A reference counts as a level of nesting of its own, also where it is an expression. *)
  and reference d at (r : data_reference_desc) =
    let d = enter d at in
    match r with
    | Entire _ | VAR_placeholder -> ()
    | Element (_, es) -> expressions d es
    | Component (r, _) -> data_reference d r

  (* Arguments are not levels of nesting of their own: only their contents are walked. *)
  and arguments d args regions =
    Array.iteri (fun i (a : argument_desc) ->
        match a with
        | Required_argument (_, e, at) -> expression_at d at e
        | Positional_argument e -> expression_at d regions.(i) e
        | Optional_argument (_, Some e) -> expression d e
        | Conditional_argument (_, r) -> data_reference d r
        | Optional_argument (_, None) | ARG_placeholder -> ()) args

  let rec statement d (s : statement) =
    let d = enter d s.at in
    match s.it with
    | Assignment (r, e) -> data_reference d r; expression d e
    | Procedure_call (p, args, regions) ->
        (match p with Late_bound e -> expression d e | Procedure_name _ -> ());
        arguments d args regions
    | Return e | Raise e -> optional_expression d e
    | Connect (r, _) -> data_reference d r
    | If i ->
        expression d i.condition;
        statements d i.then_branch;
        elseifs d i.elseifs;
        optional_statements d i.else_branch
    | Compact_if (e, s) -> expression d e; statement d s
    | For f ->
        expression d f.from_; expression d f.to_; optional_expression d f.step;
        statements d f.body
    | While (e, l) -> expression d e; statements d l
    | Test t ->
        expression d t.test_expression;
        cases d t.cases;
        optional_statements d t.default
    | Goto _ | Break | Continue | Exit | Retry | Trynext | Label _ | Statement_comment _
    | SMT_placeholder -> ()

  and statements d = function
    | [] -> ()
    | s :: rest -> statement d s; statements d rest

  and optional_statements d = function
    | None -> ()
    | Some l -> statements d l

  and elseifs d = function
    | [] -> ()
    | (c : elseif_clause) :: rest ->
        (match c.it with
         | Elseif (e, l) -> expression d e; statements d l
         | EIT_placeholder -> ());
        elseifs d rest

  and cases d = function
    | [] -> ()
    | (c : case_clause) :: rest ->
        (match c.it with
         | Case (es, l) -> expressions d es; statements d l
         | CSE_placeholder -> ());
        cases d rest

  let rec declarations = function
    | [] -> ()
    | (decl : data_declaration) :: rest ->
        (match decl.it with
         | Data_declaration { dims; initial_value; _ } ->
             expressions 0 dims; optional_expression 0 initial_value
         | Declaration_comment _ | DDN_placeholder -> ());
        declarations rest

  let body (b : routine_body) =
    declarations b.declarations;
    statements 0 b.statements;
    optional_statements 0 b.backward;
    (match b.error with Some h -> statements 0 h.handler | None -> ());
    optional_statements 0 b.undo

  let rec routines = function
    | [] -> ()
    | (r : routine_declaration) :: rest ->
        (match r.it with
         | Procedure_declaration { body = b; _ } | Function_declaration { body = b; _ }
         | Trap_declaration { body = b; _ } -> body b
         | Routine_comment _ | RDN_placeholder -> ());
        routines rest

  let check (m : module_declaration) =
    try
      declarations m.data_declarations;
      routines m.routine_declarations
    with Too_deep at ->
      refuse Fatal_static_error at
        (Printf.sprintf "program too complex: statements and expressions nested more than \
                         %d deep (§1.4)" max_nesting)
end

(* Under --strict, the dialect extension that is a rule of the static semantics rather than of
   the grammar (doc/dialect.md): §4.11, "包含错误编号的raise语句不得出现在程序的错误处理器中" (a RAISE
   with an error number may not stand in an error handler), which ABB's own add-ins break. It is
   refused as the semantic error it is, when the module is read in strict mode; by default the
   statement is accepted and raises its error from the handler (doc/rulings.md R-4.11-handler1).
   The walk runs after [Nesting.check]: the tree is at most [max_nesting] deep. *)
module Strict_raise = struct
  open Ast

  exception Found of Source.region

  let rec statement (s : statement) =
    match s.it with
    | Raise (Some _) -> raise (Found s.at)
    | If i ->
        statements i.then_branch;
        List.iter (fun (c : elseif_clause) ->
            match c.it with Elseif (_, l) -> statements l | EIT_placeholder -> ()) i.elseifs;
        Option.iter statements i.else_branch
    | Compact_if (_, s) -> statement s
    | For f -> statements f.body
    | While (_, l) -> statements l
    | Test t ->
        List.iter (fun (c : case_clause) ->
            match c.it with Case (_, l) -> statements l | CSE_placeholder -> ()) t.cases;
        Option.iter statements t.default
    | Assignment _ | Procedure_call _ | Return _ | Raise None | Connect _ | Goto _ | Break | Continue
    | Exit | Retry | Trynext | Label _ | Statement_comment _ | SMT_placeholder -> ()

  and statements l = List.iter statement l

  let check (m : module_declaration) =
    try
      List.iter (fun (r : routine_declaration) ->
          match r.it with
          | Procedure_declaration { body = b; _ } | Function_declaration { body = b; _ }
          | Trap_declaration { body = b; _ } -> Option.iter (fun h -> statements h.handler) b.error
          | Routine_comment _ | RDN_placeholder -> ()) m.routine_declarations
    with Found at ->
      refuse Semantic_error at
        "RAISE with an error number may not stand in an error handler (§4.11); accepted \
         without --strict (doc/dialect.md)"
end

(* Menhir's code back end (lib/syntax/dune): with --exn-carries-state its exception carries the
   automaton's state, which is all the messages of parser.messages need; it parses about three
   times as fast as the table back end (bench/README.md). It reads each token's positions from
   the lexbuf it is handed, which is there for that only (Lexer.next_into writes them). *)
let run_parser options file decoded lexer =
  let lexbuf = Lexing.from_string "" in
  lexbuf.lex_curr_p <- { Lexing.dummy_pos with pos_cnum = -1 };
  let here () = Source.region file lexbuf.lex_start_p.pos_cnum lexbuf.lex_curr_p.pos_cnum in
  let last = ref Parser.EOF in
  let before_module = ref true in
  let next lexbuf =
    let token = Lexer.next_into lexer lexbuf in
    (match token with
     | HEADER _ when options.strict ->
         refuse Syntax_error (here ())
           "a %%% header block is not part of a module declaration (§9.2); \
            accepted without --strict (doc/dialect.md)"
     | COMMENT _ when options.strict && !before_module ->
         refuse Syntax_error (here ())
           "a comment before MODULE is not part of a module declaration: comments are \
            elements of the module's lists (§9.2, §2.10); accepted without --strict \
            (doc/dialect.md)"
     | MODULE -> before_module := false
     | _ -> ());
    last := token;
    token
  in
  match Parser.module_file next lexbuf with
  | m -> m
  | exception Parser.Error state ->
      (* the token the automaton refused is the last one read: its positions are the lexbuf's *)
      let hint =
        Syntax_hint.hint file decoded ~installed:options.installed ~robotware:options.robotware
          ~error_start:lexbuf.lex_start_p.pos_cnum in
      raise (Refused (Diagnostic.make ?hint Syntax_error (here ())
                        (Printf.sprintf "%s; found %s" (syntax_message state) (describe_token !last))))

let parse_decoded options name (decoded : Decode.t) =
  let file = Source.register ~name ~line_starts:decoded.line_starts in
  Parse_context.start file;
  Parse_context.strict := options.strict;
  let at_start = Source.region file 0 1 in
  try
    if options.strict && decoded.byte_order_mark then
      refuse Lexical_error at_start
        "byte-order mark at the start of the file: §2.1 defines no such character; accepted \
         without --strict (doc/dialect.md)";
    let lexer = Lexer.create ~installed:options.installed ~robotware:options.robotware file decoded in
    let m = run_parser options file decoded lexer in
    if options.strict && not decoded.final_newline then
      refuse Syntax_error (Source.region file (decoded.length - 1) decoded.length)
        "the file does not end with a line break (§2.10: a line ends with <newline>); \
         accepted without --strict (doc/dialect.md)";
    Nesting.check m;
    if options.strict then Strict_raise.check m;
    Ok m
  with
  | Refused d -> Error d
  | Lexer.Error (region, message) ->
      Error (Diagnostic.make ?hint:(Syntax_hint.lexical_hint message) Lexical_error region message)
  | Parse_context.Refused (region, message) -> Error (Diagnostic.make Syntax_error region message)

(* Speed (bench/README.md): nearly all that a parse allocates is the tree, which stays alive
   to the end, so the major collector's marking during the parse of a large text finds almost
   nothing to free. From [large_text] bytes on, the parse runs with the collector's
   space_overhead raised to [parse_space_overhead], and the caller's setting is restored after:
   a fifth less time on a CAD module of 3 MiB, for about 1% more peak memory. *)
let large_text = 512 * 1024
let parse_space_overhead = 1000

let with_collector_for_parse size f =
  let old = (Gc.get ()).space_overhead in
  if size < large_text || old >= parse_space_overhead then f ()
  else begin
    Gc.set { (Gc.get ()) with space_overhead = parse_space_overhead };
    Fun.protect f ~finally:(fun () -> Gc.set { (Gc.get ()) with space_overhead = old })
  end

let parse_string ?(options = default_options) ~name contents =
  with_collector_for_parse (String.length contents) (fun () ->
      parse_decoded options name (Decode.decode contents))

let read_file path =
  if Sys.file_exists path && Sys.is_directory path then raise (Sys_error "is a directory");
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      really_input_string ic (in_channel_length ic))

(* "-" is standard input (doc/user-guide.md), read once: a second "-" in the same command
   reads the same text again rather than an exhausted stream. *)
let stdin_name = "<stdin>"
let stdin_text = ref None

let read_stdin () =
  match !stdin_text with
  | Some text -> text
  | None ->
      set_binary_mode_in stdin true;
      let b = Buffer.create 65536 in
      let chunk = Bytes.create 65536 in
      let rec go () =
        let n = input stdin chunk 0 (Bytes.length chunk) in
        if n > 0 then begin Buffer.add_subbytes b chunk 0 n; go () end
      in
      go ();
      let text = Buffer.contents b in
      stdin_text := Some text;
      text

let source_text path = if path = "-" then read_stdin () else read_file path

let display_name path = if path = "-" then stdin_name else path

let parse_file ?(options = default_options) path =
  match source_text path with
  | contents -> parse_string ~options ~name:(display_name path) contents
  | exception Sys_error message ->
      let file = Source.register ~name:(display_name path) ~line_starts:[| 0 |] in
      (* Sys_error says "PATH: reason"; the diagnostic names the path already. *)
      let prefix = path ^ ": " in
      let reason =
        if String.length message > String.length prefix
           && String.sub message 0 (String.length prefix) = prefix
        then String.sub message (String.length prefix) (String.length message - String.length prefix)
        else message
      in
      Error (Diagnostic.make File_error (Source.region file 0 0)
               (Printf.sprintf "cannot read the file: %s" reason))
