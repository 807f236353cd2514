(* §5.5: "the evaluation of a function must be terminated by a return statement". Whether the
   statements of a function can complete, so that its ENDFUNC is reached without RETURN (at run
   time the call raises ERR_FNCNORET). A warning, so the analysis errs on the side of silence:
   every path it cannot follow (a GOTO, a call) is taken as not falling off, except where a
   label after it makes the rest reachable again. *)

open Rapid_syntax
open Ast

(* Installed procedures that never return to their caller's next statement. *)
let never_returns = [ "exitcycle"; "raisetouser" ]

(* Whether the list can complete, and the last statement on the way ([None]: none). *)
let rec completes (l : statement list) : bool * region option =
  List.fold_left (fun (reachable, last) (s : statement) ->
      match s.it with
      | Label _ -> (true, Some s.at)
      | Statement_comment _ -> (reachable, last)
      | _ when not reachable -> (false, last)
      | _ -> (statement s, Some s.at)) (true, None) l

and statement (s : statement) =
  match s.it with
  | Return _ | Raise _ | Exit | Retry | Trynext | Goto _ -> false
  | Procedure_call (Procedure_name { it = Ident n; _ }, _, _) ->
      not (List.mem (String.lowercase_ascii n) never_returns)
  | If { then_branch; elseifs; else_branch; _ } -> (
      match else_branch with
      | None -> true
      | Some e ->
          fst (completes then_branch) || fst (completes e)
          || List.exists (fun (c : elseif_clause) -> match c.it with
              | Elseif (_, b) -> fst (completes b) | EIT_placeholder -> true) elseifs)
  | While ({ it = Bool_literal true; _ }, _) -> false
  | Test { cases; default; _ } -> (
      match default with
      | None -> true
      | Some d ->
          fst (completes d)
          || List.exists (fun (c : case_clause) -> match c.it with
              | Case (_, b) -> fst (completes b) | CSE_placeholder -> true) cases)
  | _ -> true

let functions (m : module_declaration) =
  List.filter_map (fun (r : routine_declaration) ->
      match r.it with
      | Function_declaration { name = { it = Ident n; at }; body; _ } -> (
          match completes body.statements with
          | true, last -> Some (n, at, last)
          | false, _ -> None)
      | _ -> None) m.routine_declarations
