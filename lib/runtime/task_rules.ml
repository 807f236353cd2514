(* Several tasks on one clock (ch. 14): what both engines' task sets share. *)

type task = {
  name : string; program : Ir.program; entry : string; host : Host.t; before : string list; after : string list;
}

let first_routine t = match t.before with r :: _ -> r | [] -> t.entry

type link = { task : int; slot : int; owner : int; owner_slot : int }

let max_tasks = 20

type order = Round_robin | Seeded of int64 ref   (* SplitMix64's state *)

let order_of_seed = function Some s -> Seeded (ref (Int64.of_int s)) | None -> Round_robin

(* SplitMix64 (Steele, Lea, Flood 2014): a small generator of our own, so that the order of a
   seed never depends on the version of OCaml's Random. *)
let splitmix state =
  state := Int64.add !state 0x9E3779B97F4A7C15L;
  let z = !state in
  let z = Int64.mul (Int64.logxor z (Int64.shift_right_logical z 30)) 0xBF58476D1CE4E5B9L in
  let z = Int64.mul (Int64.logxor z (Int64.shift_right_logical z 27)) 0x94D049BB133111EBL in
  Int64.logxor z (Int64.shift_right_logical z 31)

(* The scheduler's rule, for both engines' task sets: among the [count] tasks, those [eligible]
   (running, not waiting in vain), the next in round robin from [cursor], or SplitMix64's pick. *)
let next_turn order ~cursor ~count eligible =
  let candidates = List.filter eligible (List.init count Fun.id) in
  match candidates, order with
  | [], _ -> None
  | _, Round_robin ->
      let rec look i = if List.mem (i mod count) candidates then i mod count else look (i + 1) in
      let k = look !cursor in
      cursor := (k + 1) mod count; Some k
  | _, Seeded state ->
      let r = Int64.unsigned_rem (splitmix state) (Int64.of_int (List.length candidates)) in
      Some (List.nth candidates (Int64.to_int r))

(* Every running task waits (ch. 14, one clock): [waits] gives each running task's name, what it
   waits for, and the time its wait gave. The clock moves on to the earliest such time ([None]);
   with none, a deadlock; beyond --max-time, the time limit. For both engines' task sets. *)
let every_task_waits (clock : Host.t) waits =
  clock.every_task_waits (List.map (fun (name, _, _) -> name) waits);
  let times = List.filter_map (fun (_, _, wake) -> wake) waits in
  match List.sort compare times with
  | [] ->
      let waiting = List.map (fun (name, what, _) ->
          match what with Some what -> name ^ " for " ^ what | None -> name) waits in
      Some (Outcome.Deadlock (Printf.sprintf
                          "deadlock at %g s: every task waits (%s), and nothing can end the waits \
                           (no stimulus event left, no interrupt to come)"
                          (clock.now ()) (String.concat "; " waiting)))
  | t :: _ when t > clock.max_time -> Some (Outcome.time_limit clock.max_time)
  | t :: _ -> clock.advance_to t; None

(* §9.1: the task's entry routine is a procedure without parameters; the message names the
   others there are, which --entry runs (the installed routines, whose modules are of the
   system, are not offered). *)
let no_entry (program : Ir.program) entry =
  let offered = List.filter_map (fun (name, i) ->
      let r = program.routines.(i) in
      let file = match Rapid_syntax.Source.file_of r.at with Some f -> Rapid_syntax.Source.name f | None -> "" in
      if List.mem file Rapid_typing.Installed_env.file_names then None else Some name) program.entry_points in
  let offered = List.sort_uniq compare offered in
  Printf.sprintf "no procedure %s without parameters to run (§9.1): %s" entry
    (match offered with
     | [] -> "the task has no procedure without parameters; declare PROC " ^ entry ^ "()"
     | [ one ] -> Printf.sprintf "run the task's procedure %s with --entry %s" one one
     | l when List.length l <= 12 ->
         Printf.sprintf "run another with --entry NAME; the task's procedures without parameters: %s"
           (String.concat ", " l)
     | l ->
         Printf.sprintf "run another with --entry NAME; the task's procedures without parameters: %s, ... (%d in all)"
           (String.concat ", " (List.filteri (fun i _ -> i < 12) l)) (List.length l))

let not_an_event_routine (program : Ir.program) name =
  let lower = String.lowercase_ascii name in
  if Array.exists (fun (r : Ir.routine) -> String.lowercase_ascii r.name = lower) program.routines then
    Printf.sprintf "the event routine %s is not a procedure without parameters" name
  else Printf.sprintf "no procedure %s for the event routine" name

let sequence ~find ~before ~entry ~after =
  List.fold_right (fun (name, is_entry) acc ->
      match find ~is_entry name, acc with
      | Ok r, Ok rs -> Ok (r :: rs)
      | Error m, _ | _, Error m -> Error m)
    (List.map (fun n -> (n, false)) before @ [ (entry, true) ] @ List.map (fun n -> (n, false)) after) (Ok [])

let entry_routine (program : Ir.program) entry =
  let lower = String.lowercase_ascii entry in
  let rec find i =
    if i >= Array.length program.routines then None
    else if String.lowercase_ascii program.routines.(i).name = lower then Some i
    else find (i + 1) in
  match find 0 with
  | None -> Error (no_entry program entry)
  | Some i ->
      let r = program.routines.(i) in
      if r.kind <> Procedure || Array.length r.parameters > 0 then
        Error (Printf.sprintf "%s is not a procedure without parameters: it cannot be the entry routine (§9.1)" entry)
      else Ok i

let initial_value (program : Ir.program) j =
  match program.globals.(j).g_init with
  | Init_expr { e = Literal v; _ } -> Some v
  | Init_default shape -> Some (Value.default_of shape)
  | Init_expr _ -> None
