(* rapid-sem spec --impl: the conformance suite through the oracle's protocol, its JUnit XML and
   JSON reports (doc/oracle.md). The implementation is rapid-sem itself behind the protocol, and
   a wrapper that alters one output line. *)

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"
let cases = "golden/spec-impl-cases"

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

let contains s sub =
  let n = String.length sub and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = sub || go (i + 1)) in
  go 0

let run_with script =
  Unix.putenv "RAPID_SEM" binary;
  let junit = Filename.temp_file "junit" ".xml" and json = Filename.temp_file "report" ".json" in
  let buffer = Buffer.create 256 in
  let out = Format.formatter_of_buffer buffer in
  let passed, failed =
    Rapid_conformance.Impl_runner.run ~junit ~json
      ~template:(Printf.sprintf "sh golden/%s {mode} {options} {files}" script) out cases in
  Format.pp_print_flush out ();
  let x = read_file junit and j = Yojson.Safe.from_string (read_file json) in
  Sys.remove junit; Sys.remove json;
  (passed, failed, x, j)

let field name = function `Assoc f -> List.assoc name f | _ -> `Null

let self_agrees () =
  let passed, failed, xml, json = run_with "spec-impl-self.sh" in
  Alcotest.(check (pair int int)) "passed, failed" (4, 0) (passed, failed);
  Alcotest.(check bool) "JUnit: the totals" true (contains xml "<testsuites name=\"rapid-sem conformance\" tests=\"4\" failures=\"0\"");
  Alcotest.(check bool) "JUnit: a suite per section" true (contains xml "<testsuite name=\"§4.18\"");
  Alcotest.(check bool) "JUnit: a test case per case" true (contains xml "name=\"golden/spec-impl-cases/18-for-step.mod\"");
  Alcotest.(check bool) "JSON: passed" true (field "passed" json = `Int 4)

let wrong_is_caught () =
  let passed, failed, xml, json = run_with "spec-impl-wrong.sh" in
  Alcotest.(check (pair int int)) "passed, failed" (2, 2) (passed, failed);
  Alcotest.(check bool) "JUnit: failures" true (contains xml "failures=\"2\"");
  Alcotest.(check bool) "JUnit: the failure says what differs" true (contains xml "<failure message=\"output &quot;1!&quot;");
  Alcotest.(check bool) "JSON: failed" true (field "failed" json = `Int 2)

let suite =
  ("impl-runner", [
      Alcotest.test_case "rapid-sem behind the protocol agrees with the suite" `Quick self_agrees;
      Alcotest.test_case "a wrong implementation is caught, in JUnit and JSON too" `Quick wrong_is_caught ])
