(* The installed environment computed at build time (lib/load/installed_image.ml) is the one
   computed now: the test process takes it from the image, and the environment parsed, checked
   and lowered here afresh, from the same files' table and record ids as the build started from,
   marshals to the same bytes (so it holds no functional value either: Marshal would refuse it).
   The process's own table of files and record ids are put back afterwards. *)

module Level = Rapid_runtime.Installed_level

let image () : Level.t = Marshal.from_string Rapid_load.Installed_image.data 0

let name_of (m : Rapid_syntax.Ast.module_declaration) =
  match m.module_name.it with Rapid_syntax.Ast.Ident n -> String.lowercase_ascii n | ID_placeholder -> ""

let declarations (m : Rapid_syntax.Ast.module_declaration) =
  List.length m.type_definitions + List.length m.data_declarations + List.length m.routine_declarations

let in_use () =
  let module Env = Rapid_typing.Installed_env in
  Alcotest.(check bool) "the installed environment comes from the image" true (Rapid_load.Installed_image.in_use ());
  match Env.level (), Env.modules () with
  | Error _, _ | _, Error _ -> Alcotest.fail "the installed environment does not parse"
  | Ok level, Ok modules ->
      Alcotest.(check int) "its modules" (List.length (Level.level (image ()))) (List.length level);
      (* the checker's and the lowering's kept work is found by this list, compared physically *)
      Alcotest.(check bool) "the same level at every call" true
        (match Env.level () with Ok again -> again == level | Error _ -> false);
      Alcotest.(check bool) "the same modules at every call" true
        (match Env.modules () with Ok again -> again == modules | Error _ -> false);
      Alcotest.(check (list string)) "the level's headers name the modules, in order"
        (List.map name_of modules) (List.map name_of level);
      Alcotest.(check int) "the headers hold no declaration" 0 (List.fold_left (fun n m -> n + declarations m) 0 level);
      Alcotest.(check bool) "the modules hold their declarations" true
        (List.fold_left (fun n m -> n + declarations m) 0 modules > 100);
      Alcotest.(check bool) "the level's full modules are the modules" true
        (Env.full level == modules);
      Alcotest.(check bool) "any other list is its own full list" true
        (let copy = modules @ [] in Env.full copy == copy);
      Alcotest.(check bool) "the level and the modules are the same level" true
        (Env.same level modules && Env.same modules level);
      Alcotest.(check bool) "a copy of the modules is another level" false (Env.same level (modules @ []));
      Alcotest.(check bool) "without the assertions of rapid-sem test" true
        (List.for_all (fun m -> name_of m <> "installed_unit_test") modules)

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
  | Ok (now, trees) ->
      Alcotest.(check bool) "the same bytes as the image's" true
        (Marshal.to_string now [] = Rapid_load.Installed_image.data);
      Alcotest.(check bool) "the same trees as the image's" true
        (Marshal.to_string trees [] = Rapid_load.Installed_image.trees)

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

(* A task without signals or assertions is checked against the image's level itself: the checker
   and the lowering know the installed level by that list, and a copy of it (an append of
   nothing) would check and lower the whole installed environment again at every start. *)
let same_list () =
  match Rapid_typing.Installed_env.level (), Rapid_load.Session.installed () with
  | Ok image, Ok session -> Alcotest.(check bool) "the same list" true (image == session)
  | _ -> Alcotest.fail "the installed environment does not parse"

(* A task whose installed level is not the image's (rapid-sem test's assertions added) is
   checked from the installed modules' declarations: an installed routine, type and constant
   are found, an assertion too, and a name declared nowhere is still an error. *)
let another_level () =
  let check text =
    let m = match Rapid_syntax.Parse.parse_string ~name:"level.mod" text with
      | Ok m -> m | Error _ -> Alcotest.fail "the program does not parse" in
    match Rapid_load.Session.installed ~testing:true () with
    | Error _ -> Alcotest.fail "the installed environment does not parse"
    | Ok installed ->
        Alcotest.(check bool) "not the image's level" false
          (match Rapid_typing.Installed_env.level () with Ok l -> l == installed | Error _ -> true);
        List.length (Rapid_typing.Check.errors (Rapid_typing.Check.check_task ~installed [ m ])) in
  Alcotest.(check int) "installed objects and an assertion" 0
    (check {|MODULE m
  PROC main()
    VAR robtarget p;
    TPWrite "x" \Num:=StrLen("abc") + v100.v_tcp;
    AssertEqual 3, StrLen("abc");
  ENDPROC
ENDMODULE
|});
  Alcotest.(check int) "an unknown name" 1
    (check {|MODULE m
  PROC main()
    NoSuchRoutine 3;
  ENDPROC
ENDMODULE
|})

(* The blocks start-up takes from the executable's data (lib/load/gen/static_image.ml) are the
   marshalled image's: the same bytes again, sharing included; and no run of the tests before
   this one changed them. *)
let in_data_is_the_image () =
  Alcotest.(check bool) "the image in the data marshals to the image's bytes" true
    (Marshal.to_string (Rapid_load.Installed_image.in_data ()) [] = Rapid_load.Installed_image.data);
  Alcotest.(check bool) "the same value at every call" true
    (Rapid_load.Installed_image.in_data () == Rapid_load.Installed_image.in_data ())

(* A value stored in a block of the image, and held by nothing else, lives through minor and
   major collections and compactions (installed_image_stubs.c's roots hook): the image's blocks
   are outside the heap, where the collector does not look by itself. *)
let stored_in_image_survives () =
  let root = Obj.repr (Rapid_load.Installed_image.in_data ()) in
  let saved = Obj.field root 0 in
  let store () = Obj.set_field root 0 (Obj.repr (List.init 1_000 (fun i -> string_of_int i, [| float_of_int i |]))) in
  (Sys.opaque_identity store) ();
  for _ = 1 to 3 do
    ignore (Sys.opaque_identity (List.init 100_000 (fun i -> [ i ])));
    Gc.full_major ();
    Gc.compact ()
  done;
  let back : (string * float array) list = Obj.obj (Obj.field root 0) in
  let ok = back = List.init 1_000 (fun i -> string_of_int i, [| float_of_int i |]) in
  Obj.set_field root 0 saved;
  Alcotest.(check bool) "the stored value is intact" true ok

let suite =
  ( "installed image",
    [ Alcotest.test_case "the image in the executable's data is the marshalled image" `Quick in_data_is_the_image;
      Alcotest.test_case "the environment comes from the image" `Quick in_use;
      Alcotest.test_case "the image is the environment computed now" `Quick same_as_now;
      Alcotest.test_case "a program over the image's environment" `Quick program_runs;
      Alcotest.test_case "a plain task's installed modules are the image's list" `Quick same_list;
      Alcotest.test_case "a task over another installed level" `Quick another_level;
      Alcotest.test_case "a value stored in the image lives on through collections" `Quick stored_in_image_survives ] )
