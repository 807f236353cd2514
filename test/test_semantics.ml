(* The dynamic semantics against its documentation: every rule the machine names is stated in
   doc/semantics.md, every rule stated there is one the machine has, and every rule appears in
   the trace of at least one run of spec/ (format 3 cases). *)

open Rapid_syntax
module M = Rapid_semantics.Machine

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

(* The rule names of doc/semantics.md: the bold names of its "Rules" section, before "Not rules". *)
let documented_rules () =
  let text = read_file "../doc/semantics.md" in
  let start = Str.search_forward (Str.regexp_string "## Rules") text 0 in
  let stop = Str.search_forward (Str.regexp_string "### Not rules") text start in
  let section = String.sub text start (stop - start) in
  let rec collect pos acc =
    match Str.search_forward (Str.regexp "\\*\\*\\([a-z-]+\\)\\*\\*") section pos with
    | p -> collect (p + 1) (Str.matched_group 1 section :: acc)
    | exception Not_found -> List.sort_uniq compare acc
  in
  collect 0 []

let not_rules = [ "done"; "stuck" ]

let machine_rules () = List.filter (fun r -> not (List.mem r not_rules)) M.rule_names |> List.sort_uniq compare

let documentation_matches () =
  let doc = documented_rules () and code = machine_rules () in
  let missing = List.filter (fun r -> not (List.mem r doc)) code in
  let extra = List.filter (fun r -> not (List.mem r code)) doc in
  Alcotest.(check (list string)) "rules of the machine missing from doc/semantics.md" [] missing;
  Alcotest.(check (list string)) "rules of doc/semantics.md the machine does not have" [] extra

(* Runs every format 3 case of spec/ and collects the rules applied. *)
let rules_in_spec () =
  let used = Hashtbl.create 128 in
  (match Rapid_typing.Installed_env.modules () with
   | Ok _ -> () | Error d -> Alcotest.failf "installed: %s" (Diagnostic.to_string d));
  List.iter (fun path ->
      let case = Rapid_conformance.Spec_case.read path in
      match case.run with
      | Some run when case.format = "3" -> (
          let modules = List.filter_map (fun f -> Result.to_option (Parse.parse_file f)) case.files in
          (* As rapid-sem runs a task: checked, lowered, its initial values computed; a case with
             a stimulus file (! @io) with its signals (doc/controller.md). *)
          let io = match run.io with
            | Some f -> Result.value (Rapid_controller.Io_config.read_file f) ~default:Rapid_controller.Io_config.empty
            | None -> Rapid_controller.Io_config.empty in
          match Rapid_load.Session.load_modules ~allow_unknown:case.allow_unknown ~io modules with
          | Error _ -> ()
          | Ok { program; _ } ->
            let limits = { Rapid_runtime.Limits.default with
                           retry_limit = Option.value run.retry_limit ~default:Rapid_runtime.Limits.default.retry_limit } in
            let world = Rapid_controller.World.create ?statement_time:run.statement_time ?max_time:run.max_time io in
            match M.start ~host:(Rapid_run.Run.setup ~controller:world ()).host ~limits ~stub_unmodelled:case.Rapid_conformance.Spec_case.stub_unmodelled program ~entry:run.entry with
            | Ok cfg ->
                let max = Option.value run.max_steps ~default:1_000_000 in
                while M.outcome cfg = Running && M.steps cfg < max do
                  let rule, _ = M.step cfg in
                  Hashtbl.replace used rule path
                done
            | Error _ -> ())
      | Some ({ tasks = _ :: _; _ } as run) -> (
          (* Several tasks (format 4): the rules of every task's steps. *)
          let module TS = Rapid_semantics.Task_set in
          let world = Rapid_controller.World.create ?statement_time:run.statement_time ?max_time:run.max_time
              Rapid_controller.Io_config.empty in
          let specs = List.map (fun (name, files) -> { Rapid_run.Task_load.name; files; entry = run.entry }) run.tasks in
          match Rapid_run.Run.machine_tasks ?seed:run.schedule ~controller:world
                  ~motion:(Rapid_installed.Motion_routines.create ()) specs with
          | Error _ -> ()
          | Ok (ts, _) ->
              let rec loop n = if n > 0 then match TS.step ts with
                  | Some (_, rule, _) -> Hashtbl.replace used rule path; loop (n - 1)
                  | None -> () in
              loop 1_000_000)
      | _ -> ()) (Rapid_conformance.Spec_runner.find_cases "../spec");
  used

let every_rule_in_a_trace () =
  let used = rules_in_spec () in
  let missing = List.filter (fun r -> not (Hashtbl.mem used r)) (documented_rules ()) in
  Alcotest.(check (list string)) "rules of doc/semantics.md in no spec/ trace" [] missing

(* A routine of half a million statements is checked, lowered and run without exhausting the
   stack (bad input never crashes; CAD modules are long). *)
let long_routine () =
  let n = 500_000 in
  let b = Buffer.create (n * 16) in
  Buffer.add_string b "MODULE long\n  VAR num x;\n  PROC main()\n";
  for _ = 1 to n do Buffer.add_string b "    x := x + 1;\n" done;
  Buffer.add_string b "    TPWrite \"x=\" \\Num:=x;\n  ENDPROC\nENDMODULE\n";
  match Parse.parse_string ~name:"long.mod" (Buffer.contents b) with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Rapid_load.Session.load_modules [ m ] with
      | Error _ -> Alcotest.fail "the long routine does not check"
      | Ok loaded -> (
          match M.start ~host:(Rapid_run.Run.setup ()).host loaded.program ~entry:"main" with
          | Error e -> Alcotest.fail e
          | Ok cfg ->
              let out = ref [] in
              while M.outcome cfg = Running do
                List.iter (function Rapid_runtime.Event.Output s -> out := s :: !out | _ -> ()) (snd (M.step cfg))
              done;
              Alcotest.(check (list string)) "output" [ "x=500000" ] !out))

(* The machine of a one-module program, ready to run main. *)
let machine_of text =
  match Parse.parse_string ~name:"t.mod" text with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Rapid_load.Session.load_modules [ m ] with
      | Error _ -> Alcotest.fail "the program does not check"
      | Ok loaded -> (
          match M.start ~host:(Rapid_run.Run.setup ()).host loaded.program ~entry:"main" with Error e -> Alcotest.fail e | Ok cfg -> cfg))

(* The rules of the steps from the [from]th on, up to [count] of them. *)
let rules_of cfg ~skip ~count =
  for _ = 1 to skip do ignore (M.step cfg) done;
  List.init count (fun _ -> fst (M.step cfg))

(* Settling (doc/semantics.md): the administrative moves are not steps; what is left is one step
   per redex a programmer names. *)
let settled_steps () =
  let cfg = machine_of "MODULE t\n  VAR num x := 1;\n  PROC main()\n    x := x + 1;\n    x := 2;\n  ENDPROC\nENDMODULE\n" in
  Alcotest.(check (list string)) "x := x + 1; then x := 2;"
    [ "assign"; "binary-operands"; "read"; "binary"; "store"; "assign"; "store"; "return-entry" ]
    (rules_of cfg ~skip:0 ~count:8);
  Alcotest.(check bool) "ended" true (M.outcome cfg = Rapid_runtime.Outcome.Ended);
  (* Literal arguments and absent optional parameters are bound without steps of their own. *)
  let cfg = machine_of "MODULE t\n  PROC main()\n    TPWrite \"a\";\n  ENDPROC\nENDMODULE\n" in
  Alcotest.(check (list string)) "TPWrite \"a\";" [ "call-arguments"; "call-primitive"; "return-entry" ]
    (rules_of cfg ~skip:0 ~count:3);
  (* A component of a record parameter is read in one step; an element takes its index. *)
  let cfg = machine_of "MODULE t\n  VAR pos p := [1, 2, 3];\n  VAR num a{2} := [5, 6];\n  VAR num r;\n\
                        \  VAR pos q{2};\n  PROC main()\n    r := p.y;\n    r := a{2};\n    q{r - 5}.z := 7;\n\
                        \    TPWrite \"\" \\Num:=q{1}.z;\n  ENDPROC\nENDMODULE\n" in
  Alcotest.(check (list string)) "r := p.y; r := a{2}; q{r - 5}.z := 7;"
    [ "assign"; "read"; "store"; "assign"; "read-place"; "element"; "store";
      "assign"; "binary-operands"; "read"; "binary"; "element"; "store" ]
    (rules_of cfg ~skip:0 ~count:13);
  let out = ref [] in
  while M.outcome cfg = Running do
    List.iter (function Rapid_runtime.Event.Output s -> out := s :: !out | _ -> ()) (snd (M.step cfg))
  done;
  Alcotest.(check (list string)) "the component of the element written" [ "7" ] !out

(* Values in RAPID's syntax, numbers with enough digits to read back to the same number. *)
let value_text () =
  let module V = Rapid_runtime.Value in
  let text = Rapid_tools.Trace_view.value in
  Alcotest.(check string) "integer" "16777216" (text (V.num 16777216.));
  Alcotest.(check string) "0.1" "0.1" (text (V.num 0.1));
  Alcotest.(check string) "largest single" "3.4028235E+38" (text (V.num 3.4028235e38));
  Alcotest.(check string) "dnum 0.1" "0.1" (text (V.dnum 0.1));
  Alcotest.(check string) "string" "\"say \"\"hi\"\"\"" (text (V.String "say \"hi\""));
  Alcotest.(check string) "record" "[1,2.5,-3]" (text (V.pos 1. 2.5 (-3.)));
  Alcotest.(check string) "array of records" "[[TRUE],[FALSE]]"
    (text (V.Array [| V.Record [| V.Bool true |]; V.Record [| V.Bool false |] |]));
  let rng = Random.State.make [| 42 |] in
  for _ = 1 to 2000 do
    let f = V.to_single (Int64.float_of_bits (Random.State.int64 rng Int64.max_int)
                         *. (if Random.State.bool rng then 1. else -1.)) in
    if Float.is_finite f then begin
      let s = text (V.num f) in
      if V.to_single (float_of_string s) <> f then Alcotest.failf "num %h written %s" f s;
      let d = Int64.float_of_bits (Random.State.int64 rng Int64.max_int) in
      if Float.is_finite d then
        let s = text (V.dnum d) in
        if float_of_string s <> d then Alcotest.failf "dnum %h written %s" d s
    end
  done

let suite =
  ( "semantics",
    [ Alcotest.test_case "settling: one step per redex" `Quick settled_steps;
      Alcotest.test_case "trace values in RAPID's syntax" `Quick value_text;
      Alcotest.test_case "a routine of 500,000 statements runs" `Quick long_routine;
      Alcotest.test_case "doc/semantics.md states every rule" `Quick documentation_matches;
      Alcotest.test_case "every rule appears in a spec/ trace" `Quick every_rule_in_a_trace ] )
