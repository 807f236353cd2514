let same a b = String.lowercase_ascii a = String.lowercase_ascii b

let bind (r : Ir.routine) (args : Ir.late_argument array) =
  let n = Array.length r.parameters in
  let bound = Array.make n Ir.Absent in
  let ok = ref true in
  let next_required = ref 0 in
  let rec next_required_index i =
    if i >= n then None else if not r.parameters.(i).p_optional then Some i else next_required_index (i + 1)
  in
  let value_argument (p : Ir.parameter) (a : Ir.late_argument) =
    match a.late_value with
    | Ir.Late_expr e ->
        if p.p_mode = Mode_in then Some (Ir.By_value e)
        else (match e.e with
            | Read place | Read_signal place -> Some (By_reference (place, a.late_kind))
            | _ -> None)
    | Late_reference place -> Some (By_reference (place, a.late_kind))
    | Late_switch -> if p.p_switch then Some Present_switch else None
  in
  Array.iter (fun (a : Ir.late_argument) ->
      if !ok then
        match a.late_name, a with
        | Some name, v
          when Array.exists (fun (p : Ir.parameter) -> p.p_optional && same p.p_name name) r.parameters -> (
            let i = ref 0 in
            while not (r.parameters.(!i).p_optional && same r.parameters.(!i).p_name name) do incr i done;
            match value_argument r.parameters.(!i) v with
            | Some b -> bound.(!i) <- b
            | None -> ok := false)
        | name, v -> (
            match next_required_index !next_required with
            | None -> ok := false
            | Some i -> (
                next_required := i + 1;
                (match name with Some nm when not (same nm r.parameters.(i).p_name) -> ok := false | _ -> ());
                match value_argument r.parameters.(i) v with
                | Some b -> bound.(i) <- b
                | None -> ok := false))) args;
  if !ok && next_required_index !next_required = None then Some bound else None
