(* Issue 21, utf8: every JSON and XML document rapid-sem writes is valid UTF-8, whatever bytes it
   carries (doc/rulings.md R-2.1-utf8n). A file name with the byte 0xFF, on a program refused
   with a syntax or a semantic error, through every JSON writer of the command line; and an
   implementation under spec --impl whose output is 0xFF and an escape sequence, through the JSON
   report and the JUnit XML. Each document is decoded strictly: UTF-8 by Utf8_text.is_utf8, JSON
   by Yojson, XML by xmlm. *)

(* The command line's binary and the file helpers, as the services' tests have them. *)
let binary = Test_services.binary
let temp_dir = Test_services.temp_dir
let read_file = Test_services.read_file
let write_file = Test_services.write_file

(* Runs rapid-sem in [dir]; its standard output. *)
let run_in dir args =
  let out = Filename.temp_file "rapid-sem" ".out" in
  let _ = Sys.command (Printf.sprintf "cd %s && %s %s > %s 2>/dev/null" (Filename.quote dir)
                         (Filename.quote binary) args (Filename.quote out)) in
  let text = read_file out in
  Sys.remove out; text

let strict_utf8 what text =
  if not (Rapid_runtime.Utf8_text.is_utf8 text) then
    Alcotest.failf "%s: not valid UTF-8: %S" what text

let json_lines what text =
  strict_utf8 what text;
  List.iter (fun l -> if l <> "" then ignore (Yojson.Safe.from_string l)) (String.split_on_char '\n' text)

let contains s sub =
  let n = String.length sub and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = sub || go (i + 1)) in
  go 0

let syntax_error = "MODULE e\n  PROC main()\n    TPWrite \"x\"\n  ENDPROC\nENDMODULE\n"
let semantic_error = "MODULE e\n  PROC main()\n    nowhere := 1;\n  ENDPROC\nENDMODULE\n"

let file_name_refused program (args, lines) () =
  let dir = temp_dir () in
  let name = "e\xff.mod" in
  write_file (Filename.concat dir name) program;
  let args = args ^ " " ^ Filename.quote name in
  let out = run_in dir args in
  Sys.remove (Filename.concat dir name); Sys.rmdir dir;
  if lines then json_lines args out else (strict_utf8 args out; ignore (Yojson.Safe.from_string out));
  (* The byte read as Latin-1, as RAPID text is (R-2.1-b): 0xFF is U+00FF; SARIF's URI says %FF. *)
  if not (contains out "e\xc3\xbf.mod" || contains out "e%FF.mod") then
    Alcotest.failf "%s: the file is not named: %S" args out

let commands = [ ("run --json", true); ("verdict", true); ("check --format json", false);
                 ("check --format sarif", false) ]

(* A case of each format the implementation is asked about: a run, and a refused program. *)
let case_run =
  "! @section 4.6\n! @expect output \"hi\"\nMODULE m\n  PROC main()\n    TPWrite \"hi\";\n  ENDPROC\nENDMODULE\n"
let case_refused =
  "! @section 2.5\n! @expect syntax-error 3:5\nMODULE m\n  PROC main()\n    x := ;\n  ENDPROC\nENDMODULE\n"

let rec xml_parse input =
  match Xmlm.input input with
  | `Dtd _ | `El_start _ | `El_end | `Data _ -> if Xmlm.eoi input then () else xml_parse input

(* The spec run once for both reports' tests: its two files' texts. *)
let reports = lazy (
  let dir = temp_dir () in
  let cases = Filename.concat dir "cases" in
  Sys.mkdir cases 0o755;
  write_file (Filename.concat cases "01-run.mod") case_run;
  write_file (Filename.concat cases "02-refused.mod") case_refused;
  (* 0xFF, ESC (which XML 1.0 forbids), U+FFFE (valid UTF-8, not an XML character). *)
  let impl = Filename.quote "printf \"\\377\\033[31mRED\\357\\277\\276\\n\" # {files}" in
  let _ = run_in dir (Printf.sprintf "spec --impl %s --report-json rep.json --junit j.xml cases" impl) in
  let json = read_file (Filename.concat dir "rep.json") and xml = read_file (Filename.concat dir "j.xml") in
  List.iter (fun f -> Sys.remove (Filename.concat cases f)) [ "01-run.mod"; "02-refused.mod" ];
  Sys.rmdir cases;
  List.iter (fun f -> Sys.remove (Filename.concat dir f)) [ "rep.json"; "j.xml" ];
  Sys.rmdir dir;
  (json, xml))

let report_json () =
  let json, _ = Lazy.force reports in
  strict_utf8 "rep.json" json;
  ignore (Yojson.Safe.from_string json);
  if not (contains json "RED") then Alcotest.failf "the output is not reported: %s" json

let junit_xml () =
  let _, xml = Lazy.force reports in
  strict_utf8 "j.xml" xml;
  (match xml_parse (Xmlm.make_input (`String (0, xml))) with
   | () -> ()
   | exception Xmlm.Error ((l, c), e) -> Alcotest.failf "j.xml:%d:%d: %s\n%s" l c (Xmlm.error_message e) xml);
  if not (contains xml "RED") then Alcotest.failf "the output is not reported: %s" xml;
  if not (contains xml "\\1B") then Alcotest.failf "j.xml: ESC is not written as \\1B: %s" xml

let suite =
  ( "utf8 output",
    List.concat_map (fun (what, program, commands) ->
        List.map (fun ((args, _) as c) ->
            Alcotest.test_case (Printf.sprintf "%s, file e\\xff.mod, %s: UTF-8" what args) `Quick
              (file_name_refused program c)) commands)
      [ ("syntax error", syntax_error, commands @ [ ("verdict --stage parse", true) ]);
        ("semantic error", semantic_error, commands) ]
    @ [ Alcotest.test_case "spec --impl writing 0xFF and ESC: --report-json is UTF-8 JSON" `Quick report_json;
        Alcotest.test_case "spec --impl writing 0xFF and ESC: --junit is well-formed XML" `Quick junit_xml ] )
