(* Unit tests of the canonical layout (expected text, literally) and of the dump: two spellings
   of one tree give one dump, two trees give two dumps. *)

open Rapid_syntax
open Ast

let parse text =
  match Parse.parse_string ~name:"printer.mod" text with
  | Ok m -> m
  | Error d -> Alcotest.failf "%S does not parse: %s" text (Diagnostic.to_string d)

let in_routine body = "MODULE m\n  PROC p()\n" ^ body ^ "\n  ENDPROC\nENDMODULE\n"

let only_statement m =
  match m.routine_declarations with
  | [ { it = Procedure_declaration { body = { statements = [ s ]; _ }; _ }; _ } ] -> s
  | _ -> Alcotest.fail "expected one procedure with one statement"

(* The expression of [x := e;]. *)
let parse_expression text =
  match (only_statement (parse (in_routine ("x := " ^ text ^ ";")))).it with
  | Assignment (_, e) -> e
  | _ -> Alcotest.fail "expected an assignment"

let dump text = Ast_dump.module_declaration (parse text)

(* ------------------------------------------------------------------ expressions *)

(* §3.1: the fewest parentheses that give the tree back. Each row: as read, as printed. *)
let expression_rows =
  [ "a+b*c", "a + b * c";
    "(a+b)*c", "(a + b) * c";
    "a-(b-c)", "a - (b - c)";
    "(a-b)-c", "a - b - c";
    "a/(b*c)", "a / (b * c)";
    "a DIV b mod c", "a DIV b MOD c";
    (* a sign heads a <simple expr>: it applies to the whole first term *)
    "-a*b", "-a * b";
    "-(a*b)", "-a * b";
    "(-a)*b", "(-a) * b";
    "-a+b", "-a + b";
    "-(a+b)", "-(a + b)";
    "a*(-b)", "a * (-b)";
    "a+(-b)", "a + (-b)";
    "-(-a)", "-(-a)";
    "+a", "+a";
    "-1", "-1";
    "a < -b", "a < -b";
    "a AND -b", "a AND -b";
    (* NOT heads an <expr>: it applies to the first logical term *)
    "NOT a AND b", "NOT a AND b";
    "NOT (a AND b)", "NOT a AND b";
    "(NOT a) AND b", "(NOT a) AND b";
    "NOT a OR b", "NOT a OR b";
    "NOT (a OR b)", "NOT (a OR b)";
    "a AND (NOT b)", "a AND (NOT b)";
    "a OR (NOT b)", "a OR (NOT b)";
    "NOT (NOT a)", "NOT (NOT a)";
    "NOT -a", "NOT -a";
    "NOT a < b", "NOT a < b";
    (* relations do not chain *)
    "(a<b)=c", "(a < b) = c";
    "a=(b<c)", "a = (b < c)";
    "a+1 <= b*2", "a + 1 <= b * 2";
    "a<>b", "a <> b";
    "a OR b AND c", "a OR b AND c";
    "(a OR b) AND c", "(a OR b) AND c";
    "a XOR (b OR c)", "a XOR (b OR c)";
    "a xor b or c", "a XOR b OR c";
    "((a))", "a";
    (* primaries *)
    "f(-a,\\b:=(c+d),\\e?g, h:=1 , \\i)", "f(-a \\b:=c + d \\e?g, h:=1 \\i)";
    "f()", "f()";
    "[1,[2,3]]", "[1, [2, 3]]";
    "a{i+1,2}.b.c", "a{i + 1, 2}.b.c";
    "[(a+b)*2]", "[(a + b) * 2]";
    "\"x\"\"y\\\\z\\41\"", "\"x\"\"y\\\\z\\41\"";
    "0x1F + 0d12E+3 + .5e-3 + 38. + 0B101 + 0o17", "0x1F + 0d12E+3 + .5e-3 + 38. + 0B101 + 0o17";
    "true AND FaLsE", "TRUE AND FALSE" ]

let expression_layout =
  Alcotest.test_case "§3.1 expressions: minimal parentheses" `Quick (fun () ->
      List.iter (fun (input, expected) ->
          let e = parse_expression input in
          let printed = Printer.expression e in
          Alcotest.(check string) input expected printed;
          (* and the text gives the same tree back *)
          Alcotest.(check string) ("tree of " ^ printed) (Ast_dump.expression e)
            (Ast_dump.expression (parse_expression printed))) expression_rows)

(* Trees built by hand that no parse gives as such: the printer must put the parentheses in. *)
let hand_built_expressions =
  Alcotest.test_case "§3.1 parentheses for trees built by hand" `Quick (fun () ->
      let loc it = { it; at = Source.no_region } in
      let v s = loc (Data_reference (Entire s)) in
      let bin op l r = loc (Binary (op, l, r)) in
      let un op (e : expression) = loc (Unary (op, e.it, e.at)) in
      List.iter (fun (e, expected) -> Alcotest.(check string) expected expected (Printer.expression e))
        [ bin Mul (un Unary_minus (v "a")) (v "b"), "(-a) * b";
          un Unary_minus (bin Plus (v "a") (v "b")), "-(a + b)";
          bin And (v "a") (un Not (v "b")), "a AND (NOT b)";
          bin Less (bin Less (v "a") (v "b")) (v "c"), "(a < b) < c";
          bin Minus (v "a") (un Unary_minus (v "b")), "a - (-b)";
          un Not (un Unary_minus (bin Mul (v "a") (v "b"))), "NOT -a * b";
          bin Or (un Not (v "a")) (bin Xor (v "b") (v "c")), "NOT a OR (b XOR c)" ])

(* ------------------------------------------------------------------ statements *)

let statement_rows =
  [ "x:=1;", "x := 1;\n";
    "a{1}.b := <EXP>;", "a{1}.b := <EXP>;\n";
    "<VAR> := 1;", "<VAR> := 1;\n";
    "Foo;", "Foo;\n";
    "Foo a,b\\c,\\d:=1\\e?f,<ARG>;", "Foo a, b \\c \\d:=1 \\e?f, <ARG>;\n";
    "Foo <ARG>, n:=<EXP> \\o?<VAR>;", "Foo <ARG>, n:=<EXP> \\o?<VAR>;\n";
    "Foo \\a;", "Foo \\a;\n";
    "%\"m:\"+s% 1;", "%\"m:\" + s% 1;\n";
    "goto l;", "GOTO l;\n";
    "l:", "l:\n";
    "<ID>:", "<ID>:\n";
    "return;", "RETURN;\n";
    "return a+1;", "RETURN a + 1;\n";
    "raise;", "RAISE;\n";
    "Raise ERR_X;", "RAISE ERR_X;\n";
    "break; ", "BREAK;\n";
    "connect i with t;", "CONNECT i WITH t;\n";
    "if a b:=1;", "IF a b := 1;\n";
    "IF a <SMT>", "IF a <SMT>\n";
    "<SMT>", "<SMT>\n";
    "! a comment ", "! a comment \n";
    "IF a THEN b; ELSEIF c THEN <EIT> ELSE ENDIF",
    "IF a THEN\n  b;\nELSEIF c THEN\n<EIT>\nELSE\nENDIF\n";
    "FOR i FROM 1 TO 10 STEP 2 DO x; ENDFOR", "FOR i FROM 1 TO 10 STEP 2 DO\n  x;\nENDFOR\n";
    "WHILE NOT a DO WHILE b DO ENDWHILE ENDWHILE",
    "WHILE NOT a DO\n  WHILE b DO\n  ENDWHILE\nENDWHILE\n";
    "TEST a CASE 1,2: x; <CSE> DEFAULT: y; ENDTEST",
    "TEST a\nCASE 1, 2:\n  x;\n<CSE>\nDEFAULT:\n  y;\nENDTEST\n" ]

let statement_layout =
  Alcotest.test_case "§4 statements" `Quick (fun () ->
      List.iter (fun (input, expected) ->
          Alcotest.(check string) input expected
            (Printer.statement (only_statement (parse (in_routine input))))) statement_rows)

(* ------------------------------------------------------------------ modules *)

let messy_module = {|%%%
  VERSION:1
%%%

! made by a generator

module Cell (sysmodule,noview)
record pos2  ! header comment
num x;   ! on x's line
num y;
  ! alone, but on the last line
endrecord
! goes with the alias
local alias num mm;
! a declaration comment
task pers num n:=0;
local var num grid{2,3};
const string s:="a""b";
! between data and routines: a routine comment
local proc Go(num a,var num b{*,*}\switch fast|num slow|<ALT>,<PAR>,inout bool c)
var num i;
! before the first statement: a statement comment
i:=a;
backward
i:=0;
error (1, ERR_X)
retry;
undo
i:=0;
endproc
func num Half(num v) return v/2; endfunc
trap T <DDN> endtrap
<RDN>
! a trailing routine comment
endmodule
|}

let canonical_module = {|%%%
  VERSION:1
%%%
! made by a generator
MODULE Cell(SYSMODULE, NOVIEW)
  RECORD pos2 ! header comment
    num x; ! on x's line
    num y;
    ! alone, but on the last line
  ENDRECORD
  ! goes with the alias
  LOCAL ALIAS num mm;
  ! a declaration comment
  TASK PERS num n := 0;
  LOCAL VAR num grid{2, 3};
  CONST string s := "a""b";
  ! between data and routines: a routine comment
  LOCAL PROC Go(num a, VAR num b{*, *} \switch fast | num slow | <ALT>, <PAR>, INOUT bool c)
    VAR num i;
    ! before the first statement: a statement comment
    i := a;
  BACKWARD
    i := 0;
  ERROR (1, ERR_X)
    RETRY;
  UNDO
    i := 0;
  ENDPROC
  FUNC num Half(num v)
    RETURN v / 2;
  ENDFUNC
  TRAP T
    <DDN>
  ENDTRAP
  <RDN>
  ! a trailing routine comment
ENDMODULE
|}

let module_layout =
  Alcotest.test_case "§9.2 module layout" `Quick (fun () ->
      let printed = Printer.module_declaration (parse messy_module) in
      Alcotest.(check string) "canonical text" canonical_module printed;
      Alcotest.(check string) "same tree" (dump messy_module) (dump printed))

(* §2.10: the first list after the module header that a comment can join is decided by what
   follows it; with no types and no data, a comment before a routine is a routine comment and
   must not come out before anything that would make it a declaration comment. *)
let comment_filing =
  Alcotest.test_case "§2.10 comments come back in their lists" `Quick (fun () ->
      let cases =
        [ "MODULE m\n! c\nPROC p() ENDPROC\nENDMODULE\n",
          "MODULE m\n  ! c\n  PROC p()\n  ENDPROC\nENDMODULE\n";
          "MODULE m\n! t\nALIAS num a;\n! r\nENDMODULE\n",
          "MODULE m\n  ! t\n  ALIAS num a;\n  ! r\nENDMODULE\n";
          "MODULE m\nVAR num a;\n! r\nENDMODULE\n", "MODULE m\n  VAR num a;\n  ! r\nENDMODULE\n";
          "MODULE m\nPROC p()\n! s\nENDPROC\nENDMODULE\n",
          "MODULE m\n  PROC p()\n    ! s\n  ENDPROC\nENDMODULE\n" ]
      in
      List.iter (fun (input, expected) ->
          let printed = Printer.module_declaration (parse input) in
          Alcotest.(check string) input expected printed;
          Alcotest.(check string) ("tree of " ^ input) (dump input) (dump printed)) cases)

(* §2.10, §2.14: a comment that followed a component stays on its line; one after a comment
   can only be the last line. *)
let record_comments =
  Alcotest.test_case "§2.10 record comments" `Quick (fun () ->
      let input = "MODULE m\nRECORD r\nnum a; !one\n!two\nENDRECORD\nENDMODULE\n" in
      let expected = "MODULE m\n  RECORD r\n    num a; !one\n    !two\n  ENDRECORD\nENDMODULE\n" in
      let printed = Printer.module_declaration (parse input) in
      Alcotest.(check string) "layout" expected printed;
      Alcotest.(check string) "tree" (dump input) (dump printed);
      let input = "MODULE m\nRECORD r !first\nnum a; num b; !b\nENDRECORD\nENDMODULE\n" in
      let expected =
        "MODULE m\n  RECORD r !first\n    num a;\n    num b; !b\n  ENDRECORD\nENDMODULE\n"
      in
      let printed = Printer.module_declaration (parse input) in
      Alcotest.(check string) "layout" expected printed;
      Alcotest.(check string) "tree" (dump input) (dump printed))

let empty_header_and_placeholders =
  Alcotest.test_case "§2.9 placeholders, empty header" `Quick (fun () ->
      let input = "%%%\n%%%\nMODULE <ID>\n<TDN>\n<DDN>\nPROC <ID>(<PAR>, \\<ALT>, num <ID>{<DIM>})\n\
                   Foo <ARG>;\nENDPROC\nENDMODULE\n" in
      let expected = "%%%\n%%%\nMODULE <ID>\n  <TDN>\n  <DDN>\n  PROC <ID>(<PAR> \\<ALT>, num <ID>{<DIM>})\n\
                      \    Foo <ARG>;\n  ENDPROC\nENDMODULE\n" in
      let printed = Printer.module_declaration (parse input) in
      Alcotest.(check string) "layout" expected printed;
      Alcotest.(check string) "tree" (dump input) (dump printed))

(* ------------------------------------------------------------------ the dump *)

let expected_dump = {|(Module_declaration
  (module_name m)
  (attributes READONLY)
  (type_definitions
    (Record_definition (local true) (name r)
      (Record_component num a)
      (Component_comment " c \"q\" \\")))
  (data_declarations
    (Data_declaration (scope Task) (storage Var) (data_type num) (name x) (dims (Literal (Num_literal 2))) (initial_value (Aggregate (Literal (Num_literal 1.5E3)) (Unary Unary_minus (Literal (Num_literal 2)))))))
  (routine_declarations
    (Function_declaration (local false) (return_type bool) (name f)
      (parameters
        (Required_parameter (Parameter (mode Inout) (data_type num) (name v) (array (Conformant 2))))
        (Optional_parameter (Alternative (Switch s)) ALT_placeholder))
      (declarations)
      (statements
        (If (Binary And (Data_reference (Component (Element v (Literal (Num_literal 1))) c)) (Literal (String_literal "a\\41")))
          (then_branch
            (Return (Function_call <ID> (arguments (Required_argument (name k) (Literal (Bool_literal true))) (Optional_argument o)))))
          (elseifs
            EIT_placeholder)
          (else_branch))
        (Procedure_call (Procedure_name P) ARG_placeholder (Conditional_argument c VAR_placeholder))
        (Raise EXP_placeholder))
      (error (error_numbers (Error_number_literal 3) (Error_number_name E))
        (handler
          Trynext)))))
|}

let dump_text =
  "MODULE m(READONLY)\nLOCAL RECORD r num a; ! c \"q\" \\\nENDRECORD\n\
   TASK VAR num x{2} := [1.5E3, -2];\n\
   FUNC bool f(INOUT num v{*,*} \\switch s | <ALT>)\n\
   IF v{1}.c AND \"a\\41\" THEN RETURN <ID>(k:=TRUE \\o); <EIT> ELSE ENDIF\n\
   P <ARG> \\c?<VAR>;\nRAISE <EXP>;\nERROR (3, E) TRYNEXT;\nENDFUNC\nENDMODULE\n"

let dump_format =
  Alcotest.test_case "the dump's form" `Quick (fun () ->
      Alcotest.(check string) "dump" expected_dump (dump dump_text))

(* Spellings of one tree: white space and line breaks, letter case of reserved words and
   placeholders, redundant parentheses, the comma before an optional argument, a record
   comment on its own last line or after the last component, the file's encoding. *)
let same_tree_spellings =
  [ "MODULE m\nPROC p()\nx:=a+b*c;\nENDPROC\nENDMODULE\n",
    "module m proc p ( )  x :=\n a +(b*c) ;endproc\r\nEndModule";
    "MODULE m\nPROC p()\nFoo a, \\b;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\nFoo a \\b;\nENDPROC\nENDMODULE\n";
    "MODULE m\nRECORD r\nnum a; ! c\nENDRECORD\nENDMODULE\n",
    "MODULE m\nRECORD r\nnum a;\n! c\nENDRECORD\nENDMODULE\n";
    "MODULE m\nPROC p()\nIF a <smt>\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\nIF a <SMT>\nENDPROC\nENDMODULE\n";
    "MODULE m\nVAR string s := \"\xC3\xA9\";\nENDMODULE\n",
    "MODULE m\nVAR string s := \"\xE9\";\nENDMODULE\n" ]

let same_dumps =
  Alcotest.test_case "one tree, one dump" `Quick (fun () ->
      List.iter (fun (a, b) -> Alcotest.(check string) (a ^ " / " ^ b) (dump a) (dump b))
        same_tree_spellings)

(* Pairs of different trees, each pair differing in one detail. *)
let different_trees =
  [ "x := a - b - c;", "x := a - (b - c);";
    "x := -a * b;", "x := (-a) * b;";
    "x := NOT a AND b;", "x := (NOT a) AND b;";
    "x := a;", "x := A;";
    "x := 1.0;", "x := 1.00;";
    "x := 10;", "x := 0D10;";
    "x := \"A\";", "x := \"\\41\";";
    "x := TRUE;", "x := \"TRUE\";";
    "x := a.b;", "x := a{b};";
    "x := f(a);", "x := f(\\a);";
    "Foo \\a:=b;", "Foo \\a?b;";
    "Foo a:=b;", "Foo \\a:=b;";
    "Foo <ARG>;", "Foo;";
    "x := <EXP>;", "x := EXP_placeholder;";
    "! a", "!a";
    "!a\n!b", "!a\n!b\n!";
    "IF a THEN ENDIF", "IF a THEN ELSE ENDIF";
    "TEST a ENDTEST", "TEST a DEFAULT: ENDTEST";
    "RETURN;", "RETURN <EXP>;";
    "IF a b := 1;", "IF a THEN b := 1; ENDIF";
    "l:", "GOTO l;";
    "x := a + b;", "x := a - b;";
    "x := a < b;", "x := a <= b;";
    "x := a OR b;", "x := a XOR b;";
    "x := a DIV b;", "x := a MOD b;";
    "x := +a;", "x := -a;" ]

let different_dumps =
  Alcotest.test_case "two trees, two dumps" `Quick (fun () ->
      List.iter (fun (a, b) ->
          let da = dump (in_routine a) and db = dump (in_routine b) in
          if da = db then Alcotest.failf "%S and %S give the same dump:\n%s" a b da) different_trees;
      let modules =
        [ "MODULE m\nENDMODULE\n", "%%%\n%%%\nMODULE m\nENDMODULE\n";
          "%%%\n%%%\nMODULE m\nENDMODULE\n", "%%%\n\n%%%\nMODULE m\nENDMODULE\n";
          "MODULE m\nVAR num a;\nENDMODULE\n", "MODULE m\nLOCAL VAR num a;\nENDMODULE\n";
          "MODULE m\nVAR num a;\nENDMODULE\n", "MODULE m\nTASK VAR num a;\nENDMODULE\n";
          "MODULE m\nPROC p(num a)\nENDPROC\nENDMODULE\n",
          "MODULE m\nPROC p(\\num a)\nENDPROC\nENDMODULE\n";
          "MODULE m\nPROC p(switch a)\nENDPROC\nENDMODULE\n",
          "MODULE m\nPROC p(INOUT switch a)\nENDPROC\nENDMODULE\n";
          "MODULE m\nPROC p()\nERROR\nENDPROC\nENDMODULE\n",
          "MODULE m\nPROC p()\nUNDO\nENDPROC\nENDMODULE\n";
          "MODULE m\nPROC p()\nERROR\nENDPROC\nENDMODULE\n",
          "MODULE m\nPROC p()\nERROR (1)\nENDPROC\nENDMODULE\n";
          "MODULE m\n!a\nVAR num x;\nENDMODULE\n", "MODULE m\nVAR num x;\n!a\nENDMODULE\n";
          "MODULE m(SYSMODULE)\nENDMODULE\n", "MODULE m(NOVIEW)\nENDMODULE\n" ]
      in
      List.iter (fun (a, b) ->
          if dump a = dump b then Alcotest.failf "%S and %S give the same dump" a b) modules)

(* Injectivity over many small generated trees: two trees (all regions are no_region, so
   structural equality is equality up to locations) with one dump would show a detail the dump
   leaves out. *)
let dump_injective =
  Alcotest.test_case "different generated trees give different dumps" `Quick (fun () ->
      let st = Random.State.make [| 42 |] in
      let check_family name gen to_dump count =
        let seen = Hashtbl.create count in
        for _ = 1 to count do
          let x = gen st in
          let d = to_dump x in
          match Hashtbl.find_opt seen d with
          | Some y when y <> x -> Alcotest.failf "%s: two trees with the dump %s" name d
          | Some _ -> ()
          | None -> Hashtbl.add seen d x
        done
      in
      check_family "expressions" (fun st -> Gen_ast.expression ~top:true (1 + Random.State.int st 4) st)
        Ast_dump.expression 20_000;
      check_family "modules" (Gen_ast.module_declaration ~max_size:4 ()) Ast_dump.module_declaration 5_000)

let suite =
  ("printer",
   [ expression_layout; hand_built_expressions; statement_layout; module_layout; comment_filing;
     record_comments; empty_header_and_placeholders; dump_format; same_dumps; different_dumps;
     dump_injective ])
