open Rapid_syntax
module Check = Rapid_typing.Check

type t = {
  files_before : Source.registry;
  records_before : int;
  files : Source.registry;
  record_ids : int;
  level : Ast.module_declaration list;
  checked : Check.installed_state;
  lowered : Lower.installed_lowering;
  values : Initial_values.kept;
}

let compute () =
  let files_before = Source.registry () and records_before = Rapid_typing.Types.record_ids_used () in
  match Rapid_typing.Installed_env.parse () with
  | Error d -> Error ("the installed environment does not parse: " ^ Diagnostic.to_string d)
  | Ok modules -> (
      match Check.installed_state modules with
      | Error reports ->
          Error (String.concat "\n" ("the installed environment does not check:"
                                     :: List.map Rapid_typing.Report.to_string reports))
      | Ok checked ->
          Check.use_installed_state checked;
          (* a task without modules of its own: its elaboration's installed level is the state's *)
          let r = Check.check_task ~installed:modules [] in
          let lowered = Lower.installed_lowering ~installed:modules r.elaboration in
          Lower.use_installed_lowering lowered;
          (* the installed data's initial values, computed for the empty task and kept for any *)
          match Initial_values.evaluate (Lower.program ~installed:modules ~modules:[] r.elaboration) with
          | Error reports ->
              Error (String.concat "\n" ("the installed data's initial values:"
                                         :: List.map Rapid_typing.Report.to_string reports))
          | Ok _ ->
              (* the state keyed by the modules' headers, so that it holds no declaration's tree:
                 those are marshalled apart (Installed_env.level) *)
              let level = List.map (fun (m : Ast.module_declaration) ->
                  { m with type_definitions = []; data_declarations = []; routine_declarations = [] }) modules in
              Ok ({ files_before; records_before; files = Source.registry ();
                    record_ids = Rapid_typing.Types.record_ids_used (); level;
                    checked = Check.installed_state_of checked level;
                    lowered = Lower.installed_lowering_of lowered level;
                    values = Option.get (Initial_values.kept ()) }, modules))

let files t = t.files
let before t = (t.files_before, t.records_before)
let record_ids t = t.record_ids
let level t = t.level

let install t =
  Check.use_installed_state t.checked;
  Lower.use_installed_lowering t.lowered;
  Initial_values.keep t.values
