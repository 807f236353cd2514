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

(* With an image (lib/load/installed_image.ml), the level every task is checked over is its
   modules' headers (their names, attributes and regions): the image holds the checked and lowered
   state keyed by that list, and the declarations' trees, which only a task whose installed level
   differs (the assertions, the signals of an I/O configuration) or a reader of the declarations
   needs, are a second image, read on first use: a run that does not need them does not pay for
   them at start-up. *)
type image = { level : unit -> Ast.module_declaration list; trees : unit -> Ast.module_declaration list }

let image : image option ref = ref None

let set_image ~level ~trees = image := Some { level; trees }

let headers = lazy (Option.map (fun i -> i.level ()) !image)

let parsed =
  lazy (match !image with
      | Some i -> ignore (Lazy.force headers); Ok (i.trees ())
      | None -> parse ())

let modules () = Lazy.force parsed

let level () = match Lazy.force headers with Some l -> Ok l | None -> modules ()

(* Only the image's headers lack their declarations, and the image's trees are read, never
   parsed: no error to give. *)
let full l =
  let headers_only = Lazy.is_val headers && (match Lazy.force headers with Some h -> h == l | None -> false) in
  if headers_only then (match modules () with Ok f -> f | Error _ -> l) else l

let same a b =
  a == b
  || Lazy.is_val headers && Lazy.is_val parsed
     && (match Lazy.force headers, Lazy.force parsed with
         | Some h, Ok f -> (a == h && b == f) || (a == f && b == h)
         | _ -> false)

let tests = lazy (parse_files (List.filter (fun (name, _) -> name = test_file) Installed_sources.files))

let test_modules () = Result.bind (modules ()) (fun _ -> Lazy.force tests)

let file_names = List.map fst Installed_sources.files
