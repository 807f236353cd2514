module V = Value

type t =
  | Stored of { place : string; value : string }
  | Called of { routine : string; arguments : (string * string option) list }
  | Returned of { routine : string; value : string }
  | Propagated of { name : string; number : int; routine : string; caller : string }
  | Retried of string
  | Tried_next of string

(* R-4.5-m: the fewest significant digits that read back to the same number (num is single
   precision, §2.13: 9 digits always suffice; dnum 17). A whole number below 1E15 is written in
   plain decimal, its digits beyond the significant ones zeros, so that one value has one text
   and a programmer reads 9000000000 where the store holds the single 8999999488. *)
let shortest ~max_digits ~same f =
  if Float.is_nan f then "nan"
  else if f = 0. then "0"
  else if Float.abs f = Float.infinity then (if f > 0. then "inf" else "-inf")
  else
    let rec go p =
      let s = Printf.sprintf "%.*g" p f in
      if p >= max_digits || same (float_of_string s) then s else go (p + 1)
    in
    let s = go 1 in
    if Float.is_integer f && Float.abs f < 1e15 then Printf.sprintf "%.0f" (float_of_string s)
    else String.uppercase_ascii s

let rec value (v : V.t) =
  match v with
  | Num f -> shortest ~max_digits:9 ~same:(fun g -> V.to_single g = f) f
  | Dnum f -> shortest ~max_digits:17 ~same:(fun g -> g = f) f
  | Bool b -> if b then "TRUE" else "FALSE"
  | String s -> Text_format.string_literal s
  | Record cs | Array cs -> "[" ^ String.concat "," (Array.to_list (Array.map value cs)) ^ "]"
  | Handle h -> Printf.sprintf "<%s #%d>" (V.handle_kind h) (V.handle_id h)

type step = Index of int | Component_of of int

type roots = {
  n_locals : int;
  local : int -> V.t array * int;
  n_globals : int;
  global_box : int -> V.t array;
  global_idx : int -> int;
}

(* Two passes: a data object that is the location itself (a reference parameter is one before
   the data it denotes: the routine names it so), then one that holds it in a record or an
   array. No two module data objects share storage, so the second pass may take them in any
   order: the last declared first, the program's own before the installed ones. *)
let path_within ((box, idx) : V.t array * int) v =
  let rec within v path =
    match v with
    | V.Record cs | V.Array cs ->
        let step k = match v with V.Record _ -> Component_of k | _ -> Index (k + 1) in
        if cs == box then Some (List.rev (step idx :: path))
        else
          let rec each k =
            if k >= Array.length cs then None
            else match within cs.(k) (step k :: path) with Some p -> Some p | None -> each (k + 1)
          in
          each 0
    | _ -> None
  in
  within v []

let find ((box, idx) : V.t array * int) roots =
  let within v _ = path_within (box, idx) v in
  let rec same_local i =
    if i >= roots.n_locals then None
    else let rbox, ridx = roots.local i in
      if rbox == box && ridx = idx then Some (Ir.Local i, []) else same_local (i + 1) in
  let rec same_global g =
    if g >= roots.n_globals then None
    else if roots.global_box g == box && roots.global_idx g = idx then Some (Ir.Global g, [])
    else same_global (g + 1) in
  let rec in_local i =
    if i >= roots.n_locals then None
    else
      let rbox, ridx = roots.local i in
      match if ridx < Array.length rbox then within rbox.(ridx) [] else None with
      | Some p -> Some (Ir.Local i, p)
      | None -> in_local (i + 1) in
  let rec in_global g =
    if g < 0 then None
    else
      let rbox = roots.global_box g and ridx = roots.global_idx g in
      match if ridx < Array.length rbox then within rbox.(ridx) [] else None with
      | Some p -> Some (Ir.Global g, p)
      | None -> in_global (g - 1) in
  match same_local 0 with
  | Some _ as found -> found
  | None -> (
      match same_global 0 with
      | Some _ as found -> found
      | None -> (
          match in_local 0 with
          | Some _ as found -> found
          | None -> in_global (roots.n_globals - 1)))

(* A run that observes its stores asks this at every store, mostly for the routine of the store
   before: the answer for the last routine asked is kept (one value, read at once, so that the
   threads of several tasks never see half of it), and the search, from the first routine,
   passes the 270 and more installed routines only when the routine changes. *)
let last_index : (Ir.program * Ir.routine * int) option ref = ref None

let routine_index (program : Ir.program) (r : Ir.routine) =
  match !last_index with
  | Some (p, r', i) when p == program && r' == r -> i
  | _ ->
      let rec go i =
        if i >= Array.length program.routines then -1 else if program.routines.(i) == r then i else go (i + 1)
      in
      let i = go 0 in
      last_index := Some (program, r, i);
      i

let slot_name (program : Ir.program) ri (s : Ir.slot) =
  match s with
  | Global i -> program.globals.(i).g_name
  | Local i ->
      if ri >= 0 && ri < Array.length program.names.local_names && i < Array.length program.names.local_names.(ri)
      then program.names.local_names.(ri).(i)
      else Printf.sprintf "<local %d>" i

let component_name (program : Ir.program) ri (s : Ir.slot) path k =
  let scope = match s with Global _ -> -1 | Local _ -> ri in
  match Hashtbl.find_opt program.names.component_names (scope, s, path @ [ k ]) with
  | Some n -> n
  | None -> Printf.sprintf "<component %d>" (k + 1)

(* Consecutive indexes of a matrix are one index list, m{2,3} (§3.6). *)
let place program routine (slot, steps) =
  let ri = routine_index program routine in
  let buf = Buffer.create 16 in
  Buffer.add_string buf (slot_name program ri slot);
  let rec go path open_index = function
    | [] -> if open_index then Buffer.add_char buf '}'
    | Index k :: rest ->
        Buffer.add_string buf (if open_index then "," else "{");
        Buffer.add_string buf (string_of_int k);
        go (path @ [ -1 ]) true rest
    | Component_of k :: rest ->
        if open_index then Buffer.add_char buf '}';
        Buffer.add_char buf '.';
        Buffer.add_string buf (component_name program ri slot path k);
        go (path @ [ k ]) false rest
  in
  go [] false steps;
  Buffer.contents buf

let place_of program routine target (roots : roots) =
  match find target roots with
  | Some p -> place program routine p
  | None -> "<a value no data object holds>"

let to_string = function
  | Stored { place; value } -> Printf.sprintf "store %s := %s" place value
  | Called { routine; arguments } ->
      Printf.sprintf "call-arguments %s(%s)" routine
        (String.concat ", " (List.map (function
             | p, Some v -> p ^ " := " ^ v
             | p, None -> "\\" ^ p) arguments))
  | Returned { routine; value } -> Printf.sprintf "return-value %s %s" routine value
  | Propagated { name; number; routine; caller } ->
      Printf.sprintf "error-propagated %s %d from %s to %s" name number routine caller
  | Retried r -> "retry " ^ r
  | Tried_next r -> "trynext " ^ r

let references (args : Argument.t array) =
  Array.fold_right (fun (a : Argument.t) acc ->
      match a with
      | Location (box, j, _) when j < Array.length box -> (box, j, V.copy box.(j)) :: acc
      | _ -> acc) args []

let changed before =
  List.filter_map (fun (box, j, old) -> if V.equal old box.(j) then None else Some (box, j)) before
