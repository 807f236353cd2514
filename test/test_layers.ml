(* The layers of doc/architecture.md, checked from the dune files: the definition (lib/semantics)
   links neither the controller, the motion model, unix nor threads, the second engine
   (lib/closure) cannot name the machine, and the oracle (lib/oracle) names neither engine. A
   library's dependencies are read from its dune file's (libraries ...) field, and followed
   through the project's own libraries. *)

let read path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))

(* The words of the (name ...) and (libraries ...) fields of a dune file. *)
let fields text =
  let words = String.split_on_char ' ' (String.map (function '(' | ')' | '\n' | '\t' -> ' ' | c -> c) text)
              |> List.filter (( <> ) "") in
  let rec go name libs mode = function
    | [] -> (name, libs)
    | "name" :: n :: rest -> go (Some n) libs `Other rest
    | "libraries" :: rest -> go name libs `Libraries rest
    | ("public_name" | "flags" | "foreign_stubs" | "preprocess" | "rule" | "menhir" | "library") :: rest ->
        go name libs `Other rest
    | w :: rest -> if mode = `Libraries then go name (w :: libs) mode rest else go name libs mode rest in
  go None [] `Other words

(* The libraries of lib/, by name: each one's direct dependencies. *)
let libraries () =
  let lib = "../lib" in
  Sys.readdir lib |> Array.to_list |> List.filter_map (fun d ->
      let f = Filename.concat (Filename.concat lib d) "dune" in
      if Sys.file_exists f then
        match fields (read f) with
        | Some name, libs -> Some (name, libs)
        | None, _ -> None
      else None)

let rec closure table seen = function
  | [] -> seen
  | l :: rest when List.mem l seen -> closure table seen rest
  | l :: rest -> closure table (l :: seen) ((match List.assoc_opt l table with Some ds -> ds | None -> []) @ rest)

let links table name = List.filter (( <> ) name) (closure table [] [ name ])

let forbidden name words table =
  let reached = links table name in
  List.iter (fun w ->
      Alcotest.(check bool) (Printf.sprintf "%s does not link %s" name w) false (List.mem w reached)) words

let layers () =
  let table = libraries () in
  Alcotest.(check bool) "the dune files are read" true (List.mem_assoc "rapid_semantics" table);
  Alcotest.(check bool) "the closure engine has a library" true (List.mem_assoc "rapid_closure" table);
  forbidden "rapid_semantics"
    [ "rapid_controller"; "rapid_motion_model"; "rapid_installed"; "unix"; "threads"; "threads.posix";
      "rapid_closure" ] table;
  forbidden "rapid_runtime"
    [ "rapid_controller"; "rapid_motion_model"; "rapid_installed"; "unix"; "threads"; "threads.posix";
      "rapid_semantics"; "rapid_closure" ] table;
  forbidden "rapid_closure" [ "rapid_semantics"; "rapid_controller"; "rapid_motion_model"; "rapid_installed" ] table;
  (* The oracle compares implementations: its encoder of the events names neither engine. *)
  forbidden "rapid_oracle" [ "rapid_semantics"; "rapid_closure" ] table;
  (* The language server answers static questions: the front end, the checker and the loader,
     no engine and no world (doc/architecture.md). *)
  forbidden "rapid_lsp"
    [ "rapid_semantics"; "rapid_closure"; "rapid_installed"; "rapid_motion_model"; "rapid_run"; "threads";
      "threads.posix" ] table;
  Alcotest.(check bool) "the language server has a library" true (List.mem_assoc "rapid_lsp" table);
  (* And the checker itself sees a dependency: the run library links both engines. *)
  Alcotest.(check bool) "a link is seen through a library" true
    (List.mem "rapid_controller" (links table "rapid_run") && List.mem "rapid_semantics" (links table "rapid_run"))


(* doc/architecture.md, "Conventions": no line of lib/ and bin/ is over 120 characters (UTF-8
   characters, not bytes: a § is one). *)
let utf8_length line =
  let n = ref 0 in
  String.iter (fun c -> if Char.code c land 0xC0 <> 0x80 then incr n) line;
  !n

(* The sources as written: not what the build generates beside them (menhir's parser, the
   preprocessed files, the embedded installed environment and its image, the robot library). *)
let generated =
  [ "parser.ml"; "parser.mli"; "parser_messages.ml"; "installed_sources.ml"; "installed_image_data.ml"; "robot_files.ml" ]

let rec sources dir =
  Sys.readdir dir |> Array.to_list |> List.concat_map (fun f ->
      let p = Filename.concat dir f in
      if Sys.is_directory p then (if f = "_build" || f.[0] = '.' then [] else sources p)
      else if (Filename.check_suffix f ".ml" || Filename.check_suffix f ".mli")
              && not (Filename.check_suffix f ".pp.ml" || Filename.check_suffix f ".pp.mli" || List.mem f generated)
      then [ p ]
      else [])

let width () =
  let files = sources "../lib" @ sources "../bin" in
  Alcotest.(check bool) "the sources are read" true (List.length files > 100);
  let long = List.concat_map (fun f ->
      List.filteri (fun _ l -> utf8_length l > 120) (String.split_on_char '\n' (read f))
      |> List.map (fun l -> Printf.sprintf "%s: %d characters" f (utf8_length l))) files in
  Alcotest.(check (list string)) "lines over 120 characters" [] long;
  Alcotest.(check int) "a § counts one" 1 (utf8_length "§")

let suite =
  ("layers",
   [ Alcotest.test_case "the libraries' dependencies (doc/architecture.md)" `Quick layers;
     Alcotest.test_case "no line of lib/ and bin/ over 120 characters" `Quick width ])
