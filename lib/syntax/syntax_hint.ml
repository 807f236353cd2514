(* Hints for syntax errors: what the programmer most likely meant, found from the tokens around
   the error. The message of the automaton's error state (parser.messages) says what the grammar
   expected at the error token; the common mistakes are only visible a little further back (an
   IF without THEN is refused at its ENDIF, several lines later) or in the shape of the
   statement (a procedure called with parentheses). The tokens are read again from the start
   of the file, which costs a second lexing of the text only when a file is refused. *)

open Parser

type token_at = { token : Parser.token; start : int; stop : int }  (* character offsets *)

(* The compound constructs whose end words chapter 10 pairs with their openers. *)
type opener = {
  word : string;          (* IF, WHILE, FOR, TEST, PROC, FUNC, TRAP, RECORD, MODULE *)
  closer : string;        (* ENDIF, ... *)
  section : string;
  at : int;               (* index of the opening token *)
}

let opener_of index = function
  | IF -> Some { word = "IF"; closer = "ENDIF"; section = "4.16"; at = index }
  | WHILE -> Some { word = "WHILE"; closer = "ENDWHILE"; section = "4.19"; at = index }
  | FOR -> Some { word = "FOR"; closer = "ENDFOR"; section = "4.18"; at = index }
  | TEST -> Some { word = "TEST"; closer = "ENDTEST"; section = "4.20"; at = index }
  | PROC -> Some { word = "PROC"; closer = "ENDPROC"; section = "5.4"; at = index }
  | FUNC -> Some { word = "FUNC"; closer = "ENDFUNC"; section = "5.5"; at = index }
  | TRAP -> Some { word = "TRAP"; closer = "ENDTRAP"; section = "5.6"; at = index }
  | RECORD -> Some { word = "RECORD"; closer = "ENDRECORD"; section = "2.14"; at = index }
  | MODULE -> Some { word = "MODULE"; closer = "ENDMODULE"; section = "9.2"; at = index }
  | _ -> None

let closer_word = function
  | ENDIF -> Some "ENDIF" | ENDWHILE -> Some "ENDWHILE" | ENDFOR -> Some "ENDFOR"
  | ENDTEST -> Some "ENDTEST" | ENDPROC -> Some "ENDPROC" | ENDFUNC -> Some "ENDFUNC"
  | ENDTRAP -> Some "ENDTRAP" | ENDRECORD -> Some "ENDRECORD" | ENDMODULE -> Some "ENDMODULE"
  | _ -> None

(* The word after the condition of an IF (§4.16), WHILE (§4.19) or the bounds of a FOR
   (§4.18). *)
let header_word = function "IF" -> Some "THEN" | "WHILE" | "FOR" -> Some "DO" | _ -> None

let is_header_end word (t : Parser.token) =
  match word, t with
  | "THEN", THEN | "DO", DO -> true
  | _ -> false

type context = {
  file : Source.file;
  text : string;              (* the decoded text, UTF-8 *)
  tokens : token_at array;    (* from the start of the file, past the error where they lex *)
  error : int;                (* index of the error token *)
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
let describe cx (o : opener) =
  let name_after i =
    if i < Array.length cx.tokens then
      match cx.tokens.(i).token with IDENT s | TASK s -> " " ^ s | _ -> ""
    else ""
  in
  let name = match o.word with
    | "PROC" | "TRAP" | "RECORD" | "MODULE" -> name_after (o.at + 1)
    | "FUNC" -> name_after (o.at + 2)
    | _ -> ""
  in
  Printf.sprintf "the %s%s at line %d" o.word name (line_of cx o.at)

(* Where the header of the IF, WHILE or FOR at [i] ends: the index of its THEN or DO, of the
   ';' that ends a compact IF (§4.17), or [None] when neither comes before [limit]. *)
let header_end cx word i limit =
  let rec go j =
    if j >= limit then None
    else match cx.tokens.(j).token with
      | SEMICOLON -> Some (`Compact j)
      | t when is_header_end word t -> Some (`Block j)
      | _ -> go (j + 1)
  in
  go (i + 1)

(* The compound statements and declarations open before the error, innermost first, and the
   last compact IF (an IF whose statement ended without THEN). *)
let scan cx =
  let stack = ref [] and compact = ref None in
  let i = ref 0 in
  while !i < cx.error do
    let t = cx.tokens.(!i).token in
    (match opener_of !i t with
     | Some o -> (
         match header_word o.word with
         | Some w -> (
             match header_end cx w !i cx.error with
             | Some (`Compact _) when o.word = "IF" -> compact := Some o
             | Some (`Block _) | None -> stack := o :: !stack
             | Some (`Compact _) -> stack := o :: !stack)
         | None -> stack := o :: !stack)
     | None -> (
         match closer_word t with
         | Some w -> (
             match !stack with
             | o :: rest when o.closer = w -> stack := rest
             | _ -> ())
         | None -> ()));
    incr i
  done;
  (!stack, !compact)

let no_then cx (o : opener) =
  Printf.sprintf "%s has no THEN after its condition (at %s), so it was read as a compact IF \
                  (§4.17), which takes one simple statement and no ENDIF: write THEN after the \
                  condition (§4.16)"
    (describe cx o) (pos_string cx cx.tokens.(o.at + 1).start)

(* A FOR whose FROM and TO came before the error: what is missing is its DO (or STEP). *)
let range_complete cx at =
  let seen t = let rec go j = j < cx.error && (cx.tokens.(j).token = t || go (j + 1)) in go at in
  seen FROM && seen TO

(* An IF, WHILE or FOR whose header is still open at the error: its THEN or DO is missing. *)
let missing_header_word cx stack =
  match stack with
  | (o : opener) :: _ -> (
      match header_word o.word with
      | Some w when header_end cx w o.at cx.error = None && o.at < cx.error - 1
                    && (o.word <> "FOR" || range_complete cx o.at) ->
          let wrong = match cx.tokens.(cx.error).token with
            | THEN when w = "DO" -> Some "THEN" | DO when w = "THEN" -> Some "DO" | _ -> None in
          (match wrong with
           | Some found ->
               Some (Printf.sprintf "%s takes %s after its %s, not %s (§%s)" (describe cx o) w
                       (if o.word = "FOR" then "range" else "condition") found o.section)
           | None ->
               Some (Printf.sprintf "%s has no %s after its %s (§%s)"
                       (describe cx o) w
                       (if o.word = "FOR" then "range" else "condition") o.section))
      | _ -> None)
  | [] -> None

(* §4.16: "ELSE IF" inside the open IF [o] opened a nested IF, whose ENDIF closed it; the
   outer one is then left without its ENDIF. *)
let else_if cx (o : opener) =
  if o.word <> "IF" then None
  else
    let rec go j =
      if j + 1 >= cx.error then None
      else if cx.tokens.(j).token = ELSE && cx.tokens.(j + 1).token = IF then
        Some (Printf.sprintf "%s is not closed: the ELSE IF at line %d opened a new IF, closed by \
                              the first ENDIF; write ELSEIF for another condition of the same IF \
                              (§4.16)" (describe cx o) (line_of cx j))
      else go (j + 1)
    in
    go (o.at + 1)

(* The hint for an end word, a routine or the end of the file met while constructs are open. *)
let unclosed cx stack compact =
  let t = cx.tokens.(cx.error).token in
  let innermost = match stack with o :: _ -> Some o | [] -> None in
  let recent_compact = match compact, innermost with
    | Some (c : opener), Some o -> if c.at > o.at then Some c else None
    | Some c, None -> Some c
    | None, _ -> None
  in
  match closer_word t, t with
  | Some "ENDIF", _ when (match innermost with Some o -> o.word <> "IF" | None -> true)
                         && recent_compact <> None ->
      Option.map (no_then cx) recent_compact
  | Some w, _ -> (
      match innermost with
      | Some o when o.closer <> w && else_if cx o <> None -> else_if cx o
      | Some o when o.closer <> w ->
          if List.exists (fun (p : opener) -> p.closer = w) stack then
            Some (Printf.sprintf "%s is not closed: %s is missing before this %s (§%s)"
                    (describe cx o) o.closer w o.section)
          else
            Some (Printf.sprintf "%s closes no open construct here; %s is closed by %s (§%s)"
                    w (describe cx o) o.closer o.section)
      | _ -> None)
  | None, (ELSE | ELSEIF) when (match innermost with Some o -> o.word <> "IF" | None -> true)
                               && recent_compact <> None ->
      Option.map (no_then cx) recent_compact
  | None, (PROC | FUNC | TRAP | EOF | LOCAL) -> (
      match innermost with
      | Some o when o.word <> "MODULE" || t = EOF ->
          Some (Printf.sprintf "%s is not closed: %s is missing (§%s)"
                  (describe cx o) o.closer o.section)
      | _ -> None)
  | _ -> None

(* Tokens that end the statement before a new one: the IDENT at [j] begins a statement. *)
let begins_statement cx j =
  j = 0
  || (match cx.tokens.(j - 1).token with
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
    let stack, compact = scan cx in
    first_some [
      (fun () -> double_equal cx);
      (fun () -> operator_words cx);
      (fun () -> equals_for_assignment cx);
      (fun () -> unclosed cx stack compact);
      (fun () -> missing_header_word cx stack);
      (fun () -> procedure_with_parentheses cx);
      (fun () -> missing_semicolon cx);
    ]

(* The tokens past the error that the hints look at: the rest of the statement. *)
let lookahead = 64

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

let hint file (decoded : Decode.t) ~installed ~error_start =
  let lexer = Lexer.create ~installed file decoded in
  let tokens = ref [] and error = ref (-1) and count = ref 0 in
  (try
     let continue = ref true in
     while !continue do
       let token, (s : Lexing.position), (e : Lexing.position) = Lexer.next lexer in
       let t = { token; start = s.pos_cnum; stop = e.pos_cnum } in
       if !error < 0 && t.start >= error_start then error := !count;
       tokens := t :: !tokens;
       incr count;
       if token = EOF || (!error >= 0 && !count > !error + lookahead) then continue := false
     done
   with Lexer.Error _ -> ());
  let tokens = Array.of_list (List.rev !tokens) in
  match find { file; text = decoded.text; tokens; error = !error } with
  | h -> h
  | exception (Not_found | Invalid_argument _) -> None
