(* The tables of the kernel manual, cell by cell, through the static semantics (issue: "Every
   table of tables.md is data in lib/typing and each cell has a test").

   Each cell is written here again, independently of lib/typing/tables.ml, from the manual
   (../shared/reference/tables.md and the Chinese text beside it). For each cell the test builds
   the RAPID code that exercises exactly that cell, runs the checker, and compares accepted or
   refused (and, where the table gives one, the result type) with the manual. The code of one
   table is one batch: a few modules, one probe per line, every error mapped back to its line,
   so that thousands of cells cost a handful of checker runs. A probe is refused when the
   checker reports an error on its line, and then only by the rules named for it; a line that is
   not a probe must draw no error at all, so that a cell cannot be passed by a mistake in the
   code around it. *)

open Rapid_syntax
module Check = Rapid_typing.Check
module Report = Rapid_typing.Report
module Tables = Rapid_typing.Tables
module Types = Rapid_typing.Types

(* ------------------------------------------------------------------ batches *)

type expect = Accept | Refuse of string list   (* the rules that may refuse it *)

type line = Fixed of string | Probe of { label : string; text : string; expect : expect }

type file = { file_name : string; installed_mode : bool; lines : line list }

let fixed s = Fixed s
let probe label text expect = Probe { label; text; expect }
let accept label text = probe label text Accept
let refuse rules label text = probe label text (Refuse rules)

let user file_name lines = { file_name; installed_mode = false; lines }

(* A module read the way the installed environment is (ch. 11: REF and anytype allowed), and
   checked at the installed level of ch. 13. *)
let installed file_name lines = { file_name; installed_mode = true; lines }

let environment =
  lazy
    (match Rapid_typing.Installed_env.modules () with
     | Ok ms -> ms
     | Error d -> failwith ("installed environment: " ^ Diagnostic.to_string d))

let text_of f =
  String.concat "\n" (List.map (function Fixed s -> s | Probe p -> p.text) f.lines) ^ "\n"

let parse f =
  let options = { Parse.default_options with installed = f.installed_mode } in
  match Parse.parse_string ~options ~name:f.file_name (text_of f) with
  | Ok m -> m
  | Error d -> Alcotest.failf "the test's own module does not parse: %s" (Diagnostic.to_string d)

let place (r : Report.t) =
  let file = match Source.file_of r.region with Some f -> Source.name f | None -> "?" in
  (file, (Source.start r.region).line)

let show (r : Report.t) = Printf.sprintf "[%s] %s" r.rule (Report.to_string r)

let probes files =
  List.concat_map (fun f -> List.filter (function Probe _ -> true | Fixed _ -> false) f.lines) files

(* Runs one batch; returns the probes that disagree with the manual, one message each. *)
let mismatches files =
  let installed_modules = List.map parse (List.filter (fun f -> f.installed_mode) files) in
  let modules = List.map parse (List.filter (fun f -> not f.installed_mode) files) in
  let result =
    Check.check_task ~installed:(Lazy.force environment @ installed_modules) modules in
  let by_line = Hashtbl.create 64 in
  List.iter (fun r -> Hashtbl.add by_line (place r) r) (Check.errors result);
  let claimed = Hashtbl.create 64 in
  let out = ref [] in
  let say fmt = Printf.ksprintf (fun s -> out := s :: !out) fmt in
  List.iter (fun f ->
      List.iteri (fun i l ->
          let key = (f.file_name, i + 1) in
          Hashtbl.replace claimed key ();
          let here = List.rev (Hashtbl.find_all by_line key) in
          let errors = String.concat "; " (List.map show here) in
          match l with
          | Fixed s ->
              if here <> [] then
                say "%s:%d (not a probe) %S draws: %s" f.file_name (i + 1) s errors
          | Probe { label; text; expect } -> (
              match expect, here with
              | Accept, [] -> ()
              | Accept, _ :: _ ->
                  say "%s\n    %s\n    manual: accepted; checker refuses: %s" label text errors
              | Refuse _, [] -> say "%s\n    %s\n    manual: refused; checker accepts" label text
              | Refuse rules, _ :: _ ->
                  if not (List.for_all (fun (r : Report.t) -> List.mem r.rule rules) here) then
                    say "%s\n    %s\n    refused, but not by %s: %s" label text
                      (String.concat " or " rules) errors)) f.lines) files;
  Hashtbl.iter (fun key r ->
      if not (Hashtbl.mem claimed key) then say "an error outside the batch: %s" (show r)) by_line;
  List.rev !out

let check_batch files =
  match mismatches files with
  | [] -> ()
  | l ->
      Alcotest.failf "%d of %d cells disagree with the manual:\n%s" (List.length l)
        (List.length (probes files)) (String.concat "\n" l)

let batch name files = Alcotest.test_case name `Quick (fun () -> check_batch (files ()))

(* ------------------------------------------------------------------ §3.12 operators *)

(* The types of §3.12's operand column, after alias names are replaced by their base (§2.17). *)
type base = Num | Dnum | Bool | String | Pos | Orient | Pose

(* The operand types of the probes: the seven types of the table, the built-in alias errnum
   (§2.15) and two aliases defined in the probing module, of dnum and of pos: note (d) says an
   alias operand gives a result of its base type, and §2.17 that an alias stands for its base. *)
let operand_types =
  [ ("num", Num); ("dnum", Dnum); ("bool", Bool); ("string", String); ("pos", Pos);
    ("orient", Orient); ("pose", Pose); ("errnum", Num); ("dcount", Dnum); ("vector", Pos) ]

let operator_module_types = [ "ALIAS dnum dcount;"; "ALIAS pos vector;" ]

(* §3.12, the manual's tables transcribed (tables.md): operator, left, right, result. The row
   printed "dnum + num" is read "dnum + dnum" as tables.md restores it. *)
let manual_binary =
  [ ("*", Num, Num, Num); ("*", Dnum, Dnum, Dnum); ("*", Num, Pos, Pos); ("*", Pos, Num, Pos);
    ("*", Pos, Pos, Pos); ("*", Orient, Orient, Orient);
    ("/", Num, Num, Num); ("/", Dnum, Dnum, Dnum); ("/", Pos, Num, Pos);
    ("DIV", Num, Num, Num); ("DIV", Dnum, Dnum, Dnum);
    ("MOD", Num, Num, Num); ("MOD", Dnum, Dnum, Dnum);
    ("+", Num, Num, Num); ("+", Dnum, Dnum, Dnum); ("+", Pos, Pos, Pos);
    ("+", String, String, String);
    ("-", Num, Num, Num); ("-", Dnum, Dnum, Dnum); ("-", Pos, Pos, Pos);
    ("<", Num, Num, Bool); ("<", Dnum, Dnum, Bool);
    ("<=", Num, Num, Bool); ("<=", Dnum, Dnum, Bool);
    (">=", Num, Num, Bool); (">=", Dnum, Dnum, Bool);
    (">", Num, Num, Bool); (">", Dnum, Dnum, Bool);
    ("AND", Bool, Bool, Bool); ("XOR", Bool, Bool, Bool); ("OR", Bool, Bool, Bool) ]

(* = and <>: "any value type, both operands of equal type"; all seven types are value types
   (pose: all its components are, §2.16). *)
let equality_operators = [ "="; "<>" ]

let binary_operators =
  [ "*"; "/"; "DIV"; "MOD"; "+"; "-"; "<"; "<="; "="; ">="; ">"; "<>"; "AND"; "XOR"; "OR" ]

let manual_binary_result op l r =
  if List.mem op equality_operators then (if l = r then Some Bool else None)
  else
    List.find_map (fun (o, a, b, res) -> if o = op && a = l && b = r then Some res else None)
      manual_binary

(* §3.12 unary rows: +num +dnum +pos, -num -dnum -pos (result: same), NOT bool. *)
let manual_unary =
  [ ("+", Num, Num); ("+", Dnum, Dnum); ("+", Pos, Pos); ("-", Num, Num); ("-", Dnum, Dnum);
    ("-", Pos, Pos); ("NOT", Bool, Bool) ]

let manual_unary_result op t =
  List.find_map (fun (o, a, res) -> if o = op && a = t then Some res else None) manual_unary

(* Variables of every operand type (v_T) and result variables of every candidate type (r_T). *)
let operator_declarations =
  List.concat_map (fun (t, _) ->
      [ Printf.sprintf "VAR %s v_%s;" t t; Printf.sprintf "VAR %s r_%s;" t t ])
    operand_types

let refused_target op =
  if List.mem op [ "*"; "/"; "DIV"; "MOD"; "+"; "-" ] then "r_num" else "r_bool"

(* A result is checked by assigning it to a variable of every candidate type: exactly those whose
   base is the table's result type accept it. *)
let result_probes label expression result =
  List.map (fun (t, b) ->
      let text = Printf.sprintf "r_%s := %s;" t expression in
      if b = result then accept (label ^ " assigned to " ^ t) text
      else refuse [ "equal-types" ] (label ^ " assigned to " ^ t) text) operand_types

let operator_rule op = if List.mem op equality_operators then "equality-types" else "operator-types"

let in_section section lines =
  List.map (function
      | Probe p -> Probe { p with label = section ^ " " ^ p.label }
      | Fixed _ as l -> l) lines

let routine_module name ?(types = []) ?(declarations = []) ?(routines = []) body =
  user name
    ([ fixed ("MODULE " ^ name) ] @ List.map fixed types @ List.map fixed declarations
     @ routines @ [ fixed "PROC probes()" ] @ body @ [ fixed "ENDPROC"; fixed "ENDMODULE" ])

let binary_matrix () =
  let body =
    List.concat_map (fun op ->
        List.concat_map (fun (lt, lb) ->
            List.concat_map (fun (rt, rb) ->
                let expression = Printf.sprintf "v_%s %s v_%s" lt op rt in
                let label = Printf.sprintf "§3.12 %s %s %s" lt op rt in
                match manual_binary_result op lb rb with
                | Some result -> result_probes label expression result
                | None ->
                    [ refuse [ operator_rule op ] label
                        (Printf.sprintf "%s := %s;" (refused_target op) expression) ])
              operand_types) operand_types) binary_operators
  in
  [ routine_module "ops_binary" ~types:operator_module_types
      ~declarations:operator_declarations body ]

let unary_matrix () =
  let body =
    List.concat_map (fun op ->
        List.concat_map (fun (t, b) ->
            let expression = Printf.sprintf "%s v_%s" op t in
            let label = Printf.sprintf "§3.12 unary %s" expression in
            match manual_unary_result op b with
            | Some result -> result_probes label expression result
            | None ->
                [ refuse [ "operator-types" ] label
                    (Printf.sprintf "%s := %s;" (if op = "NOT" then "r_bool" else "r_num")
                       expression) ])
          operand_types) [ "+"; "-"; "NOT" ]
  in
  [ routine_module "ops_unary" ~types:operator_module_types
      ~declarations:operator_declarations body ]

(* "= and <> are the only operators valid on arrays" (§3.12), and both operands must have equal
   types, which for arrays means the same dimensions (§2.17). errnum{2} is num{2} (§2.15). *)
let array_operators () =
  let declarations =
    [ "VAR num a_num2{2};"; "VAR num b_num2{2};"; "VAR errnum a_err2{2};"; "VAR num a_num3{3};";
      "VAR dnum a_dnum2{2};"; "VAR num a_num22{2,2};"; "VAR num b_num22{2,2};"; "VAR num v_num;";
      "VAR bool r_bool;"; "VAR num r_num;" ]
  in
  let equal_pairs = [ ("a_num2", "b_num2"); ("a_num2", "a_err2"); ("a_num22", "b_num22") ] in
  let unequal_pairs =
    [ ("a_num2", "a_num3"); ("a_num2", "a_dnum2"); ("a_num2", "v_num"); ("v_num", "a_num2");
      ("a_num2", "a_num22") ] in
  let body =
    List.concat_map (fun op ->
        List.concat_map (fun (a, b) ->
            let label = Printf.sprintf "§3.12 arrays %s %s %s" a op b in
            let text = Printf.sprintf "r_bool := %s %s %s;" a op b in
            if List.mem op equality_operators then
              [ accept label text;
                refuse [ "equal-types" ] (label ^ " assigned to num")
                  (Printf.sprintf "r_num := %s %s %s;" a op b) ]
            else [ refuse [ "operator-types" ] label text ]) equal_pairs
        @ List.map (fun (a, b) ->
            refuse [ operator_rule op ] (Printf.sprintf "§3.12 arrays %s %s %s" a op b)
              (Printf.sprintf "r_bool := %s %s %s;" a op b)) unequal_pairs) binary_operators
    @ List.map (fun op ->
        refuse [ "operator-types" ] ("§3.12 arrays: unary " ^ op)
          (Printf.sprintf "r_num := %s a_num2;" op)) [ "+"; "-"; "NOT" ]
  in
  [ routine_module "ops_arrays" ~declarations body ]

(* A numeric literal has no type of its own: it takes dnum from a dnum operand (§2.5, §2.13;
   doc/rulings.md R-2.5-b), and is num otherwise. *)
let literal_operands () =
  let body = in_section "§3.12" [
    accept "1 + dnum is dnum" "r_dnum := 1 + v_dnum;";
    refuse [ "equal-types" ] "1 + dnum is not num" "r_num := 1 + v_dnum;";
    accept "dnum + 1 is dnum" "r_dnum := v_dnum + 1;";
    refuse [ "equal-types" ] "dnum + 1 is not num" "r_num := v_dnum + 1;";
    accept "2 * dnum is dnum" "r_dnum := 2 * v_dnum;";
    accept "dnum / 2 is dnum" "r_dnum := v_dnum / 2;";
    accept "7 - dnum is dnum" "r_dnum := 7 - v_dnum;";
    accept "dnum DIV 2 is dnum" "r_dnum := v_dnum DIV 2;";
    accept "7 MOD dnum is dnum" "r_dnum := 7 MOD v_dnum;";
    refuse [ "equal-types" ] "2 * dnum is not num" "r_num := 2 * v_dnum;";
    accept "1 + dcount (alias of dnum) is dnum" "r_dnum := 1 + v_dcount;";
    accept "1 + num is num" "r_num := 1 + v_num;";
    refuse [ "equal-types" ] "1 + num is not dnum" "r_dnum := 1 + v_num;";
    accept "1 < dnum" "r_bool := 1 < v_dnum;";
    accept "dnum >= 1" "r_bool := v_dnum >= 1;";
    accept "1 = dnum" "r_bool := 1 = v_dnum;";
    accept "dnum <> 1" "r_bool := v_dnum <> 1;";
    accept "2 * pos: the literal is num (num * pos)" "r_pos := 2 * v_pos;";
    accept "pos / 2 (pos / num)" "r_pos := v_pos / 2;";
    refuse [ "operator-types" ] "pos + 1: no pos + num row" "r_pos := v_pos + 1;";
    refuse [ "operator-types" ] "string + 1" "r_string := v_string + 1;";
    refuse [ "operator-types" ] "bool AND 1" "r_bool := v_bool AND 1;";
    refuse [ "equality-types" ] "string = 1" "r_bool := v_string = 1;";
    refuse [ "equality-types" ] "1 = pos" "r_bool := 1 = v_pos;";
  ] in
  [ routine_module "ops_literals" ~types:operator_module_types
      ~declarations:operator_declarations body ]

(* Notes (b) and (c): operands of DIV and MOD represent integers, for dnum integers >= 0; where
   an operand is a constant expression this is known before execution. *)
let div_mod_notes () =
  let declarations =
    operator_declarations
    @ [ "CONST num c_half := 0.5;"; "CONST num c_two := 2;"; "CONST dnum c_minus := -3;";
        "CONST dnum c_three := 3;" ] in
  let body = in_section "§3.12 note" [
    refuse [ "integer-operand" ] "(b) 2.5 DIV 1" "r_num := 2.5 DIV 1;";
    accept "(b) 5 DIV 2" "r_num := 5 DIV 2;";
    refuse [ "integer-operand" ] "(b) num DIV 2.5" "r_num := v_num DIV 2.5;";
    refuse [ "integer-operand" ] "(b) 2.5 MOD num" "r_num := 2.5 MOD v_num;";
    accept "(b) num MOD 2" "r_num := v_num MOD 2;";
    accept "(b) num DIV (-2): num operands may be negative" "r_num := v_num DIV (-2);";
    accept "(b) (-7) MOD num" "r_num := (-7) MOD v_num;";
    refuse [ "integer-operand" ] "(b) named constant 0.5 DIV num" "r_num := c_half DIV v_num;";
    accept "(b) named constant 2 DIV num" "r_num := c_two DIV v_num;";
    refuse [ "integer-operand" ] "(b) num MOD (1 / 4)" "r_num := v_num MOD (1 / 4);";
    refuse [ "integer-operand" ] "(c) dnum DIV (-2)" "r_dnum := v_dnum DIV (-2);";
    refuse [ "integer-operand" ] "(c) (-4) MOD dnum" "r_dnum := (-4) MOD v_dnum;";
    refuse [ "integer-operand" ] "(c) dnum DIV 2.5" "r_dnum := v_dnum DIV 2.5;";
    refuse [ "integer-operand" ] "(c) dnum MOD named constant -3" "r_dnum := v_dnum MOD c_minus;";
    accept "(c) dnum DIV 2" "r_dnum := v_dnum DIV 2;";
    accept "(c) dnum MOD named constant 3" "r_dnum := v_dnum MOD c_three;";
    accept "(c) 0 DIV dnum: 0 is >= 0" "r_dnum := 0 DIV v_dnum;";
  ] in
  [ routine_module "ops_div_mod" ~types:operator_module_types ~declarations body ]

(* ------------------------------------------------------------------ §2.16 value classes *)

(* The three classes, by the manual's own examples: num (value), iodev (non-value, §2.16's
   logfile), signaldi (semi-value, §2.16's sig1), all of the installed environment. *)
type value_class = V | N | S

let class_type = function V -> "num" | N -> "iodev" | S -> "signaldi"
let class_name = function V -> "value" | N -> "non-value" | S -> "semi-value"
let classes = [ V; N; S ]

type cell = X | Dash | Not_applicable

(* §2.16, object declarations (tables.md). *)
let manual_declarations = [
  ("constant", [ X; Dash; Not_applicable ]);
  ("persistent", [ X; Dash; Not_applicable ]);
  ("variable with initialisation", [ X; Dash; Not_applicable ]);
  ("variable without initialisation", [ X; X; X ]);
  ("routine parameter: in", [ X; Dash; Dash ]);
  ("routine parameter: var", [ X; X; X ]);
  ("routine parameter: pers", [ X; Dash; Dash ]);
  ("routine parameter: ref (installed routines only)", [ X; X; X ]);
  ("routine parameter: inout var", [ X; Dash; Dash ]);
  ("routine parameter: inout pers", [ X; Dash; Dash ]);
  ("function return value", [ X; Dash; Dash ]);
]

(* Besides the manual's examples, each class is represented by the other types §2.16 puts in
   it: a record whose components are all value types (pos, and one of the test's own), an alias
   of a value type (errnum); a record with a non-value component and an alias of a non-value
   type; a record with a semi-value component and otherwise value components, and an alias of a
   semi-value type; and, for data objects, arrays ("arrays have the class of their element
   type"). The test's types are declared in an installed-mode module, so that the installed
   module of the REF row sees them too (ch. 13). *)
let class_representatives = function
  | V -> [ "num"; "pos"; "errnum"; "t_rec_v" ]
  | N -> [ "iodev"; "t_rec_n"; "t_alias_n" ]
  | S -> [ "signaldi"; "t_rec_s"; "t_alias_s" ]

let class_types_module =
  installed "decl_types"
    (List.map fixed
       [ "MODULE decl_types (SYSMODULE)";
         "RECORD t_rec_v"; "num a;"; "bool b;"; "ENDRECORD";
         "RECORD t_rec_n"; "num a;"; "iodev d;"; "ENDRECORD";
         "RECORD t_rec_s"; "num a;"; "signaldi s;"; "ENDRECORD";
         "ALIAS iodev t_alias_n;"; "ALIAS signaldi t_alias_s;"; "ENDMODULE" ])

(* The code declaring one row's object of type [t] on one line; [k] makes names unique and
   [dims] is "" or an array's dimensions. The initial value <EXP> (§3.1) stands for a value of
   the right type without judging one. The two inout rows differ only in what the argument is
   bound to when the routine is called (§5.2); their declaration is the same INOUT parameter. *)
let declaration_code row t ~dims k =
  match row with
  | "constant" -> Printf.sprintf "CONST %s d_c%d%s := <EXP>;" t k dims
  | "persistent" -> Printf.sprintf "PERS %s d_p%d%s := <EXP>;" t k dims
  | "variable with initialisation" -> Printf.sprintf "VAR %s d_vi%d%s := <EXP>;" t k dims
  | "variable without initialisation" -> Printf.sprintf "VAR %s d_vu%d%s;" t k dims
  | "routine parameter: in" -> Printf.sprintf "PROC d_in%d (%s x) ENDPROC" k t
  | "routine parameter: var" -> Printf.sprintf "PROC d_var%d (VAR %s x) ENDPROC" k t
  | "routine parameter: pers" -> Printf.sprintf "PROC d_pers%d (PERS %s x) ENDPROC" k t
  | "routine parameter: ref (installed routines only)" ->
      Printf.sprintf "PROC d_ref%d (REF %s x) ENDPROC" k t
  | "routine parameter: inout var" -> Printf.sprintf "PROC d_iov%d (INOUT %s x) ENDPROC" k t
  | "routine parameter: inout pers" -> Printf.sprintf "PROC d_iop%d (INOUT %s x) ENDPROC" k t
  | "function return value" -> Printf.sprintf "FUNC %s d_f%d () RETURN <EXP>; ENDFUNC" t k
  | _ -> invalid_arg row

let declaration_rules =
  [ "declaration-value-class"; "parameter-value-class"; "function-value-class" ]

let data_rows =
  [ "constant"; "persistent"; "variable with initialisation"; "variable without initialisation" ]

(* A cell the manual marks "n/a" (a constant, persistent or initialised variable of a semi-value
   type) names a declaration that has no legal form: it is expected refused (doc/rulings.md
   R-2.16-a reads it so too). *)
let declarations_table () =
  let counter = ref 0 in
  let probes_of rows =
    List.concat_map (fun (row, cells) ->
        List.concat (List.map2 (fun cls cell ->
            let shapes t =
              if List.mem row data_rows then [ (t, ""); (t, "{2}") ] else [ (t, "") ] in
            List.concat_map (fun t ->
                List.map (fun (t, dims) ->
                    incr counter;
                    let label = Printf.sprintf "§2.16 declaration %s × %s (%s%s)" row
                        (class_name cls) t dims in
                    let text = declaration_code row t ~dims !counter in
                    match cell with
                    | X -> accept label text
                    | Dash | Not_applicable -> refuse declaration_rules label text) (shapes t))
              (class_representatives cls)) classes cells)) rows
  in
  let is_ref (row, _) = row = "routine parameter: ref (installed routines only)" in
  let data = List.filter (fun (r, _) -> List.mem r data_rows) manual_declarations in
  let routines =
    List.filter (fun r -> not (List.mem r data) && not (is_ref r)) manual_declarations in
  [ class_types_module;
    user "decl_user"
      ([ fixed "MODULE decl_user" ] @ probes_of data @ probes_of routines @ [ fixed "ENDMODULE" ]);
    installed "decl_installed"
      ([ fixed "MODULE decl_installed (SYSMODULE)" ]
       @ probes_of (List.filter is_ref manual_declarations) @ [ fixed "ENDMODULE" ]) ]

(* §2.16, object references (tables.md). Footnote ii: semi-value with the associated value type;
   footnote iii: non-value and semi-value arguments only to var or ref parameters. *)
let references_table () =
  let declarations =
    [ "VAR num o_v;"; "VAR iodev o_n;"; "VAR signaldi o_s;"; "VAR signaldo o_so;"; "VAR num r_num;";
      "VAR bool r_bool;" ] in
  let routines = [ fixed "TRAP o_trap"; fixed "ENDTRAP" ] in
  let obj = function V -> "o_v" | N -> "o_n" | S -> "o_s" in
  let target = [
    accept "§2.16 target of an assignment × value" "o_v := 1;";
    refuse [ "assign-value-class" ] "§2.16 target of an assignment × non-value" "o_n := <EXP>;";
    (* A semi-value target is legal with the associated value type; §2.16's example: an input
       signal refuses the update, so the legal cell is shown with an output signal. *)
    accept "§2.16 target of an assignment × semi-value (output signal, associated num)"
      "o_so := 1;";
    refuse [ "equal-types" ] "§2.16 target × semi-value: the associated type is num, not string"
      "o_so := \"a\";";
    refuse [ "assign-refused-by-type" ] "§2.16 example: sig1 := 1 is refused (input signal)"
      "o_s := 1;";
    accept "§2.16 target of a connect statement × value" "CONNECT o_v WITH o_trap;";
    refuse [ "connect-target-type" ] "§2.16 target of a connect statement × non-value"
      "CONNECT o_n WITH o_trap;";
    (* §4.15 narrows the connect target to the type num (or an alias of num): a signal is not
       one, whatever its associated type. *)
    refuse [ "connect-target-type" ] "§2.16/§4.15 target of a connect statement × semi-value"
      "CONNECT o_so WITH o_trap;";
  ] in
  (* Arguments: the installed-mode routines below take anytype, so that only the value class
     and the access mode decide. *)
  let argument = List.concat_map (fun cls ->
      List.map (fun mode ->
          let label = Printf.sprintf "§2.16 argument × %s (%s) to a%s parameter" (class_name cls)
              (class_type cls) (if mode = "in" then "n in" else " " ^ mode) in
          let text = Printf.sprintf "o_arg_%s %s;" mode (obj cls) in
          match cls, mode with
          | V, _ | (N | S), ("var" | "ref") -> accept label text
          (* The manual's cell is "X iii", legal only for var or ref parameters; doc/rulings.md
             R-2.16-b reads an in argument as an expression, so a semi-value object passes its
             associated value (pinned by spec/02-types/16-reference-argument-semi-value-in). *)
          | S, "in" -> accept label text
          | (N | S), _ -> refuse [ "value-class-reference"; "argument-value-class" ] label text)
        [ "in"; "var"; "ref"; "inout" ]) classes in
  let expression = [
    accept "§2.16 object used in an expression × value" "r_num := o_v + 1;";
    refuse [ "value-class-reference" ] "§2.16 object used in an expression × non-value"
      "r_num := o_n + 1;";
    accept "§2.16 object used in an expression × semi-value (associated num)" "r_num := o_s + 1;";
    accept "§2.16 example: IF sig1 = 1 (semi-value in value context)" "IF o_s = 1 r_num := 0;";
    refuse [ "value-class-reference"; "equality-types" ] "§2.16 non-value compared"
      "IF o_n = 1 r_num := 0;";
    refuse [ "operator-types" ] "§2.16 semi-value in an expression is num, not bool"
      "r_bool := o_s AND TRUE;";
    (* §2.17 rule 3: a value type equals a semi-value type's associated type in value context
       only; an argument of a VAR parameter is not one. *)
    refuse [ "equal-types" ] "§2.17 rule 3: num to a VAR signaldo parameter (Set)" "Set o_v;";
    refuse [ "equal-types" ] "§2.17 rule 3: signaldo to a VAR num parameter" "o_var_num o_so;";
    accept "§2.17 control: signaldo to a VAR signaldo parameter (Set)" "Set o_so;";
  ] in
  [ routine_module "refs_user" ~declarations ~routines (target @ argument @ expression);
    installed "refs_installed"
      (List.map fixed
         [ "MODULE refs_installed (SYSMODULE)"; "PROC o_arg_in (anytype x) ENDPROC";
           "PROC o_arg_var (VAR anytype x) ENDPROC"; "PROC o_arg_ref (REF anytype x) ENDPROC";
           "PROC o_arg_inout (INOUT anytype x) ENDPROC"; "PROC o_var_num (VAR num x) ENDPROC";
           "ENDMODULE" ]) ]

(* ------------------------------------------------------------------ §5.2 access modes *)

type access = Yes | No | Execution_error

(* §5.2 (tables.md): argument × in, var, pers, inout, ref. The row "persistent" is restored
   from §5.2's text; the two inout rows are both given, as the binding is what differs. *)
let manual_access = [
  ("constant", [ Yes; No; No; No; Yes ]);
  ("read-only variable", [ Yes; No; No; No; Yes ]);
  ("variable", [ Yes; Yes; No; Yes; Yes ]);
  ("persistent", [ Yes; No; Yes; Yes; Yes ]);
  ("parameter: in", [ Yes; Yes; No; Yes; Yes ]);
  ("parameter: var", [ Yes; Yes; No; Yes; Yes ]);
  ("parameter: pers", [ Yes; No; Yes; Yes; Yes ]);
  ("parameter: inout (bound to a variable)", [ Yes; Yes; Execution_error; Yes; Yes ]);
  ("parameter: inout (bound to a persistent)", [ Yes; Execution_error; Yes; Yes; Yes ]);
  ("any other expression", [ Yes; No; No; No; No ]);
]

let modes = [ "in"; "var"; "pers"; "inout"; "ref" ]

(* The arguments that stand for each row: several where the manual names several (FOR loop
   variable, ERRNO, INTNO) or where a reference may be whole, an element or a component. An
   inout parameter's binding is unknown until the call runs: the same argument stands for both
   inout rows. *)
let access_arguments = function
  | "constant" -> [ "c_a"; "c_arr{1}" ]
  | "read-only variable" -> [ "i"; "ERRNO"; "INTNO" ]
  | "variable" -> [ "v_a"; "v_arr{2}"; "v_pos.x" ]
  | "persistent" -> [ "p_a"; "p_pos.y" ]
  | "parameter: in" -> [ "x_in" ]
  | "parameter: var" -> [ "x_var" ]
  | "parameter: pers" -> [ "x_pers" ]
  | "parameter: inout (bound to a variable)" | "parameter: inout (bound to a persistent)" ->
      [ "x_inout" ]
  | "any other expression" -> [ "v_a + 1"; "1"; "Abs(v_a)" ]
  | r -> invalid_arg r

let access_modes_table () =
  let body =
    List.concat_map (fun (row, cells) ->
        List.concat_map (fun arg ->
            List.map2 (fun mode cell ->
                let call = Printf.sprintf "m_%s %s;" mode arg in
                let text = if row = "read-only variable" && arg = "i" then
                    Printf.sprintf "FOR i FROM 1 TO 2 DO %s ENDFOR" call else call in
                let label = Printf.sprintf "§5.2 %s (%s) × %s" row arg mode in
                match cell with
                (* decided when the call runs: accepted statically *)
                | Yes | Execution_error -> accept label text
                | No -> refuse [ "access-mode" ] label text) modes cells) (access_arguments row))
      manual_access
    @ [ accept "§5.2/ch. 11 constant array to REF (Dim)" "r_num := Dim(c_arr, 1);";
        accept "§5.2/ch. 11 variable to REF (Present)" "r_bool := Present(v_a);";
        refuse [ "access-mode" ] "§5.2/ch. 11 other expression to REF (Present)"
          "r_bool := Present(v_a + 1);" ]
  in
  let declarations =
    [ "CONST num c_a := 1;"; "CONST num c_arr{2} := [1, 2];"; "VAR num v_a;"; "VAR num v_arr{2};";
      "VAR pos v_pos;"; "PERS num p_a := 0;"; "PERS pos p_pos := [0, 0, 0];"; "VAR num r_num;";
      "VAR bool r_bool;" ] in
  let routines = List.map fixed
      [ "PROC m_in (num x) ENDPROC"; "PROC m_var (VAR num x) ENDPROC";
        "PROC m_pers (PERS num x) ENDPROC"; "PROC m_inout (INOUT num x) ENDPROC" ] in
  [ user "access_user"
      ([ fixed "MODULE access_user" ] @ List.map fixed declarations @ routines
       @ [ fixed "PROC probes (num x_in, VAR num x_var, PERS num x_pers, INOUT num x_inout)" ]
       @ body @ [ fixed "ENDPROC"; fixed "ENDMODULE" ]);
    installed "access_installed"
      (List.map fixed
         [ "MODULE access_installed (SYSMODULE)"; "PROC m_ref (REF num x) ENDPROC"; "ENDMODULE" ]) ]

(* ------------------------------------------------------------------ §9.2 module attributes *)

(* §9.2: the table's order; each at most once; NOVIEW excludes NOSTEPIN, VIEWONLY and READONLY,
   VIEWONLY and READONLY exclude each other. *)
let attributes = [ "SYSMODULE"; "NOVIEW"; "NOSTEPIN"; "VIEWONLY"; "READONLY" ]

let excluded =
  [ ("NOVIEW", "NOSTEPIN"); ("NOVIEW", "VIEWONLY"); ("NOVIEW", "READONLY");
    ("VIEWONLY", "READONLY") ]

let module_attributes_table () =
  let index a =
    let rec go i = function [] -> -1 | x :: r -> if x = a then i else go (i + 1) r in
    go 0 attributes in
  let excludes a b = List.mem (a, b) excluded || List.mem (b, a) excluded in
  let one k list expect label =
    let name = Printf.sprintf "attrs_%d" k in
    user name [ probe label (Printf.sprintf "MODULE %s (%s)" name (String.concat ", " list)) expect;
                fixed "ENDMODULE" ] in
  let singles = List.mapi (fun k a -> one k [ a ] Accept ("§9.2 (" ^ a ^ ")")) attributes in
  let pairs = List.concat_map (fun a -> List.map (fun b -> (a, b)) attributes) attributes in
  let pair_modules = List.mapi (fun k (a, b) ->
      let label = Printf.sprintf "§9.2 (%s, %s)" a b in
      let expect =
        if a = b then Refuse [ "attribute-once" ]
        else if index a > index b && excludes a b then
          Refuse [ "attribute-order"; "attribute-exclusion" ]
        else if index a > index b then Refuse [ "attribute-order" ]
        else if excludes a b then Refuse [ "attribute-exclusion" ]
        else Accept in
      one (10 + k) [ a; b ] expect label) pairs in
  singles @ pair_modules @ [ one 99 attributes (Refuse [ "attribute-exclusion" ]) "§9.2 all five" ]

(* ------------------------------------------------------------------ §2.14, §2.15 *)

(* §2.14 (tables.md): the built-in records and their components, in order. *)
let manual_records =
  [ ("pos", [ ("x", "num"); ("y", "num"); ("z", "num") ]);
    ("orient", [ ("q1", "num"); ("q2", "num"); ("q3", "num"); ("q4", "num") ]);
    ("pose", [ ("trans", "pos"); ("rot", "orient") ]) ]

let record_types = [ "num"; "dnum"; "bool"; "string"; "pos"; "orient"; "pose" ]

let records_table () =
  let components =
    List.concat_map (fun (record, comps) ->
        List.concat_map (fun (c, ct) ->
            List.map (fun t ->
                let label = Printf.sprintf "§2.14 %s.%s is %s, assigned to %s" record c ct t in
                let text = Printf.sprintf "r_%s := v_%s.%s;" t record c in
                if t = ct then accept label text else refuse [ "equal-types" ] label text)
              record_types)
          comps
        @ List.concat_map (fun (other, comps') ->
            List.filter_map (fun (c, _) ->
                if List.mem_assoc c comps then None
                else Some (refuse [ "component-name" ]
                             (Printf.sprintf "§2.14 %s has no component %s (of %s)" record c other)
                             (Printf.sprintf "r_num := v_%s.%s;" record c))) comps') manual_records)
      manual_records in
  (* An aggregate lists the components in the table's order (§3.10, §2.17 rule 2). *)
  let aggregates = [
    accept "§2.14 pos aggregate [x, y, z]" "v_pos := [1, 2, 3];";
    refuse [ "aggregate-size" ] "§2.14 pos has three components" "v_pos := [1, 2];";
    accept "§2.14 orient aggregate [q1, q2, q3, q4]" "v_orient := [1, 0, 0, 0];";
    refuse [ "aggregate-size" ] "§2.14 orient has four components" "v_orient := [1, 0, 0];";
    accept "§2.14 pose aggregate [trans, rot]" "v_pose := [[1, 2, 3], [1, 0, 0, 0]];";
    refuse [ "aggregate-size" ] "§2.14 pose: trans comes before rot"
      "v_pose := [[1, 0, 0, 0], [1, 2, 3]];";
    accept "§2.14 pose.trans.z" "r_num := v_pose.trans.z;";
    accept "§2.14 pose.rot.q4" "r_num := v_pose.rot.q4;";
    refuse [ "equal-types" ] "§2.14 pose.trans is pos, not orient" "v_orient := v_pose.trans;";
  ] in
  let declarations = List.concat_map (fun t -> [ Printf.sprintf "VAR %s r_%s;" t t ]) record_types
                     @ [ "VAR pos v_pos;"; "VAR orient v_orient;"; "VAR pose v_pose;" ] in
  [ routine_module "records" ~declarations (components @ aggregates) ]

(* §2.15: errnum and intnum are aliases of num; an alias may not be defined on another alias. *)
let manual_aliases = [ ("errnum", "num"); ("intnum", "num") ]

let aliases_table () =
  let types = [
    accept "§2.15 an alias of num" "ALIAS num my_num;";
    refuse [ "alias-of-alias" ] "§2.15 ALIAS on errnum is an alias of an alias"
      "ALIAS errnum my_err;";
    refuse [ "alias-of-alias" ] "§2.15 ALIAS on intnum is an alias of an alias"
      "ALIAS intnum my_int;";
    refuse [ "alias-of-alias" ] "§2.15 ALIAS on a user alias" "ALIAS my_num my_num2;";
  ] in
  let assignments =
    List.concat_map (fun (alias, base) ->
        [ accept (Printf.sprintf "§2.15 %s := %s" alias base)
            (Printf.sprintf "v_%s := v_%s;" alias base);
          accept (Printf.sprintf "§2.15 %s := %s" base alias)
            (Printf.sprintf "v_%s := v_%s;" base alias);
          accept (Printf.sprintf "§2.15 %s := literal" alias) (Printf.sprintf "v_%s := 7;" alias);
          refuse [ "equal-types" ] (Printf.sprintf "§2.15 %s is not dnum" alias)
            (Printf.sprintf "v_dnum := v_%s;" alias);
          refuse [ "equal-types" ] (Printf.sprintf "§2.15 %s is not bool" alias)
            (Printf.sprintf "v_%s := TRUE;" alias);
          accept (Printf.sprintf "§2.15 %s := my_num (both aliases of num)" alias)
            (Printf.sprintf "v_%s := v_my_num;" alias) ]) manual_aliases
    @ [ accept "§2.15 errnum := intnum" "v_errnum := v_intnum;";
        accept "§2.15 intnum := errnum" "v_intnum := v_errnum;" ] in
  let declarations =
    [ "VAR num v_num;"; "VAR dnum v_dnum;"; "VAR errnum v_errnum;"; "VAR intnum v_intnum;";
      "VAR my_num v_my_num;" ] in
  [ user "aliases"
      ([ fixed "MODULE aliases" ] @ types @ List.map fixed declarations @ [ fixed "PROC probes()" ]
       @ assignments @ [ fixed "ENDPROC"; fixed "ENDMODULE" ]) ]

(* ------------------------------------------------------------------ ch. 13 look-up order *)

(* ch. 13 (tables.md): a routine in a user module looks in its routine, its module, the global
   objects of the program, the installed level; a module-level object of a user module starts at
   its module; a routine in an installed module looks in its routine, its module and the
   installed level, never at user globals, and a module-level object there in its module and
   the installed level. Each probe is accepted only if the name is found at the right level (the
   objects of one name have different types at different levels), and each hiding is paired with
   a control where nothing hides. *)
let lookup_table () =
  [ user "look_a"
      [ fixed "MODULE look_a";
        fixed "VAR bool g_shadow;";
        fixed "VAR bool x_mod;";
        fixed "VAR num ERR_ILLDIM;";
        fixed "VAR bool lk_level;";
        fixed "VAR num r_num;";
        fixed "CONST num u_const := 1;";
        fixed "CONST bool lk_k := TRUE;";
        fixed "CONST bool lk_ik := TRUE;";
        fixed "PROC hide_module()";
        fixed "VAR num x_mod;";
        accept "ch. 13 a routine object hides a module object" "x_mod := 1;";
        fixed "ENDPROC";
        fixed "PROC no_hide_module()";
        refuse [ "equal-types" ] "ch. 13 control: the module object is bool" "x_mod := 1;";
        fixed "ENDPROC";
        fixed "PROC hide_installed()";
        fixed "VAR num ERR_DIVZERO;";
        accept "ch. 13 a routine object hides an installed object" "ERR_DIVZERO := 1;";
        fixed "ENDPROC";
        fixed "PROC no_hide_installed()";
        refuse [ "assign-constant" ] "ch. 13 control: the installed object is a constant"
          "ERR_DIVZERO := 1;";
        accept "ch. 13 a module object hides an installed object" "ERR_ILLDIM := 1;";
        refuse [ "assign-constant" ] "ch. 13 control: ERR_NOTARR is an installed constant"
          "ERR_NOTARR := 1;";
        fixed "ENDPROC";
        fixed "PROC hide_by_parameter (num g_shadow)";
        accept "ch. 13 a parameter (routine object) hides a global object" "g_shadow := 1;";
        fixed "ENDPROC";
        fixed "PROC hide_by_loop()";
        accept "§2.20 a FOR loop variable hides a module object"
          "FOR x_mod FROM 1 TO 2 DO r_num := x_mod + 1; ENDFOR";
        fixed "ENDPROC";
        fixed "ENDMODULE" ];
    user "look_b"
      [ fixed "MODULE look_b";
        fixed "LOCAL VAR num g_shadow;";
        fixed "LOCAL CONST num lk_k := 1;";
        accept "ch. 13 module level: the own module (a local object) before the program's globals"
          "CONST num lk_m1 := lk_k;";
        fixed "PROC local_hides()";
        accept "ch. 13 a local module object hides a global one of another module" "g_shadow := 1;";
        fixed "ENDPROC";
        fixed "ENDMODULE" ];
    user "look_c"
      [ fixed "MODULE look_c";
        accept "ch. 13 module level: the program's globals" "CONST bool lk_m2 := lk_k;";
        accept "ch. 13 module level: the program's globals before the installed level"
          "CONST bool lk_m3 := lk_ik;";
        accept "ch. 13 module level: the installed level" "CONST num lk_m4 := ERR_DIVZERO;";
        fixed "PROC sees_global()";
        accept "ch. 13 control: another module sees the global object (bool)" "g_shadow := TRUE;";
        refuse [ "equal-types" ] "ch. 13 control: the global object is bool, not num"
          "g_shadow := 1;";
        accept "ch. 13 user code sees an installed module's objects" "lk_own := 1;";
        accept "ch. 13 a user global (of look_a) hides an installed object" "lk_level := TRUE;";
        fixed "ENDPROC";
        fixed "ENDMODULE" ];
    (* Declared before look_inst uses it: the order of declarations is another matter (§2.20,
       below). *)
    installed "look_inst2"
      [ fixed "MODULE look_inst2 (SYSMODULE)"; fixed "VAR num lk_level;";
        fixed "CONST num lk_ik := 5;"; fixed "ENDMODULE" ];
    installed "look_inst"
      [ fixed "MODULE look_inst (SYSMODULE)";
        fixed "VAR num lk_own;";
        accept "ch. 13 installed module level: the installed level"
          "CONST num lk_c1 := ERR_DIVZERO;";
        refuse [ "unknown-name" ] "ch. 13 installed module level: user globals are not seen"
          "CONST num lk_c2 := u_const;";
        accept
          "ch. 13 installed module level: the installed level, not the user global of the same name"
          "CONST num lk_c3 := lk_ik;";
        fixed "PROC lk_routine()";
        accept "ch. 13 installed routine: its own module" "lk_own := 1;";
        accept "ch. 13 installed routine: the installed level, not the user global of the same name"
          "lk_level := 1;";
        refuse [ "unknown-name" ] "ch. 13 installed routine: user globals are not seen"
          "r_num := 1;";
        fixed "ENDPROC";
        fixed "PROC lk_hide()";
        fixed "VAR bool lk_own;";
        accept "ch. 13 installed routine: a routine object hides its module's" "lk_own := TRUE;";
        fixed "ENDPROC";
        fixed "ENDMODULE" ] ]

(* §2.20 (tables.md, scope rules): the scope of a local module data object is its whole module,
   that of a global one also the other modules of the task buffer; nothing makes it start at its
   declaration (spec/13-scope/13-routine-before-its-declaration says the same of module data).
   The checker registers all module data before it judges initial values, and an array
   dimension sees the constants in its scope only. *)
let module_data_scope () =
  [ user "scope_a"
      [ fixed "MODULE scope_a";
        accept "§2.20 a constant names a constant declared later in its module"
          "CONST num sc_a := sc_b;";
        fixed "CONST num sc_b := 2;";
        accept "§2.20 a variable's initial value names a constant declared later in its module"
          "VAR num sc_v := sc_c;";
        fixed "CONST num sc_c := 3;";
        accept "§2.20 a constant names a global constant of a module later in the task buffer"
          "CONST num sc_d := sc_e;";
        accept "§2.20 an array dimension names a constant declared later" "VAR num sc_arr{sc_f};";
        fixed "LOCAL CONST num sc_f := 2;";
        accept "§2.20 control: a constant declared earlier" "CONST num sc_g := sc_b;";
        refuse [ "unknown-name" ]
          "§2.20 a local constant of another module is not in scope (array dimension)"
          "VAR num sc_arr2{sc_h};";
        refuse [ "unknown-name" ]
          "§2.20 a local constant of another module is not in scope (initial value)"
          "CONST num sc_i := sc_h;";
        fixed "ENDMODULE" ];
    user "scope_b"
      [ fixed "MODULE scope_b"; fixed "CONST num sc_e := 4;"; fixed "LOCAL CONST num sc_h := 2;";
        fixed "ENDMODULE" ] ]

(* ------------------------------------------------------------------ §4.15 *)

(* §4.15 (tables.md): the target is of type num or an alias of num, a module variable (not a
   routine variable), or a VAR or INOUT parameter. Connecting the same target twice is an
   execution error (ERR_ALRDYCNT), not a static one. *)
let connect_table () =
  let body = [
    accept "§4.15 module variable of type intnum" "CONNECT ct_int WITH ct_trap;";
    accept "§4.15 module variable of type num" "CONNECT ct_num WITH ct_trap;";
    accept "§4.15 an element of a module array of intnum" "CONNECT ct_arr{1} WITH ct_trap;";
    refuse [ "connect-target-type" ] "§4.15 module variable of type dnum"
      "CONNECT ct_dnum WITH ct_trap;";
    refuse [ "connect-target-type" ] "§4.15 module variable of type bool"
      "CONNECT ct_bool WITH ct_trap;";
    refuse [ "connect-target-module-variable" ] "§4.15 routine variable"
      "CONNECT ct_local WITH ct_trap;";
    refuse [ "connect-target-variable" ] "§4.15 module persistent" "CONNECT ct_pers WITH ct_trap;";
    refuse [ "connect-target-variable" ] "§4.15 module constant" "CONNECT ct_const WITH ct_trap;";
    accept "§4.15 VAR parameter" "CONNECT x_var WITH ct_trap;";
    accept "§4.15 INOUT parameter" "CONNECT x_inout WITH ct_trap;";
    refuse [ "connect-target-variable" ] "§4.15 in parameter" "CONNECT x_in WITH ct_trap;";
    refuse [ "connect-target-variable" ] "§4.15 PERS parameter" "CONNECT x_pers WITH ct_trap;";
    accept "§4.15 one trap serves several interrupt numbers" "CONNECT ct_int2 WITH ct_trap;";
    accept "§4.15 the same target twice: an execution error (ERR_ALRDYCNT)"
      "CONNECT ct_int WITH ct_trap;";
  ] in
  [ user "connects"
      ([ fixed "MODULE connects" ]
       @ List.map fixed
         [ "VAR intnum ct_int;"; "VAR intnum ct_int2;"; "VAR num ct_num;"; "VAR intnum ct_arr{2};";
           "VAR dnum ct_dnum;"; "VAR bool ct_bool;"; "PERS intnum ct_pers := 0;";
           "CONST intnum ct_const := 1;"; "TRAP ct_trap"; "ENDTRAP";
           "PROC probes (intnum x_in, VAR intnum x_var, PERS intnum x_pers, INOUT intnum x_inout)";
           "VAR intnum ct_local;" ]
       @ body @ [ fixed "ENDPROC"; fixed "ENDMODULE" ]) ]

(* ------------------------------------------------------------------ ch. 11, ch. 12 *)

(* ch. 12 (tables.md): ERRNO and INTNO are read-only variables (errnum, intnum), the ERR_
   names constants of type errnum; both aliases of num (§2.15). *)
let manual_error_constants =
  [ "ERR_ALRDYCNT"; "ERR_ARGDUPCND"; "ERR_ARGNOTPER"; "ERR_ARGNOTVAR"; "ERR_CALLPROC";
    "ERR_CNTNOTVAR"; "ERR_DIVZERO"; "ERR_EXECPHR"; "ERR_FNCNORET"; "ERR_ILLDIM"; "ERR_ILLQUAT";
    "ERR_ILLRAISE"; "ERR_INOISSAFE"; "ERR_INOMAX"; "ERR_MAXINTVAL"; "ERR_NOTARR"; "ERR_NOTEQDIM";
    "ERR_NOTINTVAL"; "ERR_NOTPRES"; "ERR_OUTOFBND"; "ERR_REFUNKDAT"; "ERR_REFUNKFUN";
    "ERR_REFUNKPRC"; "ERR_REFUNKTRP"; "ERR_STRTOOLNG"; "ERR_UNKINO" ]

let builtins_table () =
  let objects =
    List.concat_map (fun (name, kind_rule) ->
        [ accept (Printf.sprintf "ch. 12 %s is of type errnum/intnum (num)" name)
            (Printf.sprintf "r_num := %s;" name);
          refuse [ "equal-types" ] (Printf.sprintf "ch. 12 %s is not dnum" name)
            (Printf.sprintf "r_dnum := %s;" name);
          refuse [ kind_rule ] (Printf.sprintf "ch. 12 %s cannot be assigned" name)
            (Printf.sprintf "%s := 1;" name) ])
      ([ ("ERRNO", "assign-read-only"); ("INTNO", "assign-read-only") ]
       @ List.map (fun n -> (n, "assign-constant")) manual_error_constants)
  in
  (* ch. 11 (tables.md): the signatures of the built-in routines. *)
  let routines = [
    accept "ch. 11 Dim (REF anytype, num): num" "r_num := Dim(b_arr, 1);";
    refuse [ "equal-types" ] "ch. 11 Dim returns num, not bool" "r_bool := Dim(b_arr, 1);";
    refuse [ "argument-required" ] "ch. 11 Dim needs dimno" "r_num := Dim(b_arr);";
    refuse [ "equal-types" ] "ch. 11 Dim's dimno is num" "r_num := Dim(b_arr, \"1\");";
    refuse [ "access-mode" ] "ch. 11 Dim's datobj is REF: not any other expression"
      "r_num := Dim(b_arr{1} + 1, 1);";
    accept "ch. 11 Present (REF anytype): bool" "r_bool := Present(x_opt);";
    refuse [ "equal-types" ] "ch. 11 Present returns bool, not num" "r_num := Present(x_opt);";
    accept "ch. 11 DebugBreak ()" "DebugBreak;";
    refuse [ "argument-count" ] "ch. 11 DebugBreak takes no argument" "DebugBreak 1;";
    accept "ch. 11 IWatch (VAR intnum)" "IWatch b_int;";
    refuse [ "access-mode" ] "ch. 11 IWatch's ino is VAR: not a constant" "IWatch b_const;";
    refuse [ "equal-types" ] "ch. 11 IWatch's ino is intnum, not string" "IWatch b_string;";
    accept "ch. 11 ISleep (VAR intnum)" "ISleep b_int;";
    refuse [ "access-mode" ] "ch. 11 ISleep's ino is VAR: not any other expression"
      "ISleep b_int + 1;";
    accept "ch. 11 IsPers (INOUT anytype): bool" "r_bool := IsPers(x_inout);";
    accept "ch. 11 IsVar (INOUT anytype): bool" "r_bool := IsVar(x_inout);";
    refuse [ "equal-types" ] "ch. 11 IsVar returns bool, not num" "r_num := IsVar(x_inout);";
    refuse [ "access-mode" ] "ch. 11 IsPers's datobj is INOUT: not a constant"
      "r_bool := IsPers(b_const);";
  ] in
  [ user "builtins"
      ([ fixed "MODULE builtins" ]
       @ List.map fixed
         [ "VAR num r_num;"; "VAR dnum r_dnum;"; "VAR bool r_bool;"; "VAR num b_arr{3};";
           "VAR intnum b_int;"; "CONST intnum b_const := 1;"; "VAR string b_string;";
           (* ch. 11: anytype is a mark of installed routines; RAPID routines cannot use it. *)
           "PROC probes (INOUT num x_inout, \\num x_opt)" ]
       @ objects @ routines @ [ fixed "ENDPROC" ]
       @ [ refuse [ "anytype-installed-only" ] "ch. 11 a RAPID routine cannot use anytype"
             "PROC b_any (anytype x) ENDPROC" ]
       @ [ fixed "ENDMODULE" ]) ]

(* ------------------------------------------------------------------ §1.4 *)

(* §1.4 (tables.md): the manual's example of each static error class, and execution errors that
   the static semantics leaves to execution. *)
let error_classes () =
  let parse_class text =
    match Parse.parse_string ~name:"classes.mod" text with
    | Ok m -> (
        let installed = Lazy.force environment in
        match Check.errors (Check.check_task ~installed [ m ]) with
        | [] -> None
        | r :: _ -> Some (Report.to_diagnostic r).error_class)
    | Error d -> Some d.error_class in
  let in_module body =
    "MODULE classes\nVAR num a;\nVAR num b;\nPROC main()\n" ^ body ^ "\nENDPROC\nENDMODULE\n" in
  (* rapid-sem's bound on nesting (doc/rulings.md R-1.4): one statement more than it allows. *)
  let nested = String.concat "" (List.init (Parse.max_nesting + 1) (fun _ -> "IF TRUE THEN\n"))
               ^ String.concat "" (List.init (Parse.max_nesting + 1) (fun _ -> "ENDIF\n")) in
  let cases = [
    ("lexical error: exponent out of range", in_module "b := 2E52786;",
     Some Diagnostic.Lexical_error);
    ("syntax error: FROM missing", in_module "FOR i 5 TO 10 DO\nENDFOR",
     Some Diagnostic.Syntax_error);
    ("semantic error: a := \"John\"", in_module "a := \"John\";", Some Diagnostic.Semantic_error);
    ("fatal error: program too complex (nested)", in_module nested,
     Some Diagnostic.Fatal_static_error);
    ("execution error, not static: division by zero", in_module "a := b / 0;", None);
    ("execution error, not static: DIV by zero", in_module "a := b DIV 0;", None);
  ] in
  let name = function
    | None -> "accepted (left to execution)" | Some c -> Diagnostic.class_name c in
  List.iter (fun (label, text, expected) ->
      Alcotest.(check string) ("§1.4 " ^ label) (name expected) (name (parse_class text))) cases

(* ------------------------------------------------------------------ run-time tables *)

(* §2.13's integer sub-domains and §2.22/§2.23's initial values are used when programs run (a
   later issue); until then the data the semantics will use is compared with the manual here. *)
let atomic_subdomains () =
  let manual =
    [ ("num", Some ("-8388607", "8388608"));
      ("dnum", Some ("-4503599627370496", "4503599627370496"));
      ("bool", None); ("string", None) ] in
  let actual = List.map (fun (r : Tables.atomic_row) ->
      (Types.name r.atomic,
       if Z.gt r.integer_min r.integer_max then None
       else Some (Z.to_string r.integer_min, Z.to_string r.integer_max))) Tables.atomic_types in
  Alcotest.(check (list (pair string (option (pair string string)))))
    "§2.13 atomic types" manual actual

let initial_values () =
  let show = function
    | Some Tables.Zero -> "0" | Some False_value -> "FALSE" | Some Empty_string -> "\"\""
    | Some All_bits_zero -> "all bits 0" | None -> "component-wise" in
  let iodev =
    Types.Installed_atomic { atomic_name = "iodev"; atomic_class = Non_value; associated = None } in
  let signal =
    Types.Installed_atomic
      { atomic_name = "signaldi"; atomic_class = Semi_value; associated = Some Num } in
  let record =
    Types.Record
      { record_id = -1; record_name = "pos";
        components = [ ("x", Num); ("y", Num); ("z", Num) ] } in
  let manual = [ ("num", "0"); ("dnum", "0"); ("bool", "FALSE"); ("string", "\"\"");
                 ("iodev", "all bits 0"); ("signaldi", "all bits 0"); ("pos", "component-wise") ] in
  let actual = List.map (fun t -> (Types.name t, show (Tables.initial_value t)))
      [ Num; Dnum; Bool; String; iodev; signal; record ] in
  Alcotest.(check (list (pair string string))) "§2.22/§2.23 initial values" manual actual

(* §2.16, §5.2, ch. 11: only installed routines have ref parameters; in a program module REF is
   not even a word of the language (the lexer makes it a token for the installed environment). *)
let ref_installed_only () =
  let text = "MODULE m\nPROC p (REF num x)\nENDPROC\nENDMODULE\n" in
  (match Parse.parse_string ~name:"ref_user.mod" text with
   | Ok _ -> Alcotest.fail "a REF parameter is accepted in a program module"
   | Error _ -> ());
  match Parse.parse_string ~options:{ Parse.default_options with installed = true }
          ~name:"ref_installed.sys" text with
  | Ok _ -> ()
  | Error d ->
      Alcotest.failf "REF refused in the installed environment: %s" (Diagnostic.to_string d)

let suite =
  ( "tables",
    [ batch "§3.12 binary operators × operand types, result types" binary_matrix;
      batch "§3.12 unary operators" unary_matrix;
      batch "§3.12 = and <> on arrays" array_operators;
      batch "§3.12 numeric literal operands" literal_operands;
      batch "§3.12 notes (b) (c): DIV and MOD with constant operands" div_mod_notes;
      batch "§2.16 object declarations × value classes" declarations_table;
      Alcotest.test_case "§2.16 ref parameters: installed routines only" `Quick ref_installed_only;
      batch "§2.16 object references × value classes" references_table;
      batch "§5.2 arguments × access modes" access_modes_table;
      batch "§9.2 module attributes" module_attributes_table;
      batch "§2.14 built-in records" records_table;
      batch "§2.15 built-in aliases" aliases_table;
      batch "ch. 13 look-up order" lookup_table;
      batch "§2.20 scope of module data objects" module_data_scope;
      batch "§4.15 connect targets" connect_table;
      batch "ch. 11 built-in routines, ch. 12 built-in data objects" builtins_table;
      Alcotest.test_case "§1.4 static error classes" `Quick error_classes;
      Alcotest.test_case "§2.13 integer sub-domains (data)" `Quick atomic_subdomains;
      Alcotest.test_case "§2.22/§2.23 initial values (data)" `Quick initial_values ] )
