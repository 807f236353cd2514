(* The installed environment computed at build time (lib/load/installed_image.ml) is the one
   computed now: the test process takes it from the image, and the environment parsed, checked
   and lowered here afresh, from the same files' table and record ids as the build started from,
   marshals to the same bytes (so it holds no functional value either: Marshal would refuse it).
   The process's own table of files and record ids are put back afterwards. *)

module Level = Rapid_runtime.Installed_level

let image () : Level.t = Marshal.from_string Rapid_load.Installed_image.data 0

let in_use () =
  Alcotest.(check bool) "the installed environment comes from the image" true (Rapid_load.Installed_image.in_use ());
  match Rapid_typing.Installed_env.modules () with
  | Error _ -> Alcotest.fail "the installed environment does not parse"
  | Ok modules ->
      Alcotest.(check int) "its modules" (List.length (Level.modules (image ()))) (List.length modules);
      (* the checker's and the lowering's kept work is found by this list, compared physically *)
      Alcotest.(check bool) "the same list at every call" true
        (match Rapid_typing.Installed_env.modules () with Ok again -> again == modules | Error _ -> false);
      Alcotest.(check bool) "without the assertions of rapid-sem test" true
        (List.for_all (fun (m : Rapid_syntax.Ast.module_declaration) ->
             match m.module_name.it with
             | Rapid_syntax.Ast.Ident n -> String.lowercase_ascii n <> "installed_unit_test"
             | ID_placeholder -> true) modules)

let same_as_now () =
  let files, records = Level.before (image ()) in
  let saved_files = Rapid_syntax.Source.registry () and saved_records = Rapid_typing.Types.record_ids_used () in
  Rapid_syntax.Source.restore_registry files;
  Rapid_typing.Types.restore_record_ids records;
  let now = Level.compute () in
  Rapid_syntax.Source.restore_registry saved_files;
  Rapid_typing.Types.restore_record_ids saved_records;
  match now with
  | Error e -> Alcotest.fail e
  | Ok now ->
      Alcotest.(check bool) "the same bytes as the image's" true
        (Marshal.to_string now [] = Rapid_load.Installed_image.data)

(* A program over the image's environment: its routines and globals come after the installed
   ones, and an installed routine, a record type and an installed constant are found. *)
let program_runs () =
  let text = {|MODULE m
  VAR robtarget p := [[1,2,3],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TPWrite "x" \Num:=p.trans.x + StrLen("abc");
    TPWrite ValToStr(v100);
  ENDPROC
ENDMODULE
|} in
  let m = match Rapid_syntax.Parse.parse_string ~name:"image.mod" text with
    | Ok m -> m | Error _ -> Alcotest.fail "the program does not parse" in
  match Rapid_fuzz.Fuzz_run.load m with
  | Error _ -> Alcotest.fail "the program does not check"
  | Ok l ->
      List.iter (fun (e : Rapid_fuzz.Fuzz_run.engine) ->
          let o = e.run l.program ~max_steps:10_000 in
          let lines = List.filter (fun l -> String.length l > 7 && String.sub l 0 7 = "output ") o.events in
          Alcotest.(check (list string)) e.engine_name [ "output x4"; "output [100,500,5000,1000]" ] lines)
        [ Rapid_fuzz.Fuzz_run.machine; Rapid_fuzz.Fuzz_run.closure ]

(* A task without signals or assertions is checked against the image's list itself: the checker
   and the lowering know the installed level by that list, and a copy of it (an append of
   nothing) would check and lower the whole installed environment again at every start. *)
let same_list () =
  match Rapid_typing.Installed_env.modules (), Rapid_load.Session.installed () with
  | Ok image, Ok session -> Alcotest.(check bool) "the same list" true (image == session)
  | _ -> Alcotest.fail "the installed environment does not parse"

(* Data read by Gc_pacing.read_marked is allocated marked in a cycle begun for it: it must live
   through that cycle's end and the next ones like any other, its fields updated with values
   younger than it (the write barrier on marked blocks), and compaction. *)
let read_marked_survives () =
  let tree = Array.init 2_000 (fun i -> (string_of_int i, [ float_of_int i; 0.5 ], Array.make 3 (Some i))) in
  let bytes = Marshal.to_string tree [] in
  Gc.full_major ();
  let kept : (string * float list * int option array) array =
    Rapid_load.Gc_pacing.read_marked (fun () -> Marshal.from_string bytes 0) in
  let expected = Array.map (fun (s, l, a) -> (s, l, Array.copy a)) tree in
  let garbage = ref [] in
  for round = 1 to 200 do
    for i = 0 to 99 do
      let k = (round * 100 + i) mod Array.length kept in
      let _, _, a = kept.(k) and _, _, e = expected.(k) in
      let fresh = Some (round + k) in
      a.(round mod 3) <- fresh; e.(round mod 3) <- fresh;
      garbage := List.init 50 (fun j -> string_of_int (j + round)) :: !garbage
    done;
    if round mod 50 = 0 then (garbage := []; Gc.full_major ())
  done;
  Gc.compact ();
  Alcotest.(check bool) "the data read is intact" true (kept = expected)

let suite =
  ( "installed image",
    [ Alcotest.test_case "the environment comes from the image" `Quick in_use;
      Alcotest.test_case "the image is the environment computed now" `Quick same_as_now;
      Alcotest.test_case "a program over the image's environment" `Quick program_runs;
      Alcotest.test_case "a plain task's installed modules are the image's list" `Quick same_list;
      Alcotest.test_case "data read marked lives on through collections" `Quick read_marked_survives ] )
