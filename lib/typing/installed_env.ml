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

let image : (unit -> Ast.module_declaration list) option ref = ref None

let set_image f = image := Some f

let parsed =
  lazy (match !image with Some f -> Ok (f ()) | None -> parse ())

let is_test (m : Ast.module_declaration) =
  match m.module_name.it with Ast.Ident n -> String.lowercase_ascii n = "installed_unit_test" | ID_placeholder -> false

let modules () = Result.map (List.filter (fun m -> not (is_test m))) (Lazy.force parsed)

let test_modules () = Result.map (List.filter is_test) (Lazy.force parsed)
