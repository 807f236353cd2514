open Rapid_syntax

(* The assertions of rapid-sem test (doc/testing.md) are installed only in the task buffers
   that command runs (doc/rulings.md R-test-a): they are parsed apart, and only by that command,
   so that every other run's installed modules are the build-time image's list itself (the
   checker knows an installed level it has seen by that list). *)
let test_file = "installed/unit_test.sys"

let parse_files files =
  let modules =
    List.fold_left (fun acc (name, text) ->
        match acc with
        | Error _ -> acc
        | Ok ms -> (
            match Parse.parse_string ~options:{ Parse.default_options with installed = true } ~name text with
            | Ok m -> Ok (m :: ms)
            | Error d -> Error d)) (Ok []) files
    |> Result.map List.rev in
  (* Their file ids stay theirs for the life of the process (Source.keep). *)
  Source.keep ();
  modules

let parse () = parse_files (List.filter (fun (name, _) -> name <> test_file) Installed_sources.files)

let image : (unit -> Ast.module_declaration list) option ref = ref None

let set_image f = image := Some f

let parsed =
  lazy (match !image with Some f -> Ok (f ()) | None -> parse ())

let modules () = Lazy.force parsed

let tests = lazy (parse_files (List.filter (fun (name, _) -> name = test_file) Installed_sources.files))

let test_modules () = Result.bind (modules ()) (fun _ -> Lazy.force tests)

let file_names = List.map fst Installed_sources.files
