(* The lexical elements of chapter 2, read by sedlex. *)

open Parser

exception Error of Source.region * string

type t = {
  buf : Sedlexing.lexbuf;
  file : Source.file;
  names : (string, string) Hashtbl.t;   (* one copy of each spelling: CAD modules repeat them *)
  mutable token_start : int;            (* start of a token read by a sub-lexer, else -1 *)
}

let create file (decoded : Decode.t) =
  { buf = Sedlexing.Utf8.from_string decoded.text; file; names = Hashtbl.create 1024;
    token_start = -1 }

let intern lx s =
  match Hashtbl.find_opt lx.names s with
  | Some s -> s
  | None -> if Hashtbl.length lx.names < 100_000 then Hashtbl.add lx.names s s; s

let error_at lx start stop message = raise (Error (Source.region lx.file start stop, message))

let error lx message =
  let start, stop = Sedlexing.loc lx.buf in
  error_at lx start stop message

(* §2.4: reserved words, compared without regard to letter case. TASK and switch are not
   among them. *)
let reserved_words =
  let table = Hashtbl.create 64 in
  List.iter (fun (w, t) -> Hashtbl.add table w t) [
    "ALIAS", ALIAS; "AND", AND; "BACKWARD", BACKWARD; "BREAK", BREAK; "CASE", CASE;
    "CONNECT", CONNECT; "CONST", CONST; "CONTINUE", CONTINUE; "DEFAULT", DEFAULT; "DIV", DIV;
    "DO", DO; "ELSE", ELSE; "ELSEIF", ELSEIF; "ENDFOR", ENDFOR; "ENDFUNC", ENDFUNC;
    "ENDIF", ENDIF; "ENDMODULE", ENDMODULE; "ENDPROC", ENDPROC; "ENDRECORD", ENDRECORD;
    "ENDTEST", ENDTEST; "ENDTRAP", ENDTRAP; "ENDWHILE", ENDWHILE; "ERROR", ERROR;
    "EXIT", EXIT; "FALSE", FALSE; "FOR", FOR; "FROM", FROM; "FUNC", FUNC; "GOTO", GOTO;
    "IF", IF; "INOUT", INOUT; "LOCAL", LOCAL; "MOD", MOD; "MODULE", MODULE;
    "NOSTEPIN", NOSTEPIN; "NOT", NOT; "NOVIEW", NOVIEW; "OR", OR; "PERS", PERS; "PROC", PROC;
    "RAISE", RAISE; "READONLY", READONLY; "RECORD", RECORD; "RETRY", RETRY;
    "RETURN", RETURN; "STEP", STEP; "SYSMODULE", SYSMODULE; "TEST", TEST; "THEN", THEN;
    "TO", TO; "TRAP", TRAP; "TRUE", TRUE; "TRYNEXT", TRYNEXT; "UNDO", UNDO; "VAR", VAR;
    "VIEWONLY", VIEWONLY; "WHILE", WHILE; "WITH", WITH; "XOR", XOR ];
  table

(* §2.9: placeholders, compared without regard to letter case like reserved words. *)
let placeholders =
  let table = Hashtbl.create 16 in
  List.iter (fun (w, t) -> Hashtbl.add table w t) [
    "<TDN>", TDN_PH; "<DDN>", DDN_PH; "<RDN>", RDN_PH; "<PAR>", PAR_PH; "<ALT>", ALT_PH;
    "<DIM>", DIM_PH; "<SMT>", SMT_PH; "<VAR>", VAR_PH; "<EIT>", EIT_PH; "<CSE>", CSE_PH;
    "<EXP>", EXP_PH; "<ARG>", ARG_PH; "<ID>", ID_PH ];
  table

let max_identifier_length = 32       (* §2.3 *)
let max_string_bytes = 80            (* §2.7, §2.13 *)

(* §2.1 letters: A..Z, a..z and the Latin-1 letters À..Ö Ø..ö ø..ÿ (× and ÷ are not). *)
let letter = [%sedlex.regexp? 'A' .. 'Z' | 'a' .. 'z' | 0xC0 .. 0xD6 | 0xD8 .. 0xF6 | 0xF8 .. 0xFF]
let digit = [%sedlex.regexp? '0' .. '9']
let hex_digit = [%sedlex.regexp? '0' .. '9' | 'A' .. 'F' | 'a' .. 'f']
let octal_digit = [%sedlex.regexp? '0' .. '7']
let binary_digit = [%sedlex.regexp? '0' | '1']
let integer = [%sedlex.regexp? Plus digit]
let exponent = [%sedlex.regexp? ('E' | 'e'), Opt ('+' | '-'), integer]

(* §2.5 <num literal> *)
let num_literal = [%sedlex.regexp?
    integer, Opt exponent
  | '0', ('D' | 'd'), integer, Opt exponent
  | '0', ('X' | 'x'), Plus hex_digit
  | '0', ('O' | 'o'), Plus octal_digit
  | '0', ('B' | 'b'), Plus binary_digit
  | integer, '.', Opt integer, Opt exponent
  | '.', integer, Opt exponent]

let ident = [%sedlex.regexp? letter, Star (letter | digit | '_')]
let placeholder = [%sedlex.regexp?
    '<', ( Chars "Tt", Chars "Dd", Chars "Nn"
         | Chars "Dd", Chars "Dd", Chars "Nn"
         | Chars "Rr", Chars "Dd", Chars "Nn"
         | Chars "Pp", Chars "Aa", Chars "Rr"
         | Chars "Aa", Chars "Ll", Chars "Tt"
         | Chars "Dd", Chars "Ii", Chars "Mm"
         | Chars "Ss", Chars "Mm", Chars "Tt"
         | Chars "Vv", Chars "Aa", Chars "Rr"
         | Chars "Ee", Chars "Ii", Chars "Tt"
         | Chars "Cc", Chars "Ss", Chars "Ee"
         | Chars "Ee", Chars "Xx", Chars "Pp"
         | Chars "Aa", Chars "Rr", Chars "Gg"
         | Chars "Ii", Chars "Dd" ), '>']

let newline = [%sedlex.regexp? "\r\n" | '\n' | '\r']
let white_space = [%sedlex.regexp? ' ' | '\t' | '\012' | '\r' | '\n']

let describe_char c =
  let code = Uchar.to_int c in
  if code >= 0x20 && code < 0x7F then Printf.sprintf "'%c'" (Char.chr code)
  else Printf.sprintf "U+%04X" code

(* §2.7: the body of a string literal, after its opening quote. [raw] gets the text as
   written, [bytes] the value. *)
let rec string_body lx start raw bytes =
  let buf = lx.buf in
  match%sedlex buf with
  | "\"\"" -> Buffer.add_string raw "\"\""; Buffer.add_char bytes '"'; string_body lx start raw bytes
  | "\\\\" -> Buffer.add_string raw "\\\\"; Buffer.add_char bytes '\\'; string_body lx start raw bytes
  | '\\', hex_digit, hex_digit ->
      let s = Sedlexing.Utf8.lexeme buf in
      Buffer.add_string raw s;
      Buffer.add_char bytes (Char.chr (int_of_string ("0x" ^ String.sub s 1 2)));
      string_body lx start raw bytes
  | '\\' ->
      error lx "a backslash in a string literal is written twice (\\\\) or starts a character \
                code of two hexadecimal digits (§2.7)"
  | '"' -> ()
  | newline | eof ->
      let stop, _ = Sedlexing.loc buf in
      error_at lx start stop "string literal not closed by '\"' before the end of the line (§2.7)"
  | any ->
      let s = Sedlexing.Utf8.lexeme buf in
      Buffer.add_string raw s; Buffer.add_string bytes s; string_body lx start raw bytes
  | _ -> error lx "illegal character in string literal (§2.7)"

(* The lines of a %%% header block, up to the line that closes it (doc/dialect.md). *)
let rec header_lines lx start acc =
  let buf = lx.buf in
  match%sedlex buf with
  | Star (' ' | '\t'), "%%%", Star (' ' | '\t'), (newline | eof) -> List.rev acc
  | Star (Compl ('\n' | '\r')), newline ->
      let line = Sedlexing.Utf8.lexeme buf in
      let line = String.sub line 0 (String.length line - (if String.length line >= 2 && String.sub line (String.length line - 2) 2 = "\r\n" then 2 else 1)) in
      header_lines lx start (line :: acc)
  | _ ->
      let stop, _ = Sedlexing.loc buf in
      error_at lx start stop "%%% header block not closed by a line %%%"

(* One token; [lx.token_start] is set to where it begins. *)
let rec token lx =
  let buf = lx.buf in
  match%sedlex buf with
  | Plus white_space -> token lx
  | '!', Star (Compl ('\n' | '\r')) ->
      let s = Sedlexing.Utf8.lexeme buf in
      COMMENT (String.sub s 1 (String.length s - 1))
  | "%%%", Star (' ' | '\t'), newline ->
      let start = Sedlexing.lexeme_start buf in
      lx.token_start <- start;
      if start <> 0 then error lx "a %%% header block may stand only at the start of a file";
      HEADER (header_lines lx start [])
  | num_literal ->
      let s = Sedlexing.Utf8.lexeme buf in
      (match Num_literal.of_text s with
       | Ok _ -> NUM (intern lx s)
       | Error message -> error lx message)
  (* Listed after [num_literal] so that a match of equal length is a literal: [2E5] is one
     literal, [2E5x] and [12abc] are not separated (§2.2). *)
  | num_literal, (letter | digit | '_') ->
      error lx "a numeric literal must be separated from a following identifier, reserved \
                word or numeric literal by white space (§2.2)"
  | ident ->
      let s = Sedlexing.Utf8.lexeme buf in
      (match Hashtbl.find_opt reserved_words (String.uppercase_ascii s) with
       | Some t -> t
       | None ->
           if Sedlexing.lexeme_length buf > max_identifier_length then
             error lx (Printf.sprintf "identifier longer than %d characters (§2.3)"
                         max_identifier_length);
           IDENT (intern lx s))
  | placeholder ->
      Hashtbl.find placeholders (String.uppercase_ascii (Sedlexing.Utf8.lexeme buf))
  | '"' ->
      let start = Sedlexing.lexeme_start buf in
      lx.token_start <- start;
      let raw = Buffer.create 16 and bytes = Buffer.create 16 in
      string_body lx start raw bytes;
      let stop = Sedlexing.lexeme_end buf in
      if Buffer.length bytes > max_string_bytes then
        error_at lx start stop
          (Printf.sprintf "string literal of %d bytes: a string holds at most %d (§2.7)"
             (Buffer.length bytes) max_string_bytes);
      STRING { Ast.raw = Buffer.contents raw; bytes = Buffer.contents bytes }
  | ":=" -> ASSIGN
  | "<>" -> NE
  | ">=" -> GE
  | "<=" -> LE
  | '{' -> LBRACE
  | '}' -> RBRACE
  | '(' -> LPAREN
  | ')' -> RPAREN
  | '[' -> LBRACKET
  | ']' -> RBRACKET
  | ',' -> COMMA
  | '.' -> DOT
  | '=' -> EQ
  | '<' -> LT
  | '>' -> GT
  | '+' -> PLUS
  | '-' -> MINUS
  | '*' -> STAR
  | '/' -> SLASH
  | ':' -> COLON
  | ';' -> SEMICOLON
  | '\\' -> BACKSLASH
  | '?' -> QUESTION
  | '%' -> PERCENT
  | '|' -> BAR
  | eof -> EOF
  | any ->
      let c = (Sedlexing.lexeme buf).(0) in
      if Uchar.to_int c > 0xFF then
        error lx (Printf.sprintf "character %s is not in ISO 8859-1: outside comments and \
                                  string literals a module uses Latin-1 characters only (§2.1)"
                    (describe_char c))
      else error lx (Printf.sprintf "illegal character %s (§2.1)" (describe_char c))
  | _ -> error lx "illegal character (§2.1)"

let position offset = { Lexing.pos_fname = ""; pos_lnum = 0; pos_bol = 0; pos_cnum = offset }

let next lx =
  lx.token_start <- -1;
  let t = token lx in
  let stop = Sedlexing.lexeme_end lx.buf in
  let start = if lx.token_start >= 0 then lx.token_start else Sedlexing.lexeme_start lx.buf in
  (t, position start, position stop)
