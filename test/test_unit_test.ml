(* rapid-sem test (doc/testing.md): the tests of a task buffer found and run each in a fresh
   controller, the assertions and what their failures say, the coverage the machine reports,
   and the reports other tools read: JUnit XML (parsed here as a JUnit consumer reads it), lcov
   (rendered by Debian's genhtml when it is installed) and Cobertura XML. *)

module U = Rapid_unit_test
module Suite = U.Test_suite

let temp_dir = Test_services.temp_dir
let write_file = Test_services.write_file
let read_file = Test_cli.read_file

let options = Rapid_run.Run_options.{
    max_steps = 10_000_000; allow_unknown = false; stub_unmodelled = false; limits = Rapid_runtime.Limits.default;
    controller = { io = None; statement_time = Rapid_controller.World.default_statement_time;
                   max_time = Rapid_controller.World.default_max_time; epoch = Rapid_controller.World.default_epoch; robotware = None; units = [];
                   services = { fs = None; fs_quota = None; net = []; map_address = []; egm_device = []; operator = None } };
    robot = None; base_frames = [] }

let cell = "../examples/pickcell"

let suite_of files =
  match Suite.discover ~notify:ignore options files with
  | Ok s -> s
  | Error (Usage m) -> Alcotest.failf "usage: %s" m
  | Error _ -> Alcotest.fail "the task buffer is refused"

let run ?jobs ?(coverage = false) ?(engine = `Closure) s = Suite.run ?jobs ~coverage ~engine ~on_result:(fun _ _ -> ()) s

let verdicts results =
  List.map (fun (r : Suite.result) -> match r.verdict with
      | Passed -> r.test.name ^ " passed"
      | Failed { at; message } -> Printf.sprintf "%s failed at %s: %s" r.test.name (Option.value at ~default:"-") message)
    results

let contains s sub = match Str.search_forward (Str.regexp_string sub) s 0 with _ -> true | exception Not_found -> false

(* The cell of doc/testing.md: six tests pass, the deliberate failure says what it expected, what
   it found, and where the assertion is. *)
let pick_cell () =
  let files = Result.get_ok (Suite.module_files [ cell ]) in
  Alcotest.(check (list string)) "the modules of the folder, in name order"
    (List.map (Filename.concat cell) [ "nopart_test.mod"; "pick_cell.mod"; "pick_cell_test.mod" ]) files;
  let s = suite_of files in
  Alcotest.(check (list string)) "test modules" [ "noparttest"; "pickcelltest" ] s.test_modules;
  let results = run s in
  Alcotest.(check (list string)) "verdicts"
    [ "test_grip_gives_up passed"; "test_slot_offsets passed"; "test_slot_out_of_range passed";
      "test_vacuum_by_part_type passed"; "test_grip_holds_part passed"; "test_pick_and_place_one_part passed";
      "test_two_cycles_count failed at ../examples/pickcell/pick_cell_test.mod:47:5: parts on the pallet: \
       AssertEqual: expected 3, actual 2" ]
    (verdicts results);
  (* Each test in its own controller: the clock starts at 0 (Grip waits for the part until 0.5 s
     of the stimulus, so the three retries of nopart.io take 3 x 1 s + 2 x 0.2 s). *)
  let time name = (List.find (fun (r : Suite.result) -> r.test.name = name) results).time in
  Alcotest.(check bool) "grip waits for the stimulus's part" true (Float.abs (time "test_grip_holds_part" -. 0.5) < 0.01);
  Alcotest.(check bool) "three tries of a second" true (Float.abs (time "test_grip_gives_up" -. 3.4) < 0.01);
  Alcotest.(check (list string)) "the same with the machine" (verdicts results) (verdicts (run ~engine:`Machine s));
  Alcotest.(check (list string)) "the same in three processes, in the same order" (verdicts results)
    (verdicts (run ~jobs:3 s));
  let only = Suite.filter (Str.regexp "slot") s in
  Alcotest.(check (list string)) "--filter" [ "test_slot_offsets"; "test_slot_out_of_range" ]
    (List.map (fun (t : Suite.test) -> t.name) only.tests)

(* One module of tests, each failing one assertion (or not), in a folder of its own. *)
let module_ ?(io = "") name body =
  let dir = temp_dir () in
  if io <> "" then write_file (Filename.concat dir "t.io") io;
  let file = Filename.concat dir (name ^ ".mod") in
  write_file file ((if io <> "" then "!rapid-sem: --io t.io\n" else "") ^ "MODULE " ^ name ^ "\n" ^ body ^ "ENDMODULE\n");
  (dir, file)

let one_test ?io ?(engine = `Closure) ?(decls = "") stmts =
  let _, file = module_ ?io "T" (decls ^ "  PROC test_it()\n" ^ stmts ^ "  ENDPROC\n") in
  match run ~engine (suite_of [ file ]) with
  | [ r ] -> (match r.verdict with
      | Passed -> "passed"
      | Failed { at; message } ->
          let at = match at with
            | Some a -> String.sub a (String.length file + 1) (String.length a - String.length file - 1)
            | None -> "-" in
          at ^ " " ^ message)
  | _ -> Alcotest.fail "one test expected"

(* Each assertion: what a failure says (expected, actual) and the place of its call (line 5 is
   the first statement of test_it); a passing one returns. Both engines agree. *)
let assertions () =
  let io = "signal doLamp do\nsignal aiLevel ai 2.5\n" in
  let target = "  CONST robtarget pA := [[300,0,300],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];\n" in
  let cases = [
    ("    AssertEqual 1, 2;\n", "5:5 AssertEqual: expected 1, actual 2");
    ("    AssertEqual 1, 1.5 \\Tol:=0.1;\n", "5:5 AssertEqual: expected 1, actual 1.5 (tolerance 0.1)");
    ("    AssertEqual 1, 1.05 \\Tol:=0.1;\n", "passed");
    ("    AssertEqual 1, 1 \\Tol:=-1;\n",
     "5:5 execution error ERR_ARGVALERR: no error handler took it (test_it)");
    ("    AssertEqualStr \"abc\", \"abd\";\n", "5:5 AssertEqualStr: expected \"abc\", actual \"abd\"");
    ("    AssertTrue 1 > 2;\n", "5:5 AssertTrue: expected TRUE, actual FALSE");
    ("    AssertFalse 1 < 2 \\Msg:=\"order\";\n", "5:5 order: AssertFalse: expected FALSE, actual TRUE");
    ("    AssertEqualPose [[0,0,0],[1,0,0,0]], [[0,0,1],[1,0,0,0]];\n",
     "5:5 AssertEqualPose: expected [0,0,0] [1,0,0,0], actual [0,0,1] [1,0,0,0] (1 mm and 0 degrees apart; \
      tolerance 0.001 mm, 0.01 degrees)");
    ("    AssertEqualPose [[0,0,0],[1,0,0,0]], [[0,0,0],[-1,0,0,0]];\n", "passed");
    ("    AssertEqualPose [[0,0,0],[1,0,0,0]], [[0,0,0],[0.7071068,0.7071068,0,0]] \\RotTol:=89;\n",
     "5:5 AssertEqualPose: expected [0,0,0] [1,0,0,0], actual [0,0,0] [0.707107,0.707107,0,0] (0 mm and 90 degrees \
      apart; tolerance 0.001 mm, 89 degrees)");
    ("    AssertEqualTarget pA, Offs(pA, 0.5, 0, 0) \\Tol:=0.1;\n",
     "5:5 AssertEqualTarget: expected [300,0,300] [0,0,1,0], actual [300.5,0,300] [0,0,1,0] (0.5 mm and 0 degrees \
      apart; tolerance 0.1 mm, 0.01 degrees)");
    ("    AssertEqualTarget pA, Offs(pA, 0.5, 0, 0) \\Tol:=1;\n", "passed");
    ("    SetDO doLamp, 1;\n    AssertSignal doLamp, 0;\n", "6:5 AssertSignal: expected doLamp = 0, actual 1");
    ("    AssertSignal aiLevel, 2.5;\n    AssertSignal aiLevel, 3 \\Tol:=0.1;\n",
     "6:5 AssertSignal: expected aiLevel = 3, actual 2.5");
    ("    MoveL pA, v200, fine, tool0;\n    AssertAtTarget pA;\n    AssertAtTarget Offs(pA, 0, 0, 5);\n",
     "7:5 AssertAtTarget: expected [300,0,305] [0,0,1,0], actual [300,0,300] [0,0,1,0] (5 mm and 0 degrees apart; \
      tolerance 0.1 mm, 0.1 degrees)");
    ("    AssertFail \"not here\";\n", "5:5 AssertFail: not here");
  ] in
  List.iter (fun (stmts, expected) ->
      Alcotest.(check string) stmts expected (one_test ~io ~decls:target stmts);
      Alcotest.(check string) (stmts ^ " (machine)") expected (one_test ~io ~decls:target ~engine:`Machine stmts))
    cases

(* An expected error, RAPID's way: the statement that should raise it, AssertFail after it, and
   AssertErrno in the ERROR handler with RETURN. A failed assertion is no error a handler takes
   (R-test-b): the RETRY below never runs. An error no handler takes fails the test where it
   occurs; Stop ends the test as it ends a run (R-test-c). *)
let errors () =
  let handler = "  ERROR\n    AssertErrno ERR_DIVZERO, ERRNO;\n    RETURN;\n" in
  Alcotest.(check string) "the error expected" "passed" (one_test ("    VAR num x := 1;\n    x := 1 / 0;\n    AssertFail \"none\";\n" ^ handler));
  Alcotest.(check string) "no error: AssertFail stops the test, no handler takes it" "4:5 AssertFail: no error"
    (one_test ("    VAR num x := 1;\n    AssertFail \"no error\";\n" ^ handler));
  Alcotest.(check string) "another error" "7:5 AssertErrno: expected ERR_DIVZERO, actual ERR_OUTOFBND"
    (one_test ("    VAR num a{2};\n    VAR num i := 3;\n    a{i} := 1;\n" ^ handler));
  Alcotest.(check string) "no handler takes a failed assertion" "3:5 AssertFail: once"
    (one_test "    AssertFail \"once\";\n  ERROR\n    RETRY;\n");
  Alcotest.(check string) "an unhandled error" "5:5 execution error ERR_OUTOFBND (index 3 outside the dimension 1 to 2): no error handler took it \
                                           (test_it)"
    (one_test "    VAR num a{2};\n    VAR num i := 3;\n    a{i} := 1;\n");
  Alcotest.(check string) "Stop ends the test" "passed" (one_test "    Stop;\n    AssertFail \"after Stop\";\n");
  Alcotest.(check string) "the step limit, at the test's name" "2:8 the step limit (10000000) is exhausted"
    (one_test "    WHILE TRUE DO\n    ENDWHILE\n");
  (* What a failing test wrote goes under its message. *)
  let _, file = module_ "Out" "  PROC test_it()\n    TPWrite \"gripper on\";\n    AssertTrue FALSE;\n  ENDPROC\n" in
  match run (suite_of [ file ]) with
  | [ r ] ->
      Alcotest.(check (list string)) "output" [ "gripper on" ] r.output;
      Alcotest.(check (list string)) "the report's lines"
        [ "FAIL test_it                                  0.000 s";
          "  " ^ file ^ ":4:5: AssertTrue: expected TRUE, actual FALSE"; "  | gripper on" ]
        (U.Test_report.line r)
  | _ -> Alcotest.fail "one test"

(* Tests are parameterless procedures named test_ (any letter case); each starts with fresh
   module data (a variable, a persistent) and a fresh controller (its clock, its signals). *)
let discovery () =
  let fresh = "    n := n + 1;\n    p := p + 1;\n    AssertEqual 1, n;\n    AssertEqual 1, p;\n\
               \    AssertSignal doLamp, 0;\n    SetDO doLamp, 1;\n    AssertTrue ClkRead(c) = 0;\n\
               \    ClkStart c;\n    WaitTime 1;\n" in
  let _, file = module_ ~io:"signal doLamp do\n" "Found"
      ("  VAR num n := 0;\n  PERS num p := 0;\n  VAR clock c;\n  PROC TEST_One()\n" ^ fresh ^ "  ENDPROC\n\
       \  PROC test_two()\n" ^ fresh ^ "  ENDPROC\n\
       \  PROC test_param(num x)\n  ENDPROC\n  FUNC num test_f()\n    RETURN 1;\n  ENDFUNC\n\
       \  PROC tester()\n  ENDPROC\n") in
  let s = suite_of [ file ] in
  Alcotest.(check (list string)) "tests" [ "TEST_One"; "test_two" ] (List.map (fun (t : Suite.test) -> t.name) s.tests);
  Alcotest.(check (list string)) "fresh data" [ "TEST_One passed"; "test_two passed" ] (verdicts (run s));
  Alcotest.(check (list string)) "fresh data (machine)" [ "TEST_One passed"; "test_two passed" ]
    (verdicts (run ~engine:`Machine s));
  Alcotest.(check (list (float 0.01))) "each clock from 0: a second of WaitTime, and the statements" [ 1.; 1. ]
    (List.map (fun (r : Suite.result) -> r.time) (run s))

(* The assertions are rapid-sem test's only (R-test-a): check and run do not know them. *)
let only_under_test () =
  let _, file = module_ "Plain" "  PROC main()\n    AssertTrue TRUE;\n  ENDPROC\n" in
  (match Rapid_load.Session.load [ file ] with
   | Error (Static (r :: _)) -> Alcotest.(check bool) "unknown procedure" true (contains r.message "AssertTrue")
   | _ -> Alcotest.fail "AssertTrue is unknown to check");
  match Rapid_load.Session.load ~testing:true [ file ] with
  | Ok _ -> ()
  | Error _ -> Alcotest.fail "AssertTrue is known to test"

(* The directive: its options, a file named relative to the module, its mistakes with their
   place. *)
let directives () =
  let dir, file = module_ "D" "" in
  write_file file "MODULE D\n  ! the cell's stimulus\n  !rapid-sem: --io cell.io --robot r.robot --max-time 20\nENDMODULE\n";
  (match Suite.directive_options options file with
   | Ok o ->
       Alcotest.(check (option string)) "--io" (Some (Filename.concat dir "cell.io")) o.controller.io;
       Alcotest.(check (option string)) "--robot" (Some (Filename.concat dir "r.robot")) o.robot;
       Alcotest.(check bool) "--max-time" true (o.controller.max_time = 20.)
   | Error m -> Alcotest.fail m);
  write_file file "MODULE D\n   !rapid-sem: --io\nENDMODULE\n";
  (match Suite.directive_options options file with
   | Error m -> Alcotest.(check string) "a value missing" (file ^ ":2:16: test directive: --io needs a value") m
   | Ok _ -> Alcotest.fail "--io without a file is refused");
  write_file file "!rapid-sem: --entry x\nMODULE D\nENDMODULE\n";
  (match Suite.directive_options options file with
   | Error m -> Alcotest.(check bool) "not an option" true (contains m (file ^ ":1:13: test directive: --entry is not"))
   | Ok _ -> Alcotest.fail "--entry is refused")

let coverage_of ?jobs files =
  let s = suite_of files in
  let results = run ?jobs ~coverage:true s in
  List.iter (fun (r : Suite.result) -> Option.iter (U.Test_coverage.add s.coverage) r.hits) results;
  s.coverage

let logic = "MODULE Logic\n  FUNC num Classify(num x)\n    IF x < 0 THEN\n      RETURN -1;\n    ELSEIF x = 0 THEN\n\
             \      RETURN 0;\n    ELSE\n      RETURN 1;\n    ENDIF\n  ENDFUNC\n  FUNC num SumTo(num n)\n\
             \    VAR num s := 0;\n    VAR num i := 0;\n    WHILE i < n DO\n      i := i + 1;\n      s := s + i;\n\
             \    ENDWHILE\n    IF s > 100 s := 100;\n    FOR k FROM 1 TO n DO\n      s := s + 0;\n    ENDFOR\n\
             \    TEST n\n    CASE 1, 2:\n      s := s + 1;\n    CASE 3:\n    DEFAULT:\n      s := s + 2;\n    ENDTEST\n\
             \    RETURN s;\n  ENDFUNC\n  PROC Unused()\n    Classify 1;\n  ENDPROC\nENDMODULE\n"

(* Statement and branch coverage as the machine's steps give it: IF and ELSEIF, WHILE, the
   compact IF, FOR's rounds and exit, TEST's cases and DEFAULT; a branch of a statement never
   reached is "-"; test modules are not covered. *)
let coverage () =
  let dir = temp_dir () in
  let logic_file = Filename.concat dir "logic.mod" and test_file = Filename.concat dir "logic_test.mod" in
  write_file logic_file (Str.global_replace (Str.regexp_string "    Classify 1;\n") "    counter := 1;\n" logic
                         |> Str.global_replace (Str.regexp_string "MODULE Logic\n") "MODULE Logic\n  VAR num counter;\n");
  write_file test_file "MODULE LogicTest\n  PROC test_classify()\n    AssertEqual -1, Classify(-5);\n\
                        \    AssertEqual 1, Classify(5);\n  ENDPROC\n  PROC test_sum()\n    AssertEqual 7, SumTo(3);\n\
                        \  ENDPROC\nENDMODULE\n";
  let lcov = U.Test_coverage.lcov (coverage_of [ logic_file; test_file ]) in
  let lines = String.split_on_char '\n' lcov in
  let has l = Alcotest.(check bool) l true (List.mem l lines) in
  has ("SF:" ^ logic_file);
  Alcotest.(check bool) "the test module is not covered" false (contains lcov "logic_test.mod");
  List.iter has [ "BRDA:4,0,0,1"; "BRDA:4,0,1,1"; (* IF x < 0: once each way *)
                  "BRDA:6,1,0,0"; "BRDA:6,1,1,1"; (* ELSEIF x = 0: never true *)
                  "BRDA:15,2,0,3"; "BRDA:15,2,1,1"; (* WHILE: three rounds, one exit *)
                  "BRDA:19,3,0,0"; "BRDA:19,3,1,1"; (* the compact IF *)
                  "BRDA:20,4,0,3"; "BRDA:20,4,1,1"; (* FOR: three rounds, one exit *)
                  "BRDA:23,5,0,0"; "BRDA:23,5,1,1"; "BRDA:23,5,2,0"; (* TEST 3: the second case *)
                  "BRF:13"; "BRH:9";
                  "FN:3,Classify"; "FNDA:2,Classify"; "FNDA:1,SumTo"; "FN:32,Unused"; "FNDA:0,Unused";
                  "FNF:3"; "FNH:2";
                  "DA:4,2"; "DA:5,1"; "DA:7,0"; "DA:16,3"; "DA:19,1"; "DA:33,0"; "end_of_record" ];
  Alcotest.(check bool) "a label is no line" false (List.exists (fun l -> l = "DA:27,0" || l = "DA:27,1") lines);
  (* The ELSEIF reached once is the other statement of line 6; never reached: the "-" of lcov. *)
  let unused = Str.global_replace (Str.regexp_string "AssertEqual -1, Classify(-5);\n    AssertEqual 1, Classify(5);")
      "AssertTrue TRUE;" (read_file test_file) in
  write_file test_file unused;
  let lcov = U.Test_coverage.lcov (coverage_of [ logic_file; test_file ]) in
  Alcotest.(check bool) "never reached: -" true (contains lcov "BRDA:4,0,0,-\nBRDA:4,0,1,-\n")

(* The lcov file of the cell renders with Debian's genhtml (lcov), when it is installed (CI
   installs it: scripts/install-deps.sh). *)
let genhtml () =
  if Sys.command "command -v genhtml > /dev/null 2>&1" <> 0 then print_endline "genhtml is not installed: skipped"
  else begin
    let out = temp_dir () in
    let info = Filename.concat out "cell.info" in
    let status = Sys.command (Printf.sprintf "%s test %s --coverage %s > /dev/null 2>&1" (Filename.quote Test_cli.binary)
                                cell (Filename.quote info)) in
    Alcotest.(check int) "one deliberate failure" 1 status;
    let html = Filename.concat out "html" in
    let log = Filename.concat out "genhtml.log" in
    let status = Sys.command (Printf.sprintf "genhtml --branch-coverage --quiet -o %s %s > %s 2>&1"
                                (Filename.quote html) (Filename.quote info) (Filename.quote log)) in
    Alcotest.(check string) "genhtml's messages" "" (read_file log);
    Alcotest.(check int) "genhtml's status" 0 status;
    Alcotest.(check bool) "the index" true (Sys.file_exists (Filename.concat html "index.html"));
    (* The page of the cell's module, with its lines' counts. *)
    let pages = Filename.concat out "pages" in
    ignore (Sys.command (Printf.sprintf "find %s -name 'pick_cell.mod.gcov.html' > %s" (Filename.quote html)
                           (Filename.quote pages)));
    match String.split_on_char '\n' (String.trim (read_file pages)) with
    | [ page ] when page <> "" ->
        Alcotest.(check bool) "the TEST line's source" true (contains (read_file page) "TEST partType")
    | _ -> Alcotest.fail "genhtml wrote no page for pick_cell.mod"
  end

(* An XML document as a tree, read with xmlm as a consumer reads it. *)
type xml = Element of string * (string * string) list * xml list | Text of string

let parse_xml text =
  let input = Xmlm.make_input ~strip:true (`String (0, text)) in
  let el ((_, name), attrs) children = Element (name, List.map (fun ((_, k), v) -> (k, v)) attrs, children) in
  snd (Xmlm.input_doc_tree ~el ~data:(fun d -> Text d) input)

let children name = function Element (_, _, cs) -> List.filter (function Element (n, _, _) -> n = name | _ -> false) cs
                             | Text _ -> []

let attr k = function Element (_, a, _) -> List.assoc_opt k a | Text _ -> None

let text_of = function Element (_, _, [ Text t ]) -> t | _ -> ""

(* The JUnit XML of the cell, as a JUnit consumer reads it: testsuites > testsuite > testcase,
   the counts agreeing with the cases, the failure with its message and place. *)
let junit () =
  let s = suite_of (Result.get_ok (Suite.module_files [ cell ])) in
  let results = run s in
  let doc = parse_xml (U.Test_report.junit results) in
  (match doc with Element ("testsuites", _, _) -> () | _ -> Alcotest.fail "the root is testsuites");
  Alcotest.(check (option string)) "tests" (Some "7") (attr "tests" doc);
  Alcotest.(check (option string)) "failures" (Some "1") (attr "failures" doc);
  let suites = children "testsuite" doc in
  Alcotest.(check (list (option string))) "a suite per module" [ Some "NoPartTest"; Some "PickCellTest" ]
    (List.map (attr "name") suites);
  List.iter (fun suite ->
      let cases = children "testcase" suite in
      Alcotest.(check (option string)) "tests of the suite" (Some (string_of_int (List.length cases))) (attr "tests" suite);
      Alcotest.(check (option string)) "failures of the suite"
        (Some (string_of_int (List.length (List.filter (fun c -> children "failure" c <> []) cases))))
        (attr "failures" suite);
      List.iter (fun c ->
          List.iter (fun k -> Alcotest.(check bool) ("testcase " ^ k) true (attr k c <> None))
            [ "name"; "classname"; "time"; "file"; "line" ];
          Alcotest.(check bool) "time is seconds" true (Option.bind (attr "time" c) float_of_string_opt <> None)) cases)
    suites;
  let failed = List.concat_map (fun s -> List.filter (fun c -> children "failure" c <> []) (children "testcase" s)) suites in
  match failed with
  | [ c ] ->
      Alcotest.(check (option string)) "the failing case" (Some "test_two_cycles_count") (attr "name" c);
      let f = List.hd (children "failure" c) in
      Alcotest.(check (option string)) "its message" (Some "parts on the pallet: AssertEqual: expected 3, actual 2")
        (attr "message" f);
      Alcotest.(check bool) "its place" true (contains (text_of f) "pick_cell_test.mod:47:5")
  | _ -> Alcotest.fail "one failing case"

(* Markup and bytes that are not UTF-8 in a message stay well-formed XML. *)
let junit_escapes () =
  let t : Suite.test = { name = "test_<x>"; module_name = "M&N"; file = "a\"b.mod"; line = 1; col = 3; options } in
  let r : Suite.result = { test = t; verdict = Failed { at = Some "a.mod:1:1"; message = "expected \"<\xff>\", actual ]]>" };
                           time = 0.; output = [ "line\x01" ]; hits = None } in
  match parse_xml (U.Test_report.junit [ r ]) with
  | exception Xmlm.Error ((l, c), e) -> Alcotest.failf "not XML at %d:%d: %s" l c (Xmlm.error_message e)
  | doc ->
      let case = List.hd (children "testcase" (List.hd (children "testsuite" doc))) in
      Alcotest.(check (option string)) "name" (Some "test_<x>") (attr "name" case)

(* Cobertura XML: the cell's module a class, its routines methods, the rates the counts'. *)
let cobertura () =
  let files = Result.get_ok (Suite.module_files [ cell ]) in
  let c = coverage_of files in
  Alcotest.(check string) "the counts of three child processes are those of one"
    (U.Test_coverage.lcov c) (U.Test_coverage.lcov (coverage_of ~jobs:3 files));
  let doc = parse_xml (U.Test_coverage.cobertura c ~version:"rapid-sem test") in
  (match doc with Element ("coverage", _, _) -> () | _ -> Alcotest.fail "the root is coverage");
  let covered = int_of_string (Option.get (attr "lines-covered" doc))
  and valid = int_of_string (Option.get (attr "lines-valid" doc)) in
  Alcotest.(check bool) "most lines" true (covered > 0 && covered < valid);
  let classes = List.concat_map (children "class") (List.concat_map (children "classes")
                                                       (List.concat_map (children "package") (children "packages" doc))) in
  Alcotest.(check (list (option string))) "one class, the cell's module" [ Some "PickCell" ] (List.map (attr "name") classes);
  let methods = List.concat_map (children "method") (List.concat_map (children "methods") classes) in
  Alcotest.(check (list (option string))) "its routines"
    [ Some "SlotTarget"; Some "Vacuum"; Some "Grip"; Some "Release"; Some "PickAndPlace"; Some "main" ]
    (List.map (attr "name") methods);
  let lines = List.concat_map (children "line") (List.concat_map (children "lines") classes) in
  Alcotest.(check int) "its lines" valid (List.length lines);
  Alcotest.(check bool) "the TEST's three ways" true
    (List.exists (fun l -> attr "condition-coverage" l = Some "100% (3/3)") lines)

(* A test whose dialogue the operator's script leaves unanswered fails with what happened, not
   with "not modelled" (R-13-ui2); without a script the dialogue is not modelled. *)
let operator_dialogue () =
  let dir = temp_dir () in
  let m = Filename.concat dir "t_ui.mod" and script = Filename.concat dir "answers.txt" in
  write_file m "MODULE t_ui\n  PROC test_dialogue()\n    VAR num key;\n\
               \    TPReadFK key, \"Go on?\", \"Yes\", \"No\", stEmpty, stEmpty, stEmpty;\n\
               \    AssertEqual key, 1;\n\
               \    TPReadFK key, \"Again?\", \"Yes\", \"No\", stEmpty, stEmpty, stEmpty;\n  ENDPROC\nENDMODULE\n";
  write_file script "TPReadFK 1\n";
  let with_operator operator =
    { options with controller = { options.controller with
                                  services = { options.controller.services with operator } } } in
  let verdict operator =
    match Suite.discover ~notify:ignore (with_operator operator) [ m ] with
    | Error _ -> Alcotest.fail "the task buffer is refused"
    | Ok s -> verdicts (run s) in
  Alcotest.(check (list string)) "the second dialogue has no answer"
    [ Printf.sprintf "test_dialogue failed at %s:6:5: no answer from the operator: the operator script %s has no \
                      answer left for TPReadFK (its 1 answers are used)" m script ]
    (verdict (Some script));
  Alcotest.(check (list string)) "without an operator"
    [ Printf.sprintf "test_dialogue failed at %s:4:5: not modelled: TPReadFK is an installed routine whose \
                      behaviour rapid-sem does not model yet" m ]
    (verdict None)

let suite =
  ( "unit-test",
    [ Alcotest.test_case "the pick-and-place cell" `Quick pick_cell;
      Alcotest.test_case "assertions" `Quick assertions;
      Alcotest.test_case "expected and unexpected errors" `Quick errors;
      Alcotest.test_case "discovery, fresh data" `Quick discovery;
      Alcotest.test_case "assertions only under test" `Quick only_under_test;
      Alcotest.test_case "directives" `Quick directives;
      Alcotest.test_case "coverage" `Quick coverage;
      Alcotest.test_case "genhtml renders the lcov file" `Quick genhtml;
      Alcotest.test_case "JUnit XML read by a consumer" `Quick junit;
      Alcotest.test_case "JUnit XML escapes" `Quick junit_escapes;
      Alcotest.test_case "Cobertura XML" `Quick cobertura;
      Alcotest.test_case "a dialogue the operator's script leaves open" `Quick operator_dialogue ] )
