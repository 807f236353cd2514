open Rapid_syntax

(* The assertions of rapid-sem test (doc/testing.md) are installed only in the task buffers
   that command runs (doc/rulings.md R-test-a). *)
let file_names =
  List.filter (( <> ) "installed/unit_test.sys") (List.map fst Installed_sources.files)

let parse () =
  let modules =
    List.fold_left (fun acc (name, text) ->
        match acc with
        | Error _ -> acc
        | Ok ms -> (
            match Parse.parse_string ~options:{ Parse.default_options with installed = true } ~name text with
            | Ok m -> Ok (m :: ms)
            | Error d -> Error d)) (Ok []) Installed_sources.files
    |> Result.map List.rev in
  (* Their file ids stay theirs for the life of the process (Source.keep). *)
  Source.keep ();
  modules

let is_test (m : Ast.module_declaration) =
  match m.module_name.it with Ast.Ident n -> String.lowercase_ascii n = "installed_unit_test" | ID_placeholder -> false

let without_tests all = List.filter (fun m -> not (is_test m)) all

(* All the modules, those of every task and the assertions, each list made once: the checker and
   the lowering keep their work for the installed modules keyed by the list, compared
   physically (Check.installed_half), so every task must get the same one. *)
type parts = { installed : Ast.module_declaration list; tests : Ast.module_declaration list }

let image : (unit -> Ast.module_declaration list * Ast.module_declaration list) option ref = ref None

let set_image f = image := Some f

let parsed =
  lazy (match !image with
      | Some f -> let all, installed = f () in Ok { installed; tests = List.filter is_test all }
      | None -> Result.map (fun all -> { installed = without_tests all; tests = List.filter is_test all }) (parse ()))

let modules () = Result.map (fun p -> p.installed) (Lazy.force parsed)

let test_modules () = Result.map (fun p -> p.tests) (Lazy.force parsed)
