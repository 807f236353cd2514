let file = ref (Source.register ~name:"<none>" ~line_starts:[| 0 |])

let strict = ref false

exception Refused of Source.region * string

(* One [Num_literal] node per short spelling and parse: 9E+09, 0, 1 and the like stand for a
   good part of a CAD module's literals (bench/README.md), and the node holds no region (its
   [located] record does), so all occurrences can share it. Only spellings the lexer interns
   (at most 5 characters) are looked up: longer ones seldom repeat. Each parse starts with
   fresh tables ([start]), so that trees of different parses share nothing; the last parse's
   tables stay alive until the next one starts (a node per distinct spelling). *)
let num_literals : (string, Ast.expression_desc) Hashtbl.t ref = ref (Hashtbl.create 1)

(* The same for [Ident] nodes: a CAD module calls MoveL, MoveJ and SetDO, and names WObj, tens
   of thousands of times. Every spelling is looked up: the lexer already keeps one copy of each
   (up to its limit), so the table adds a node per distinct name, not per occurrence. *)
let idents : (string, Ast.identifier_desc) Hashtbl.t ref = ref (Hashtbl.create 1)

(* The node [make spelling] kept in [table], made on the first occurrence of [spelling]. *)
let shared table make spelling =
  match Hashtbl.find_opt !table spelling with
  | Some node -> node
  | None ->
      let node = make spelling in
      Hashtbl.add !table spelling node;
      node

let ident spelling = shared idents (fun s -> Ast.Ident s) spelling

let num_literal text =
  if String.length text > 5 then Ast.Num_literal text
  else shared num_literals (fun t -> Ast.Num_literal t) text

(* And for an entire variable read in an expression, [Data_reference (Entire name)]: the two
   nodes hold no region since the expression's record holds it (ast.ml), and tool0, wobj0, v500
   and z50 are most of the arguments of a CAD module's motions. *)
let entire_references : (string, Ast.expression_desc) Hashtbl.t ref = ref (Hashtbl.create 1)

let entire_reference spelling =
  shared entire_references (fun s -> Ast.Data_reference (Entire s)) spelling

let start f =
  file := f;
  num_literals := Hashtbl.create 256;
  idents := Hashtbl.create 256;
  entire_references := Hashtbl.create 256
