let file = ref (Source.register ~name:"<none>" ~line_starts:[| 0 |])

let strict = ref false

exception Refused of Source.region * string

(* One [Num_literal] node per short spelling and parse: 9E+09, 0, 1 and the like stand for a
   good part of a CAD module's literals (bench/README.md), and the node holds no region (its
   [located] record does), so all occurrences can share it. Only spellings the lexer interns
   (at most 5 characters) are looked up: longer ones seldom repeat. Each parse starts with
   fresh tables ([start]), so that trees of different parses share nothing; the last parse's
   tables stay alive until the next one starts (a node per distinct spelling). *)
(* The tables are looked up once for every name and short number of the text: the generic
   Hashtbl hashed each key in C and compared keys with the polymorphic comparison, some 280
   instructions a lookup (bench/README.md, "Fuzzing, fourth round"). *)
module Spelling = Hashtbl.Make (struct
    type t = string
    let equal = String.equal
    (* FNV-1a, as the lexer's names (Lexer.Names) *)
    let hash s =
      let h = ref 0 in
      for i = 0 to String.length s - 1 do h := (!h lxor Char.code (String.unsafe_get s i)) * 0x100000001B3 done;
      (!h lxor (!h lsr 31)) land max_int
  end)

let num_literals : Ast.expression_desc Spelling.t ref = ref (Spelling.create 1)

(* The same for [Ident] nodes: a CAD module calls MoveL, MoveJ and SetDO, and names WObj, tens
   of thousands of times. Every spelling is looked up: the lexer already keeps one copy of each
   (up to its limit), so the table adds a node per distinct name, not per occurrence. *)
let idents : Ast.identifier_desc Spelling.t ref = ref (Spelling.create 1)

(* The node [make spelling] kept in [table], made on the first occurrence of [spelling]. *)
let shared table make spelling =
  match Spelling.find_opt !table spelling with
  | Some node -> node
  | None ->
      let node = make spelling in
      Spelling.add !table spelling node;
      node

let ident spelling = shared idents (fun s -> Ast.Ident s) spelling

let num_literal text =
  if String.length text > 5 then Ast.Num_literal text
  else shared num_literals (fun t -> Ast.Num_literal t) text

(* And for an entire variable read in an expression, [Data_reference (Entire name)]: the two
   nodes hold no region since the expression's record holds it (ast.ml), and tool0, wobj0, v500
   and z50 are most of the arguments of a CAD module's motions. *)
let entire_references : Ast.expression_desc Spelling.t ref = ref (Spelling.create 1)

let entire_reference spelling =
  shared entire_references (fun s -> Ast.Data_reference (Entire s)) spelling

let start f =
  file := f;
  num_literals := Spelling.create 256;
  idents := Spelling.create 256;
  entire_references := Spelling.create 256
