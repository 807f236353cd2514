(* The comparison of bench/README.md: the grammar of lib/syntax/parser.mly compiled by Menhir's
   table back end (exp_parser, built in this directory with --table) against the code back end
   that lib/syntax uses (--exn-carries-state), on the same lexer.

   Parse needs, of a syntax error, the automaton's state (for parser.messages) and the last
   token. The table back end's incremental API gives the state; with --exn-carries-state the
   code back end's exception Error carries it too. [outcome] keeps exactly what Parse builds
   its diagnostics from, so that equal outcomes mean equal diagnostics. *)

open Rapid_syntax

type outcome =
  | Tree of Ast.module_declaration
  | Syntax_error of int * Parser.token * int * int  (* state, last token, its offsets *)
  | Lexical_error of Source.region * string
  | Refused of Source.region * string              (* by a grammar action *)

(* Both parsers read the same registered [file], so that their trees carry the same regions. *)
let start file decoded =
  Parse_context.start file;
  Lexer.create file decoded

(* As Parse.run_parser drives the table back end (without the options of --strict). *)
let table file decoded =
  let module I = Exp_parser.MenhirInterpreter in
  let lexer = start file decoded in
  let last = ref (Parser.EOF, Lexing.dummy_pos, Lexing.dummy_pos) in
  let rec loop checkpoint =
    match checkpoint with
    | I.InputNeeded _ ->
        let t = Lexer.next lexer in
        last := t;
        loop (I.offer checkpoint t)
    | I.Shifting _ | I.AboutToReduce _ -> loop (I.resume checkpoint)
    | I.HandlingError env ->
        let token, s, e = !last in
        Syntax_error (I.current_state_number env, token, s.pos_cnum, e.pos_cnum)
    | I.Accepted m -> Tree m
    | I.Rejected -> let token, s, e = !last in Syntax_error (-1, token, s.pos_cnum, e.pos_cnum)
  in
  match loop (Exp_parser.Incremental.module_file { Lexing.dummy_pos with pos_cnum = 0 }) with
  | outcome -> outcome
  | exception Lexer.Error (r, m) -> Lexical_error (r, m)
  | exception Parse_context.Refused (r, m) -> Refused (r, m)

(* The code back end reads each token's positions from a lexbuf that it is handed. *)
let code file decoded =
  let lexer = start file decoded in
  let lexbuf = Lexing.from_string "" in
  let last = ref (Parser.EOF, Lexing.dummy_pos, Lexing.dummy_pos) in
  let next _ =
    let (token, s, e) as t = Lexer.next lexer in
    last := t;
    lexbuf.lex_start_p <- s;
    lexbuf.lex_curr_p <- e;
    token
  in
  match Parser.module_file next lexbuf with
  | m -> Tree m
  | exception Parser.Error state ->
      let token, s, e = !last in
      Syntax_error (state, token, s.pos_cnum, e.pos_cnum)
  | exception Lexer.Error (r, m) -> Lexical_error (r, m)
  | exception Parse_context.Refused (r, m) -> Refused (r, m)

(* Structural equality, trees included (the lexer shares strings, so trees are compared by
   their unshared serialization). *)
let same a b =
  match a, b with
  | Tree x, Tree y ->
      Marshal.to_string x [ No_sharing ] = Marshal.to_string y [ No_sharing ]
  | _ -> a = b

let describe = function
  | Tree _ -> "a tree"
  | Syntax_error (state, _, s, e) -> Printf.sprintf "syntax error in state %d at %d-%d" state s e
  | Lexical_error (r, m) | Refused (r, m) -> Printf.sprintf "%s: %s" (Source.to_string r) m
