open Rapid_syntax

let named (args : Ast.argument array) =
  Array.to_list args
  |> List.filter_map (fun (a : Ast.argument) ->
      match a.it with
      | Optional_argument ({ it = Ident n; _ }, _) | Conditional_argument ({ it = Ident n; _ }, _) ->
          Some (String.lowercase_ascii n)
      | _ -> None)

let raise_to_user ~report ~in_error_handler ~in_nostepin ~installed ~at name args =
  if installed && Types.same_name name "raisetouser" then begin
    (* §7.3: RaiseToUser hands an error of a NOSTEPIN routine's handler to the user level;
       elsewhere there is no error in hand, or no level below the user's (R-7.3-n). *)
    if not in_error_handler then
      Report.error report ~rule:"raise-to-user-in-handler" ~section:"7.3" at
        "RaiseToUser may be used only in an error handler (of a routine of a NOSTEPIN module)"
    else if not in_nostepin then
      Report.error report ~rule:"raise-to-user-nostepin" ~section:"7.3,9.4" at
        "RaiseToUser may be used only in a routine of a NOSTEPIN module: this routine is at the \
         user level already";
    (* ABB's RaiseToUser: one of \Continue and \BreakOff is required (\Resume is §7.3's name
       for \Continue, R-7.3-m). *)
    let given = named args in
    if not (List.exists (fun n -> List.mem n given) [ "continue"; "resume"; "breakoff" ]) then
      Report.error report ~rule:"raise-to-user-switch" ~section:"7.3" at
        "RaiseToUser needs \\Continue (or \\Resume) or \\BreakOff: whether the NOSTEPIN routines \
         go on after the user's error handler or are broken off"
  end
