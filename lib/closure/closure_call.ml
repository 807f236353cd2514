open Ir

type source = Value of expr | Read of place

let direct (r : routine) (arguments : argument array) =
  let plain (p : parameter) = p.p_mode = Rapid_typing.Tables.Mode_in && not p.p_optional && not p.p_switch in
  if r.primitive <> None || r.error <> None || r.undo <> None
     || Array.length arguments <> Array.length r.parameters
     || not (Array.for_all plain r.parameters) then None
  else
    let source = function
      | By_value e -> Some (Value e)
      | By_reference (p, _) -> Some (Read p)
      | Absent | Present_switch | Pass_on _ -> None in
    let sources = Array.map source arguments in
    if Array.for_all Option.is_some sources then Some (Array.map Option.get sources) else None
