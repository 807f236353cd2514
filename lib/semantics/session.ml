open Rapid_syntax

type loaded = { program : Ir.program; warnings : Rapid_typing.Report.t list }

type failure =
  | Front_end of Diagnostic.t list
  | Static of Rapid_typing.Report.t list
  | Internal of string

let load_modules ?(allow_unknown = false) modules =
  match Rapid_typing.Installed_env.modules () with
  | Error d -> Error (Internal ("the installed environment does not parse: " ^ Diagnostic.to_string d))
  | Ok installed ->
      let result = Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
      if Rapid_typing.Check.errors result <> [] then Error (Static result.reports)
      else
        let program = Lower.program ~installed ~modules result.elaboration in
        (* The initial values of data are known before the run (§3.2): their errors are static. *)
        match Initial_values.evaluate program with
        | Ok program -> Ok { program; warnings = result.reports }
        | Error reports -> Error (Static (result.reports @ reports))

let load ?(strict = false) ?allow_unknown files =
  let options = { Parse.default_options with strict } in
  let parsed = List.map (Parse.parse_file ~options) files in
  match List.filter_map (function Error d -> Some d | Ok _ -> None) parsed with
  | [] -> load_modules ?allow_unknown (List.filter_map Result.to_option parsed)
  | errors -> Error (Front_end errors)
