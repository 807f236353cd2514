(* Hints for syntax errors: what the programmer most likely meant, found from the tokens around
   the error. The message of the automaton's error state (parser.messages) says what the grammar
   expected at the error token; the common mistakes are only visible a little further back (an
   IF without THEN is refused at its ENDIF, several lines later) or in the shape of the
   statement (a procedure called with parentheses). The tokens are read again from the start
   of the file, which costs a second lexing of the text only when a file is refused. *)

open Parser

type token_at = { token : Parser.token; start : int; stop : int }  (* character offsets *)

(* The tokens past the error that the hints look at: the rest of the statement. *)
let lookahead = 64

(* The compound constructs whose end words chapter 10 pairs with their openers, as the scan
   met them: all it later needs is kept here, so that only a window of tokens is kept. *)
type opener = {
  word : string;          (* IF, WHILE, FOR, TEST, PROC, FUNC, TRAP, RECORD, MODULE *)
  closer : string;        (* ENDIF, ... *)
  section : string;
  line : int;
  order : int;            (* the opening token's number in the file *)
  mutable name : string;  (* of a routine, record or module, once read *)
  mutable name_in : int;  (* tokens until the name: 1 after PROC, 2 after FUNC; 0 none *)
  mutable condition_at : int;   (* offset of the token after the opener, -1 before it *)
  mutable header_open : bool;   (* IF, WHILE, FOR: THEN or DO not met yet *)
  mutable range_words : int;    (* FOR: FROM and TO met *)
  mutable else_if_line : int;   (* IF: line of an ELSE IF inside it, 0 none *)
}

let opener_of = function
  | IF -> Some ("IF", "ENDIF", "4.16", 0)
  | WHILE -> Some ("WHILE", "ENDWHILE", "4.19", 0)
  | FOR -> Some ("FOR", "ENDFOR", "4.18", 0)
  | TEST -> Some ("TEST", "ENDTEST", "4.20", 0)
  | PROC -> Some ("PROC", "ENDPROC", "5.4", 1)
  | FUNC -> Some ("FUNC", "ENDFUNC", "5.5", 2)
  | TRAP -> Some ("TRAP", "ENDTRAP", "5.6", 1)
  | RECORD -> Some ("RECORD", "ENDRECORD", "2.14", 1)
  | MODULE -> Some ("MODULE", "ENDMODULE", "9.2", 1)
  | _ -> None

let closer_word = function
  | ENDIF -> Some "ENDIF" | ENDWHILE -> Some "ENDWHILE" | ENDFOR -> Some "ENDFOR"
  | ENDTEST -> Some "ENDTEST" | ENDPROC -> Some "ENDPROC" | ENDFUNC -> Some "ENDFUNC"
  | ENDTRAP -> Some "ENDTRAP" | ENDRECORD -> Some "ENDRECORD" | ENDMODULE -> Some "ENDMODULE"
  | _ -> None

(* The word after the condition of an IF (§4.16), WHILE (§4.19) or the bounds of a FOR
   (§4.18). *)
let header_word = function "IF" -> Some "THEN" | "WHILE" | "FOR" -> Some "DO" | _ -> None

(* The compound statements and declarations open before the error, innermost first, and the
   last compact IF (an IF whose statement ended with ';' before any THEN), read token by token
   from the start of the file. *)
type scanner = {
  file : Source.file;
  mutable stack : opener list;
  mutable compact : opener option;
  mutable previous : Parser.token;
  mutable count : int;
}

let new_scanner file = { file; stack = []; compact = None; previous = EOF; count = 0 }

let step sc (t : Parser.token) start =
  let line () = (Source.pos_of_offset sc.file start).line in
  (* What the innermost opener learns from the token after it. *)
  (match sc.stack with
   | o :: rest ->
       if o.condition_at < 0 then o.condition_at <- start;
       if o.name_in > 0 then begin
         o.name_in <- o.name_in - 1;
         if o.name_in = 0 then
           (match t with IDENT s | TASK s -> o.name <- s | _ -> ())
       end;
       if o.header_open then begin
         match o.word, t with
         | "IF", THEN | ("WHILE" | "FOR"), DO -> o.header_open <- false
         | "IF", SEMICOLON -> sc.stack <- rest; sc.compact <- Some o
         | "FOR", (FROM | TO) -> o.range_words <- o.range_words + 1
         | _ -> ()
       end
   | [] -> ());
  (match opener_of t with
   | Some (word, closer, section, name_in) ->
       let o = { word; closer; section; line = line (); order = sc.count; name = "";
                 name_in; condition_at = -1; header_open = header_word word <> None;
                 range_words = 0; else_if_line = 0 } in
       (match t, sc.previous, sc.stack with
        | IF, ELSE, (p :: _) when p.word = "IF" && p.else_if_line = 0 -> p.else_if_line <- o.line
        | _ -> ());
       sc.stack <- o :: sc.stack
   | None -> (
       match closer_word t, sc.stack with
       | Some w, o :: rest when o.closer = w -> sc.stack <- rest
       | _ -> ()));
  sc.previous <- t;
  sc.count <- sc.count + 1

type context = {
  file : Source.file;
  text : string;              (* the decoded text, UTF-8 *)
  tokens : token_at array;    (* a window: the tokens before the error, the error's, a few after *)
  error : int;                (* index of the error token in [tokens] *)
  from_start : bool;          (* the window begins at the file's first token *)
  stack : opener list;
  compact : opener option;
}

let line_of cx i = (Source.pos_of_offset cx.file cx.tokens.(i).start).line
let pos_string cx offset =
  let p = Source.pos_of_offset cx.file offset in
  Printf.sprintf "%d:%d" p.line p.col

(* The text between two character offsets. *)
let slice cx start stop =
  let n = String.length cx.text in
  let byte_of char_offset =
    let b = ref 0 and c = ref 0 in
    while !c < char_offset && !b < n do
      let byte = Char.code cx.text.[!b] in
      b := !b + (if byte < 0x80 then 1 else if byte < 0xE0 then 2 else if byte < 0xF0 then 3 else 4);
      incr c
    done;
    min !b n
  in
  let a = byte_of start and b = byte_of stop in
  if b > a then String.sub cx.text a (b - a) else ""

let token_text cx i = slice cx cx.tokens.(i).start cx.tokens.(i).stop

(* An opener's description: "the IF at line 4", "the PROC main at line 2". *)
let describe (o : opener) =
  Printf.sprintf "the %s%s at line %d" o.word (if o.name = "" then "" else " " ^ o.name) o.line

let no_then cx (o : opener) =
  Printf.sprintf "%s has no THEN after its condition%s, so it was read as a compact IF \
                  (§4.17), which takes one simple statement and no ENDIF: write THEN after the \
                  condition (§4.16)"
    (describe o) (if o.condition_at < 0 then "" else " (at " ^ pos_string cx o.condition_at ^ ")")

(* An IF, WHILE or FOR whose header is still open at the error: its THEN or DO is missing (for
   a FOR, once its FROM and TO came). *)
let missing_header_word cx stack =
  match stack with
  | (o : opener) :: _ -> (
      match header_word o.word with
      | Some w when o.header_open && o.condition_at >= 0
                    && o.condition_at < cx.tokens.(cx.error).start
                    && (o.word <> "FOR" || o.range_words >= 2) ->
          let wrong = match cx.tokens.(cx.error).token with
            | THEN when w = "DO" -> Some "THEN" | DO when w = "THEN" -> Some "DO" | _ -> None in
          (match wrong with
           | Some found ->
               Some (Printf.sprintf "%s takes %s after its %s, not %s (§%s)" (describe o) w
                       (if o.word = "FOR" then "range" else "condition") found o.section)
           | None ->
               Some (Printf.sprintf "%s has no %s after its %s (§%s)"
                       (describe o) w
                       (if o.word = "FOR" then "range" else "condition") o.section))
      | _ -> None)
  | [] -> None

(* §4.16: "ELSE IF" inside the open IF [o] opened a nested IF, whose ENDIF closed it; the
   outer one is then left without its ENDIF. *)
let else_if (o : opener) =
  if o.word <> "IF" || o.else_if_line = 0 then None
  else
    Some (Printf.sprintf "%s is not closed: the ELSE IF at line %d opened a new IF, closed by \
                          the first ENDIF; write ELSEIF for another condition of the same IF \
                          (§4.16)" (describe o) o.else_if_line)

(* The hint for an end word, a routine or the end of the file met while constructs are open. *)
let unclosed cx stack compact =
  let t = cx.tokens.(cx.error).token in
  let innermost = match stack with o :: _ -> Some o | [] -> None in
  let recent_compact = match compact, innermost with
    | Some (c : opener), Some o -> if c.order > o.order then Some c else None
    | Some c, None -> Some c
    | None, _ -> None
  in
  match closer_word t, t with
  | Some "ENDIF", _ when (match innermost with Some o -> o.word <> "IF" | None -> true)
                         && recent_compact <> None ->
      Option.map (no_then cx) recent_compact
  | Some w, _ -> (
      match innermost with
      | Some o when o.closer <> w && else_if o <> None -> else_if o
      | Some o when o.closer <> w ->
          if List.exists (fun (p : opener) -> p.closer = w) stack then
            Some (Printf.sprintf "%s is not closed: %s is missing before this %s (§%s)"
                    (describe o) o.closer w o.section)
          else
            Some (Printf.sprintf "%s closes no open construct here; %s is closed by %s (§%s)"
                    w (describe o) o.closer o.section)
      | _ -> None)
  | None, (ELSE | ELSEIF) when (match innermost with Some o -> o.word <> "IF" | None -> true)
                               && recent_compact <> None ->
      Option.map (no_then cx) recent_compact
  | None, (PROC | FUNC | TRAP | EOF | LOCAL) -> (
      match innermost with
      | Some o when o.word <> "MODULE" || t = EOF ->
          Some (Printf.sprintf "%s is not closed: %s is missing (§%s)"
                  (describe o) o.closer o.section)
      | _ -> None)
  | _ -> None

(* Tokens that end the statement before a new one: the IDENT at [j] begins a statement. *)
let begins_statement cx j =
  (j = 0 && cx.from_start)
  || j > 0 && (match cx.tokens.(j - 1).token with
      | SEMICOLON | THEN | ELSE | DO | COMMENT _ | COLON -> true
      | RPAREN ->
          (* the closing parenthesis of a routine's parameter list *)
          let rec back k depth =
            if k < 0 then false
            else match cx.tokens.(k).token with
              | SEMICOLON -> false
              | RPAREN -> back (k - 1) (depth + 1)
              | LPAREN when depth = 1 ->
                  k >= 2 && (match cx.tokens.(k - 2).token with PROC -> true | _ -> false)
                  || k >= 3 && (match cx.tokens.(k - 3).token with FUNC -> true | _ -> false)
              | LPAREN -> back (k - 1) (depth - 1)
              | _ -> back (k - 1) depth
          in
          back (j - 1) 0
      | _ -> false)

(* §4.6: a procedure called with its arguments in parentheses, "greet("Bob", 2);". The
   statement began with a name and '(', and the error lies inside or just after them. *)
let procedure_with_parentheses cx =
  let rec find j =
    if j < 0 then None
    else match cx.tokens.(j).token with
      | SEMICOLON | ASSIGN -> None
      | LPAREN when j >= 1
                    && (match cx.tokens.(j - 1).token with IDENT _ -> true | _ -> false)
                    && begins_statement cx (j - 1) -> Some (j - 1)
      | _ -> find (j - 1)
  in
  match find (cx.error - 1) with
  | None -> None
  | Some name ->
      (* The matching ')' and the ';' after it, where the text has them. *)
      let n = Array.length cx.tokens in
      let rec close k depth =
        if k >= n then None
        else match cx.tokens.(k).token with
          | LPAREN -> close (k + 1) (depth + 1)
          | RPAREN when depth = 1 -> Some k
          | RPAREN -> close (k + 1) (depth - 1)
          | SEMICOLON | EOF -> None
          | _ -> close (k + 1) depth
      in
      let proc = token_text cx name in
      let example =
        match close (name + 1) 0 with
        | Some r when r + 1 < n && cx.tokens.(r + 1).token = SEMICOLON ->
            let inside = String.trim (slice cx cx.tokens.(name + 1).stop cx.tokens.(r).start) in
            let original = slice cx cx.tokens.(name).start cx.tokens.(r + 1).stop in
            Printf.sprintf ": write %s%s; instead of %s" proc
              (if inside = "" then "" else " " ^ inside) original
        | _ -> Printf.sprintf ": write %s arg1, arg2; instead of %s(arg1, arg2);" proc proc
      in
      Some (Printf.sprintf "a procedure call takes its arguments without parentheses (§4.6)%s"
              example)

(* §3.1: RAPID compares with one '='. *)
let double_equal cx =
  let k = cx.error in
  if k >= 1 && cx.tokens.(k).token = EQ && cx.tokens.(k - 1).token = EQ
     && cx.tokens.(k - 1).stop = cx.tokens.(k).start
  then Some "RAPID compares with a single '=' (§3.1): write a = b, not a == b; an assignment \
             is written ':=' (§4.5)"
  else if k + 1 < Array.length cx.tokens && cx.tokens.(k).token = EQ
          && cx.tokens.(k + 1).token = EQ && begins_statement cx (max 0 (k - 1)) then
    Some "an assignment is written ':=' (§4.5); RAPID compares with a single '=' (§3.1)"
  else None

(* §4.5: "x = 1;" for an assignment. *)
let equals_for_assignment cx =
  let k = cx.error in
  if k >= 1 && cx.tokens.(k).token = EQ
     && (match cx.tokens.(k - 1).token with IDENT _ | RBRACE -> true | _ -> false)
  then
    (* The statement's first token, when the target is a plain name. *)
    match cx.tokens.(k - 1).token with
    | IDENT _ when begins_statement cx (k - 1) -> Some "an assignment is written ':=' (§4.5)"
    | _ -> None
  else None

(* Tokens that may end an expression, and so a statement that lacks its ';'. *)
let ends_expression = function
  | IDENT _ | TASK _ | NUM _ | STRING _ | TRUE | FALSE | RPAREN | RBRACKET | RBRACE -> true
  | _ -> false

(* Tokens that begin a statement, a declaration or an end word at the start of a line. *)
let begins_line_item = function
  | IDENT _ | TASK _ | IF | WHILE | FOR | TEST | RETURN | RAISE | EXIT | RETRY | TRYNEXT | GOTO
  | BREAK | CONTINUE | CONNECT | VAR | PERS | CONST | LOCAL | ENDIF | ENDWHILE | ENDFOR | ENDTEST
  | ENDPROC | ENDFUNC | ENDTRAP | ELSE | ELSEIF | CASE | DEFAULT | ERROR | UNDO | BACKWARD
  | ENDRECORD | ENDMODULE | PROC | FUNC | TRAP | PERCENT -> true
  | _ -> false

(* The first token of the line the token [i] stands on. *)
let first_of_line cx i =
  let line = line_of cx i in
  let rec back j = if j > 0 && line_of cx (j - 1) = line then back (j - 1) else j in
  back i

(* Tokens that begin a simple statement or a declaration, which end with ';'. *)
let begins_simple_item = function
  | IDENT _ | TASK _ | GOTO | RETURN | RAISE | VAR | PERS | CONST | LOCAL | ALIAS | CONNECT
  | PERCENT -> true
  | _ -> false

(* §4.3, §2.18: a statement or declaration whose ';' is missing is refused at the next line's
   first token (or at a comment on its line). The line that lacks it must begin like a simple
   statement or a declaration: a header line (IF ... THEN, CASE 1:, PROC p()) ends otherwise. *)
let missing_semicolon cx =
  let k = cx.error in
  if k < 1 || not (begins_simple_item cx.tokens.(first_of_line cx (k - 1)).token) then None
  else
    let prev = cx.tokens.(k - 1) and t = cx.tokens.(k) in
    let next_line = line_of cx k > (Source.pos_of_offset cx.file prev.stop).line in
    match t.token with
    | COMMENT _ when ends_expression prev.token && not next_line ->
        Some (Printf.sprintf "';' is missing before the comment on line %d: a simple statement \
                              and a declaration end with ';' (§4.3, §2.18)" (line_of cx k))
    | tok when ends_expression prev.token && next_line && begins_line_item tok ->
        Some (Printf.sprintf "';' is missing at the end of line %d: a simple statement and a \
                              declaration end with ';' (§4.3, §2.18)"
                (Source.pos_of_offset cx.file prev.stop).line)
    | _ -> None

(* §2.4: reserved words that begin or end a statement, a declaration or a routine, which a
   slip of the fingers turns into an identifier (ENDFI, ELSIF, WHLIE): the parser then reads a
   procedure call, and stops a little later. *)
let structure_words = [
  "IF"; "THEN"; "ELSEIF"; "ELSE"; "ENDIF"; "WHILE"; "ENDWHILE"; "FOR"; "ENDFOR"; "TEST"; "CASE";
  "DEFAULT"; "ENDTEST"; "RETURN"; "RAISE"; "RETRY"; "TRYNEXT"; "GOTO"; "CONNECT"; "BREAK";
  "CONTINUE"; "ENDPROC"; "ENDFUNC"; "ENDTRAP"; "ENDRECORD"; "ENDMODULE"; "LOCAL"; "CONST";
  "PERS"; "PROC"; "FUNC"; "TRAP"; "RECORD"; "ALIAS"; "BACKWARD"; "UNDO" ]

(* Spellings of other languages. *)
let other_spellings = [ ("ELSIF", "ELSEIF"); ("ELIF", "ELSEIF"); ("ELSE_IF", "ELSEIF");
                        ("END_IF", "ENDIF"); ("WEND", "ENDWHILE"); ("END_WHILE", "ENDWHILE");
                        ("END_FOR", "ENDFOR"); ("NEXT", "ENDFOR"); ("END_PROC", "ENDPROC");
                        ("ENDSUB", "ENDPROC") ]

let misspelt_word cx =
  let k = cx.error in
  let candidate i =
    if i < 0 || i > k then None
    else
      let followed_by_use =
        i + 1 < Array.length cx.tokens
        && (match cx.tokens.(i + 1).token with
            | ASSIGN | LBRACE | DOT | COLON -> true | _ -> false) in
      match cx.tokens.(i).token with
      | IDENT s when not followed_by_use -> (
          let upper = String.uppercase_ascii s in
          match List.assoc_opt upper other_spellings with
          | Some w -> Some (s, [ w ])
          | None ->
              if String.length s < 4 then None
              else
                match Suggest.closest s structure_words with
                | [] -> None
                | ws when List.for_all (fun w -> Suggest.distance s w <= 1
                                                 || String.length s > 6) ws -> Some (s, ws)
                | _ -> None)
      | _ -> None
  in
  let here = first_of_line cx k in
  let before = if k >= 1 then first_of_line cx (k - 1) else -1 in
  match (match candidate here with Some c -> Some c | None -> candidate before) with
  | Some (s, ws) ->
      Some (Printf.sprintf "%s is not a reserved word of RAPID (§2.4): did you mean %s?" s
              (String.concat " or " ws))
  | None -> None

(* §3.1: the logical operators are words. *)
let operator_words cx =
  let k = cx.error in
  match cx.tokens.(k).token with
  | BAR when k + 1 < Array.length cx.tokens && cx.tokens.(k + 1).token = BAR ->
      Some "'or' is written OR (§3.1)"
  | COMMENT c when String.length c > 0 && c.[0] = '=' ->
      Some "'!' begins a comment (§2.10): 'not equal' is written <> (§3.1)"
  | _ -> None

let first_some fs = List.fold_left (fun acc f -> match acc with Some _ -> acc | None -> f ()) None fs

let find cx =
  if cx.error < 0 || cx.error >= Array.length cx.tokens then None
  else
    first_some [
      (fun () -> double_equal cx);
      (fun () -> operator_words cx);
      (fun () -> equals_for_assignment cx);
      (fun () -> misspelt_word cx);
      (fun () -> unclosed cx cx.stack cx.compact);
      (fun () -> missing_header_word cx cx.stack);
      (fun () -> procedure_with_parentheses cx);
      (fun () -> missing_semicolon cx);
    ]


(* Lexical errors: characters other languages use where RAPID has a word or another delimiter. *)
let lexical_hint message =
  let mentions c =
    let needle = Printf.sprintf "illegal character '%c'" c in
    let n = String.length needle and m = String.length message in
    let rec go i = i + n <= m && (String.sub message i n = needle || go (i + 1)) in
    go 0
  in
  if mentions '\'' then Some "a string literal is written between double quotes: \"text\" (§2.7)"
  else if mentions '&' then Some "'and' is written AND (§3.1); strings are joined with + (§3.12)"
  else if mentions '#' then Some "a comment begins with '!' (§2.10)"
  else None

(* The tokens before the error that the local hints look back at: a statement's worth. *)
let window = 512

(* What the arrays of tokens are made with before they are filled: an array of hundreds made
   from a fresh element forces a minor collection (the runtime's caml_make_vect), and a hint is
   sought for every syntax error a fuzzer's mutants meet. *)
let no_token = { token = EOF; start = 0; stop = 0 }

let hint file (decoded : Decode.t) ~installed ~robotware ~error_start =
  let lexer = Lexer.create ~installed ~robotware file decoded in
  let sc = new_scanner file in
  (* The last [window] tokens before the error, in a ring. *)
  let ring = Array.make window no_token in
  let before = ref 0 in
  let after = ref [] and error = ref None in
  (try
     let continue = ref true in
     while !continue do
       let token, (s : Lexing.position), (e : Lexing.position) = Lexer.next lexer in
       let t = { token; start = s.pos_cnum; stop = e.pos_cnum } in
       match !error with
       | None when t.start < error_start && token <> EOF ->
           step sc token t.start;
           ring.(!before mod window) <- t;
           incr before
       | None -> error := Some t; if token = EOF then continue := false
       | Some _ ->
           after := t :: !after;
           if token = EOF || List.length !after >= lookahead then continue := false
     done
   with Lexer.Error _ -> ());
  match !error with
  | None -> None
  | Some e ->
      let kept = min !before window in
      let first = !before - kept in
      let after = Array.of_list (List.rev !after) in
      let tokens = Array.make (kept + 1 + Array.length after) no_token in
      for i = 0 to kept - 1 do tokens.(i) <- ring.((first + i) mod window) done;
      tokens.(kept) <- e;
      Array.blit after 0 tokens (kept + 1) (Array.length after);
      let cx = { file; text = decoded.text; tokens; error = kept; from_start = first = 0;
                 stack = sc.stack; compact = sc.compact } in
      match find cx with
      | h -> h
      | exception (Not_found | Invalid_argument _) -> None
