module O = Rapid_runtime.Observation

let event ~text (o : O.t) : Yojson.Safe.t =
  let obj kind fields = `Assoc (("event", `String kind) :: fields) in
  match o with
  | Stored { place; value } -> obj "store" [ ("place", text place); ("value", text value) ]
  | Called { routine; arguments } ->
      obj "arguments"
        [ ("routine", text routine);
          ("arguments", `List (List.map (fun (p, v) ->
               `Assoc (("parameter", text p) :: (match v with Some v -> [ ("value", text v) ] | None -> [])))
               arguments)) ]
  | Returned { routine; value } -> obj "returned" [ ("routine", text routine); ("value", text value) ]
  | Propagated { name; number; routine; caller } ->
      obj "error-propagated"
        [ ("name", text name); ("number", `Int number); ("routine", text routine); ("caller", text caller) ]
  | Retried r -> obj "retry" [ ("routine", text r) ]
  | Tried_next r -> obj "trynext" [ ("routine", text r) ]
