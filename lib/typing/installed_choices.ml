(* ABB, Technical reference manual - RAPID Instructions, Functions and Data types (3HAC050917,
   RobotWare 6): SearchL, SearchJ and SearchC take "Signal | PersBool" (the PERS bool form,
   RobotWare 6 and later). *)
let required = [
  ("SearchL", [ "Signal"; "PersBool" ]);
  ("SearchJ", [ "Signal"; "PersBool" ]);
  ("SearchC", [ "Signal"; "PersBool" ]);
]

let same a b = String.lowercase_ascii a = String.lowercase_ascii b

let apply routine slots =
  let groups = List.filter_map (fun (r, g) -> if same r routine then Some g else None) required in
  if groups = [] then slots
  else
    List.map (function
        | Env.Optional_slot ps as slot ->
            let names = List.map (fun (p : Env.parameter) -> p.p_name) ps in
            if List.exists (fun g -> List.length g = List.length names && List.for_all2 same g names) groups
            then Env.Required_choice ps
            else slot
        | slot -> slot) slots
