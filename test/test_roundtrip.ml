(* The printer's contract: for every module that parses, printing it and parsing the text gives
   the same tree (same Ast_dump), and printing is idempotent. Checked on generated trees
   (Gen_ast) and on every module under spec/ and examples/ that parses. *)

open Rapid_syntax
open Ast

(* Generated trees may hold the access mode REF, which only the installed environment's
   modules are read with (ch. 11); the generator never makes a name "ref". *)
let parse_text text =
  Parse.parse_string ~options:{ Parse.default_options with installed = true } ~name:"printed.mod" text

(* [Ok ()] or a message that shows what went wrong. *)
let round_trip (m : module_declaration) =
  let dump = Ast_dump.module_declaration m in
  match Printer.module_declaration m with
  | exception e -> Error ("the printer raised " ^ Printexc.to_string e ^ "\n" ^ dump)
  | printed -> (
      match parse_text printed with
      | Error d ->
          Error (Printf.sprintf "the printed module does not parse: %s\n--- printed:\n%s"
                   (Diagnostic.to_string d) printed)
      | Ok m' ->
          let dump' = Ast_dump.module_declaration m' in
          if dump' <> dump then
            Error (Printf.sprintf "the tree changed\n--- printed:\n%s\n--- dump before:\n%s\n\
                                   --- dump after:\n%s" printed dump dump')
          else
            let printed' = Printer.module_declaration m' in
            if printed' <> printed then
              Error (Printf.sprintf "printing is not idempotent\n--- first:\n%s\n--- second:\n%s"
                       printed printed')
            else Ok ())

(* ------------------------------------------------------------------ generated trees *)

let print_module m = Printer.module_declaration m

let generated_round_trip =
  Alcotest.test_case "generated modules: parse (print m) = m" `Slow (fun () ->
      let test =
        QCheck.Test.make ~count:1500 ~name:"print-parse round trip"
          (QCheck.make ~print:print_module (Gen_ast.module_declaration ()))
          (fun m ->
             match round_trip m with
             | Ok () -> true
             | Error message -> QCheck.Test.fail_report message)
      in
      QCheck.Test.check_exn ~rand:(Random.State.make [| 20240611 |]) test)

(* Expressions are where the printer decides most (parentheses, §3.1): larger ones, alone in
   an assignment. *)
let expression_round_trip =
  Alcotest.test_case "generated expressions: parse (print e) = e" `Slow (fun () ->
      let loc it = { it; at = Source.no_region } in
      let in_module e =
        let x = loc (Entire "x") in
        let body = { declarations = []; statements = [ loc (Assignment (x, e)) ]; backward = None;
                     error = None; undo = None } in
        { header = None; prologue_comments = []; module_name = loc (Ident "m"); attributes = []; type_definitions = [];
          data_declarations = [];
          routine_declarations =
            [ loc (Procedure_declaration
                     { local = false; name = loc (Ident "p"); parameters = []; body }) ];
          module_region = Source.no_region }
      in
      let test =
        QCheck.Test.make ~count:2000 ~name:"expression round trip"
          (QCheck.make ~print:Printer.expression
             QCheck.Gen.(int_range 1 40 >>= fun n -> Gen_ast.expression ~top:true n))
          (fun e ->
             match round_trip (in_module e) with
             | Ok () -> true
             | Error message -> QCheck.Test.fail_report message)
      in
      QCheck.Test.check_exn ~rand:(Random.State.make [| 31 |]) test)

(* ------------------------------------------------------------------ constructor census *)

(* Every constructor of Ast, by type. The walk below names what it meets with exhaustive
   matches (no wildcard), so a constructor added to Ast does not compile until it is named
   there; the test then fails until it is listed here and the generator reaches it. *)
let all_constructors =
  [ "identifier", [ "Ident"; "ID_placeholder" ];
    "unary_operator", [ "Unary_plus"; "Unary_minus"; "Not" ];
    "binary_operator",
    [ "Mul"; "Div"; "Int_div"; "Modulo"; "Plus"; "Minus"; "Less"; "Less_equal"; "Equal";
      "Greater"; "Greater_equal"; "Not_equal"; "And"; "Or"; "Xor" ];
    "expression",
    [ "Num_literal"; "String_literal"; "Bool_literal"; "Data_reference"; "Function_call"; "Aggregate"; "Unary"; "Binary";
      "EXP_placeholder" ];
    "data_reference", [ "Entire"; "Element"; "Component"; "VAR_placeholder" ];
    "argument",
    [ "Required_argument"; "Positional_argument"; "Optional_argument"; "Conditional_argument";
      "ARG_placeholder" ];
    "procedure", [ "Procedure_name"; "Late_bound" ];
    "statement",
    [ "Assignment"; "Procedure_call"; "Goto"; "Break"; "Continue"; "Return"; "Raise"; "Exit";
      "Retry"; "Trynext"; "Connect"; "If"; "Compact_if"; "For"; "While"; "Test"; "Label";
      "Statement_comment"; "SMT_placeholder" ];
    "elseif", [ "Elseif"; "EIT_placeholder" ];
    "case", [ "Case"; "CSE_placeholder" ];
    "storage", [ "Var"; "Pers"; "Const" ];
    "declaration_scope", [ "Global"; "Local"; "Task" ];
    "data_declaration", [ "Data_declaration"; "Declaration_comment"; "DDN_placeholder" ];
    "record_component", [ "Record_component"; "Component_comment" ];
    "type_definition",
    [ "Record_definition"; "Alias_definition"; "Type_comment"; "TDN_placeholder" ];
    "access_mode", [ "In"; "Var_mode"; "Pers_mode"; "Inout"; "Ref_mode" ];
    "array_parameter", [ "Not_array"; "Conformant"; "DIM_placeholder" ];
    "parameter_declaration", [ "Parameter"; "Switch" ];
    "alternative", [ "Alternative"; "ALT_placeholder" ];
    "parameter", [ "Required_parameter"; "Optional_parameter"; "PAR_placeholder" ];
    "recovery_error_number", [ "Error_number_literal"; "Error_number_name" ];
    "routine_declaration",
    [ "Procedure_declaration"; "Function_declaration"; "Trap_declaration"; "Routine_comment";
      "RDN_placeholder" ];
    "module_attribute", [ "SYSMODULE"; "NOVIEW"; "NOSTEPIN"; "VIEWONLY"; "READONLY" ] ]

(* [census see m] calls [see type constructor] for every node of [m]. *)
let census see (m : module_declaration) =
  let identifier (i : identifier) =
    match i.it with Ident _ -> see "identifier" "Ident" | ID_placeholder -> see "identifier" "ID_placeholder"
  in
  let unary = function
    | Unary_plus -> "Unary_plus" | Unary_minus -> "Unary_minus" | Not -> "Not"
  in
  let binary = function
    | Mul -> "Mul" | Div -> "Div" | Int_div -> "Int_div" | Modulo -> "Modulo" | Plus -> "Plus"
    | Minus -> "Minus" | Less -> "Less" | Less_equal -> "Less_equal" | Equal -> "Equal"
    | Greater -> "Greater" | Greater_equal -> "Greater_equal" | Not_equal -> "Not_equal"
    | And -> "And" | Or -> "Or" | Xor -> "Xor"
  in
  let rec expression (e : expression) =
    let s = see "expression" in
    match e.it with
    | Num_literal _ -> s "Num_literal"
    | String_literal _ -> s "String_literal"
    | Bool_literal _ -> s "Bool_literal"
    | Data_reference r -> s "Data_reference"; data_reference (Ast.reference e r)
    | Function_call f -> s "Function_call"; identifier f.func; Array.iter argument (call_arguments f)
    | Aggregate (es, rs) -> s "Aggregate"; Array.iter expression (members es rs)
    | Unary (op, e, at) -> s "Unary"; see "unary_operator" (unary op); expression (operand e at)
    | Binary (op, l, r) -> s "Binary"; see "binary_operator" (binary op); expression l; expression r
    | EXP_placeholder -> s "EXP_placeholder"
  and data_reference (r : data_reference) =
    let s = see "data_reference" in
    match r.it with
    | Entire _ -> s "Entire"
    | Element (_, es) -> s "Element"; List.iter expression es
    | Component (r, _) -> s "Component"; data_reference r
    | VAR_placeholder -> s "VAR_placeholder"
  and argument (a : argument) =
    let s = see "argument" in
    match a.it with
    | Required_argument (n, e, at) -> s "Required_argument"; Option.iter identifier n; expression (operand e at)
    | Positional_argument e -> s "Positional_argument"; expression (operand e a.at)
    | Optional_argument (n, e) -> s "Optional_argument"; identifier n; Option.iter expression e
    | Conditional_argument (n, r) -> s "Conditional_argument"; identifier n; data_reference r
    | ARG_placeholder -> s "ARG_placeholder"
  in
  let rec statement (st : statement) =
    let s = see "statement" in
    match st.it with
    | Assignment (r, e) -> s "Assignment"; data_reference r; expression e
    | Procedure_call (p, args, regions) ->
        s "Procedure_call";
        (match p with
         | Procedure_name i -> see "procedure" "Procedure_name"; identifier i
         | Late_bound e -> see "procedure" "Late_bound"; expression e);
        Array.iter argument (Ast.arguments args regions)
    | Goto i -> s "Goto"; identifier i
    | Break -> s "Break"
    | Continue -> s "Continue"
    | Return e -> s "Return"; Option.iter expression e
    | Raise e -> s "Raise"; Option.iter expression e
    | Exit -> s "Exit"
    | Retry -> s "Retry"
    | Trynext -> s "Trynext"
    | Connect (r, i) -> s "Connect"; data_reference r; identifier i
    | If i ->
        s "If"; expression i.condition; statements i.then_branch;
        List.iter (fun (c : elseif_clause) ->
            match c.it with
            | Elseif (e, l) -> see "elseif" "Elseif"; expression e; statements l
            | EIT_placeholder -> see "elseif" "EIT_placeholder") i.elseifs;
        Option.iter statements i.else_branch
    | Compact_if (e, st) -> s "Compact_if"; expression e; statement st
    | For f ->
        s "For"; identifier f.loop_variable; expression f.from_; expression f.to_;
        Option.iter expression f.step; statements f.body
    | While (e, l) -> s "While"; expression e; statements l
    | Test t ->
        s "Test"; expression t.test_expression;
        List.iter (fun (c : case_clause) ->
            match c.it with
            | Case (vs, l) -> see "case" "Case"; List.iter expression vs; statements l
            | CSE_placeholder -> see "case" "CSE_placeholder") t.cases;
        Option.iter statements t.default
    | Label i -> s "Label"; identifier i
    | Statement_comment _ -> s "Statement_comment"
    | SMT_placeholder -> s "SMT_placeholder"
  and statements l = List.iter statement l in
  let data_declaration (d : data_declaration) =
    let s = see "data_declaration" in
    match d.it with
    | Data_declaration d ->
        s "Data_declaration";
        see "storage" (match d.storage with Var -> "Var" | Pers -> "Pers" | Const -> "Const");
        see "declaration_scope"
          (match d.scope with Global -> "Global" | Local -> "Local" | Task -> "Task");
        identifier d.data_type; identifier d.name; List.iter expression d.dims;
        Option.iter expression d.initial_value
    | Declaration_comment _ -> s "Declaration_comment"
    | DDN_placeholder -> s "DDN_placeholder"
  in
  let type_definition (t : type_definition) =
    let s = see "type_definition" in
    match t.it with
    | Record_definition r ->
        s "Record_definition"; identifier r.name;
        List.iter (fun (c : record_component) ->
            match c.it with
            | Record_component (t, n) -> see "record_component" "Record_component"; identifier t; identifier n
            | Component_comment _ -> see "record_component" "Component_comment") r.components
    | Alias_definition a -> s "Alias_definition"; identifier a.base; identifier a.name
    | Type_comment _ -> s "Type_comment"
    | TDN_placeholder -> s "TDN_placeholder"
  in
  let parameter_declaration (p : parameter_declaration) =
    match p.it with
    | Parameter p ->
        see "parameter_declaration" "Parameter";
        see "access_mode"
          (match p.mode with
           | In -> "In" | Var_mode -> "Var_mode" | Pers_mode -> "Pers_mode" | Inout -> "Inout"
           | Ref_mode -> "Ref_mode");
        see "array_parameter"
          (match p.array with
           | Not_array -> "Not_array" | Conformant _ -> "Conformant" | DIM_placeholder -> "DIM_placeholder");
        identifier p.data_type; identifier p.name
    | Switch n -> see "parameter_declaration" "Switch"; identifier n
  in
  let parameter (p : parameter) =
    let s = see "parameter" in
    match p.it with
    | Required_parameter d -> s "Required_parameter"; parameter_declaration d
    | Optional_parameter alts ->
        s "Optional_parameter";
        List.iter (fun (a : alternative) ->
            match a.it with
            | Alternative d -> see "alternative" "Alternative"; parameter_declaration d
            | ALT_placeholder -> see "alternative" "ALT_placeholder") alts
    | PAR_placeholder -> s "PAR_placeholder"
  in
  let body (b : routine_body) =
    List.iter data_declaration b.declarations;
    statements b.statements;
    Option.iter statements b.backward;
    Option.iter (fun (h : error_handler) ->
        Option.iter (List.iter (fun (n : recovery_error_number) ->
            match n.it with
            | Error_number_literal _ -> see "recovery_error_number" "Error_number_literal"
            | Error_number_name _ -> see "recovery_error_number" "Error_number_name")) h.error_numbers;
        statements h.handler) b.error;
    Option.iter statements b.undo
  in
  let routine (r : routine_declaration) =
    let s = see "routine_declaration" in
    match r.it with
    | Procedure_declaration p ->
        s "Procedure_declaration"; identifier p.name; List.iter parameter p.parameters; body p.body
    | Function_declaration f ->
        s "Function_declaration"; identifier f.return_type; identifier f.name;
        List.iter parameter f.parameters; body f.body
    | Trap_declaration t -> s "Trap_declaration"; identifier t.name; body t.body
    | Routine_comment _ -> s "Routine_comment"
    | RDN_placeholder -> s "RDN_placeholder"
  in
  identifier m.module_name;
  List.iter (fun (a : module_attribute) ->
      see "module_attribute"
        (match a.it with
         | SYSMODULE -> "SYSMODULE" | NOVIEW -> "NOVIEW" | NOSTEPIN -> "NOSTEPIN"
         | VIEWONLY -> "VIEWONLY" | READONLY -> "READONLY")) m.attributes;
  List.iter type_definition m.type_definitions;
  List.iter data_declaration m.data_declarations;
  List.iter routine m.routine_declarations

let constructor_coverage =
  Alcotest.test_case "the generator reaches every constructor of Ast" `Quick (fun () ->
      let seen = Hashtbl.create 128 in
      let see ty c = Hashtbl.replace seen (ty, c) () in
      let st = Random.State.make [| 7 |] in
      for _ = 1 to 2000 do census see (Gen_ast.module_declaration () st) done;
      let missing =
        List.concat_map (fun (ty, cs) ->
            List.filter_map (fun c -> if Hashtbl.mem seen (ty, c) then None else Some (ty ^ "." ^ c)) cs)
          all_constructors
      in
      let unlisted =
        Hashtbl.fold (fun (ty, c) () acc ->
            match List.assoc_opt ty all_constructors with
            | Some cs when List.mem c cs -> acc
            | _ -> (ty ^ "." ^ c) :: acc) seen []
      in
      Alcotest.(check (list string)) "constructors never generated" [] missing;
      Alcotest.(check (list string)) "constructors met but not listed" [] (List.sort compare unlisted))

(* The census itself must notice what it is asked to: a module built by hand with known
   constructors. *)
let census_sees =
  Alcotest.test_case "the census names the constructors of a parsed module" `Quick (fun () ->
      match Parse.parse_string ~name:"census.mod"
              "MODULE m\n  PROC p(\\switch s)\n    x := -a;\n  ENDPROC\nENDMODULE\n" with
      | Error d -> Alcotest.fail (Diagnostic.to_string d)
      | Ok m ->
          let seen = ref [] in
          census (fun ty c -> seen := (ty ^ "." ^ c) :: !seen) m;
          List.iter (fun c ->
              Alcotest.(check bool) c true (List.mem c !seen))
            [ "parameter.Optional_parameter"; "alternative.Alternative";
              "parameter_declaration.Switch"; "statement.Assignment"; "unary_operator.Unary_minus";
              "routine_declaration.Procedure_declaration" ];
          Alcotest.(check bool) "no If" false (List.mem "statement.If" !seen))

(* ------------------------------------------------------------------ files *)

let mod_files = Corpus.files ~extensions:[ ".mod" ]

let file_round_trips =
  Alcotest.test_case "every parsing module of spec/ and examples/ round-trips" `Quick (fun () ->
      let files = mod_files "../spec" @ mod_files "../examples" in
      Alcotest.(check bool) "examples/ holds modules" true (mod_files "../examples" <> []);
      let parsed = ref 0 in
      List.iter (fun path ->
          match Parse.parse_file path with
          | Error _ -> ()   (* a refusal case *)
          | Ok m ->
              incr parsed;
              (match round_trip m with
               | Ok () -> ()
               | Error message -> Alcotest.failf "%s: %s" path message)) files;
      Alcotest.(check bool) "some module parses" true (!parsed > 0))

(* A long statement list and a deep expression: the printer and the dump must not recurse on
   list length, and must handle the deepest nesting the parser accepts. *)
let large_inputs =
  Alcotest.test_case "a 200000-statement routine and deep nesting round-trip" `Slow (fun () ->
      let b = Buffer.create (1 lsl 22) in
      Buffer.add_string b "MODULE big\n  PROC p()\n";
      for i = 1 to 200_000 do
        Buffer.add_string b (Printf.sprintf "    x{%d} := -x{%d} * 2 + 1;\n" i i)
      done;
      Buffer.add_string b "  ENDPROC\nENDMODULE\n";
      (match parse_text (Buffer.contents b) with
       | Error d -> Alcotest.fail (Diagnostic.to_string d)
       | Ok m -> (match round_trip m with Ok () -> () | Error msg -> Alcotest.fail msg));
      (* 300 nested parentheses around alternating unary minus and NOT: each level needs its
         parentheses back. *)
      let depth = 300 in
      let b = Buffer.create 8192 in
      Buffer.add_string b "MODULE deep\n  PROC p()\n    x := ";
      for i = 1 to depth do Buffer.add_string b (if i mod 2 = 0 then "-(" else "NOT (") done;
      Buffer.add_string b "a";
      for _ = 1 to depth do Buffer.add_string b ")" done;
      Buffer.add_string b ";\n  ENDPROC\nENDMODULE\n";
      match parse_text (Buffer.contents b) with
      | Error d -> Alcotest.fail (Diagnostic.to_string d)
      | Ok m -> (match round_trip m with Ok () -> () | Error msg -> Alcotest.fail msg))

(* A million statements and a million-element aggregate, built directly: printing and dumping
   walk lists without recursion on their length (a parse of that size is left to the bench). *)
let million_elements =
  Alcotest.test_case "a million statements print and dump" `Slow (fun () ->
      let loc it = { it; at = Source.no_region } in
      let n = 1_000_000 in
      let one = loc (Num_literal "1") in
      let statements = List.init n (fun _ -> loc (Assignment (loc (Entire "x"), one))) in
      let statements = loc (Assignment (loc (Entire "y"), loc (Aggregate (Array.make n one.it, Array.make n one.at)))) :: statements in
      let body = { declarations = []; statements; backward = None; error = None; undo = None } in
      let m =
        { header = None; prologue_comments = []; module_name = loc (Ident "m"); attributes = []; type_definitions = [];
          data_declarations = [];
          routine_declarations =
            [ loc (Procedure_declaration { local = false; name = loc (Ident "p"); parameters = []; body }) ];
          module_region = Source.no_region }
      in
      let count_lines s = String.fold_left (fun k c -> if c = '\n' then k + 1 else k) 0 s in
      let printed = Printer.module_declaration m in
      (* MODULE, PROC, the aggregate's assignment, n assignments, ENDPROC, ENDMODULE *)
      Alcotest.(check int) "printed lines" (n + 5) (count_lines printed);
      let dump = Ast_dump.module_declaration m in
      Alcotest.(check bool) "dump holds every statement" true (count_lines dump > n))

let suite =
  ("roundtrip",
   [ census_sees; constructor_coverage; generated_round_trip; expression_round_trip;
     file_round_trips; large_inputs; million_elements ])
