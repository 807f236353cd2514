(* Unit tests of the lexical rules of chapter 2, through the whole front end
   ([Parse.parse_string]) and, where the token itself is the point, through [Lexer] alone. *)

open Rapid_syntax

let file_name = "lex.mod"

let parse ?options text = Parse.parse_string ?options ~name:file_name text

let strict = { Parse.default_options with strict = true }

(* ------------------------------------------------------------------------------ helpers *)

let token_name (t : Parser.token) =
  match t with
  | IDENT s -> "IDENT " ^ s
  | NUM s -> "NUM " ^ s
  | STRING s -> Printf.sprintf "STRING %S" s.bytes
  | COMMENT s -> Printf.sprintf "COMMENT %S" s
  | HEADER l -> "HEADER [" ^ String.concat "; " l ^ "]"
  | EOF -> "EOF"
  | TDN_PH -> "<TDN>" | DDN_PH -> "<DDN>" | RDN_PH -> "<RDN>" | PAR_PH -> "<PAR>"
  | ALT_PH -> "<ALT>" | DIM_PH -> "<DIM>" | SMT_PH -> "<SMT>" | VAR_PH -> "<VAR>"
  | EIT_PH -> "<EIT>" | CSE_PH -> "<CSE>" | EXP_PH -> "<EXP>" | ARG_PH -> "<ARG>"
  | ID_PH -> "<ID>"
  | LBRACE -> "{" | RBRACE -> "}" | LPAREN -> "(" | RPAREN -> ")" | LBRACKET -> "["
  | RBRACKET -> "]" | COMMA -> "," | DOT -> "." | EQ -> "=" | LT -> "<" | GT -> ">"
  | PLUS -> "+" | MINUS -> "-" | STAR -> "*" | SLASH -> "/" | COLON -> ":"
  | SEMICOLON -> ";" | BACKSLASH -> "\\" | QUESTION -> "?" | ASSIGN -> ":=" | NE -> "<>"
  | GE -> ">=" | LE -> "<=" | PERCENT -> "%" | BAR -> "|"
  | t ->
      let found = ref "?" in
      Hashtbl.iter (fun w t' -> if t' = t then found := w) Lexer.reserved_words;
      !found

let token = Alcotest.testable (fun ppf t -> Format.pp_print_string ppf (token_name t)) ( = )

(* The tokens of [text] read by the lexer alone, up to the end of the file. *)
let lex text =
  let decoded = Decode.decode text in
  let file = Source.register ~name:file_name ~line_starts:decoded.line_starts in
  let lexer = Lexer.create file decoded in
  let rec go acc =
    match Lexer.next lexer with
    | Parser.EOF, _, _ -> Ok (List.rev acc)
    | t, _, _ -> go (t :: acc)
    | exception Lexer.Error (region, message) -> Error (region, message)
  in
  go []

let check_tokens text expected =
  match lex text with
  | Ok ts -> Alcotest.(check (list token)) (Printf.sprintf "tokens of %S" text) expected ts
  | Error (r, m) -> Alcotest.failf "%S: unexpected lexical error at %s: %s" text (Source.to_string r) m

let in_module body = "MODULE m\n" ^ body ^ "\nENDMODULE\n"
let in_routine body = in_module ("PROC p()\n" ^ body ^ "\nENDPROC")

let parse_ok ?options text =
  match parse ?options text with
  | Ok m -> m
  | Error d -> Alcotest.failf "%S: unexpected error %s" text (Diagnostic.to_string d)

(* An error of [cls] at [line]:[col]; [message], when given, is the exact message. *)
let parse_error ?options ?message ~cls ~line ~col text =
  match parse ?options text with
  | Ok _ -> Alcotest.failf "%S: accepted, expected a %s" text (Diagnostic.class_name cls)
  | Error d ->
      let p = Source.start d.region in
      let where = Diagnostic.to_string d in
      Alcotest.(check string) ("class of " ^ where) (Diagnostic.class_name cls)
        (Diagnostic.class_name d.error_class);
      Alcotest.(check (pair int int)) ("line, column of " ^ where) (line, col) (p.line, p.col);
      Option.iter (fun m -> Alcotest.(check string) ("message of " ^ where) m d.message) message

let statements (m : Ast.module_declaration) =
  match m.routine_declarations with
  | [ { it = Procedure_declaration { body; _ }; _ } ] -> body.statements
  | _ -> Alcotest.fail "expected one procedure"

(* The expression [e] of [x := e;] read in a routine. *)
let expression text =
  match statements (parse_ok (in_routine ("x := " ^ text ^ ";"))) with
  | [ { it = Assignment (_, e); _ } ] -> e.it
  | _ -> Alcotest.failf "%s: expected one assignment" text

let declared_name (m : Ast.module_declaration) =
  match m.data_declarations with
  | [ { it = Data_declaration { name = { it = Ident s; _ }; _ }; _ } ] -> s
  | _ -> Alcotest.fail "expected one data declaration"

let q = Alcotest.testable (fun ppf v -> Format.pp_print_string ppf (Q.to_string v)) Q.equal

(* ------------------------------------------------------------------------------ §2.3, §2.4 *)

let latin1_letters () =
  (* §2.1: À..Ö, Ø..ö, ø..ÿ are letters and may start or continue an identifier. *)
  List.iter (fun id ->
      check_tokens id [ IDENT id ];
      Alcotest.(check string) "spelling kept" id
        (declared_name (parse_ok (in_module ("VAR num " ^ id ^ ";")))))
    [ "À"; "Ö"; "Ø"; "ö"; "ø"; "ÿ"; "ß"; "Þ"; "Åsa_1"; "aÿ9"; "ÉÈÊËéèêë" ];
  (* Latin-1 characters that are not letters: × and ÷ inside the blocks, ¿ and the no-break
     space before them. *)
  List.iter (fun (text, code) ->
      parse_error ~cls:Lexical_error ~line:2 ~col:10
        ~message:(Printf.sprintf "illegal character U+%04X (§2.1)" code)
        (in_module ("VAR num a" ^ text ^ "b;")))
    [ ("×", 0xD7); ("÷", 0xF7); ("¿", 0xBF); ("\xC2\xA0", 0xA0) ];
  (* Outside comments and strings only Latin-1 (§2.1). *)
  parse_error ~cls:Lexical_error ~line:2 ~col:10
    ~message:"character U+0100 is not in ISO 8859-1: outside comments and string literals a \
              module uses Latin-1 characters only (§2.1)"
    (in_module "VAR num aĀb;");
  (* §2.3: an identifier starts with a letter. *)
  parse_error ~cls:Lexical_error ~line:2 ~col:9 ~message:"illegal character '_' (§2.1)"
    (in_module "VAR num _a;")

let identifier_length () =
  (* §2.3: at most 32 characters; characters, not bytes, are counted. *)
  List.iter (fun id -> Alcotest.(check string) "32 characters" id
                (declared_name (parse_ok (in_module ("VAR num " ^ id ^ ";")))))
    [ String.make 32 'a'; String.concat "" (List.init 32 (fun _ -> "é")) ];
  List.iter (fun id ->
      parse_error ~cls:Lexical_error ~line:2 ~col:9
        ~message:"identifier longer than 32 characters (§2.3)"
        (in_module ("VAR num " ^ id ^ ";")))
    [ String.make 33 'a'; String.concat "" (List.init 33 (fun _ -> "é")); "a" ^ String.make 32 '_' ]

(* §2.4, the manual's list. *)
let manual_reserved_words = [
  "ALIAS"; "AND"; "BACKWARD"; "BREAK"; "CASE"; "CONNECT"; "CONST"; "CONTINUE"; "DEFAULT";
  "DIV"; "DO"; "ELSE"; "ELSEIF"; "ENDFOR"; "ENDFUNC"; "ENDIF"; "ENDMODULE"; "ENDPROC";
  "ENDRECORD"; "ENDTEST"; "ENDTRAP"; "ENDWHILE"; "ERROR"; "EXIT"; "FALSE"; "FOR"; "FROM";
  "FUNC"; "GOTO"; "IF"; "INOUT"; "LOCAL"; "MOD"; "MODULE"; "NOSTEPIN"; "NOT"; "NOVIEW"; "OR";
  "PERS"; "PROC"; "RAISE"; "READONLY"; "RECORD"; "RETRY"; "RETURN"; "STEP"; "SYSMODULE";
  "TEST"; "THEN"; "TO"; "TRAP"; "TRUE"; "TRYNEXT"; "UNDO"; "VAR"; "VIEWONLY"; "WHILE";
  "WITH"; "XOR" ]

let mixed_case w = String.mapi (fun i c -> if i mod 2 = 1 then Char.lowercase_ascii c else c) w

let reserved_words () =
  Alcotest.(check int) "as many reserved words as §2.4 lists"
    (List.length manual_reserved_words) (Hashtbl.length Lexer.reserved_words);
  List.iter (fun w ->
      match lex w with
      | Ok [ (IDENT _) ] -> Alcotest.failf "%s read as an identifier" w
      | Ok [ t ] ->
          (* §2.3: letter case does not matter, for reserved words too. *)
          check_tokens (String.lowercase_ascii w) [ t ];
          check_tokens (mixed_case w) [ t ];
          (match parse (in_module ("VAR num " ^ String.lowercase_ascii w ^ ";")) with
           | Ok _ -> Alcotest.failf "%s accepted as a variable name" w
           | Error _ -> ())
      | Ok _ | Error _ -> Alcotest.failf "%s is not one token" w)
    manual_reserved_words;
  let m = parse_ok "module M\nproc P()\n  while TRUE do\n  endwhile\nEndProc\nendModule\n" in
  Alcotest.(check int) "lower-case keywords" 1 (List.length (statements m))

let not_reserved () =
  (* TASK (§2.18) and switch (§5.2) are not in the list of §2.4. The lexer marks TASK, which
     begins a task declaration (§2.18), but the parser takes it as a name wherever one may
     stand; REF is an access mode only in the installed environment (ch. 11). *)
  check_tokens "TASK task switch SWITCH ref" [ TASK "TASK"; TASK "task"; IDENT "switch"; IDENT "SWITCH"; IDENT "ref" ];
  Alcotest.(check string) "task names a routine variable" "task"
    (declared_name (parse_ok (in_module "VAR num task;")));
  (match Parse.parse_string ~name:"t.mod" "MODULE m\n  PROC p()\n    task := 1;\n    Task;\n  task:\n  ENDPROC\nENDMODULE\n" with
   | Ok _ -> ()
   | Error d -> Alcotest.failf "task as a name in statements: %s" (Diagnostic.to_string d));
  Alcotest.(check string) "TASK names a variable" "TASK"
    (declared_name (parse_ok (in_module "VAR num TASK;")));
  Alcotest.(check string) "switch names a variable" "switch"
    (declared_name (parse_ok (in_module "VAR num switch;")));
  (* Identifiers keep their spelling even though case does not distinguish them. *)
  Alcotest.(check string) "spelling" "MyVar" (declared_name (parse_ok (in_module "VAR num MyVar;")))

(* ------------------------------------------------------------------------------ §2.5 *)

let num_value text expected =
  Alcotest.check q ("value of " ^ text) expected (Num_literal.value text);
  check_tokens text [ NUM text ];
  match expression text with
  | Num_literal s -> Alcotest.(check string) "kept as written" text s
  | _ -> Alcotest.failf "%s: not a numeric literal" text

let numeric_forms () =
  let ( // ) a b = Q.of_ints a b and i = Q.of_int in
  List.iter (fun (text, v) -> num_value text v) [
    (* the manual's examples (§2.5) *)
    ("7990", i 7990); ("23.67", 2367 // 100); ("2E6", i 2_000_000); (".27", 27 // 100);
    ("2.5E-3", 1 // 400); ("38.", i 38);
    (* every form of <num literal> *)
    ("0XFF", i 255); ("0xff", i 255); ("0xA0", i 160); ("0b101", i 5); ("0B0", i 0);
    ("0o17", i 15); ("0O777", i 511); ("0D12E2", i 1200); ("0d17", i 17); (".5", 1 // 2);
    ("1e+3", i 1000); ("1E-0", i 1); ("38.E1", i 380); ("38.5e-1", 77 // 20); (".5E1", i 5);
    ("007", i 7); ("0.000", i 0); ("1.50", 3 // 2); ("0d0", i 0) ];
  (* 400 digits whose value is exactly 1. *)
  num_value ("1" ^ String.make 399 '0' ^ "E-399") Q.one;
  num_value ("0." ^ String.make 398 '0' ^ "1E399") Q.one

let numeric_separation () =
  (* §2.2: a numeric literal is separated from a following identifier, reserved word or
     literal; a malformed based literal is such a case, not a shorter literal. *)
  List.iter (fun text ->
      parse_error ~cls:Lexical_error ~line:3 ~col:6
        ~message:"a numeric literal must be separated from a following identifier, reserved \
                  word or numeric literal by white space (§2.2)"
        (in_routine ("x := " ^ text ^ ";")))
    [ "0x"; "0xG"; "0b2"; "0o8"; "1E"; "1e+"; "12abc"; "2E5x"; "3_"; "1.5e2e" ];
  (* With white space the same characters are tokens of their own. *)
  check_tokens "12 abc 2E5 x" [ NUM "12"; IDENT "abc"; NUM "2E5"; IDENT "x" ];
  check_tokens "1+2-3" [ NUM "1"; PLUS; NUM "2"; MINUS; NUM "3" ]

let pow2 n = Z.shift_left Z.one n

(* [digits] * 10^[exponent], exactly. *)
let decimal digits exponent =
  let p = Z.pow (Z.of_int 10) (abs exponent) in
  if exponent >= 0 then Q.of_bigint (Z.mul (Z.of_string digits) p)
  else Q.make (Z.of_string digits) p

let numeric_range () =
  let out_of_range = "numeric literal out of the range of IEEE 754 (§2.5)" in
  let refused text =
    (match Num_literal.of_text text with
     | Ok _ -> Alcotest.failf "%s accepted" text
     | Error m -> Alcotest.(check string) ("refusal of " ^ text) out_of_range m);
    parse_error ~cls:Lexical_error ~line:3 ~col:6 ~message:out_of_range
      (in_routine ("x := " ^ text ^ ";"))
  in
  let accepted text v = num_value text v in
  (* The manual's example of a lexical error (§1.4). *)
  refused "2E52786";
  (* Largest: the midpoint between the largest double and 2^1024 already rounds to infinity. *)
  let max_double = Z.sub (pow2 1024) (pow2 971) in
  let midpoint = Z.sub (pow2 1024) (pow2 970) in
  accepted (Z.to_string max_double) (Q.of_bigint max_double);
  accepted ("0x" ^ Z.format "%x" max_double) (Q.of_bigint max_double);
  accepted (Z.to_string (Z.pred midpoint)) (Q.of_bigint (Z.pred midpoint));
  refused (Z.to_string midpoint);
  refused ("0x" ^ Z.format "%x" midpoint);
  refused ("0x1" ^ String.make 256 '0');
  refused ("0b1" ^ String.make 1024 '0');
  accepted "1.7976931348623157E308" (decimal "17976931348623157" 292);
  accepted "1.7976931348623158e308" (decimal "17976931348623158" 292);
  refused "1.7976931348623159E308";
  refused "1E309";
  accepted "1E308" (Q.of_bigint (Z.pow (Z.of_int 10) 308));
  (* Smallest: half the smallest subnormal, 2^-1075 = 5^1075 * 10^-1075, rounds to zero. *)
  let half_subnormal = Z.pow (Z.of_int 5) 1075 in
  refused (Z.to_string half_subnormal ^ "E-1075");
  accepted (Z.to_string (Z.succ half_subnormal) ^ "E-1075")
    (decimal (Z.to_string (Z.succ half_subnormal)) (-1075));
  accepted "4.9406564584124654E-324" (decimal "49406564584124654" (-340));
  accepted "2.4703282292062328E-324" (decimal "24703282292062328" (-340));
  refused "2.4703282292062327E-324";
  refused "1E-400";
  refused "1E99999999999999999999";
  refused "1E-99999999999999999999";
  (* Zero is in range whatever its exponent. *)
  accepted "0E-400" Q.zero;
  accepted "0.0E99999999999999999999" Q.zero

(* ------------------------------------------------------------------------------ §2.7 *)

let string_literal text =
  match expression text with
  | String_literal s -> s
  | _ -> Alcotest.failf "%s: not a string literal" text

let check_string text ~raw ~bytes =
  let s = string_literal text in
  Alcotest.(check string) ("raw text of " ^ text) raw s.raw;
  Alcotest.(check string) ("value of " ^ text) bytes s.bytes

let strings () =
  check_string {|""|} ~raw:"" ~bytes:"";
  check_string {|"A string literal"|} ~raw:"A string literal" ~bytes:"A string literal";
  (* §2.7: '"' and '\' are written twice. *)
  check_string {|"Contains a "" character"|} ~raw:{|Contains a "" character|}
    ~bytes:{|Contains a " character|};
  check_string {|"Contains a \\ character"|} ~raw:{|Contains a \\ character|}
    ~bytes:{|Contains a \ character|};
  check_string {|""""|} ~raw:{|""|} ~bytes:{|"|};
  (* §2.7: a character code names one byte, whatever it is. *)
  check_string {|"Ends with BEL control character \07"|}
    ~raw:{|Ends with BEL control character \07|} ~bytes:"Ends with BEL control character \007";
  check_string {|"\41\4a\4A\00\ff\FF"|} ~raw:{|\41\4a\4A\00\ff\FF|} ~bytes:"AJJ\000\255\255";
  check_string {|"\\41"|} ~raw:{|\\41|} ~bytes:{|\41|};
  (* UTF-8 is allowed in strings (§2.7); the value is its bytes. *)
  check_string {|"é😀"|} ~raw:"é😀" ~bytes:"\xC3\xA9\xF0\x9F\x98\x80";
  (* ! does not start a comment in a string *)
  check_string {|"a ! b"|} ~raw:"a ! b" ~bytes:"a ! b"

let string_length () =
  (* §2.7, §2.13: at most 80 bytes, counted in the value. *)
  let quoted s = "\"" ^ s ^ "\"" in
  let repeat n s = String.concat "" (List.init n (fun _ -> s)) in
  List.iter (fun body -> ignore (string_literal (quoted body)))
    [ String.make 80 'a'; repeat 40 "é"; repeat 20 "😀"; repeat 80 {|\41|};
      String.make 79 'a' ^ {|""|}; String.make 78 'a' ^ {|\\|} ^ "b" ];
  List.iter (fun (body, bytes) ->
      parse_error ~cls:Lexical_error ~line:3 ~col:6
        ~message:(Printf.sprintf "string literal of %d bytes: a string holds at most 80 (§2.7)" bytes)
        (in_routine ("x := " ^ quoted body ^ ";")))
    [ (String.make 81 'a', 81); (repeat 41 "é", 82); (repeat 81 {|\41|}, 81);
      (String.make 80 'a' ^ {|""|}, 81); (repeat 21 "😀", 84) ]

let string_errors () =
  let bad_escape = "a backslash in a string literal is written twice (\\\\) or starts a \
                    character code of two hexadecimal digits (§2.7)" in
  let not_closed = "string literal not closed by '\"' before the end of the line (§2.7)" in
  (* Every error of a string literal is reported at its opening quote (spec/README.md). *)
  parse_error ~cls:Lexical_error ~line:3 ~col:6 ~message:bad_escape (in_routine {|x := "ab\g";|});
  parse_error ~cls:Lexical_error ~line:3 ~col:6 ~message:bad_escape (in_routine {|x := "\4";|});
  parse_error ~cls:Lexical_error ~line:3 ~col:6 ~message:bad_escape (in_routine {|x := "\";|});
  (* An unterminated literal is reported where it starts. *)
  parse_error ~cls:Lexical_error ~line:3 ~col:6 ~message:not_closed (in_routine {|x := "abc;|});
  parse_error ~cls:Lexical_error ~line:3 ~col:6 ~message:not_closed
    "MODULE m\nPROC p()\nx := \"abc\r\nENDPROC\nENDMODULE\n";
  parse_error ~cls:Lexical_error ~line:1 ~col:10 ~message:not_closed "MODULE m \"abc"

(* ------------------------------------------------------------------------------ §2.10 *)

let comments () =
  check_tokens "a ! b c\nd" [ IDENT "a"; COMMENT " b c"; IDENT "d" ];
  check_tokens "!\n!x\r!y\r\n!z" [ COMMENT ""; COMMENT "x"; COMMENT "y"; COMMENT "z" ];
  check_tokens "! é 😀 \"ENDPROC\t" [ COMMENT " é 😀 \"ENDPROC\t" ];
  (match statements (parse_ok (in_routine "! ENDPROC ENDMODULE\nx := 1; ! é\n")) with
   | [ { it = Statement_comment " ENDPROC ENDMODULE"; _ }; { it = Assignment _; _ };
       { it = Statement_comment " é"; _ } ] -> ()
   | _ -> Alcotest.fail "comments as statements");
  (* The end of the file ends a comment too (without --strict, doc/dialect.md). *)
  check_tokens "a ! end" [ IDENT "a"; COMMENT " end" ]

(* ------------------------------------------------------------------------------ §2.9 *)

let placeholders () =
  check_tokens "<TDN> <DDN> <RDN> <PAR> <ALT> <DIM> <SMT> <VAR> <EIT> <CSE> <EXP> <ARG> <ID>"
    [ TDN_PH; DDN_PH; RDN_PH; PAR_PH; ALT_PH; DIM_PH; SMT_PH; VAR_PH; EIT_PH; CSE_PH; EXP_PH;
      ARG_PH; ID_PH ];
  (* Letter case does not matter, as for reserved words (§2.3). *)
  check_tokens "<smt> <Smt> <id> <eXp>" [ SMT_PH; SMT_PH; ID_PH; EXP_PH ];
  (* A placeholder is one token: no white space inside, no other names. *)
  check_tokens "< SMT >" [ LT; IDENT "SMT"; GT ];
  check_tokens "<FOO>" [ LT; IDENT "FOO"; GT ];
  check_tokens "a<ID>b" [ IDENT "a"; ID_PH; IDENT "b" ];
  (match statements (parse_ok (in_routine "<smt>\nx := <EXP>;")) with
   | [ { it = SMT_placeholder; _ }; { it = Assignment (_, { it = EXP_placeholder; _ }); _ } ] -> ()
   | _ -> Alcotest.fail "placeholders in a routine")

(* ------------------------------------------------------------------------------ §2.8 *)

let delimiters () =
  check_tokens {|{ } ( ) [ ] , . = < > + - * / : ; \ ? := <> >= <= % ||}
    [ LBRACE; RBRACE; LPAREN; RPAREN; LBRACKET; RBRACKET; COMMA; DOT; EQ; LT; GT; PLUS; MINUS;
      STAR; SLASH; COLON; SEMICOLON; BACKSLASH; QUESTION; ASSIGN; NE; GE; LE; PERCENT; BAR ];
  (* Compound symbols are read longest first, and only without white space inside. *)
  check_tokens "a:=b.c" [ IDENT "a"; ASSIGN; IDENT "b"; DOT; IDENT "c" ];
  check_tokens ": =" [ COLON; EQ ];
  check_tokens "<>=" [ NE; EQ ];
  check_tokens "<=>" [ LE; GT ];
  check_tokens "> =" [ GT; EQ ];
  check_tokens "x{1}" [ IDENT "x"; LBRACE; NUM "1"; RBRACE ];
  List.iter (fun c ->
      parse_error ~cls:Lexical_error ~line:3 ~col:6
        ~message:(Printf.sprintf "illegal character '%c' (§2.1)" c)
        (in_routine (Printf.sprintf "x := %c;" c)))
    [ '$'; '@'; '#'; '&'; '^'; '~'; '`'; '\'' ]

(* ------------------------------------------------------------------------------ white space *)

let white_space () =
  (* §2.1, §2.2: space, tab, form feed and newline separate tokens. *)
  check_tokens "a\tb\012c\rd\ne\r\nf g" [ IDENT "a"; IDENT "b"; IDENT "c"; IDENT "d"; IDENT "e";
                                          IDENT "f"; IDENT "g" ];
  ignore (parse_ok "MODULE\tm\012\r\nPROC p()\rx:=1;\r\nENDPROC\n\nENDMODULE\r\n");
  (* Other control characters are not white space. *)
  List.iter (fun (c, code) ->
      parse_error ~cls:Lexical_error ~line:1 ~col:7
        ~message:(Printf.sprintf "illegal character U+%04X (§2.1)" code)
        ("MODULE" ^ c ^ "m\nENDMODULE\n"))
    [ ("\011", 0x0B); ("\000", 0x00); ("\027", 0x1B); ("\127", 0x7F) ];
  (* LF, CRLF and a lone CR each end one line. *)
  parse_error ~cls:Lexical_error ~line:4 ~col:8 "MODULE m\r\n\r\nPROC p()\r\n  x := $;\r\n";
  parse_error ~cls:Lexical_error ~line:4 ~col:8 "MODULE m\r\rPROC p()\r  x := $;\r";
  parse_error ~cls:Lexical_error ~line:5 ~col:3 "MODULE m\n\r\n\rPROC p()\n\t $\n"

(* ------------------------------------------------------------------------------ positions *)

let positions () =
  (* Columns count characters (Source), not bytes: é is two bytes, 😀 four. *)
  parse_error ~cls:Lexical_error ~line:3 ~col:11 (in_routine {|x := "éé" $;|});
  parse_error ~cls:Lexical_error ~line:3 ~col:10 (in_routine {|x := "😀" $;|});
  parse_error ~cls:Syntax_error ~line:3 ~col:17 (in_routine {|x := "é" + "😀" ;;|});
  (* Characters of earlier lines (in a comment) do not shift later positions. *)
  parse_error ~cls:Lexical_error ~line:4 ~col:3 (in_routine "! ééé 😀😀😀\n  $");
  parse_error ~cls:Lexical_error ~line:4 ~col:1 (in_routine "x := 1; ! ü ü\n$");
  (* The region of an error is counted in characters too. *)
  match parse (in_routine {|x := "ééé" + 12abc;|}) with
  | Error d ->
      Alcotest.(check int) "start offset in characters"
        (String.length "MODULE m\nPROC p()\nx := \"ééé\" + " - 3) (Source.start_offset d.region)
  | Ok _ -> Alcotest.fail "12abc accepted"

(* ------------------------------------------------------------------------------ §2.1 files *)

let latin1_file () =
  (* A file that is not UTF-8 is read as Latin-1: 0xE9 is é, 0xC5 is Å. *)
  let m = parse_ok "MODULE m\nVAR num \xC5r;\n! caf\xE9\nENDMODULE\n" in
  Alcotest.(check string) "identifier in UTF-8" "År" (declared_name m);
  (match m.routine_declarations with
   | [ { it = Routine_comment " café"; _ } ] -> ()
   | _ -> Alcotest.fail "comment read as Latin-1");
  (* one byte, one column *)
  parse_error ~cls:Lexical_error ~line:3 ~col:15 "MODULE m\n! \xE9\xE9\xE9\nVAR num \xE9\xE9 := $;\n";
  (* × is a Latin-1 character but not a letter (§2.1). *)
  parse_error ~cls:Lexical_error ~line:2 ~col:10 ~message:"illegal character U+00D7 (§2.1)"
    "MODULE m\nVAR num a\xD7b;\nENDMODULE\n";
  (* A string of a Latin-1 file holds the UTF-8 encoding of its characters. *)
  match statements (parse_ok "MODULE m\nPROC p()\nx := \"\xE9\";\nENDPROC\nENDMODULE\n") with
  | [ { it = Assignment (_, { it = String_literal s; _ }); _ } ] ->
      Alcotest.(check string) "Latin-1 string value" "\xC3\xA9" s.bytes
  | _ -> Alcotest.fail "Latin-1 string"

let byte_order_mark () =
  let bom = "\xEF\xBB\xBF" in
  ignore (parse_ok (bom ^ "MODULE m\nENDMODULE\n"));
  (* The mark is not a character of the file: columns start after it. *)
  parse_error ~cls:Syntax_error ~line:1 ~col:8 (bom ^ "MODULE 1\nENDMODULE\n");
  (* Under --strict the mark is an illegal character: a lexical error (§1.4). *)
  parse_error ~options:strict ~cls:Lexical_error ~line:1 ~col:1
    ~message:"byte-order mark at the start of the file: §2.1 defines no such character; \
              accepted without --strict (doc/dialect.md)"
    (bom ^ "MODULE m\nENDMODULE\n");
  ignore (parse_ok ~options:strict "MODULE m\nENDMODULE\n")

let header () =
  let text = "%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%%\nMODULE m\nENDMODULE\n" in
  let m = parse_ok text in
  Alcotest.(check (option (list string))) "header lines"
    (Some [ "  VERSION:1"; "  LANGUAGE:ENGLISH" ]) m.header;
  Alcotest.(check (option (list string))) "no header" None (parse_ok (in_module "")).header;
  Alcotest.(check (option (list string))) "CRLF header" (Some [ "  VERSION:1" ])
    (parse_ok "%%%\r\n  VERSION:1\r\n%%%\r\nMODULE m\r\nENDMODULE\r\n").header;
  parse_error ~options:strict ~cls:Syntax_error ~line:1 ~col:1
    ~message:"a %%% header block is not part of a module declaration (§9.2); accepted without \
              --strict (doc/dialect.md)"
    text;
  parse_error ~cls:Lexical_error ~line:2 ~col:1
    ~message:"a %%% header block may stand only at the start of a file"
    "MODULE m\n%%%\n%%%\nENDMODULE\n";
  parse_error ~cls:Lexical_error ~line:1 ~col:1
    ~message:"%%% header block not closed by a line %%%" "%%%\n  VERSION:1\nMODULE m\nENDMODULE\n"

let final_newline () =
  ignore (parse_ok "MODULE m\nENDMODULE");
  List.iter (fun text -> ignore (parse_ok ~options:strict text))
    [ "MODULE m\nENDMODULE\n"; "MODULE m\nENDMODULE\r"; "MODULE m\nENDMODULE\r\n" ];
  parse_error ~options:strict ~cls:Syntax_error ~line:2 ~col:9
    ~message:"the file does not end with a line break (§2.10: a line ends with <newline>); \
              accepted without --strict (doc/dialect.md)"
    "MODULE m\nENDMODULE";
  (* The refusal points at the last character, white space included. *)
  parse_error ~options:strict ~cls:Syntax_error ~line:2 ~col:11 "MODULE m\nENDMODULE  "

(* Decode's line starts (eight bytes a step on ASCII texts) against the plain definition: a
   line starts after "\n", after "\r" not followed by "\n", and after "\r\n", counted in
   characters. Random texts of line breaks, letters and now and then a byte above 0x7F. *)
let line_starts () =
  let reference text =
    let n = String.length text and starts = ref [ 0 ] and chars = ref 0 in
    String.iteri (fun i c ->
        if Char.code c land 0xC0 <> 0x80 then incr chars;
        if c = '\n' || (c = '\r' && (i + 1 >= n || text.[i + 1] <> '\n')) then starts := !chars :: !starts)
      text;
    Array.of_list (List.rev !starts) in
  let rs = Random.State.make [| 20 |] in
  let pieces = [| "\n"; "\r"; "\r\n"; "a"; " "; "abcdefgh"; "ENDPROC"; "\xC3\xA9"; "\xE9" |] in
  for _ = 1 to 3000 do
    let k = Random.State.int rs 60 in
    let high = Random.State.int rs 4 = 0 in
    let text = String.concat "" (List.init k (fun _ ->
        pieces.(Random.State.int rs (if high then Array.length pieces else Array.length pieces - 2)))) in
    let d = Decode.decode text in
    if not d.latin1 then
      Alcotest.(check (array int)) (String.escaped text) (reference d.text) d.line_starts
  done

let suite =
  ( "lexer",
    List.map (fun (name, f) -> Alcotest.test_case name `Quick f) [
      ("§2.1 Latin-1 letters in identifiers", latin1_letters);
      ("§2.3 identifier length", identifier_length);
      ("§2.4 reserved words, any letter case", reserved_words);
      ("§2.4 TASK and switch are identifiers", not_reserved);
      ("§2.5 numeric forms and exact values", numeric_forms);
      ("§2.2 numeric literal separation", numeric_separation);
      ("§2.5 numeric range limits", numeric_range);
      ("§2.7 string literals", strings);
      ("§2.7 string length in bytes", string_length);
      ("§2.7 string errors", string_errors);
      ("§2.10 comments", comments);
      ("§2.9 placeholders", placeholders);
      ("§2.8 delimiters", delimiters);
      ("§2.1 white space and line breaks", white_space);
      ("positions count characters", positions);
      ("§2.1 Latin-1 files", latin1_file);
      ("byte-order mark", byte_order_mark);
      ("%%% header", header);
      ("missing final newline", final_newline);
      ("line starts of ASCII and UTF-8 texts", line_starts);
    ] )
