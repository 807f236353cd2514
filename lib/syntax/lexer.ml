(* The lexical elements of chapter 2, read by sedlex. *)

open Parser

exception Error of Source.region * string

(* Speed and memory (bench/README.md). Sedlex's own buffer ([Sedlexing.Utf8.from_string])
   decodes the whole text into two arrays of 8 bytes per character before the first token, and
   compares every character it reads with a polymorphic equality. The rules below run instead
   on [Sedlexing], a buffer that reads the UTF-8 text in place: sedlex documents this use
   (sedlexing.mli: "bind this module to the name Sedlexing"). Lexemes are then plain
   substrings of the text, and names and literals are looked up in [Names] without first
   building the string. *)

(* The buffer: positions are counted in characters, as sedlex counts them and as every region
   of the tree is (Source); the byte offset of each is kept alongside. *)
module Sedlexing = struct
  type lexbuf = {
    text : string;                  (* UTF-8 *)
    mutable pos : int;              (* byte offset of the next character *)
    mutable pos_char : int;         (* ... and its character offset *)
    mutable start : int;            (* the current lexeme's first byte *)
    mutable start_char : int;
    mutable marked : int;           (* where [backtrack] returns to *)
    mutable marked_char : int;
    mutable marked_value : int;
  }

  let from_string text =
    { text; pos = 0; pos_char = 0; start = 0; start_char = 0; marked = 0; marked_char = 0;
      marked_value = -1 }

  (* The code point at byte [i] and its length in bytes. Decode hands over valid UTF-8; a
     byte that does not begin a valid sequence is taken as the Latin-1 character it would be,
     so that no text makes the lexer fail on its own account. *)
  let decode text i =
    let n = String.length text in
    let c = Char.code (String.unsafe_get text i) in
    let cont k = if i + k < n then Char.code (String.unsafe_get text (i + k)) lxor 0x80 else 0xFF in
    if c < 0xC2 then (c, 1)
    else if c < 0xE0 then
      let c1 = cont 1 in
      if c1 < 0x40 then (((c land 0x1F) lsl 6) lor c1, 2) else (c, 1)
    else if c < 0xF0 then
      let c1 = cont 1 and c2 = cont 2 in
      let code = ((c land 0x0F) lsl 12) lor (c1 lsl 6) lor c2 in
      if c1 < 0x40 && c2 < 0x40 && code >= 0x800 && (code < 0xD800 || code > 0xDFFF)
      then (code, 3) else (c, 1)
    else if c < 0xF5 then
      let c1 = cont 1 and c2 = cont 2 and c3 = cont 3 in
      let code = ((c land 0x07) lsl 18) lor (c1 lsl 12) lor (c2 lsl 6) lor c3 in
      if c1 < 0x40 && c2 < 0x40 && c3 < 0x40 && code >= 0x10000 && code <= 0x10FFFF
      then (code, 4) else (c, 1)
    else (c, 1)

  (* What sedlex's automata call: the next code point, or -1 at the end of the text. *)
  let __private__next_int b =
    let p = b.pos in
    if p >= String.length b.text then -1
    else begin
      let c = Char.code (String.unsafe_get b.text p) in
      b.pos_char <- b.pos_char + 1;
      if c < 0x80 then begin b.pos <- p + 1; c end
      else begin
        let code, width = decode b.text p in
        b.pos <- p + width;
        code
      end
    end

  let start b =
    b.start <- b.pos; b.start_char <- b.pos_char;
    b.marked <- b.pos; b.marked_char <- b.pos_char; b.marked_value <- -1

  let mark b value = b.marked <- b.pos; b.marked_char <- b.pos_char; b.marked_value <- value

  let backtrack b = b.pos <- b.marked; b.pos_char <- b.marked_char; b.marked_value

  let lexeme_start b = b.start_char
  let lexeme_end b = b.pos_char
  let lexeme_length b = b.pos_char - b.start_char
  let loc b = (b.start_char, b.pos_char)
  let first_char b = Uchar.of_int (fst (decode b.text b.start))
end

(* One copy of each spelling: CAD modules repeat the same names and short literals (tool0,
   9E+09) hundreds of thousands of times. The table is keyed by a stretch of the text, so a
   spelling already seen costs no allocation; it stops growing at [max_names], after which new
   spellings are simply not shared. *)
module Names = struct
  type t = { mutable keys : string array; mutable count : int }

  let max_names = 100_000

  let create () = { keys = Array.make 256 ""; count = 0 }

  (* One byte into a hash (FNV-1a's step), and the last step: [hash], Reserved's and
     Shortcut.name's, which computes both as it reads a name, are made of these. *)
  let mix h code = (h lxor code) * 0x100000001B3 [@@inline]
  let finish h = h lxor (h lsr 31) [@@inline]

  let hash text start stop =
    let h = ref 0 in
    for i = start to stop - 1 do h := mix !h (Char.code (String.unsafe_get text i)) done;
    finish !h

  (* This runs for every name and literal. *)
  let same key text start stop =
    let n = stop - start in
    String.length key = n
    && (let i = ref 0 in
        while !i < n && String.unsafe_get key !i = String.unsafe_get text (start + !i) do incr i done;
        !i = n)

  (* Linear probing in a table kept at most half full; "" marks an empty slot (the empty
     string is never a name or a literal). *)
  let rec slot keys mask text start stop i =
    let key = Array.unsafe_get keys i in
    if String.length key = 0 || same key text start stop then i
    else slot keys mask text start stop ((i + 1) land mask)

  let grow t =
    let keys = Array.make (2 * Array.length t.keys) "" in
    let mask = Array.length keys - 1 in
    Array.iter (fun key ->
        let n = String.length key in
        if n > 0 then begin
          keys.(slot keys mask key 0 n (hash key 0 n land mask)) <- key
        end) t.keys;
    t.keys <- keys

  (* [h] is [hash text start stop], computed by the caller as it read the name. *)
  let find_or_add_hashed t text start stop h =
    let mask = Array.length t.keys - 1 in
    let i = slot t.keys mask text start stop (h land mask) in
    let key = Array.unsafe_get t.keys i in
    if String.length key > 0 then key
    else begin
      let s = String.sub text start (stop - start) in
      if t.count < max_names then begin
        t.keys.(i) <- s;
        t.count <- t.count + 1;
        if 2 * t.count > Array.length t.keys then grow t
      end;
      s
    end

  let find_or_add t text start stop = find_or_add_hashed t text start stop (hash text start stop)
end

type t = {
  buf : Sedlexing.lexbuf;
  file : Source.file;
  names : Names.t;
  mutable token_start : int;            (* start of a token read by a sub-lexer, else -1; then the token's *)
  mutable token_stop : int;             (* where the token read last stops *)
  mutable last_stop : Lexing.position;  (* where the previous token stopped *)
  installed : bool;                     (* reading the installed environment: REF is a word *)
  robotware : Robotware.t;              (* RobotWare 5 and 6: BREAK and CONTINUE are names *)
  mutable after_switch : bool;          (* the previous token is the name "switch" *)
  mutable after_proc : bool;            (* in the installed environment, the previous token is PROC *)
  mutable name_hash : int;              (* of the name [Shortcut.name] read last: Names.hash, *)
  mutable word_hash : int;              (* and Reserved.raw_hash *)
}

let position offset = { Lexing.pos_fname = ""; pos_lnum = 0; pos_bol = 0; pos_cnum = offset }

let create ?(installed = false) ?(robotware = Robotware.default) file (decoded : Decode.t) =
  { buf = Sedlexing.from_string decoded.text; file; names = Names.create (); token_start = -1; token_stop = 0;
    last_stop = position (-1); installed; robotware; after_switch = false; after_proc = false;
    name_hash = 0; word_hash = 0 }

(* The current lexeme, as UTF-8, without its first [skip] bytes. *)
let text_of ?(skip = 0) lx =
  let b = lx.buf in
  String.sub b.text (b.start + skip) (b.pos - b.start - skip)

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

(* [reserved_words] looked up in a stretch of the text, folding letter case as the bytes are
   read instead of building the upper-case spelling of every identifier. *)
module Reserved = struct
  let size = 256
  let keys = Array.make size ""
  let tokens = Array.make size EOF
  let max_length = Hashtbl.fold (fun w _ m -> max m (String.length w)) reserved_words 0

  let upper c = if c >= 'a' && c <= 'z' then Char.unsafe_chr (Char.code c - 32) else c
  let upper_code code = if code >= 97 && code <= 122 then code - 32 else code [@@inline]

  (* Before its last step ([slot_of]): Shortcut.name computes it as it reads a name. *)
  let raw_hash text start stop =
    let h = ref 0 in
    for i = start to stop - 1 do h := Names.mix !h (upper_code (Char.code (String.unsafe_get text i))) done;
    !h

  let slot_of h = Names.finish h land (size - 1)

  let hash text start stop = slot_of (raw_hash text start stop)

  let () =
    Hashtbl.iter (fun w t ->
        let i = ref (hash w 0 (String.length w)) in
        while keys.(!i) <> "" do i := (!i + 1) land (size - 1) done;
        keys.(!i) <- w;
        tokens.(!i) <- t) reserved_words

  let rec same_from key text start stop i =
    i >= stop - start
    || (String.unsafe_get key i = upper (String.unsafe_get text (start + i))
        && same_from key text start stop (i + 1))

  let rec probe text start stop i =
    let key = Array.unsafe_get keys i in
    if String.length key = 0 then -1
    else if String.length key = stop - start && same_from key text start stop 0 then i
    else probe text start stop ((i + 1) land (size - 1))

  (* The slot of the reserved word spelt by [text.[start..stop-1]], or -1; [h] is
     [raw_hash text start stop]. *)
  let find_hashed text start stop h =
    if stop - start > max_length then -1 else probe text start stop (slot_of h)
end

(* A sufficient condition for [Num_literal.of_text] to accept a decimal literal, checked
   without building numbers: a value m x 10^e whose leading digit stands at decimal exponent
   -322 .. 307 lies strictly between 2^-1075 and 2^1024 - 2^970, the bounds of §2.5's IEEE 754
   range as Num_literal states them, and zero is always in range. Anything else (based
   literals, long exponents, values near the bounds) goes to [Num_literal.of_text], so the
   literals accepted and the messages given are its own. *)
let plainly_in_range text start stop =
  let based =
    stop - start >= 2 && String.unsafe_get text start = '0'
    && (match String.unsafe_get text (start + 1) with
        | 'x' | 'X' | 'o' | 'O' | 'b' | 'B' | 'd' | 'D' -> true
        | _ -> false)
  in
  if based then false
  else begin
    let i = ref start and significant = ref 0 and fraction = ref 0 and dot = ref false in
    let continue = ref true in
    while !continue && !i < stop do
      (match String.unsafe_get text !i with
       | '.' -> dot := true
       | '0' .. '9' as c ->
           if !dot then incr fraction;
           if !significant > 0 || c <> '0' then incr significant
       | _ -> continue := false);
      if !continue then incr i
    done;
    if !significant = 0 then true
    else begin
      (* [!i] is at the exponent's 'E', or at [stop]. *)
      let j = ref (!i + 1) and negative = ref false in
      if !i < stop && !j < stop then begin
        match String.unsafe_get text !j with
        | '-' -> negative := true; incr j
        | '+' -> incr j
        | _ -> ()
      end;
      if !i < stop && stop - !j > 6 then false
      else begin
        let e = ref 0 in
        if !i < stop then
          for k = !j to stop - 1 do e := (10 * !e) + Char.code (String.unsafe_get text k) - 48 done;
        let e = if !negative then - !e else !e in
        let adjusted = e - !fraction + !significant - 1 in
        adjusted >= -322 && adjusted <= 307
      end
    end
  end

let max_identifier_length = 32       (* §2.3 *)

let is_ascii_name name =
  let ok_char = function 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_' -> true | _ -> false in
  name <> "" && String.length name <= max_identifier_length
  && (match name.[0] with 'A' .. 'Z' | 'a' .. 'z' -> true | _ -> false) && String.for_all ok_char name
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

(* The token of the numeric literal text.[start..stop-1] once it is known to be in range.
   Short literals repeat (0, 1, 9E+09); coordinates such as 1125.58 seldom do, and would only
   fill the table. *)
let number lx text start stop =
  NUM (if stop - start <= 5 then Names.find_or_add lx.names text start stop
       else String.sub text start (stop - start))

(* R-2.4-rw6: RobotWare 5 and 6 reserve neither BREAK nor CONTINUE (the statements of §4.8 and §4.9
   are RobotWare 7's). The installed environment declares RobotWare 6's instruction Break (the
   name right after PROC), which a RobotWare 7 module cannot name. *)
let loop_word_is_name lx token =
  match token with
  | BREAK -> (lx.installed && lx.after_proc) || not (Robotware.reserves_loop_words lx.robotware)
  | CONTINUE -> not (Robotware.reserves_loop_words lx.robotware)
  | _ -> false

(* Whether text.[start..] spells [word] (lower case, as long as the name) in any case, without a
   lowered copy: every name of four letters asks. *)
let is_lower_word word text start =
  let rec go i =
    i >= String.length word
    || (Char.lowercase_ascii (String.unsafe_get text (start + i)) = String.unsafe_get word i && go (i + 1)) in
  go 0

(* §2.3, §2.4: the token of the name text.[start..stop-1], [chars] characters long, which is
   the current lexeme (an error is reported at it). *)
let name_hashed lx text start stop chars ~word_hash ~name_hash =
  let reserved = Reserved.find_hashed text start stop word_hash in
  if reserved >= 0 && lx.installed && lx.after_switch && Reserved.tokens.(reserved) = CONTINUE then
    (* The installed RaiseToUser declares ABB's switch Continue (doc/rulings.md R-7.3-m): in the
       installed environment, right after "switch", the word is the parameter's name. *)
    IDENT (Names.find_or_add_hashed lx.names text start stop name_hash)
  else if reserved >= 0 && loop_word_is_name lx Reserved.tokens.(reserved) then
    IDENT (Names.find_or_add_hashed lx.names text start stop name_hash)
  else if reserved >= 0 then Reserved.tokens.(reserved)
  else begin
    if chars > max_identifier_length then
      error lx (Printf.sprintf "identifier longer than %d characters (§2.3)"
                  max_identifier_length);
    let name = Names.find_or_add_hashed lx.names text start stop name_hash in
    (* TASK (§2.18) and, in the installed environment, REF (ch. 11) are not reserved
       words but begin constructs of their own: the parser accepts TASK as a name too. *)
    if stop - start = 4 && is_lower_word "task" text start then TASK name
    else if lx.installed && stop - start = 3 && is_lower_word "ref" text start then REF
    else IDENT name
  end

let name lx text start stop chars =
  name_hashed lx text start stop chars ~word_hash:(Reserved.raw_hash text start stop)
    ~name_hash:(Names.hash text start stop)

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
      let s = text_of lx in
      Buffer.add_string raw s;
      Buffer.add_char bytes (Char.chr (int_of_string ("0x" ^ String.sub s 1 2)));
      string_body lx start raw bytes
  | '\\' ->
      (* Reported at the literal's opening quote, like every error of a string literal. *)
      let _, stop = Sedlexing.loc buf in
      error_at lx start stop "a backslash in a string literal is written twice (\\\\) or starts a \
                              character code of two hexadecimal digits (§2.7)"
  | '"' -> ()
  | newline | eof ->
      let stop, _ = Sedlexing.loc buf in
      error_at lx start stop "string literal not closed by '\"' before the end of the line (§2.7)"
  (* A run of plain characters at once: every character the run stops at is one that a rule
     above takes. *)
  | Plus (Compl ('"' | '\\' | '\n' | '\r')) ->
      let s = text_of lx in
      Buffer.add_string raw s; Buffer.add_string bytes s; string_body lx start raw bytes
  | _ -> error lx "illegal character in string literal (§2.7)"

(* The lines of a %%% header block, up to the line that closes it (doc/dialect.md). *)
let rec header_lines lx start acc =
  let buf = lx.buf in
  match%sedlex buf with
  | Star (' ' | '\t'), "%%%", Star (' ' | '\t'), (newline | eof) -> List.rev acc
  | Star (Compl ('\n' | '\r')), newline ->
      let line = text_of lx in
      let line =
        String.sub line 0
          (String.length line
           - (if String.length line >= 2 && String.sub line (String.length line - 2) 2 = "\r\n" then 2 else 1)) in
      header_lines lx start (line :: acc)
  | _ ->
      let stop, _ = Sedlexing.loc buf in
      error_at lx start stop "%%% header block not closed by a line %%%"

(* One token; [lx.token_start] is set to where it begins. *)
let rec token lx =
  let buf = lx.buf in
  match%sedlex buf with
  | Plus white_space -> token lx
  | '!', Star (Compl ('\n' | '\r')) -> COMMENT (text_of ~skip:1 lx)
  | "%%%", Star (' ' | '\t'), newline ->
      let start = Sedlexing.lexeme_start buf in
      lx.token_start <- start;
      if start <> 0 then error lx "a %%% header block may stand only at the start of a file";
      HEADER (header_lines lx start [])
  | num_literal ->
      let text = buf.text and start = buf.start and stop = buf.pos in
      if plainly_in_range text start stop then number lx text start stop
      else begin
        match Num_literal.of_text (String.sub text start (stop - start)) with
        | Ok _ -> number lx text start stop
        | Error message -> error lx message
      end
  (* Listed after [num_literal] so that a match of equal length is a literal: [2E5] is one
     literal, [2E5x] and [12abc] are not separated (§2.2). *)
  | num_literal, (letter | digit | '_') | num_literal, '.', digit ->
      (* [1.2.3], [0x1.5]: a literal touching the next one (§2.2); reported at the first. *)
      error lx "a numeric literal must be separated from a following identifier, reserved \
                word or numeric literal by white space (§2.2)"
  | ident -> name lx buf.text buf.start buf.pos (Sedlexing.lexeme_length buf)
  | placeholder ->
      Hashtbl.find placeholders (String.uppercase_ascii (text_of lx))
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
      let c = Sedlexing.first_char buf in
      if Uchar.to_int c > 0xFF then
        error lx (Printf.sprintf "character %s is not in ISO 8859-1: outside comments and \
                                  string literals a module uses Latin-1 characters only (§2.1)"
                    (describe_char c))
      else error lx (Printf.sprintf "illegal character %s (§2.1)" (describe_char c))
  | _ -> error lx "illegal character (§2.1)"

(* Speed (bench/README.md): the tokens that make up most of a CAD module (white space,
   punctuation, plain decimal literals, ASCII names) are read here directly from the text, and
   everything else by the rules of [token]. Each shortcut takes exactly the lexeme that the
   rules would take (their longest match), or leaves the text untouched for them:
   - a white-space character is skipped as [Plus white_space] skips it;
   - no rule reads more than one character from [ ] ( ) { } , ; + - * / ? | \ ;
   - digits, optionally '.' and digits, followed by a character that cannot continue a
     literal nor make it one run into a name (not a letter, digit, '_' or '.', and ASCII):
     the rules would read the same literal, and [number] gives the same token. Without an
     exponent, a literal of at most 300 characters lies between 10^-300 and 10^300, well
     inside the range that [plainly_in_range] checks;
   - an ASCII letter, then ASCII letters, digits and '_', followed by an ASCII character that
     cannot continue a name: the Latin-1 letters of §2.1 are not ASCII, so a name that runs on
     into one is left to the rules. *)
module Shortcut = struct
  (* Make text.[b.pos..stop-1], all ASCII, the current lexeme, as the rules' [start] would. *)
  let take (b : Sedlexing.lexbuf) stop =
    b.start <- b.pos;
    b.start_char <- b.pos_char;
    b.pos_char <- b.pos_char + (stop - b.pos);
    b.pos <- stop

  (* Inlined: a call for every character of every name and number was a tenth of the lexer. *)
  let is_digit c = c >= '0' && c <= '9' [@@inline]
  let is_name_char c =
    (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || is_digit c || c = '_' [@@inline]

  let rec digits text n i =
    if i < n && is_digit (String.unsafe_get text i) then digits text n (i + 1) else i

  (* Where the plain decimal literal at [i] (a digit) stops, or -1: the rules must decide. *)
  let number text i =
    let n = String.length text in
    let stop = digits text n i in
    let stop =
      if stop < n && String.unsafe_get text stop = '.' then
        let f = digits text n (stop + 1) in
        if f = stop + 1 then -1 else f
      else stop
    in
    if stop < 0 || stop >= n then stop
    else
      let c = String.unsafe_get text stop in
      if is_name_char c || c = '.' || Char.code c >= 0x80 then -1 else stop

  (* Where the ASCII name at [i] (a letter) stops, or -1: the rules must decide. Its hashes for
     the names' table and for the reserved words (Names.hash, Reserved.raw_hash) are computed
     on the way and left in [lx]: one reading of the name instead of three. *)
  let name lx text i =
    let n = String.length text in
    let j = ref i and exact = ref 0 and folded = ref 0 in
    while !j < n && is_name_char (String.unsafe_get text !j) do
      let code = Char.code (String.unsafe_get text !j) in
      exact := Names.mix !exact code;
      folded := Names.mix !folded (Reserved.upper_code code);
      incr j
    done;
    let stop = !j in
    if stop < n && Char.code (String.unsafe_get text stop) >= 0x80 then -1
    else begin
      lx.name_hash <- Names.finish !exact;
      lx.word_hash <- !folded;
      stop
    end
end

let rec shortcut lx =
  let b = lx.buf in
  let text = b.text and p = b.pos in
  if p >= String.length text then token lx
  else
    let single t = Shortcut.take b (p + 1); t in
    match String.unsafe_get text p with
    | ' ' | '\t' | '\012' | '\r' | '\n' ->
        b.pos <- p + 1;
        b.pos_char <- b.pos_char + 1;
        shortcut lx
    | '[' -> single LBRACKET
    | ']' -> single RBRACKET
    | ',' -> single COMMA
    | ';' -> single SEMICOLON
    | '(' -> single LPAREN
    | ')' -> single RPAREN
    | '{' -> single LBRACE
    | '}' -> single RBRACE
    | '+' -> single PLUS
    | '-' -> single MINUS
    | '*' -> single STAR
    | '/' -> single SLASH
    | '?' -> single QUESTION
    | '|' -> single BAR
    | '\\' -> single BACKSLASH
    | '0' .. '9' ->
        let stop = Shortcut.number text p in
        if stop < 0 || (stop - p > 300 && not (plainly_in_range text p stop)) then token lx
        else begin Shortcut.take b stop; number lx text p stop end
    | 'A' .. 'Z' | 'a' .. 'z' ->
        let stop = Shortcut.name lx text p in
        if stop < 0 then token lx
        else begin
          Shortcut.take b stop;
          name_hashed lx text p stop (stop - p) ~word_hash:lx.word_hash ~name_hash:lx.name_hash
        end
    | _ -> token lx

(* The next token; where it starts and stops is left in [token_start] and [token_stop]. *)
let scan lx =
  lx.token_start <- -1;
  let t = shortcut lx in
  lx.token_stop <- Sedlexing.lexeme_end lx.buf;
  if lx.token_start < 0 then lx.token_start <- Sedlexing.lexeme_start lx.buf;
  lx.after_switch <- lx.installed && (match t with IDENT w -> String.lowercase_ascii w = "switch" | _ -> false);
  lx.after_proc <- lx.installed && t = PROC;
  t

(* A token that starts where the previous one stopped shares its position record: in CAD
   aggregates most tokens touch ([[1125.58,-0.7,...]]), and the parser's stack keeps these
   records as long as it keeps the tokens. *)
let start_after lx (previous : Lexing.position) =
  if lx.token_start = previous.pos_cnum then previous else position lx.token_start

let next lx =
  let t = scan lx in
  let startp = start_after lx lx.last_stop in
  let stopp = position lx.token_stop in
  lx.last_stop <- stopp;
  (t, startp, stopp)

(* The same for the parser, which reads the positions from its lexbuf: they are written there,
   the previous stop read back from it, and no triple is made. The lexbuf is old after the
   first minor collection, and each young value stored in it is one more entry of the
   collector's remembered set (bench/README.md, "The parser's token supplier"). *)
let next_into lx (lexbuf : Lexing.lexbuf) =
  let t = scan lx in
  lexbuf.lex_start_p <- start_after lx lexbuf.lex_curr_p;
  lexbuf.lex_curr_p <- position lx.token_stop;
  t
