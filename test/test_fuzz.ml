(* Robustness of the front end: whatever the input, [Parse.parse_string] answers with a tree or
   one diagnostic that points into the input; it never raises, never overflows the stack, and
   refuses what is too deep with the fatal static error of §1.4.

   Every random test has a fixed seed, so a failure is reproduced by running the suite again. *)

open Rapid_syntax

let file_name = "fuzz.mod"

(* ---------------------------------------------------------------- checked parsing *)

(* Why a diagnostic does not point into [text], if it does not. Lines and columns count
   characters of the decoded text, as Source does. *)
let region_problem text (region : Source.region) =
  let decoded = Decode.decode text in
  let starts = decoded.line_starts in
  let lines = Array.length starts in
  let line_length i = (if i + 1 < lines then starts.(i + 1) else decoded.length) - starts.(i) in
  let valid (p : Source.pos) =
    p.line >= 1 && p.line <= lines && p.col >= 1 && p.col - 1 <= line_length (p.line - 1)
  in
  match Source.file_of region with
  | None -> Some "the region has no file"
  | Some f when Source.name f <> file_name -> Some ("the region is in " ^ Source.name f)
  | Some _ ->
      let start = Source.start_offset region and stop = Source.stop_offset region in
      if not (0 <= start && start <= stop && stop <= decoded.length) then
        Some (Printf.sprintf "offsets %d-%d outside the %d characters of the input" start stop
                decoded.length)
      else if not (valid (Source.start region)) then
        Some ("invalid start " ^ Source.to_range_string region)
      else if not (valid (Source.stop region)) then
        Some ("invalid stop " ^ Source.to_range_string region)
      else None

(* Parses [text] and checks the answer; [Error message] says what is wrong with it. *)
let parse_checked ?options text =
  match Parse.parse_string ?options ~name:file_name text with
  | exception e -> Error ("raised " ^ Printexc.to_string e)
  | Ok m ->
      (match region_problem text m.module_region with
       | None -> Ok (Ok m)
       | Some p -> Error ("module region: " ^ p))
  | Error d ->
      (match region_problem text d.region with
       | Some p -> Error (Diagnostic.to_string d ^ ": " ^ p)
       | None when d.message = "" -> Error "empty message"
       | None -> Ok (Error d))

(* Why printing [m] and reading it back does not give [m] again, if it does not (the promise
   of Printer, with Ast_dump's equality). *)
let round_trip_problem ?options (m : Ast.module_declaration) =
  match Printer.module_declaration m with
  | exception e -> Some ("the printer raised " ^ Printexc.to_string e)
  | printed ->
      match Parse.parse_string ?options ~name:file_name printed with
      | exception e ->
          Some (Printf.sprintf "printed as %S, which raised %s" printed (Printexc.to_string e))
      | Error d -> Some (Printf.sprintf "printed as %S: %s" printed (Diagnostic.to_string d))
      | Ok m' ->
          let before = Ast_dump.module_declaration m and after = Ast_dump.module_declaration m' in
          if before = after then None
          else
            Some (Printf.sprintf "printed as %S, read back as\n%s\ninstead of\n%s" printed after
                    before)

(* A QCheck property: the answer is well formed, whatever it is, and a tree survives printing. *)
let answers text =
  match parse_checked text with
  | Ok (Ok m) ->
      (match round_trip_problem m with
       | None -> true
       | Some problem -> QCheck.Test.fail_reportf "accepted, but %s" problem)
  | Ok (Error _) -> true
  | Error problem -> QCheck.Test.fail_reportf "%s" problem

let run_property ~seed ~count ~name ~print gen =
  QCheck.Test.check_exn ~rand:(Random.State.make [| seed |])
    (QCheck.Test.make ~count ~name (QCheck.make ~print ~shrink:QCheck.Shrink.string gen) answers)

let print_text = Printf.sprintf "%S"

(* ---------------------------------------------------------------- vocabulary *)

let reserved_words =
  List.sort compare (Hashtbl.fold (fun w _ acc -> w :: acc) Lexer.reserved_words [])

let placeholder_texts = [
  ("TDN_PH", "<TDN>"); ("DDN_PH", "<DDN>"); ("RDN_PH", "<RDN>"); ("PAR_PH", "<PAR>");
  ("ALT_PH", "<ALT>"); ("DIM_PH", "<DIM>"); ("SMT_PH", "<SMT>"); ("VAR_PH", "<VAR>");
  ("EIT_PH", "<EIT>"); ("CSE_PH", "<CSE>"); ("EXP_PH", "<EXP>"); ("ARG_PH", "<ARG>");
  ("ID_PH", "<ID>") ]

let delimiter_texts = [
  ("LBRACE", "{"); ("RBRACE", "}"); ("LPAREN", "("); ("RPAREN", ")"); ("LBRACKET", "[");
  ("RBRACKET", "]"); ("COMMA", ","); ("DOT", "."); ("EQ", "="); ("LT", "<"); ("GT", ">");
  ("PLUS", "+"); ("MINUS", "-"); ("STAR", "*"); ("SLASH", "/"); ("COLON", ":");
  ("SEMICOLON", ";"); ("BACKSLASH", "\\"); ("QUESTION", "?"); ("ASSIGN", ":="); ("NE", "<>");
  ("GE", ">="); ("LE", "<="); ("PERCENT", "%"); ("BAR", "|") ]

let num_texts = [ "0"; "1"; "7990"; "23.67"; "2E6"; ".27"; "2.5E-3"; "38."; "0XFF"; "0b101";
                  "0o17"; "0D12E2"; "1e+3"; "1.7976931348623157E308"; "5E-324" ]

let string_texts = [ {|""|}; {|"s"|}; {|"a""b"|}; {|"\41\\"|}; {|"é😀"|}; {|"! not a comment"|} ]

(* Token texts for soups and insertions, valid and not. *)
let soup_vocabulary = Array.of_list (List.concat [
    reserved_words; List.map snd placeholder_texts; List.map snd delimiter_texts; num_texts;
    string_texts;
    [ "x"; "y1"; "é"; "Åsa_2"; "TASK"; "switch"; "<smt>"; "! comment\n"; "!\n"; "\n"; "\r\n";
      "\r"; "\t"; "\012"; "%%%\n"; "%%%\n VERSION:1\n%%%\n"; "$"; "\xEF\xBB\xBF"; "\xE9";
      "\x00"; "\xFF\xFE"; "12abc"; "0x"; "1E99999"; {|"\g"|}; {|"unterminated|};
      String.make 33 'a'; "\"" ^ String.make 81 'a' ^ "\""; "×"; "Ā"; "😀"; "<"; "<ID"; "!";
      "\"" ] ])

(* ---------------------------------------------------------------- random bytes and soups *)

let random_bytes () =
  run_property ~seed:1 ~count:10_000 ~name:"random bytes" ~print:print_text
    QCheck.Gen.(string_size ~gen:char (int_bound 300))

let frames = [|
  ("", "");
  ("MODULE m\n", "\nENDMODULE\n");
  ("MODULE m\nPROC p()\n", "\nENDPROC\nENDMODULE\n");
  ("MODULE m\nPROC p()\n  x := ", ";\nENDPROC\nENDMODULE\n") |]

let separators = [| " "; " "; " "; "\n"; "\t"; ""; "\r\n"; "  " |]

let token_soup =
  QCheck.Gen.(
    let token = oneofa soup_vocabulary in
    let piece = map2 ( ^ ) token (oneofa separators) in
    map2 (fun (prefix, suffix) pieces -> prefix ^ String.concat "" pieces ^ suffix)
      (oneofa frames) (list_size (int_bound 60) piece))

let random_soups () =
  run_property ~seed:2 ~count:10_000 ~name:"token soups" ~print:print_text token_soup

(* ---------------------------------------------------------------- mutations of valid modules *)

(* Modules that use most of the grammar, the seeds of the mutations together with the .mod
   files of ../spec and ../examples that parse. *)
let seed_modules = [
  {|%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%
MODULE seed1 (SYSMODULE, NOSTEPIN)
  ! types
  RECORD pair ! the name
    num first; ! a component
    num second;
    ! last line
  ENDRECORD
  LOCAL ALIAS num distance;
  <TDN>
  ! data
  VAR num counter := 0;
  LOCAL CONST num limit := 2.5E-3;
  TASK PERS pair p := [1, 0XFF];
  PERS string s{2, 3} := [["a""b", "\41", ""], ["é", "\\", "x"]];
  <DDN>
  ! routines
  PROC main(num a, \switch on | num level, VAR num arr{*, *}, INOUT num b \ <ALT>, <PAR>)
    VAR num i;
    ! statements
    i := -a * b + 1 DIV 2 MOD 3 - (4 / 5);
    IF NOT i < 3 AND TRUE OR FALSE XOR i >= 2 THEN
      counter := counter + 1;
    ELSEIF i <> 0 THEN
      <SMT>
    <EIT>
    ELSE
      RETURN;
    ENDIF
    IF i = 1 counter := 0;
    FOR k FROM 1 TO 10 STEP 2 DO
      TEST k
      CASE 1, 2:
        BREAK;
      <CSE>
      DEFAULT:
        CONTINUE;
      ENDTEST
    ENDFOR
    WHILE counter > 0 DO
      counter := counter - 1;
    ENDWHILE
    MoveL p, v \V:=1, z \T?t, \Conc, <ARG>;
    %"proc" + s{1, 1}% a;
    CONNECT <VAR> WITH trap1;
    next: GOTO next;
    p.first := f(a, b:=2 \c \d:=3, \e?t);
  BACKWARD
    EXIT;
  ERROR (1, ERR_DIVZERO)
    RETRY;
    TRYNEXT;
    RAISE 42;
  UNDO
    RAISE;
  ENDPROC
  LOCAL FUNC num f(num x \num c | switch d)
    RETURN <EXP>;
  ERROR
    RETURN 0;
  ENDFUNC
  TRAP trap1
    counter := 0;
  ENDTRAP
  <RDN>
ENDMODULE
|};
  "module seed2\r\n  var num x;\r\n  proc p()\r\n    x := .5 + 38. + 0b101 + 0o17 + 0D12E2;\r\n\
   \    if x > 1 then\r\n      x := 1;\r\n    endif\r\n  endproc\r\nendmodule\r\n";
  "MODULE \xC5r\n! caf\xE9\nPROC p()\n  x := \"\xE9\";\nENDPROC\nENDMODULE\n";
  "\xEF\xBB\xBFMODULE <ID>\n  PROC <ID>(<ID> <ID>)\n    <ID>;\n  ENDPROC\nENDMODULE" ]

let mod_files = Corpus.files ~extensions:[ ".mod"; ".sys" ]

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      really_input_string ic (in_channel_length ic))

let parses text = match Parse.parse_string ~name:file_name text with Ok _ -> true | _ -> false

let seeds_parse () =
  List.iteri (fun i text ->
      match Parse.parse_string ~name:file_name text with
      | Ok m -> Option.iter (Alcotest.failf "seed module %d: %s" (i + 1)) (round_trip_problem m)
      | Error d -> Alcotest.failf "seed module %d: %s" (i + 1) (Diagnostic.to_string d))
    seed_modules

(* The byte spans of the tokens of [text] (comments included), as far as it lexes. *)
let token_spans text =
  let decoded = Decode.decode text in
  let utf8 = decoded.text in
  (* byte offset of each character *)
  let offsets = Array.make (decoded.length + 1) (String.length utf8) in
  let c = ref 0 in
  String.iteri (fun i ch ->
      if Char.code ch land 0xC0 <> 0x80 then begin offsets.(!c) <- i; incr c end) utf8;
  let file = Source.register ~name:file_name ~line_starts:decoded.line_starts in
  let lexer = Lexer.create file decoded in
  let rec go acc =
    match Lexer.next lexer with
    | Parser.EOF, _, _ -> acc
    | _, s, e -> go ((offsets.(s.pos_cnum), offsets.(e.pos_cnum)) :: acc)
    | exception Lexer.Error _ -> acc
  in
  (utf8, Array.of_list (List.rev (go [])))

let sub s a b = String.sub s a (b - a)

(* One random change to [text]: a token deleted, duplicated, swapped or inserted, or bytes
   deleted, inserted, replaced or duplicated. *)
let mutate rand text =
  let text, spans = token_spans text in
  let n = String.length text and k = Array.length spans in
  let int bound = Random.State.int rand (max 1 bound) in
  let vocabulary () = soup_vocabulary.(int (Array.length soup_vocabulary)) in
  let byte () = String.make 1 (Char.chr (int 256)) in
  match int 9 with
  | 0 when k > 0 ->
      let s, e = spans.(int k) in sub text 0 s ^ sub text e n
  | 1 when k > 0 ->
      let s, e = spans.(int k) in sub text 0 e ^ " " ^ sub text s n
  | 2 when k > 1 ->
      let i = int k and j = int k in
      let i, j = (min i j, max i j) in
      if i = j then text
      else
        let si, ei = spans.(i) and sj, ej = spans.(j) in
        String.concat ""
          [ sub text 0 si; sub text sj ej; sub text ei sj; sub text si ei; sub text ej n ]
  | 3 when k > 0 ->
      let s, _ = spans.(int k) in sub text 0 s ^ vocabulary () ^ " " ^ sub text s n
  | 4 when n > 0 -> let i = int n in sub text 0 i ^ sub text (i + 1) n
  | 5 -> let i = int (n + 1) in sub text 0 i ^ byte () ^ sub text i n
  | 6 when n > 0 -> let i = int n in sub text 0 i ^ byte () ^ sub text (i + 1) n
  | 7 when n > 0 ->
      let i = int n in let j = i + int (min 200 (n - i)) in
      sub text 0 j ^ sub text i n
  | _ -> sub text 0 (int (n + 1))   (* truncated *)

let corpus = lazy (
  let files = mod_files "../spec" @ mod_files "../examples" in
  let from_files = List.filter parses (List.map read_file files) in
  Array.of_list (seed_modules @ from_files))

let mutations () =
  let corpus = Lazy.force corpus in
  let gen rand =
    let text = ref corpus.(Random.State.int rand (Array.length corpus)) in
    for _ = 1 to 1 + Random.State.int rand 4 do text := mutate rand !text done;
    !text
  in
  run_property ~seed:3 ~count:5000 ~name:"mutations" ~print:print_text gen

(* ---------------------------------------------------------------- Menhir's random sentences *)

(* A sentence of menhir --random-sentence: the nonterminal it derives and its token names. *)
type sentence = { symbol : string; tokens : string array; line : int }

let read_sentences lines =
  List.concat (List.mapi (fun i line ->
      match String.index_opt line ':' with
      | None -> []
      | Some colon ->
          let symbol = String.trim (String.sub line 0 colon) in
          let tokens = String.split_on_char ' ' (sub line (colon + 1) (String.length line)) in
          let tokens = List.filter (fun t -> t <> "" && t <> "EOF") tokens in
          [ { symbol; tokens = Array.of_list tokens; line = i + 1 } ]) lines)

(* The sentences: those test/sentences/dune builds, or, when that file is missing or older than
   the grammar (it is not among the test's dependencies), asked of menhir here in the same way. *)
let sentence_file = "sentences/sentences.txt"
let grammar = "../lib/syntax/parser.mly"

let symbols = [ ("module_file", 100); ("routine_declaration_item", 40); ("statement_list", 40);
                ("expression", 40); ("data_declaration_item", 40); ("type_definition_item", 40) ]

let input_lines ic =
  let rec go acc = match input_line ic with
    | line -> go (line :: acc)
    | exception End_of_file -> List.rev acc in
  go []

let run_menhir () =
  let seed = ref 0 in
  List.concat_map (fun (symbol, count) ->
      List.concat (List.init count (fun _ ->
          incr seed;
          let args = [| "menhir"; "--random-sentence"; symbol; "--random-seed";
                        string_of_int !seed; "--random-sentence-length";
                        string_of_int (!seed mod 50 * 4 + 8); grammar |] in
          let ic = Unix.open_process_args_in "menhir" args in
          let lines = input_lines ic in
          (match Unix.close_process_in ic with
           | WEXITED 0 -> ()
           | _ ->
               Alcotest.failf "menhir --random-sentence %s --random-seed %d failed" symbol !seed);
          lines))) symbols

let sentences = lazy (
  let lines =
    let mtime f = (Unix.stat f).st_mtime in
    let current () =
      try mtime sentence_file >= mtime grammar with Unix.Unix_error _ -> true in
    if Sys.file_exists sentence_file && current () then
      let ic = open_in sentence_file in
      Fun.protect ~finally:(fun () -> close_in ic) (fun () -> input_lines ic)
    else run_menhir ()
  in
  read_sentences lines)

(* Concrete text for the token names of a sentence. The choices are random but fixed by the
   sentence's line, and made so that the text lexes to exactly those tokens: every token is
   followed by white space (§2.2), and a comment stays on the line of the token before it, so that only a comment that follows another comment stands on a line of its own. *)
let concrete_text (s : sentence) =
  let rand = Random.State.make [| s.line |] in
  let pick a = a.(Random.State.int rand (Array.length a)) in
  let any_case w =
    match Random.State.int rand 3 with
    | 0 -> w | 1 -> String.lowercase_ascii w
    | _ -> String.mapi (fun i c -> if i mod 2 = 0 then Char.lowercase_ascii c else c) w
  in
  let buf = Buffer.create 256 in
  let fresh = ref 0 in
  let n = Array.length s.tokens in
  Array.iteri (fun i name ->
      let next = if i + 1 < n then s.tokens.(i + 1) else "" in
      (match name with
       | "COMMENT" ->
           Buffer.add_string buf (pick [| "! c"; "!"; "! é 😀 ENDRECORD"; "!\t!" |] ^ "\n")
       | "HEADER" -> Buffer.add_string buf "%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%%\n"
       | "TASK" -> Buffer.add_string buf (any_case "TASK")
       | "REF" -> Buffer.add_string buf (any_case "REF")
       | "IDENT" ->
           incr fresh;
           Buffer.add_string buf (pick [| "v"; "é"; "Ab_"; "ÿØ" |] ^ string_of_int !fresh)
       | "NUM" -> Buffer.add_string buf (pick (Array.of_list num_texts))
       | "STRING" -> Buffer.add_string buf (pick (Array.of_list string_texts))
       | _ when Hashtbl.mem Lexer.reserved_words name -> Buffer.add_string buf (any_case name)
       | _ ->
           match List.assoc_opt name placeholder_texts, List.assoc_opt name delimiter_texts with
           | Some p, _ ->
               Buffer.add_string buf (if Random.State.bool rand then p else String.lowercase_ascii p)
           | None, Some d -> Buffer.add_string buf d
           | None, None -> Alcotest.failf "line %d: unknown token %s" s.line name);
      (* the separator; a comment has its line break *)
      if name <> "COMMENT" && name <> "HEADER" then
        Buffer.add_string buf
          (if next = "COMMENT" then " " else pick [| " "; " "; "\n"; "\t"; "\r\n  " |]))
    s.tokens;
  let body = Buffer.contents buf in
  let text = match s.symbol with
    | "module_file" -> body
    | "routine_declaration_item" | "data_declaration_item" | "type_definition_item" ->
        "MODULE m\n" ^ body ^ "\nENDMODULE\n"
    | "statement_list" -> "MODULE m\nPROC p()\n" ^ body ^ "\nENDPROC\nENDMODULE\n"
    | "expression" -> "MODULE m\nPROC p()\n  x := " ^ body ^ ";\nENDPROC\nENDMODULE\n"
    | other -> Alcotest.failf "line %d: no frame for %s" s.line other
  in
  (body, text)

(* The token names of [text] as the lexer reads it, named as in the grammar. *)
let token_names =
  let fixed = Hashtbl.create 128 in
  let lex text =
    let decoded = Decode.decode text in
    let file = Source.register ~name:file_name ~line_starts:decoded.line_starts in
    let lexer = Lexer.create ~installed:true file decoded in
    let rec go acc =
      match Lexer.next lexer with
      | Parser.EOF, _, _ -> List.rev acc
      | t, _, _ -> go (t :: acc)
    in
    go []
  in
  Hashtbl.iter (fun word t -> Hashtbl.replace fixed t word) Lexer.reserved_words;
  List.iter (fun (name, text) ->
      match lex text with
      | [ t ] -> Hashtbl.replace fixed t name
      | _ -> failwith ("not one token: " ^ text)) (placeholder_texts @ delimiter_texts);
  fun text ->
    List.map (fun (t : Parser.token) ->
        match t with
        | IDENT _ -> "IDENT" | NUM _ -> "NUM" | STRING _ -> "STRING" | COMMENT _ -> "COMMENT"
        | HEADER _ -> "HEADER" | TASK _ -> "TASK" | REF -> "REF"
        | t -> (match Hashtbl.find_opt fixed t with Some name -> name | None -> "?"))
      (lex text)

let comment_in_record =
  "a comment may not stand on a line of its own inside RECORD ... ENDRECORD, except on the \
   last line (§2.10)"
let continue_as_argument =
  "CONTINUE is a reserved word (§2.4): it cannot name an optional argument; the manual's switch \
   is \\Resume (§7.3)"
let empty_record =
  "expected a record component: a record definition has at least one (§2.14); found ENDRECORD"
let raise_in_handler =
  "RAISE with an error number may not stand in an error handler (§4.11); accepted without \
   --strict (doc/dialect.md)"

(* The refusal the grammar's actions owe the sentence, if any: the first record whose items
   break §2.10 (a comment alone on its line that is not the last item) or §2.14 (no
   component). With [concrete_text]'s layout, a comment stands alone exactly when it follows
   another comment. *)
let expected_refusal ?(strict = false) (s : sentence) =
  let t = s.tokens and n = Array.length s.tokens in
  let verdict items =
    let rec alone_before_last = function
      | `Comment true :: _ :: _ -> true
      | _ :: rest -> alone_before_last rest
      | [] -> false
    in
    (* Comment lines inside a record are the dialect's (doc/dialect.md): refused under
       --strict only. *)
    if strict && alone_before_last items then Some comment_in_record
    else if not (List.mem `Component items) then Some empty_record
    else None
  in
  (* \Continue as an argument's name is the dialect's (doc/dialect.md, R-7.3-m): refused under
     --strict only. Records precede routines, so a record's refusal comes first. *)
  let rec continue_argument i =
    if i + 1 >= n then None
    else if t.(i) = "BACKSLASH" && t.(i + 1) = "CONTINUE" then Some continue_as_argument
    else continue_argument (i + 1) in
  (* RAISE with an error number in an error handler is the dialect's too (R-4.11-handler1):
     refused under --strict once the module has parsed, so after every refusal of the grammar.
     ERROR is reserved: it opens an error clause, which UNDO or the routine's end closes. *)
  let rec raise_in_error_clause i inside =
    if i + 1 >= n then None
    else match t.(i) with
      | "ERROR" -> raise_in_error_clause (i + 1) true
      | "UNDO" | "ENDPROC" | "ENDFUNC" | "ENDTRAP" -> raise_in_error_clause (i + 1) false
      | "RAISE" when inside && t.(i + 1) <> "SEMICOLON" -> Some raise_in_handler
      | _ -> raise_in_error_clause (i + 1) inside in
  let rec find i =
    if i >= n then
      (if strict then (match continue_argument 0 with None -> raise_in_error_clause 0 false | m -> m) else None)
    else if t.(i) = "RECORD" then record (i + 2) [] else find (i + 1)
  and record i items =
    if i >= n then None
    else match t.(i) with
      | "ENDRECORD" ->
          (match verdict (List.rev items) with Some m -> Some m | None -> find (i + 1))
      | "COMMENT" -> record (i + 1) (`Comment (t.(i - 1) = "COMMENT") :: items)
      | "SEMICOLON" -> record (i + 1) (`Component :: items)
      | _ -> record (i + 1) items
  in
  find 0

(* The sentences may hold REF (ch. 11), a word of the installed environment only. *)
let installed = { Parse.default_options with installed = true }

let random_sentences () =
  let sentences = Lazy.force sentences in
  if List.length sentences < 100 then Alcotest.failf "only %d sentences" (List.length sentences);
  let refused = ref 0 in
  List.iter (fun s ->
      let body, text = concrete_text s in
      (* The text is the sentence: the lexer reads the token names back. *)
      (match token_names body with
       | names when names = Array.to_list s.tokens -> ()
       | names -> Alcotest.failf "sentence %d %S lexes as %s" s.line body (String.concat " " names)
       | exception Lexer.Error (_, m) -> Alcotest.failf "sentence %d %S: %s" s.line body m);
      (match parse_checked ~options:installed text, expected_refusal s with
      | Error problem, _ -> Alcotest.failf "sentence %d %S: %s" s.line text problem
      | Ok (Ok _), None -> ()
      | Ok (Error d), Some message when d.error_class = Syntax_error && d.message = message ->
          incr refused
      | Ok (Error d), _ -> Alcotest.failf "sentence %d %S: %s" s.line text (Diagnostic.to_string d)
      | Ok (Ok _), Some message ->
          Alcotest.failf "sentence %d %S: accepted, expected %s" s.line text message);
      (* Under --strict too, where nothing before MODULE is accepted. *)
      let dialect_prologue = Array.length s.tokens > 0 && (s.tokens.(0) = "HEADER" || s.tokens.(0) = "COMMENT") in
      if not (s.symbol = "module_file" && dialect_prologue) then begin
        let strict = { installed with strict = true } in
        (* strict mode also wants the final line break that module_file sentences lack *)
        let text = text ^ "\n" in
        match parse_checked ~options:strict text, expected_refusal ~strict:true s with
        | Error problem, _ -> Alcotest.failf "strict: sentence %d %S: %s" s.line text problem
        | Ok (Ok _), None -> ()
        | Ok (Error d), Some message
          when d.error_class = (if message == raise_in_handler then Semantic_error else Syntax_error)
               && d.message = message ->
            incr refused
        | Ok (Error d), _ ->
            Alcotest.failf "strict: sentence %d %S: %s" s.line text (Diagnostic.to_string d)
        | Ok (Ok _), Some message ->
            Alcotest.failf "strict: sentence %d %S: accepted, expected %s" s.line text message
      end)
    sentences;
  (* The sentences exercise the refusals too, or the check above says little about them. *)
  if !refused = 0 then Alcotest.fail "no sentence has a refused record"

(* The sentences that parse survive printing (Printer's promise). *)
let round_trip () =
  let trees = List.filter_map (fun s ->
      let _, text = concrete_text s in
      match Parse.parse_string ~options:installed ~name:file_name text with
      | Ok m -> Some (s, text, m)
      | Error _ -> None) (Lazy.force sentences) in
  if List.length trees < 100 then Alcotest.failf "only %d sentences parse" (List.length trees);
  List.iter (fun (s, text, m) ->
      Option.iter (fun problem -> Alcotest.failf "sentence %d %S: %s" s.line text problem)
        (round_trip_problem ~options:installed m))
    trees

(* ---------------------------------------------------------------- deep nesting *)

let repeat n s =
  let b = Buffer.create (n * String.length s) in
  for _ = 1 to n do Buffer.add_string b s done;
  Buffer.contents b

let in_routine body = "MODULE m\nPROC p()\n" ^ body ^ "ENDPROC\nENDMODULE\n"

let contains s part =
  let n = String.length s and k = String.length part in
  let rec at i = i + k <= n && (String.sub s i k = part || at (i + 1)) in
  at 0

let ends_with s suffix =
  let n = String.length s and k = String.length suffix in
  n >= k && String.sub s (n - k) k = suffix

(* The fatal static error "program too complex (nested)" of §1.4. *)
let too_complex (d : Diagnostic.t) =
  let s = Diagnostic.to_string d in
  d.error_class = Fatal_static_error
  && contains s "fatal error: program too complex"
  && contains s (string_of_int Parse.max_nesting)
  && ends_with s "(§1.4)"

(* [text] parses and survives printing, or, unless it is [flat], is refused as too complex
   (§1.4). A long flat tree is printed and dumped, which must not overflow the stack, but not
   read back, to save time. *)
let deep ?(flat = false) name text =
  match parse_checked text with
  | Error problem -> Alcotest.failf "%s: %s" name problem
  | Ok (Error d) when too_complex d && not flat -> ()
  | Ok (Error d) -> Alcotest.failf "%s: %s" name (Diagnostic.to_string d)
  | Ok (Ok m) when flat ->
      (match Printer.module_declaration m, Ast_dump.module_declaration m with
       | _ -> ()
       | exception e -> Alcotest.failf "%s: printing raised %s" name (Printexc.to_string e))
  | Ok (Ok m) -> Option.iter (Alcotest.failf "%s: %s" name) (round_trip_problem m)

let deep_nesting () =
  let n = 10_000 in
  let nested open_ inner close = repeat n open_ ^ inner ^ repeat n close in
  let assign e = in_routine ("x := " ^ e ^ ";\n") in
  deep "10,000 nested IF statements" (in_routine (nested "IF a THEN\n" "" "ENDIF\n"));
  deep "10,000 nested WHILE statements" (in_routine (nested "WHILE a DO\n" "" "ENDWHILE\n"));
  deep "10,000 nested FOR and TEST statements"
    (in_routine (nested "FOR i FROM 1 TO 2 DO TEST i CASE 1:\n" "" "ENDTEST ENDFOR\n"));
  deep "10,000 nested parentheses" (assign (nested "(" "1" ")"));
  deep "10,000 nested aggregates" (assign (nested "[" "1" "]"));
  deep "10,000 nested aggregates in a declaration"
    ("MODULE m\nCONST num c := " ^ nested "[" "1" "]" ^ ";\nENDMODULE\n");
  deep "10,000 nested function calls" (assign (nested "f(" "1" ")"));
  deep "10,000 nested signs" (assign (nested "-(" "1" ")"));
  deep "10,000 nested NOT" (assign (nested "NOT (" "a" ")"));
  deep "10,000 nested indexes" (assign (nested "a{" "1" "}"));
  deep "100,000 + operands" (assign ("1" ^ repeat 100_000 " + 1"));
  deep "100,000 AND operands" (assign ("a" ^ repeat 100_000 " AND a"));
  deep "100,000 components" (assign ("a" ^ repeat 100_000 ".b"));
  deep ~flat:true "100,000 arguments" (in_routine ("P 1" ^ repeat 100_000 ", 1" ^ ";\n"));
  deep ~flat:true "100,000 aggregate elements" (assign ("[1" ^ repeat 100_000 ", 1" ^ "]"));
  deep ~flat:true "100,000 ELSEIF"
    (in_routine ("IF a THEN " ^ repeat 100_000 "ELSEIF a THEN " ^ "ENDIF\n"));
  deep ~flat:true "100,000 comment lines in a routine" (in_routine (repeat 100_000 "! comment\n"));
  deep ~flat:true "100,000 comment lines in a module"
    ("MODULE m\n" ^ repeat 100_000 "! comment\n" ^ "ENDMODULE\n");
  deep ~flat:true "100,000 declarations and comments"
    ("MODULE m\n" ^ repeat 100_000 "VAR num a;\n! c\n" ^ "PROC p()\nENDPROC\nENDMODULE\n");
  deep ~flat:true "100,000 routines"
    ("MODULE m\n" ^ repeat 100_000 "PROC p()\nENDPROC\n" ^ "ENDMODULE\n");
  deep ~flat:true "100,000 record components"
    ("MODULE m\nRECORD r\n" ^ repeat 100_000 "num a; ! c\n" ^ "ENDRECORD\nENDMODULE\n");
  deep ~flat:true "1,000,000 statements in one routine"
    (in_routine (repeat 1_000_000 "x := 1;\n"))

let unclosed () =
  (* Deep input that never closes is a syntax error at its end, reached without recursion. *)
  let at_end = function
    | Ok _ -> Some "accepted"
    | Error (d : Diagnostic.t) when d.error_class = Syntax_error -> None
    | Error d -> Some (Diagnostic.to_string d)
  in
  let check name text =
    match parse_checked text with
    | Error problem -> Alcotest.failf "%s: %s" name problem
    | Ok answer -> Option.iter (fun m -> Alcotest.failf "%s: %s" name m) (at_end answer)
  in
  check "100,000 unclosed IF" (in_routine (repeat 100_000 "IF a THEN\n"));
  check "100,000 unclosed parentheses" (in_routine ("x := " ^ repeat 100_000 "("));
  check "100,000 unclosed aggregates" (in_routine ("x := " ^ repeat 100_000 "[1, "));
  check "100,000 closing parentheses" (in_routine ("x := 1" ^ repeat 100_000 ")"))

(* Parse.max_nesting bounds the enclosing statements and expressions of any statement or
   expression: exactly max_nesting parses, one more is the fatal error of §1.4, reported at the
   first node (in source order) that is too deep. *)
let at_the_limit () =
  let n = Parse.max_nesting in
  let accepted name text =
    match parse_checked text with
    | Ok (Ok m) -> Option.iter (Alcotest.failf "%s: %s" name) (round_trip_problem m)
    | Ok (Error d) -> Alcotest.failf "%s: %s" name (Diagnostic.to_string d)
    | Error problem -> Alcotest.failf "%s: %s" name problem
  in
  let refused name ~line ~col text =
    match parse_checked text with
    | Ok (Error d) when too_complex d ->
        let p = Source.start d.region in
        Alcotest.(check (pair int int)) (name ^ ": " ^ Diagnostic.to_string d) (line, col)
          (p.line, p.col)
    | Ok (Error d) -> Alcotest.failf "%s: %s" name (Diagnostic.to_string d)
    | Ok (Ok _) -> Alcotest.failf "%s: accepted" name
    | Error problem -> Alcotest.failf "%s: %s" name problem
  in
  (* k IF statements, one in another: the condition of the innermost has k ancestors. *)
  let ifs k = in_routine (repeat k "IF TRUE THEN\n" ^ repeat k "ENDIF\n") in
  accepted "max_nesting IF statements" (ifs n);
  refused "max_nesting + 1 IF statements" ~line:(n + 3) ~col:4 (ifs (n + 1));
  (* k aggregates in a declaration: the literal has k ancestors. *)
  let declaration k =
    "MODULE m\nCONST num c := " ^ repeat k "[" ^ "1" ^ repeat k "]" ^ ";\nENDMODULE\n" in
  accepted "max_nesting aggregates" (declaration n);
  refused "max_nesting + 1 aggregates" ~line:2 ~col:(String.length "CONST num c := " + n + 2)
    (declaration (n + 1));
  (* In a statement, the statement is one of the ancestors. *)
  let statement k = in_routine ("x := " ^ repeat k "[" ^ "1" ^ repeat k "]" ^ ";\n") in
  accepted "max_nesting - 1 aggregates in a statement" (statement (n - 1));
  refused "max_nesting aggregates in a statement" ~line:3 ~col:(String.length "x := " + n + 1)
    (statement n);
  (* Statements and expressions count alike. *)
  let mixed k = in_routine (repeat (n / 2) "WHILE TRUE DO\n" ^ "x := " ^ repeat k "[" ^ "1"
                            ^ repeat k "]" ^ ";\n" ^ repeat (n / 2) "ENDWHILE\n") in
  accepted "max_nesting in statements and expressions" (mixed (n - n / 2 - 1));
  refused "max_nesting + 1 in statements and expressions" ~line:(n / 2 + 3)
    ~col:(String.length "x := " + (n - n / 2) + 1) (mixed (n - n / 2))

(* ---------------------------------------------------------------- programs that run *)

(* Random programs that pass the static semantics and then run: late-bound calls with arguments
   that fit their procedure and arguments that do not (types, access modes, alternatives,
   switches, conditional arguments), CallByVar, conditional arguments of mutually exclusive
   alternatives, CONNECT through parameters, errors in ELSEIF conditions, functions without
   RETURN, arrays too large for the memory budget. The property: a checked program never ends
   stuck (exit status 125) nor with an OCaml exception. *)

let run_module_header array_size = Printf.sprintf {|MODULE fz
  RECORD point
    num x;
    num y;
    num z;
  ENDRECORD
  CONST num c := 5;
  VAR num v;
  VAR dnum d;
  PERS num pv := 0;
  PERS intnum pirq := 0;
  VAR string s := "p_num";
  VAR num arr{%d};
  VAR pos p;
  VAR point pt;
  VAR intnum irq1;
  VAR intnum irq2;
  VAR num k;
  PROC p_num(num x)
    v := x * 2;
  ENDPROC
  PROC p_dnum(dnum x)
    d := x + 1;
  ENDPROC
  PROC p_var(VAR num x)
    x := x + 1;
  ENDPROC
  PROC p_inout(INOUT num x)
    x := 2;
  ENDPROC
  PROC p_pers(PERS num x)
    x := 3;
  ENDPROC
  PROC p_pos(pos x)
    p := x;
    v := x.z + p.y;
  ENDPROC
  PROC p_point(point x)
    pt := x;
    v := x.z * 2;
  ENDPROC
  PROC p_opt(\num a | num b, \switch sw)
    IF Present(a) v := a;
    IF Present(b) v := b;
  ENDPROC
  PROC p_arr(num a{*})
    v := Dim(a, 1) + a{1};
  ENDPROC
  PROC p_string(string x)
    s := x + "";
  ENDPROC
  PROC p_alt(\switch on | switch off)
    IF Present(on) v := 1;
  ENDPROC
  PROC pass_late(\num a, \num b)
    %% "p_opt" %% \a ? a \b ? b;
  ENDPROC
  PROC pass_direct(\switch a, \switch b)
    p_alt \on ? a \off ? b;
  ENDPROC
  PROC conn_var(VAR intnum t)
    CONNECT t WITH tr;
  ENDPROC
  PROC conn_inout(INOUT intnum t)
    CONNECT t WITH tr;
  ENDPROC
  PROC conn_local()
    VAR intnum r;
    conn_var r;
  ENDPROC
  PROC big_local()
    VAR num big{%d};
    big{1} := 1;
  ENDPROC
  PROC deep(num n)
    IF n > 0 deep n - 1;
    RAISE 5;
  ERROR
    IF n MOD 2 = 0 RAISE;
    TRYNEXT;
  ENDPROC
  PROC cb1()
    v := 1;
  ENDPROC
  PROC cb2(num x)
    v := x;
  ENDPROC
  FUNC num f_noret(num x)
    IF x > 0 RETURN x;
  ENDFUNC
  TRAP tr
    v := 0;
  ENDTRAP
|} array_size array_size

let late_names = [| "p_num"; "p_dnum"; "p_var"; "p_inout"; "p_pers"; "p_pos"; "p_point"; "p_opt";
                    "p_arr"; "p_string"; "p_alt"; "pass_late"; "conn_var"; "conn_inout"; "big_local";
                    "deep"; "cb1"; "f_noret"; "tr"; "no_such"; "fz:p_num"; "other:p_num"; "" |]

let late_arguments = [| "v"; "c"; "5"; "2.5"; "4294967295"; "d"; "pv"; "p"; "pt"; "arr"; "[1,2,3]";
                        "[1,2]"; "[[1,2],[3,4]]"; "s"; "\"txt\""; "\\a:=1"; "\\b:=2"; "\\sw"; "\\a";
                        "TRUE"; "x:=v"; "y:=v"; "arr{1}"; "pt.x"; "k"; "irq1"; "pirq"; "1 + c";
                        "f_noret(1)"; "-v" |]

let run_statements = [|
  (fun pick -> Printf.sprintf "%% \"%s\" %% %s;" (pick late_names)
      (String.concat ", " (List.init (Random.int 4) (fun _ -> pick late_arguments))));
  (fun pick ->
     let a = pick late_arguments and b = pick late_arguments in
     Printf.sprintf "%% \"%s\" %% %s%s%s;" (pick late_names) a (if b.[0] = '\\' then " " else ", ") b);
  (fun pick -> Printf.sprintf "s := \"%s\";\n    %% s %% %s;" (pick late_names) (pick late_arguments));
  (fun pick -> Printf.sprintf "CallByVar \"cb\", %s;" (pick [| "1"; "2"; "3"; "v" |]));
  (fun pick -> pick [| "pass_late \\a:=1;"; "pass_late \\b:=2;"; "pass_late \\a:=1 \\b:=2;"; "pass_late;" |]);
  (fun pick -> pick [| "pass_direct \\a;"; "pass_direct \\b;"; "pass_direct \\a \\b;"; "pass_direct;" |]);
  (fun pick -> pick [| "conn_var irq1;"; "conn_var irq2;"; "conn_inout irq1;"; "conn_inout pirq;"; "conn_local;";
                       "CONNECT irq2 WITH tr;" |]);
  (fun pick -> pick [| "big_local;"; "arr{1} := 2;"; "p_arr arr;" |]);
  (fun pick -> pick [| "v := f_noret(-1);"; "v := f_noret(1);" |]);
  (fun pick -> Printf.sprintf "IF v = %s THEN\n      v := 1;\n    ELSEIF 1 / k > 0 THEN\n      v := 2;\n    ELSEIF v = 3 THEN\n      v := 3;\n    ENDIF"
      (pick [| "1"; "2"; "0" |]));
  (fun pick -> Printf.sprintf "deep %s;" (pick [| "0"; "3"; "8" |]));
|]

let random_program rand =
  let pick a = a.(Random.State.int rand (Array.length a)) in
  let array_size = pick [| 3; 10; 1000; 100_000_000 |] in
  let statements = List.init (1 + Random.State.int rand 8) (fun _ -> (pick run_statements) pick) in
  let handler = pick [| "TRYNEXT;"; "IF ERRNO = ERR_DIVZERO k := 1;\n    RETRY;"; "RETURN;"; "" |] in
  run_module_header array_size
  ^ "  PROC main()\n    " ^ String.concat "\n    " statements ^ "\n  ERROR\n    " ^ handler
  ^ "\n  ENDPROC\nENDMODULE\n"

let programs_run () =
  let module M = Rapid_semantics.Machine in
  let rand = Random.State.make [| 2026 |] in
  Random.init 2026;
  let checked = ref 0 and total = 200 in
  for _ = 1 to total do
    let text = random_program rand in
    match Parse.parse_string ~name:file_name text with
    | Error d -> Alcotest.failf "a generated program does not parse: %s\n%s" (Diagnostic.to_string d) text
    | Ok m -> (
        match Rapid_load.Session.load_modules [ m ] with
        | Error _ -> ()
        | Ok loaded -> (
            incr checked;
            let limits = { Rapid_runtime.Limits.default with max_memory = 1_000_000 } in
            match M.start ~host:(Rapid_run.Run.setup ()).host ~limits loaded.program ~entry:"main" with
            | Error e -> Alcotest.failf "cannot start: %s\n%s" e text
            | Ok cfg ->
                (try
                   while M.outcome cfg = Running && M.steps cfg < 200_000 do ignore (M.step cfg) done
                 with e -> Alcotest.failf "exception %s running\n%s" (Printexc.to_string e) text);
                match M.outcome cfg with
                | Stuck m -> Alcotest.failf "stuck (%s) after %d steps:\n%s" m (M.steps cfg) text
                | o -> if Sys.getenv_opt "FUZZ_STATS" <> None then prerr_endline (match o with
                    | Stopped { name; _ } -> "stopped " ^ name | Ended -> "ended"
                    | Resource_exhausted (m, _) -> "exhausted " ^ m
                    | Running -> "running" | Unsupported { name; _ } -> "unsupported " ^ name | Deadlock m -> "deadlock " ^ m | Stuck _ -> "")))
  done;
  (* The generator is meant to make checked programs: the property must not hold vacuously. *)
  if !checked < total * 9 / 10 then Alcotest.failf "only %d of %d generated programs pass the check" !checked total

(* Raising and handling an error costs O(1) at any call depth: a recursion through error
   handlers down to the depth limit takes well under a second and a few MB (it took minutes and
   more than a GB when each error copied the call chain). *)
let recursion_through_handlers () =
  let module M = Rapid_semantics.Machine in
  let text = "MODULE r\n  PROC dive(num n)\n    RAISE 1;\n  ERROR\n    dive n + 1;\n  ENDPROC\n  PROC main()\n    dive 1;\n  ENDPROC\nENDMODULE\n" in
  match Parse.parse_string ~name:file_name text with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Rapid_load.Session.load_modules [ m ] with
      | Error _ -> Alcotest.fail "the program does not pass the check"
      | Ok loaded -> (
          match M.start ~host:(Rapid_run.Run.setup ()).host loaded.program ~entry:"main" with
          | Error e -> Alcotest.fail e
          | Ok cfg ->
              Gc.compact ();
              let heap_before = (Gc.quick_stat ()).heap_words in
              let t0 = Unix.gettimeofday () in
              while M.outcome cfg = Running do ignore (M.step cfg) done;
              let seconds = Unix.gettimeofday () -. t0 in
              let grown = ((Gc.quick_stat ()).heap_words - heap_before) * (Sys.word_size / 8) in
              (match M.outcome cfg with
               | Resource_exhausted _ -> ()
               | _ -> Alcotest.fail "expected the call-depth limit");
              if seconds > 2.0 then Alcotest.failf "%.2f s to reach the depth limit" seconds;
              if grown > 8 * 1024 * 1024 then Alcotest.failf "the heap grew by %d bytes" grown))

(* JSON text is valid UTF-8 whatever the bytes (doc/trace-format.md, "Text"): valid UTF-8 is kept,
   any other byte becomes its Latin-1 character. *)
let json_text () =
  let module U = Rapid_runtime.Utf8_text in
  let valid = [ ""; "abc"; "café"; "é😀"; "\xEF\xBB\xBF"; "\xF4\x8F\xBF\xBF" ] in
  List.iter (fun s -> Alcotest.(check string) "valid UTF-8 is kept" s (U.of_bytes s)) valid;
  List.iter (fun (s, expected) -> Alcotest.(check string) (Printf.sprintf "%S" s) expected (U.of_bytes s))
    [ ("caf\xE9", "café"); ("\xC3", "Ã"); ("\xED\xA0\x80", "í\xC2\xA0\xC2\x80"); ("\xC0\xAF", "À¯");
      ("\xF5", "õ"); ("a\x80b", "a\xC2\x80b") ];
  let rand = Random.State.make [| 8 |] in
  for _ = 1 to 2000 do
    let s = String.init (Random.State.int rand 40) (fun _ -> Char.chr (Random.State.int rand 256)) in
    let u = U.of_bytes s in
    if not (U.is_utf8 u) then Alcotest.failf "%S gave %S, not UTF-8" s u;
    if U.of_bytes u <> u then Alcotest.failf "%S: not idempotent" s;
    let chars = U.characters ~latin1:true s in
    if Array.length chars <> String.length s || String.concat "" (Array.to_list chars) <> U.of_bytes (String.concat "" (List.map (fun c -> U.of_bytes (String.make 1 c)) (List.init (String.length s) (String.get s)))) then
      Alcotest.failf "%S: Latin-1 characters" s
  done

(* A closed pipe on standard output ends rapid-sem with exit status 141, quietly. *)
let closed_output () =
  let dir = Filename.get_temp_dir_name () in
  let file = Filename.concat dir "rapid-sem-fuzz-lines.mod" and status = Filename.concat dir "rapid-sem-fuzz-status" in
  let oc = open_out_bin file in
  output_string oc "MODULE lines\n  PROC main()\n    FOR i FROM 1 TO 100000 DO\n      TPWrite \"line \" \\Num:=i;\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
  close_out oc;
  let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe" in
  List.iter (fun args ->
      let command = Printf.sprintf "(%s %s %s 2>%s.err; echo $? > %s) | head -1 > /dev/null"
          (Filename.quote binary) args (Filename.quote file) (Filename.quote status) (Filename.quote status) in
      ignore (Sys.command command);
      let ic = open_in status in
      let code = String.trim (input_line ic) in
      close_in ic;
      let ic = open_in (status ^ ".err") in
      let err = really_input_string ic (in_channel_length ic) in
      close_in ic;
      Alcotest.(check string) (args ^ ": exit status") "141" code;
      Alcotest.(check string) (args ^ ": standard error") "" err)
    [ "run"; "run --json"; "trace"; "trace --format jsonl" ]

let suite =
  ( "fuzz",
    List.map (fun (name, speed, f) -> Alcotest.test_case name speed f) [
      ("seed modules parse", `Quick, seeds_parse);
      ("random bytes", `Quick, random_bytes);
      ("random token soups", `Quick, random_soups);
      ("mutations of valid modules", `Quick, mutations);
      ("menhir random sentences parse", `Quick, random_sentences);
      ("random sentences round trip through the printer", `Quick, round_trip);
      ("deep nesting and long lists", `Quick, deep_nesting);
      ("deep input never closed", `Quick, unclosed);
      ("nesting at the limit (§1.4)", `Quick, at_the_limit);
      ("checked programs never get stuck", `Quick, programs_run);
      ("a closed standard output", `Quick, closed_output);
      ("JSON text is UTF-8", `Quick, json_text);
      ("recursion through error handlers (O(1) errors)", `Quick, recursion_through_handlers);
    ] )
