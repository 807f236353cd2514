(* Unit tests of the grammar's decisions that show in the tree (chapter 10 and the sections it
   cites): precedence, comment filing, arguments, switch, TASK, <ID>, error number lists, and
   where syntax errors are reported. *)

open Rapid_syntax
open Ast

let file_name = "parse.mod"

let parse ?(strict = false) text =
  Parse.parse_string ~options:{ Parse.default_options with strict } ~name:file_name text

let in_module body = "MODULE m\n" ^ body ^ "\nENDMODULE\n"
let in_routine body = in_module ("PROC p()\n" ^ body ^ "\nENDPROC")

let parse_ok text =
  match parse text with
  | Ok m -> m
  | Error d -> Alcotest.failf "%S: unexpected error %s" text (Diagnostic.to_string d)

let error_at ?strict ?message ~cls ~line ~col text =
  match parse ?strict text with
  | Ok _ -> Alcotest.failf "%S: accepted, expected a %s" text (Diagnostic.class_name cls)
  | Error d ->
      let where = Diagnostic.to_string d in
      let p = Source.start d.region in
      Alcotest.(check string) ("class of " ^ where) (Diagnostic.class_name cls)
        (Diagnostic.class_name d.error_class);
      Alcotest.(check (pair int int)) ("line, column of " ^ where) (line, col) (p.line, p.col);
      Option.iter (fun m -> Alcotest.(check string) ("message of " ^ where) m d.message) message

let syntax_error_at = error_at ~cls:Syntax_error

let routine_body (m : module_declaration) =
  match m.routine_declarations with
  | [ { it = Procedure_declaration { body; _ } | Function_declaration { body; _ }
             | Trap_declaration { body; _ }; _ } ] -> body
  | _ -> Alcotest.fail "expected one routine"

let statements m = (routine_body m).statements

(* ---------------------------------------------------------------- a compact view of trees *)

let identifier (i : identifier) = match i.it with Ident s -> s | ID_placeholder -> "<ID>"

let binary_name = function
  | Mul -> "*" | Div -> "/" | Int_div -> "DIV" | Modulo -> "MOD" | Plus -> "+" | Minus -> "-"
  | Less -> "<" | Less_equal -> "<=" | Equal -> "=" | Greater -> ">" | Greater_equal -> ">="
  | Not_equal -> "<>" | And -> "AND" | Or -> "OR" | Xor -> "XOR"

let rec shape (e : expression) =
  match e.it with
  | Num_literal s -> s
  | String_literal s -> "\"" ^ s.raw ^ "\""
  | Bool_literal b -> if b then "TRUE" else "FALSE"
  | Data_reference r -> reference (Ast.reference e r)
  | Function_call f -> identifier f.func ^ "(" ^ args (call_arguments f) ^ ")"
  | Aggregate (es, rs) -> "[" ^ String.concat "," (Array.to_list (Array.map shape (members es rs))) ^ "]"
  | Unary (Unary_minus, e, at) -> "(neg " ^ shape (operand e at) ^ ")"
  | Unary (Unary_plus, e, at) -> "(pos " ^ shape (operand e at) ^ ")"
  | Unary (Not, e, at) -> "(NOT " ^ shape (operand e at) ^ ")"
  | Binary (op, l, r) -> Printf.sprintf "(%s %s %s)" (binary_name op) (shape l) (shape r)
  | EXP_placeholder -> "<EXP>"

and reference (r : data_reference) =
  match r.it with
  | Entire n -> n
  | Element (n, es) -> n.it ^ "{" ^ String.concat "," (List.map shape es) ^ "}"
  | Component (r, n) -> reference r ^ "." ^ n.it
  | VAR_placeholder -> "<VAR>"

and args l =
  String.concat "," (List.map (fun (a : argument) ->
      match a.it with
      | Required_argument (None, e, at) -> shape (operand e at)
      | Positional_argument e -> shape (operand e a.at)
      | Required_argument (Some n, e, at) -> identifier n ^ ":=" ^ shape (operand e at)
      | Optional_argument (n, None) -> "\\" ^ identifier n
      | Optional_argument (n, Some e) -> "\\" ^ identifier n ^ ":=" ^ shape e
      | Conditional_argument (n, r) -> "\\" ^ identifier n ^ "?" ^ reference r
      | ARG_placeholder -> "<ARG>") (Array.to_list l))

let expression text =
  match statements (parse_ok (in_routine ("x := " ^ text ^ ";"))) with
  | [ { it = Assignment (_, e); _ } ] -> e
  | _ -> Alcotest.failf "%s: expected one assignment" text

let check_expression text expected =
  Alcotest.(check string) text expected (shape (expression text))

(* The statement kinds of a list, comments with their text. *)
let kind (s : statement) =
  match s.it with
  | Statement_comment c -> "!" ^ c
  | Assignment _ -> "assignment"
  | Procedure_call (Procedure_name n, a, rs) -> identifier n ^ "(" ^ args (Ast.arguments a rs) ^ ")"
  | Procedure_call (Late_bound e, a, rs) -> "%" ^ shape e ^ "%(" ^ args (Ast.arguments a rs) ^ ")"
  | Label i -> identifier i ^ ":"
  | Goto i -> "GOTO " ^ identifier i
  | Connect (r, t) -> "CONNECT " ^ reference r ^ " WITH " ^ identifier t
  | If _ -> "IF" | Compact_if _ -> "compact IF" | For f -> "FOR " ^ identifier f.loop_variable
  | While _ -> "WHILE" | Test _ -> "TEST" | Return _ -> "RETURN" | Raise _ -> "RAISE"
  | Retry -> "RETRY" | Trynext -> "TRYNEXT" | Break -> "BREAK" | Continue -> "CONTINUE"
  | Exit -> "EXIT" | SMT_placeholder -> "<SMT>"

let declaration_kind (d : data_declaration) =
  match d.it with
  | Declaration_comment c -> "!" ^ c
  | Data_declaration { name; _ } -> "decl " ^ identifier name
  | DDN_placeholder -> "<DDN>"

let routine_kind (r : routine_declaration) =
  match r.it with
  | Routine_comment c -> "!" ^ c
  | Procedure_declaration { name; _ } | Function_declaration { name; _ }
  | Trap_declaration { name; _ } -> "routine " ^ identifier name
  | RDN_placeholder -> "<RDN>"

let type_kind (t : type_definition) =
  match t.it with
  | Type_comment c -> "!" ^ c
  | Record_definition { name; _ } -> "record " ^ identifier name
  | Alias_definition { name; _ } -> "alias " ^ identifier name
  | TDN_placeholder -> "<TDN>"

let strings = Alcotest.(list string)

(* ---------------------------------------------------------------- §3.1 expressions *)

let precedence () =
  List.iter (fun (text, expected) -> check_expression text expected) [
    ("a+b*c", "(+ a (* b c))");
    ("a*b+c", "(+ (* a b) c)");
    ("a-b-c", "(- (- a b) c)");
    ("a/b/c", "(/ (/ a b) c)");
    ("a * b / c DIV d MOD e", "(MOD (DIV (/ (* a b) c) d) e)");
    (* §3.1: the sign belongs to the <simple expr>, so it covers the whole first term *)
    ("-a*b", "(neg (* a b))");
    ("-a+b", "(+ (neg a) b)");
    ("+a", "(pos a)");
    ("-(a+b)", "(neg (+ a b))");
    ("(a+b)*c", "(* (+ a b) c)");
    (* §3.1: NOT applies to the first <logical term> *)
    ("NOT a AND b", "(NOT (AND a b))");
    ("NOT a OR b", "(OR (NOT a) b)");
    ("NOT (a OR b)", "(NOT (OR a b))");
    ("NOT a = b", "(NOT (= a b))");
    ("a OR b AND c", "(OR a (AND b c))");
    ("a AND b OR c", "(OR (AND a b) c)");
    ("a XOR b OR c", "(OR (XOR a b) c)");
    ("a AND b AND c", "(AND (AND a b) c)");
    ("a < b + c", "(< a (+ b c))");
    ("a + b >= c * d", "(>= (+ a b) (* c d))");
    ("a = b AND c <> d", "(AND (= a b) (<> c d))");
    ("a <= b OR a > b", "(OR (<= a b) (> a b))");
    ("-1 < 2", "(< (neg 1) 2)");
    ("x{i+1, 2}.c.d", "x{(+ i 1),2}.c.d");
    ("[1, [2, -3]]", "[1,[2,(neg 3)]]");
    ("f() + g(a, b:=1 \\c \\d:=2, \\e?h.k)", "(+ f() g(a,b:=1,\\c,\\d:=2,\\e?h.k))");
  ]

let refused_expressions () =
  (* "x := " puts the expression at column 6 of line 3. *)
  List.iter (fun (text, col) -> syntax_error_at ~line:3 ~col (in_routine ("x := " ^ text ^ ";")))
    [ ("a < b = c", 12);       (* §3.1: a <relation> has at most one <relop> *)
      ("a < b < c", 12);
      ("a AND NOT b", 12);     (* NOT only before the first logical term *)
      ("NOT NOT a", 10);
      ("a * -b", 10);          (* the sign only before the first term *)
      ("a + -b", 10);
      ("- -a", 8);
      ("a OR", 10);
      ("(a", 8);
      ("a)", 7);
      ("[]", 7);               (* §3.10: an aggregate has at least one element *)
      ("x.1", 7) ]            (* .1 is a numeric literal (§2.5) *)

(* ---------------------------------------------------------------- §2.10 comment filing *)

let comment_filing () =
  (* In a routine: a comment after the last data declaration belongs to the statement list. *)
  let body = routine_body (parse_ok (in_routine
      "! before decl\nVAR num a;\n! between decls\nVAR num b;\n! after decls 1\n! after decls 2\n\
       a := 1;\n! between statements\nb := 2;\n! at the end")) in
  Alcotest.check strings "declarations"
    [ "! before decl"; "decl a"; "! between decls"; "decl b" ]
    (List.map declaration_kind body.declarations);
  Alcotest.check strings "statements"
    [ "! after decls 1"; "! after decls 2"; "assignment"; "! between statements"; "assignment";
      "! at the end" ]
    (List.map kind body.statements);
  (* No declarations: every comment is a statement. *)
  let body = routine_body (parse_ok (in_routine "! a\n! b")) in
  Alcotest.check strings "comments only" [ "! a"; "! b" ] (List.map kind body.statements);
  Alcotest.(check int) "no declarations" 0 (List.length body.declarations);
  (* In a module: a comment after the last data declaration belongs to the routine list, a
     comment before a type definition to the type list. *)
  let m = parse_ok (in_module
      "! t1\nRECORD r\n  num c;\nENDRECORD\n! t2\nALIAS num n;\n! d1\nVAR num a;\n! d2\n\
       VAR num b;\n! r1\n! r2\nPROC p()\nENDPROC\n! r3\nPROC q()\nENDPROC\n! r4") in
  Alcotest.check strings "type definitions" [ "! t1"; "record r"; "! t2"; "alias n" ]
    (List.map type_kind m.type_definitions);
  Alcotest.check strings "data declarations" [ "! d1"; "decl a"; "! d2"; "decl b" ]
    (List.map declaration_kind m.data_declarations);
  Alcotest.check strings "routine declarations"
    [ "! r1"; "! r2"; "routine p"; "! r3"; "routine q"; "! r4" ]
    (List.map routine_kind m.routine_declarations);
  (* Without data declarations, comments between the types and the routines go to the routines. *)
  let m = parse_ok (in_module "ALIAS num n;\n! c\nPROC p()\nENDPROC") in
  Alcotest.check strings "types then routines" [ "! c"; "routine p" ]
    (List.map routine_kind m.routine_declarations);
  (* A comment that nothing follows in a module goes to the routine list. *)
  let m = parse_ok (in_module "VAR num a;\n! c") in
  Alcotest.check strings "trailing module comment" [ "! c" ]
    (List.map routine_kind m.routine_declarations);
  Alcotest.check strings "only comments" [ "! c" ]
    (List.map routine_kind (parse_ok (in_module "! c")).routine_declarations)

let record_comments () =
  (* §2.10: in RECORD..ENDRECORD a comment may follow a component on its line, or stand
     alone on the last line. *)
  let m = parse_ok (in_module
      "RECORD my_rec ! after the name\n  num mynum; ! allowed comment (not separate line)\n\
       \  string mystring;\n  ! allowed comment on last line\nENDRECORD") in
  (match m.type_definitions with
   | [ { it = Record_definition { components; _ }; _ } ] ->
       Alcotest.check strings "components"
         [ "! after the name"; "num mynum"; "! allowed comment (not separate line)";
           "string mystring"; "! allowed comment on last line" ]
         (List.map (fun (c : record_component) -> match c.it with
              | Component_comment c -> "!" ^ c
              | Record_component (t, n) -> identifier t ^ " " ^ identifier n) components)
   | _ -> Alcotest.fail "one record");
  let message = "a comment may not stand on a line of its own inside RECORD ... ENDRECORD, \
                 except on the last line (§2.10)" in
  syntax_error_at ~strict:true ~message ~line:3 ~col:3
    (in_module "RECORD my_rec\n  ! DISALLOWED COMMENT\n  num mynum;\nENDRECORD");
  syntax_error_at ~strict:true ~message ~line:4 ~col:3
    (in_module "RECORD r\n  num a; ! fine\n  ! alone\n  ! last\nENDRECORD");
  (* Without --strict, comment lines of their own are the dialect's (doc/dialect.md), kept in
     order among the components. *)
  (match (parse_ok (in_module "RECORD r\n  ! the speed,\n  ! in mm/s\n  num a; ! fine\n  ! alone\n  num b;\nENDRECORD")).type_definitions with
   | [ { it = Record_definition { components; _ }; _ } ] ->
       Alcotest.check strings "components in order"
         [ "! the speed,"; "! in mm/s"; "num a"; "! fine"; "! alone"; "num b" ]
         (List.map (fun (c : record_component) -> match c.it with
              | Component_comment c -> "!" ^ c
              | Record_component (t, n) -> identifier t ^ " " ^ identifier n) components)
   | _ -> Alcotest.fail "one record");
  (* The missing component is reported where it was due: at ENDRECORD. *)
  syntax_error_at ~line:4 ~col:1
    ~message:"expected a record component: a record definition has at least one (§2.14); found ENDRECORD"
    (in_module "RECORD r ! c\n  ! only\nENDRECORD")

(* ---------------------------------------------------------------- §3.11, §4.6 arguments *)

let call text =
  match statements (parse_ok (in_routine text)) with
  | [ s ] -> kind s
  | _ -> Alcotest.failf "%s: expected one statement" text

let arguments () =
  List.iter (fun (text, expected) -> Alcotest.(check string) text expected (call text)) [
    (* §4.6: the comma before an optional or conditional argument may be left out *)
    ("MoveL p, v \\V:=1, z;", "MoveL(p,v,\\V:=1,z)");
    ("MoveL p, v, \\V:=1, z;", "MoveL(p,v,\\V:=1,z)");
    ("P x \\s;", "P(x,\\s)");
    ("P x, \\s;", "P(x,\\s)");
    ("P \\s;", "P(\\s)");
    ("P \\a?b;", "P(\\a?b)");
    ("P x \\a?b.c;", "P(x,\\a?b.c)");
    ("P x, \\a?<VAR>;", "P(x,\\a?<VAR>)");
    ("P \\a \\b:=1 \\c?d;", "P(\\a,\\b:=1,\\c?d)");
    ("P n:=1, m:=x+1;", "P(n:=1,m:=(+ x 1))");
    ("P <ARG>, <ARG>;", "P(<ARG>,<ARG>)");
    ("P;", "P()");
    ("% \"proc\" + s % x;", "%(+ \"proc\" s)%(x)");
    ("x := f(a \\b) + f(a, \\b) + f(\\c?d) + f(e:=1);", "assignment") ];
  check_expression "f(a \\b)" "f(a,\\b)";
  check_expression "f(a, \\b)" "f(a,\\b)";
  check_expression "f(\\c?d, e \\f:=1)" "f(\\c?d,e,\\f:=1)";
  check_expression "f(a, b:=c)" "f(a,b:=c)";
  (* A required argument needs its comma. *)
  syntax_error_at ~line:3 ~col:6 (in_routine "P \\a x;");
  syntax_error_at ~line:3 ~col:5 (in_routine "P x y;");
  syntax_error_at ~line:3 ~col:10 (in_routine "x := f(a b);");
  (* <ARG> is for procedure calls only (§2.9, §3.11). *)
  syntax_error_at ~line:3 ~col:8 (in_routine "x := f(<ARG>);")

(* ---------------------------------------------------------------- §5.2 parameters *)

let parameters_of text =
  match (parse_ok (in_module text)).routine_declarations with
  | [ { it = Procedure_declaration { parameters; _ } | Function_declaration { parameters; _ }; _ } ] ->
      parameters
  | _ -> Alcotest.fail "one routine"

let mode_name = function
  | In -> "" | Var_mode -> "VAR " | Pers_mode -> "PERS " | Inout -> "INOUT " | Ref_mode -> "REF "

let declaration_shape (p : parameter_declaration) =
  match p.it with
  | Switch n -> "switch " ^ identifier n
  | Parameter { mode; data_type; name; array } ->
      mode_name mode ^ identifier data_type ^ " " ^ identifier name
      ^ (match array with
         | Not_array -> "" | DIM_placeholder -> "{<DIM>}"
         | Conformant n -> "{" ^ String.concat "," (List.init n (fun _ -> "*")) ^ "}")

let parameter_shape (p : parameter) =
  match p.it with
  | Required_parameter d -> declaration_shape d
  | Optional_parameter alts ->
      "\\" ^ String.concat "|" (List.map (fun (a : alternative) -> match a.it with
          | Alternative d -> declaration_shape d | ALT_placeholder -> "<ALT>") alts)
  | PAR_placeholder -> "<PAR>"

let switch_parameters () =
  Alcotest.check strings "parameters"
    [ "switch s"; "\\switch t"; "\\switch u|num v"; "VAR switch w"; "switch x{*}";
      "switch y"; "INOUT num z{*,*}"; "PERS num a{<DIM>}"; "<PAR>"; "\\<ALT>|num b" ]
    (List.map parameter_shape (parameters_of
       "PROC p(switch s, \\switch t \\switch u | num v, VAR switch w, switch x{*}, SWITCH y, \
        INOUT num z{*,*}, PERS num a{<DIM>}, <PAR> \\<ALT> | num b)\nENDPROC"));
  (* §5.2: an optional parameter may follow without a comma, a required one may not *)
  syntax_error_at ~line:2 ~col:14 (in_module "PROC p(num a num b)\nENDPROC")

(* ---------------------------------------------------------------- §2.18 TASK *)

let scopes text =
  List.map (fun (d : data_declaration) -> match d.it with
      | Data_declaration { scope = Global; _ } -> "global"
      | Data_declaration { scope = Local; _ } -> "local"
      | Data_declaration { scope = Task; _ } -> "task"
      | Declaration_comment _ | DDN_placeholder -> "other")
    (parse_ok (in_module text)).data_declarations

let task () =
  Alcotest.check strings "scopes" [ "task"; "task"; "task"; "local"; "global"; "other" ]
    (scopes "TASK VAR num a;\ntask PERS num b := 1;\nTask VAR num c;\nLOCAL CONST num d := 1;\n\
             CONST num e := 2;\n<DDN>");
  (* At module level only TASK may begin an item with a name: another name is refused where
     it stands. *)
  syntax_error_at ~line:2 ~col:1 (in_module "TASKS VAR num a;");
  syntax_error_at ~line:2 ~col:3 (in_module "  foo PERS num a;");
  (* §2.18: TASK goes with VAR and PERS only. *)
  syntax_error_at ~line:2 ~col:6 (in_module "TASK CONST num a := 1;");
  syntax_error_at ~line:2 ~col:7 (in_module "LOCAL TASK VAR num a;")

(* ---------------------------------------------------------------- §2.3 <ID> *)

let id_placeholder () =
  (* <ID> stands for an <identifier> ... *)
  let m = parse_ok ("MODULE <ID>\nRECORD <ID>\n  <ID> <ID>;\nENDRECORD\nVAR <ID> <ID>{2};\n\
                     PROC <ID>(<ID> <ID>)\n  <ID>:\n  GOTO <ID>;\n  <ID> \\<ID>, <ID>:=1;\n\
                     \  CONNECT i WITH <ID>;\n  FOR <ID> FROM 1 TO 2 DO ENDFOR\n\
                     \  x := <ID>(1);\nENDPROC\nENDMODULE\n") in
  Alcotest.(check string) "module name" "<ID>" (identifier m.module_name);
  Alcotest.check strings "statements"
    [ "<ID>:"; "GOTO <ID>"; "<ID>(\\<ID>,<ID>:=1)"; "CONNECT i WITH <ID>"; "FOR <ID>"; "assignment" ]
    (List.map kind (statements m));
  (match statements m with
   | [ _; _; _; _; _; { it = Assignment (_, e); _ } ] ->
       Alcotest.(check string) "function name" "<ID>(1)" (shape e)
   | _ -> Alcotest.fail "six statements");
  (* ... but not for an <ident>: an entire variable, a component name, a function argument name
     (§3.6, §3.11), an error number (§7.2). *)
  List.iter (fun (text, col) -> syntax_error_at ~line:3 ~col (in_routine text))
    [ ("x := <ID>;", 10);
      ("x := <ID> + 1;", 11);
      ("<ID> := 1;", 6);
      ("x := a.<ID>;", 8);
      ("x := f(<ID>:=1);", 12);
      ("x := f(\\<ID>);", 9) ];
  syntax_error_at ~line:4 ~col:8 (in_routine "x := 1;\nERROR (<ID>)")

(* ---------------------------------------------------------------- §7.2 error number lists *)

let error_numbers text =
  match (routine_body (parse_ok (in_module text))).error with
  | None -> "no handler"
  | Some { error_numbers = None; handler } -> Printf.sprintf "all, %d" (List.length handler)
  | Some { error_numbers = Some l; handler } ->
      String.concat "," (List.map (fun (n : recovery_error_number) -> match n.it with
          | Error_number_literal s -> s | Error_number_name n -> n.it) l)
      ^ Printf.sprintf ", %d" (List.length handler)

let error_lists () =
  List.iter (fun (text, expected) -> Alcotest.(check string) text expected (error_numbers text)) [
    ("PROC p()\nERROR (1, ERR_X, 0x10, err_y) RETRY;\nENDPROC", "1,ERR_X,0x10,err_y, 1");
    ("PROC p()\nERROR RETRY; TRYNEXT;\nENDPROC", "all, 2");
    ("PROC p()\nERROR\nENDPROC", "all, 0");
    ("PROC p()\nx := 1;\nENDPROC", "no handler");
    ("FUNC num f()\nRETURN 1;\nERROR (ERR_DIVZERO) RETURN 0;\nENDFUNC", "ERR_DIVZERO, 1");
    ("TRAP t\nERROR (41)\nUNDO\nENDTRAP", "41, 0") ];
  (* §7.2: <num literal> | <entire constant> | <entire variable> | <entire persistent> *)
  List.iter (fun (text, col) ->
      syntax_error_at ~line:3 ~col (in_module ("PROC p()\n" ^ text ^ "\nENDPROC")))
    [ ("ERROR ()", 8); ("ERROR (x.y)", 9); ("ERROR (-1)", 8); ("ERROR (a{1})", 9);
      ("ERROR (1,)", 10); ("ERROR (1 2)", 10); ("ERROR (\"s\")", 8) ]

(* ---------------------------------------------------------------- diagnostics' positions *)

let error_positions () =
  (* §1.4's example of a syntax error: FROM is missing; the error is at the 5. *)
  syntax_error_at ~line:3 ~col:9 (in_routine "  FOR i 5 TO 10 DO\n  ENDFOR");
  (* A missing ';' is seen at the next token. *)
  syntax_error_at ~line:4 ~col:3 (in_routine "  x := 1\n  y := 2;");
  (* A missing ENDIF is seen at ENDPROC. *)
  syntax_error_at ~line:5 ~col:1 (in_routine "IF a THEN\n  x := 1;");
  (* The end of the file is where the last line ends. *)
  syntax_error_at ~line:3 ~col:1 "MODULE m\nPROC p()\n";
  syntax_error_at ~line:2 ~col:9 "MODULE m\nPROC p()";
  syntax_error_at ~line:1 ~col:1 "";
  syntax_error_at ~line:1 ~col:1 "PROC p()\nENDPROC\n";
  (* Nothing may follow ENDMODULE (§9.2: one module per file). *)
  syntax_error_at ~line:3 ~col:1 "MODULE m\nENDMODULE\nMODULE n\nENDMODULE\n";
  (* Statements before declarations are refused at the declaration (§5.4). *)
  syntax_error_at ~line:4 ~col:1 (in_routine "x := 1;\nVAR num a;")

(* ---------------------------------------------------------------- statements *)

let compound_statements () =
  let one text = match statements (parse_ok (in_routine text)) with
    | [ s ] -> s.it | _ -> Alcotest.failf "%s: one statement" text in
  (match one "IF a x := 1;" with
   | Compact_if ({ it = Data_reference _; _ }, { it = Assignment _; _ }) -> ()
   | _ -> Alcotest.fail "compact IF");
  (match one "IF a <SMT>" with
   | Compact_if (_, { it = SMT_placeholder; _ }) -> () | _ -> Alcotest.fail "compact IF <SMT>");
  (match one "IF a THEN x := 1; ELSEIF b THEN <EIT> ELSE ENDIF" with
   | If { then_branch = [ _ ]; elseifs = [ { it = Elseif (_, []); _ }; { it = EIT_placeholder; _ } ];
          else_branch = Some []; _ } -> ()
   | _ -> Alcotest.fail "IF with ELSEIF and <EIT>");
  (match one "TEST a CASE 1, 2: x := 1; <CSE> DEFAULT: ENDTEST" with
   | Test { cases = [ { it = Case ([ _; _ ], [ _ ]); _ }; { it = CSE_placeholder; _ } ];
            default = Some []; _ } -> ()
   | _ -> Alcotest.fail "TEST");
  (match one "FOR i FROM 10 TO 1 STEP -1 DO ENDFOR" with
   | For { step = Some { it = Unary (Unary_minus, _, _); _ }; body = []; _ } -> ()
   | _ -> Alcotest.fail "FOR STEP");
  (* §4.17: the compact IF takes a simple statement only. *)
  syntax_error_at ~line:3 ~col:6 (in_routine "IF a IF b x := 1;")

(* The tree keeps an argument's region apart from its expression's only where they differ
   (ast.ml, [Positional_argument]): in parentheses the argument's region takes them in. *)
let argument_regions () =
  let columns (r : Source.region) = ((Source.start r).col, (Source.stop r).col) in
  let check_call text ~argument ~expression =
    match statements (parse_ok (in_routine text)) with
    | [ { it = Procedure_call (_, descs, regions); _ } ] -> (
        match Ast.arguments descs regions with
        | [| a |] ->
            Alcotest.(check (pair int int)) (text ^ ": argument") argument (columns a.at);
            (match Ast.argument_value a with
             | Some e -> Alcotest.(check (pair int int)) (text ^ ": expression") expression (columns e.at)
             | None -> Alcotest.failf "%s: no expression" text)
        | _ -> Alcotest.failf "%s: expected one argument" text)
    | _ -> Alcotest.failf "%s: expected one call" text
  in
  check_call "P a + 1;" ~argument:(3, 8) ~expression:(3, 8);
  check_call "P (a + 1);" ~argument:(3, 10) ~expression:(4, 9);
  check_call "P ( a );" ~argument:(3, 8) ~expression:(5, 6);
  check_call "P x := a;" ~argument:(3, 9) ~expression:(8, 9)

(* Hints (Syntax_hint) that depend on what lies far before the error: the open constructs are
   remembered from the start of the file, while only a window of tokens is kept. *)
let hint_of text =
  match parse text with
  | Ok _ -> Alcotest.failf "%S: accepted" text
  | Error d -> d.hint

let distant_hints () =
  let many = String.concat "\n" (List.init 5000 (fun i -> Printf.sprintf "    x{%d} := %d;" i i)) in
  Alcotest.(check (option string)) "an IF opened 5000 statements before"
    (Some "the IF at line 3 is not closed: ENDIF is missing before this ENDPROC (§4.16)")
    (hint_of (in_module ("PROC p()\n  IF a THEN\n" ^ many ^ "\nENDPROC")));
  Alcotest.(check (option string)) "ELSE IF 5000 statements before"
    (Some "the IF at line 3 is not closed: the ELSE IF at line 5 opened a new IF, closed by the \
           first ENDIF; write ELSEIF for another condition of the same IF (§4.16)")
    (hint_of (in_module ("PROC p()\n  IF a THEN\n    x := 1;\n  ELSE IF b THEN\n" ^ many
                         ^ "\n  ENDIF\nENDPROC")));
  Alcotest.(check (option string)) "a routine left open, then another"
    (Some "the FUNC f at line 2 is not closed: ENDFUNC is missing (§5.5)")
    (hint_of (in_module ("FUNC num f()\n" ^ many ^ "\nPROC q()\nENDPROC")));
  Alcotest.(check (option string)) "no hint where no mistake is recognised" None
    (hint_of (in_routine "x := 1 +;"));
  (* a hint needs no more than the tokens of its statement *)
  Alcotest.(check (option string)) "a procedure called with parentheses after 5000 statements"
    (Some "a procedure call takes its arguments without parentheses (§4.6): write greet \"Bob\", \
           2; instead of greet(\"Bob\", 2);")
    (hint_of (in_routine (many ^ "\n    greet(\"Bob\", 2);")))

let suite =
  ( "parser",
    List.map (fun (name, f) -> Alcotest.test_case name `Quick f) [
      ("§3.1 precedence and associativity", precedence);
      ("§3.1 refused expressions", refused_expressions);
      ("§2.10 comment filing", comment_filing);
      ("§2.10 comments in records", record_comments);
      ("§3.11 §4.6 arguments", arguments);
      ("§3.11 §4.6 argument regions", argument_regions);
      ("§5.2 switch and other parameters", switch_parameters);
      ("§2.18 TASK", task);
      ("§2.3 <ID> where <identifier> is", id_placeholder);
      ("§7.2 error number lists", error_lists);
      ("diagnostic positions", error_positions);
      ("§4 compound statements", compound_statements);
      ("hints from far before the error", distant_hints);
    ] )
