open Rapid_syntax

type buffer = { name : string; modules : Ast.module_declaration list }

type checked = { reports : Rapid_typing.Report.t list; unknown_summaries : (string * string) list }

let check ?testing ~allow_unknown ~io ~several buffers =
  match Session.installed ?testing ~io () with
  | Error d -> Error d
  | Ok installed ->
      let checked = List.map (fun { name; modules } ->
          let result = Rapid_typing.Check.check_task ~options:{ allow_unknown } ~installed modules in
          let reports =
            if Rapid_typing.Check.errors result <> [] then result.reports
            else match Session.lower ~io ~installed ~modules result with
              | Ok _ -> result.reports
              | Error initial_value_errors -> result.reports @ initial_value_errors in
          (name, modules, result, reports)) buffers in
      let is_error (r : Rapid_typing.Report.t) = r.severity = Error in
      (* ch. 14: the buffers together, once each is sound on its own. *)
      let across =
        if not several || List.exists (fun (_, _, _, reports) -> List.exists is_error reports) checked then []
        else Task_check.shared_persistents
            (List.map (fun (name, modules, (result : Rapid_typing.Check.result), _) ->
                 { Task_check.name; modules; elaboration = result.elaboration }) checked) in
      let reports = List.map (Session.at_io_place io)
          (List.concat_map (fun (_, _, _, reports) -> reports) checked @ across) in
      let unknown_summaries = List.filter_map (fun (name, _, result, _) ->
          Option.map (fun s -> (name, s)) (Rapid_typing.Check.unknown_summary result)) checked in
      Ok { reports; unknown_summaries }
