(* --save (doc/services.md, R-2.23-a, R-2.23-save1): the values written read back exactly, in
   modules of every encoding, and saving again changes nothing; what --save refuses; its
   temporary files. *)

module P = Rapid_run.Persistent_save
module V = Rapid_runtime.Value
module M = Rapid_semantics.Machine

(* Numbers compared by their bits: -0 is not 0, and a value that reads back "nearly" is wrong. *)
let rec exact a b =
  match (a, b) with
  | V.Num x, V.Num y | V.Dnum x, V.Dnum y -> Int64.equal (Int64.bits_of_float x) (Int64.bits_of_float y)
  | V.Bool x, V.Bool y -> x = y
  | V.String x, V.String y -> String.equal x y
  | V.Record xs, V.Record ys | V.Array xs, V.Array ys ->
      Array.length xs = Array.length ys && Array.for_all2 exact xs ys
  | _ -> false

let rec show = function
  | V.Num x -> Printf.sprintf "num %h" x
  | V.Dnum x -> Printf.sprintf "dnum %h" x
  | V.Bool b -> string_of_bool b
  | V.String s -> Printf.sprintf "%S" s
  | V.Record xs -> "(" ^ String.concat ", " (Array.to_list (Array.map show xs)) ^ ")"
  | V.Array xs -> "{" ^ String.concat ", " (Array.to_list (Array.map show xs)) ^ "}"
  | V.Handle _ -> "handle"

(* The module-level data of a module's text as a run starts with it, or why it does not load. *)
let load text =
  match Rapid_syntax.Parse.parse_string ~name:"m.mod" text with
  | Error d -> Error (Rapid_syntax.Diagnostic.to_string d)
  | Ok m -> (
      match Rapid_load.Session.load_modules ~allow_unknown:false ~io:Rapid_controller.Io_config.empty [ m ] with
      | Error _ -> Error "the module does not load"
      | Ok loaded -> (
          let world = Rapid_controller.World.create Rapid_controller.Io_config.empty in
          match M.start ~host:(Rapid_run.Run.setup ~controller:world ()).host loaded.program ~entry:"main" with
          | Error e -> Error e
          | Ok cfg -> Ok (m, M.module_data cfg)))

let value_of data name =
  List.find_map (fun (_, n, v) -> if String.lowercase_ascii n = name then Some v else None) data

(* ---------------------------------------------------------------- generated values *)

type ty = Num | Dnum | Bool | Str | Pos | Rec | Arr of ty * int

let rec type_name = function
  | Num -> "num" | Dnum -> "dnum" | Bool -> "bool" | Str -> "string" | Pos -> "pos" | Rec -> "cell"
  | Arr (t, _) -> type_name t

let rec default = function
  | Num -> "0" | Dnum -> "0" | Bool -> "FALSE" | Str -> "\"\"" | Pos -> "[0,0,0]" | Rec -> "[\"\",0,0]"
  | Arr (t, n) -> "[" ^ String.concat "," (List.init n (fun _ -> default t)) ^ "]"

let open_ = QCheck.Gen.(oneofl [ Num; Dnum; Bool; Str; Pos; Rec ])
let ty = QCheck.Gen.(frequency [ (3, open_); (1, map2 (fun t n -> Arr (t, n)) open_ (int_range 1 4)) ])

(* Numbers at the edges of single and double precision, and any finite bit pattern. *)
let single =
  let open QCheck.Gen in
  let edges = [ 0.; -0.; 1.; -1.; 0.1; 1. /. 3.; 16777216.; 16777218.; 3.4028234663852886e38; -3.4028234663852886e38;
                1.1754943508222875e-38; 1.401298464324817e-45; -1.401298464324817e-45; 1e15; 123456792.;
                9.999999e14; 4.2e-40 ] in
  let bits = map (fun i -> Int32.float_of_bits (Int32.of_int i)) (int_bound 0xFFFFFFFF) in
  let small = map float_of_int (int_range (-100000) 100000) in
  map V.to_single (frequency [ (1, oneofl edges); (3, bits); (1, small) ])
  |> map (fun f -> if Float.is_finite f then f else 1.5)

let double =
  let open QCheck.Gen in
  let edges = [ 0.; -0.; 0.1; 1. /. 3.; max_float; -.max_float; min_float; 4.9406564584124654e-324; 9007199254740993.;
                123456789012345678.; 1e300; 2.2250738585072009e-308 ] in
  let word = int_bound 0xFFFFFFFF in
  let bits = map2 (fun hi lo -> Int64.(float_of_bits (logor (shift_left (of_int hi) 32) (of_int lo)))) word word in
  frequency [ (1, oneofl edges); (3, bits) ] |> map (fun f -> if Float.is_finite f then f else 2.5)

(* Strings of every byte, at most the 80 bytes of §2.7; some valid UTF-8 and Latin-1 text. *)
let bytes_string =
  let open QCheck.Gen in
  let any = string_size ~gen:char (int_range 0 80) in
  let text = oneofl [ "é"; "Värde ✓"; "\xE9"; "a\"b\\c"; "\xC3\xA9\xFF"; "\x00\x7F\xC2\x85"; "日本語"; "😀";
                      "\xED\xA0\x80" ] in
  let both = map2 (fun a b -> let s = a ^ b in if String.length s > 80 then a else s) text any in
  frequency [ (4, any); (1, text); (1, both) ]

let rec value t =
  let open QCheck.Gen in
  match t with
  | Num -> map V.num single
  | Dnum -> map V.dnum double
  | Bool -> map (fun b -> V.Bool b) bool
  | Str -> map (fun s -> V.String s) bytes_string
  | Pos -> map (fun l -> V.Record (Array.of_list (List.map V.num l))) (list_repeat 3 single)
  | Rec -> map3 (fun s n d -> V.Record [| V.String s; V.Num n; V.Dnum d |]) bytes_string single double
  | Arr (t, n) -> map (fun l -> V.Array (Array.of_list l)) (list_repeat n (value t))

(* How the module is stored: UTF-8 (with non-ASCII text elsewhere, a byte-order mark or
   neither), Latin-1, and its line breaks. *)
type file = { header : string; comment : string; newline : string }

let file =
  QCheck.Gen.(map2 (fun (header, comment) newline -> { header; comment; newline })
                (oneofl [ ("", "! ascii"); ("", "! V\xC3\xA4rde \xE2\x9C\x93"); ("\xEF\xBB\xBF", "! V\xC3\xA4rde");
                          ("", "! V\xE4rde, Latin-1"); ("\xEF\xBB\xBF", "! \xE4 Latin-1 after a mark") ])
                (oneofl [ "\n"; "\r\n"; "\r" ]))

let module_text f (t, with_initial) =
  let dims = match t with Arr (_, n) -> Printf.sprintf "{%d}" n | _ -> "" in
  String.concat f.newline
    [ f.header ^ "MODULE m"; "  " ^ f.comment;
      "  RECORD cell"; "    string name;"; "    num n;"; "    dnum d;"; "  ENDRECORD";
      Printf.sprintf "  PERS %s p%s%s;  ! kept" (type_name t) dims (if with_initial then " := " ^ default t else "");
      "  PERS string q := \"q\";"; "  PROC main()"; "  ENDPROC"; "ENDMODULE"; "" ]

let case =
  QCheck.Gen.(file >>= fun f -> ty >>= fun t -> bool >>= fun init -> value t >>= fun v -> return (f, (t, init), v))

let print (f, (t, init), v) =
  Printf.sprintf "%S\nvalue %s" (module_text f (t, init)) (show v)

(* The property: the saved module loads, p reads back exactly, every other datum is as it
   was, and saving the saved module again with the same value writes the same bytes. *)
let round_trip (f, decl, v) =
  let original = module_text f decl in
  let save text =
    match Rapid_syntax.Parse.parse_string ~name:"m.mod" text with
    | Error d -> QCheck.Test.fail_reportf "does not parse: %s" (Rapid_syntax.Diagnostic.to_string d)
    | Ok m -> P.splice ~original:text m (fun n -> if String.lowercase_ascii n = "p" then Some v else None) in
  let once = save original in
  (match load once with
   | Error e -> QCheck.Test.fail_reportf "the saved module does not load: %s\n%S" e once
   | Ok (_, data) ->
       (match value_of data "p" with
        | Some w when exact v w -> ()
        | Some w -> QCheck.Test.fail_reportf "read back as %s\n%S" (show w) once
        | None -> QCheck.Test.fail_reportf "p is missing\n%S" once);
       if value_of data "q" <> Some (V.String "q") then QCheck.Test.fail_reportf "q changed\n%S" once);
  (* Everything but the value stays byte for byte (doc/services.md), in a Latin-1 module too:
     every Latin-1 comment here holds a byte that is not UTF-8, so the module stays Latin-1. *)
  let lines t =
    Str.split (Str.regexp "[\r\n]") t
    |> List.filter (fun l -> not (Str.string_match (Str.regexp ".*PERS [a-z]+ p[^a-z]") l 0)) in
  if lines once <> lines original then
    QCheck.Test.fail_reportf "a byte outside the value changed:\n%S\n%S" original once;
  let twice = save once in
  if twice <> once then QCheck.Test.fail_reportf "a second save changed the module:\n%S\n%S" once twice;
  true

let property () =
  QCheck.Test.check_exn ~rand:(Random.State.make [| 2123 |])
    (QCheck.Test.make ~count:2000 ~name:"--save reads back" (QCheck.make ~print case) round_trip)

(* The case of issue 21: a string with bytes above 0x7F, saved twice by the command, loads and
   holds its value. *)
(* The command line's binary and the file helpers, as the services' tests have them. *)
let binary = Test_services.binary
let temp_dir = Test_services.temp_dir
let read_file = Test_services.read_file
let write_file = Test_services.write_file

let run_quietly args =
  let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
  let err = Filename.temp_file "rapid-sem-save" ".err" in
  let fd = Unix.openfile err [ Unix.O_WRONLY; Unix.O_TRUNC ] 0o600 in
  let pid = Unix.create_process binary (Array.of_list (binary :: args)) devnull devnull fd in
  Unix.close devnull; Unix.close fd;
  let status = match snd (Unix.waitpid [] pid) with Unix.WEXITED n -> n | _ -> -1 in
  let message = read_file err in
  Sys.remove err; (status, message)

let with_dir f =
  let dir = temp_dir () in
  Fun.protect ~finally:(fun () -> ignore (Sys.command ("rm -rf " ^ Filename.quote dir))) (fun () -> f dir)

let high_bytes_twice () =
  with_dir @@ fun dir ->
  let source = Filename.concat dir "m.mod" and out = Filename.concat dir "out" in
  write_file source
    "MODULE m\n  PERS string s := \"a\";\n  PROC main()\n    s := s + \"\\FF\\C3;\\E9\";\n  ENDPROC\nENDMODULE\n";
  let saved = Filename.concat out "m.mod" in
  Alcotest.(check int) "first save" 0 (fst (run_quietly [ "run"; "--save"; out; source ]));
  Alcotest.(check int) "second save" 0 (fst (run_quietly [ "run"; "--save"; out; saved ]));
  Alcotest.(check int) "the saved module checks" 0 (fst (run_quietly [ "check"; saved ]));
  match load (read_file saved) with
  | Error e -> Alcotest.fail e
  | Ok (_, data) ->
      Alcotest.(check (option string)) "s after two runs" (Some "a\xFF\xC3;\xE9\xFF\xC3;\xE9")
        (match value_of data "s" with Some (V.String s) -> Some s | _ -> None)

(* A Latin-1 module whose only byte above 0x7F stood in the value replaced would read as UTF-8
   afterwards; q's Latin-1 "Ã©" (bytes C3 A9) would become "é". It is written as UTF-8. *)
let latin1_that_would_turn_utf8 () =
  let original =
    "MODULE m\n  PERS string p := \"\xE9\";\n  PERS string q := \"\xC3\xA9\";\n  PROC main()\n  ENDPROC\nENDMODULE\n" in
  let m = match Rapid_syntax.Parse.parse_string ~name:"m.mod" original with Ok m -> m | Error _ -> assert false in
  let saved = P.splice ~original m (fun n -> if n = "p" then Some (V.String "abc") else None) in
  match load saved with
  | Error e -> Alcotest.fail e
  | Ok (_, data) ->
      Alcotest.(check bool) "p" true (value_of data "p" = Some (V.String "abc"));
      Alcotest.(check bool) "q as before" true (value_of data "q" = Some (V.String "\xC3\x83\xC2\xA9"))

(* A Latin-1 module (its comment's byte E9 is not UTF-8) whose string is set to é€ (bytes C3 A9
   E2 82 AC): é is its one Latin-1 byte, € has none and is written \E2\82\AC; every other byte
   stays as it was, and the value reads back (R-2.23-save2n). It was rewritten as UTF-8. *)
let latin1_beyond_latin1 () =
  with_dir @@ fun dir ->
  let source = Filename.concat dir "m.mod" and out = Filename.concat dir "out" in
  let module_with value =
    "MODULE m\n  ! caf\xE9\n  PERS string s1 := " ^ value
    ^ ";\n  PROC main()\n    s1 := \"\\C3\\A9\\E2\\82\\AC\";\n  ENDPROC\nENDMODULE\n" in
  write_file source (module_with "\"\"");
  Alcotest.(check int) "saved" 0 (fst (run_quietly [ "run"; "--save"; out; source ]));
  let saved = read_file (Filename.concat out "m.mod") in
  Alcotest.(check string) "only the value changed, Latin-1 where it can be"
    (module_with "\"\xE9\\E2\\82\\AC\"") saved;
  match load saved with
  | Error e -> Alcotest.fail e
  | Ok (_, data) ->
      Alcotest.(check bool) "s1 reads back" true (value_of data "s1" = Some (V.String "\xC3\xA9\xE2\x82\xAC"))

(* A save is linear in the persistents: each declaration looked its value up in the whole list,
   N * N / 2 comparisons (minutes for 50,000). The bound is wide: linear takes about a second. *)
let many_persistents () =
  with_dir @@ fun dir ->
  let n = 50_000 in
  let source = Filename.concat dir "big.mod" and out = Filename.concat dir "out" in
  let b = Buffer.create (n * 24) in
  Buffer.add_string b "MODULE big\n";
  for i = 0 to n - 1 do Buffer.add_string b (Printf.sprintf "PERS num p%d := %d;\n" i i) done;
  Buffer.add_string b "ENDMODULE\n";
  write_file source (Buffer.contents b);
  let data = List.init n (fun i -> ("BIG", Printf.sprintf "P%d" i, V.num (float_of_int (if i = 0 then 1 else i)))) in
  let t0 = Unix.gettimeofday () in
  (match P.save_modules ~dir:out ~files:[ source ] data with Ok _ -> () | Error e -> Alcotest.fail e);
  let took = Unix.gettimeofday () -. t0 in
  Alcotest.(check bool) (Printf.sprintf "50,000 persistents saved in %.1f s (bound 20 s)" took) true (took < 20.);
  let saved = read_file (Filename.concat out "big.mod") in
  let expected = Str.replace_first (Str.regexp_string "p0 := 0;") "p0 := 1;" (Buffer.contents b) in
  Alcotest.(check bool) "only p0 changed" true (saved = expected)

let refusals () =
  with_dir @@ fun dir ->
  let a = Filename.concat dir "m.mod" and sub = Filename.concat dir "b" in
  Unix.mkdir sub 0o755;
  let b = Filename.concat sub "m.mod" and out = Filename.concat dir "out" in
  write_file a "MODULE m\n  PERS num k := 1;\n  PROC main()\n    k := 2;\n  ENDPROC\nENDMODULE\n";
  write_file b "MODULE n\n  PERS num j := 1;\nENDMODULE\n";
  let status, message = run_quietly [ "run"; "--save"; out; a; b ] in
  Alcotest.(check int) "two files of one base name: exit 2" 2 status;
  Alcotest.(check bool) "... named" true
    (Str.string_match (Str.regexp ".*rapid-sem: --save: .*m.mod and .*b/m.mod would both be saved as") message 0);
  Alcotest.(check bool) "... nothing saved" false (Sys.file_exists (Filename.concat out "m.mod"));
  let status, message = run_quietly [ "run"; "--save"; ""; a ] in
  Alcotest.(check int) "--save \"\": exit 2" 2 status;
  Alcotest.(check string) "... said"
    "rapid-sem: --save: the folder is an empty name (for the current folder, write --save .)\n" message;
  let status, _ = run_quietly [ "run"; "--save"; a; a ] in
  Alcotest.(check int) "--save onto a file: exit 2" 2 status

(* Several modules are saved all or nothing: b.mod's destination is a folder, so the save fails,
   and a.mod's, whether it was not there or held an older module, is as it was. a.mod was
   renamed into place before b.mod's rename failed (exit 2, "Is a directory"). *)
let all_or_nothing () =
  with_dir @@ fun dir ->
  let a = Filename.concat dir "a.mod" and b = Filename.concat dir "b.mod" and out = Filename.concat dir "out" in
  write_file a "MODULE A\nPERS num pa := 1;\nPROC main()\npa := pa + 1;\nENDPROC\nENDMODULE\n";
  write_file b "MODULE B\nPERS num pb := 1;\nENDMODULE\n";
  Unix.mkdir out 0o755;
  Unix.mkdir (Filename.concat out "b.mod") 0o755;
  let saved_a = Filename.concat out "a.mod" in
  let no_parts what =
    Alcotest.(check (list string)) (what ^ ": no temporary file left") []
      (List.filter (fun f -> Filename.check_suffix f ".part") (Array.to_list (Sys.readdir out))) in
  let status, message = run_quietly [ "run"; "--save"; out; a; b ] in
  Alcotest.(check int) "b.mod's destination is a folder: exit 2" 2 status;
  Alcotest.(check string) "... said" (Printf.sprintf "rapid-sem: --save: %s: Is a directory\n" (Filename.concat out "b.mod")) message;
  Alcotest.(check bool) "a.mod not saved" false (Sys.file_exists saved_a);
  no_parts "first";
  let older = "MODULE A\n! older\nPERS num pa := 7;\nPROC main()\nENDPROC\nENDMODULE\n" in
  write_file saved_a older;
  let status, _ = run_quietly [ "run"; "--save"; out; a; b ] in
  Alcotest.(check int) "again, over an older a.mod: exit 2" 2 status;
  Alcotest.(check string) "the older a.mod byte for byte" older (read_file saved_a);
  no_parts "second";
  (* Once b.mod can be saved, both are. *)
  Unix.rmdir (Filename.concat out "b.mod");
  Alcotest.(check int) "saved" 0 (fst (run_quietly [ "run"; "--save"; out; a; b ]));
  Alcotest.(check bool) "a.mod saved" true
    (Str.string_match (Str.regexp ".*pa := 2;") (String.concat " " (String.split_on_char '\n' (read_file saved_a))) 0);
  Alcotest.(check bool) "b.mod saved" true (Sys.file_exists (Filename.concat out "b.mod"));
  no_parts "third";
  (* A save folder it made itself is removed again when nothing is saved. *)
  let fresh = Filename.concat dir "fresh" in
  (match P.save_modules ~dir:fresh ~files:[ a; Filename.concat dir "missing.mod" ] [] with
   | Ok _ -> Alcotest.fail "a missing module saved"
   | Error _ -> ());
  Alcotest.(check bool) "the folder it made is gone" false (Sys.file_exists fresh)

(* The temporary file of a save killed before its rename is removed by the next save of that
   module, whatever process has its id now; one another save is writing (it holds its lock) is
   left to it, as is a file of another program's naming. *)
let stale_parts () =
  with_dir @@ fun dir ->
  let target = Filename.concat dir "m.mod" in
  let part pid = Filename.concat dir (Printf.sprintf "m.mod.%d.rapid-sem.part" pid) in
  (* A process id that is gone, and one that is alive but holds no lock. *)
  let gone = match Unix.fork () with 0 -> Unix._exit 0 | pid -> ignore (Unix.waitpid [] pid); pid in
  let stale = part gone and reused = part (Unix.getppid ()) and foreign = Filename.concat dir "m.mod.x.part" in
  List.iter (fun f -> write_file f "MODULE m\n") [ stale; reused; foreign ];
  (* A save in progress: another process holding the lock of its part file. *)
  let ready_r, ready_w = Unix.pipe () and go_r, go_w = Unix.pipe () in
  let writing = part 1 in
  write_file writing "MODULE m\n";
  let child = match Unix.fork () with
    | 0 ->
        let fd = Unix.openfile writing [ Unix.O_RDWR ] 0 in
        Unix.lockf fd Unix.F_LOCK 0;
        ignore (Unix.write_substring ready_w "x" 0 1);
        ignore (Unix.read go_r (Bytes.create 1) 0 1);
        Unix._exit 0
    | pid -> pid in
  ignore (Unix.read ready_r (Bytes.create 1) 0 1);
  let result = P.write_atomically target "MODULE m\nENDMODULE\n" in
  ignore (Unix.write_substring go_w "x" 0 1);
  ignore (Unix.waitpid [] child);
  List.iter Unix.close [ ready_r; ready_w; go_r; go_w ];
  (match result with Ok () -> () | Error e -> Alcotest.fail e);
  Alcotest.(check string) "written" "MODULE m\nENDMODULE\n" (read_file target);
  Alcotest.(check bool) "a killed save's removed" false (Sys.file_exists stale);
  Alcotest.(check bool) "... also when its process id is in use again" false (Sys.file_exists reused);
  Alcotest.(check bool) "the one being written kept" true (Sys.file_exists writing);
  Alcotest.(check bool) "another program's kept" true (Sys.file_exists foreign);
  Alcotest.(check bool) "no temporary file of this save" false (Sys.file_exists (part (Unix.getpid ())))

let suite = ("save", [
    Alcotest.test_case "--save: random values read back, a second save changes nothing" `Quick property;
    Alcotest.test_case "--save: bytes above 0x7F saved twice" `Quick high_bytes_twice;
    Alcotest.test_case "--save: a Latin-1 module that would read as UTF-8" `Quick latin1_that_would_turn_utf8;
    Alcotest.test_case "--save: a Latin-1 module given characters beyond Latin-1" `Quick latin1_beyond_latin1;
    Alcotest.test_case "--save: 50,000 persistents, linear" `Quick many_persistents;
    Alcotest.test_case "--save: empty folder, one base name twice" `Quick refusals;
    Alcotest.test_case "--save: temporary files of killed saves" `Quick stale_parts;
    Alcotest.test_case "--save: several modules, all or nothing" `Quick all_or_nothing;
  ])
