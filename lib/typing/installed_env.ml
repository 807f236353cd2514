open Rapid_syntax

let file_names = List.map fst Installed_sources.files

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

let modules () = Lazy.force parsed
