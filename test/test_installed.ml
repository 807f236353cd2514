(* The installed environment and the names it lacks: --allow-unknown reports each unknown name
   once, at its first use in source order, with its number of uses (doc/typing.md, unknown-name);
   every installed routine without a primitive is one the machine reports as not modelled. *)

open Rapid_syntax

let installed () =
  match Rapid_typing.Installed_env.modules () with
  | Ok ms -> ms | Error d -> Alcotest.failf "installed: %s" (Diagnostic.to_string d)

let parse name text =
  match Parse.parse_string ~name text with
  | Ok m -> m | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)

let check modules =
  Rapid_typing.Check.check_task ~options:{ allow_unknown = true } ~installed:(installed ()) modules

let describe (u : Rapid_typing.Check.unknown_name) =
  let p = Source.start u.first in
  let file = match Source.file_of u.first with Some f -> Source.name f | None -> "" in
  Printf.sprintf "%s %s %s:%d:%d x%d" u.what u.name file p.line p.col u.uses

(* The module-level declaration of b.mod is judged before the routine bodies of a.mod, yet the
   first use is a.mod's: source order is file order, then position. Letter case does not make
   another name (§2.3); a procedure and a data object of one name are two unknown names. *)
let first_use_in_source_order () =
  let a = parse "a.mod" "MODULE a\n  PROC main()\n    Grip;\n    x := 1;\n    GRIP;\n  ENDPROC\nENDMODULE\n" in
  let b = parse "b.mod" "MODULE b\n  VAR num y := X;\n  PROC other()\n    grip;\n  ENDPROC\nENDMODULE\n" in
  let result = check [ a; b ] in
  Alcotest.(check (list string)) "unknown names"
    [ "procedure Grip a.mod:3:5 x3"; "data object x a.mod:4:5 x2" ]
    (List.map describe result.unknown);
  Alcotest.(check int) "one warning per name" 2
    (List.length (List.filter (fun (r : Rapid_typing.Report.t) -> r.rule = "unknown-name") result.reports));
  Alcotest.(check (option string)) "summary"
    (Some "2 names unknown (5 uses); they are warnings under --allow-unknown")
    (Rapid_typing.Check.unknown_summary result)

(* Without --allow-unknown an unknown name is an error once per routine (the issue's "reported
   once per routine"), in each routine that uses it; nothing is summed up. *)
let errors_stay_per_use () =
  let a = parse "a.mod" "MODULE a\n  PROC main()\n    Grip;\n    Grip;\n  ENDPROC\n  PROC other()\n    Grip;\n  ENDPROC\nENDMODULE\n" in
  let result = Rapid_typing.Check.check_task ~installed:(installed ()) [ a ] in
  Alcotest.(check int) "one error per routine" 2 (List.length (Rapid_typing.Check.errors result));
  Alcotest.(check (option string)) "no summary" None (Rapid_typing.Check.unknown_summary result)

(* A stubbed function gives its result type's initial value (RunMode: a symnum, 0), and the run
   goes on. *)
let stubbed_record_result () =
  let m = parse "r.mod"
      "MODULE r\n  VAR symnum m;\n  PROC main()\n    m := RunMode();\n    TPWrite \"m=\" \\Num:=m;\n  ENDPROC\nENDMODULE\n" in
  match Rapid_load.Session.load_modules [ m ] with
  | Error _ -> Alcotest.fail "does not load"
  | Ok loaded -> (
      let module M = Rapid_semantics.Machine in
      match M.start ~host:(Rapid_run.Run.setup ()).host ~stub_unmodelled:true loaded.program ~entry:"main" with
      | Error e -> Alcotest.fail e
      | Ok cfg ->
          let out = ref [] and stubbed = ref [] in
          while M.outcome cfg = Running do
            List.iter (function
                | Rapid_runtime.Event.Output s -> out := s :: !out
                | Rapid_runtime.Event.Stubbed { routine; _ } -> stubbed := routine :: !stubbed
                | _ -> ()) (snd (M.step cfg))
          done;
          Alcotest.(check bool) "ended" true (M.outcome cfg = Ended);
          Alcotest.(check (list string)) "stubbed" [ "RunMode" ] !stubbed;
          Alcotest.(check (list string)) "output" [ "m=0" ] !out)

(* Source ids are reused after 1023 files; the installed modules, parsed once per process, keep
   theirs (Source.keep): a file parsed later never has regions equal to theirs, which key the
   tables of every check (a literal's kind: btnNone := -1 once read as a dnum). *)
let installed_ids_kept () =
  let open Rapid_syntax in
  let installed = installed () in
  let names () = List.map (fun (m : Ast.module_declaration) ->
      match Source.file_of m.module_region with Some f -> Source.name f | None -> "") installed in
  let before = names () in
  for i = 1 to 2100 do ignore (Source.register ~name:(Printf.sprintf "other%d.mod" i) ~line_starts:[| 0 |]) done;
  Alcotest.(check (list string)) "the installed modules' files" before (names ());
  Alcotest.(check bool) "they have names" true (List.for_all (fun n -> n <> "") before)

(* R-13-choice1: SearchL's "Signal | PersBool" is a required choice (Installed_choices): a signal
   or a PERS bool in that place, by type or by name; a VAR bool is refused for PersBool (PERS),
   and a missing argument names both alternatives. *)
let required_choice () =
  let errors text =
    let m = parse "c.mod" text in
    List.filter_map (fun (r : Rapid_typing.Report.t) ->
        if r.severity = Rapid_typing.Report.Error then
          let p = Source.start r.region in Some (Printf.sprintf "%d:%d %s" p.line p.col r.rule)
        else None) (check [ m ]).reports in
  let prog call =
    "MODULE c\n  PERS bool pb := FALSE;\n  VAR bool vb;\n  VAR signaldi sdi;\n  VAR robtarget f;\n\
     \  CONST robtarget t := [[300,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n\
     \  PROC main()\n    " ^ call ^ "\n  ENDPROC\nENDMODULE\n" in
  Alcotest.(check (list string)) "a signal" [] (errors (prog "SearchL \\Stop, sdi, f, t, v100, tool0;"));
  Alcotest.(check (list string)) "a PERS bool" [] (errors (prog "SearchL \\SStop, pb, f, t, v100, tool0;"));
  Alcotest.(check (list string)) "named" [] (errors (prog "SearchJ PersBool:=pb, f, t, v100, tool0;"));
  Alcotest.(check (list string)) "a VAR bool" [ "8:20 access-mode" ]
    (errors (prog "SearchL \\Stop, vb, f, t, v100, tool0;"));
  Alcotest.(check (list string)) "a wrong name" [ "8:13 argument-name" ]
    (errors (prog "SearchL Sensor:=pb, f, t, v100, tool0;"));
  Alcotest.(check bool) "\\PersBool is not optional" true
    (List.exists (fun e -> e = "8:19 argument-required")
       (errors (prog "SearchL \\Stop \\PersBool:=pb, f, t, v100, tool0;")))

(* Installed_routine.fixed: the closure engine calls a function of required parameters by their
   number; its answer must be the general form's, on every kind of argument (a wrong type raises
   the same way too). *)
let fixed_arity_same_answers () =
  let module V = Rapid_runtime.Value in
  let module L = Rapid_installed.Library in
  let values = [ V.Num 0.; V.Num 2.5; V.Num (-3.); V.Num 1e30; V.Dnum 7.; V.Dnum (-0.5); V.String "";
                 V.String "abcdef"; V.Bool true; V.Record [| V.Num 1.; V.Num 2.; V.Num 3. |];
                 V.Record [| V.Num 1.; V.Num 0.; V.Num 0.; V.Num 0. |] ] in
  let answer f = match f () with r -> Ok r | exception V.Type_mismatch w -> Error w in
  let same name general fixed =
    if answer general <> answer fixed then Alcotest.failf "%s: the two forms differ" name in
  let known = ref 0 in
  List.iter (fun (name, arity, f) ->
      match L.find_fixed name with
      | None -> ()
      | Some fixed ->
          incr known;
          let general args = fun () -> f (Array.of_list (List.map Option.some args)) in
          (match fixed with
           | Rapid_runtime.Installed_routine.One g ->
               Alcotest.(check int) (name ^ ": one parameter") 1 arity;
               List.iter (fun a -> same name (general [ a ]) (fun () -> g a)) values
           | Length g ->
               (* the promise an engine computes it by: a string's length, as a num *)
               Alcotest.(check int) (name ^ ": one parameter") 1 arity;
               List.iter (fun a -> same name (general [ a ]) (fun () -> g a)) values;
               List.iter (fun s -> if g (V.String s) <> Ok (V.Num (float_of_int (String.length s))) then
                             Alcotest.failf "%s: not the length of %S" name s) [ ""; "a"; "abcdef"; String.make 80 'x' ]
           | Two g ->
               Alcotest.(check int) (name ^ ": two parameters") 2 arity;
               List.iter (fun a -> List.iter (fun b -> same name (general [ a; b ]) (fun () -> g a b)) values) values
           | Three g ->
               Alcotest.(check int) (name ^ ": three parameters") 3 arity;
               List.iter (fun a -> List.iter (fun b -> List.iter (fun c ->
                   same name (general [ a; b; c ]) (fun () -> g a b c)) values) values) values))
    L.functions;
  Alcotest.(check bool) "most functions are known by their number of parameters" true (!known > 40);
  Alcotest.(check bool) "StrFind (an optional switch) is not" true (L.find_fixed "StrFind" = None)

let suite =
  ( "installed",
    [ Alcotest.test_case "--allow-unknown: one report per name, first use in source order" `Quick
        first_use_in_source_order;
      Alcotest.test_case "without --allow-unknown: an error per use" `Quick errors_stay_per_use;
      Alcotest.test_case "--stub-unmodelled: a record result is its initial value" `Quick
        stubbed_record_result;
      Alcotest.test_case "the installed modules keep their source ids" `Quick installed_ids_kept;
      Alcotest.test_case "a required choice: SearchL Signal | PersBool (R-13-choice1)" `Quick required_choice;
      Alcotest.test_case "a function by its number of parameters answers as its general form" `Quick
        fixed_arity_same_answers ] )
