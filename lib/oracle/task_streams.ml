let world_kinds = [
  "signal-changed"; "interrupt-occurred"; "interrupt-discarded";
  "move-planned"; "move-started"; "move-ended"; "move-dropped"; "path-command"; "motion-warning";
  "tcp-sample" ]

let stream_of e =
  if List.mem (Event_stream.kind e) world_kinds then "world"
  else match e with
    | `Assoc f -> (match List.assoc_opt "task" f with Some (`String t) -> "task " ^ t | _ -> "run")
    | _ -> "run"

let streams events =
  let names = ref [] and table = Hashtbl.create 8 in
  List.iteri (fun i e ->
      let s = stream_of e in
      if not (Hashtbl.mem table s) then names := s :: !names;
      Hashtbl.replace table s ((i + 1, e) :: Option.value (Hashtbl.find_opt table s) ~default:[])) events;
  (* The tasks first, then the world, then what names no task. *)
  let rank s = if s = "world" then 1 else if s = "run" then 2 else 0 in
  List.stable_sort (fun a b -> compare (rank a) (rank b)) (List.rev !names)
  |> List.map (fun s -> (s, List.rev (Hashtbl.find table s)))

type divergence = { stream : string; divergence : Event_diff.divergence }
type verdict = Agree of int | Diverge of divergence | Broken of string

let compare ?(ignore = []) ~(expected : Event_stream.t) ~(actual : Event_stream.t) () =
  if actual.schema <> expected.schema then
    Broken (Printf.sprintf
              "the implementation's first line names the schema %s; expected %s (the schema of several tasks)"
              (Event_stream.clip (Option.value actual.schema ~default:"(none)"))
              (Option.value expected.schema ~default:"(none)"))
  else
    let keep e = not (List.mem (Event_stream.kind e) ignore) in
    let expected_streams = streams (List.filter keep expected.events)
    and actual_streams = streams (List.filter keep actual.events) in
    let names = List.map fst expected_streams
                @ List.filter (fun s -> not (List.mem_assoc s expected_streams)) (List.map fst actual_streams) in
    let events_of l s = Option.value (List.assoc_opt s l) ~default:[] in
    (* Where a divergence comes in rapid-sem's whole stream: its expected event's place, or, when
       rapid-sem's stream had ended, just after its last event. *)
    let diverging = List.filter_map (fun s ->
        let e = events_of expected_streams s and a = events_of actual_streams s in
        match Event_diff.compare ~expected:(List.map snd e) ~actual:(List.map snd a) () with
        | None -> None
        | Some d ->
            let key = match List.nth_opt e (d.index - 1) with
              | Some (i, _) -> i
              | None -> (match List.rev e with (i, _) :: _ -> i + 1 | [] -> max_int) in
            Some (key, { stream = s; divergence = d })) names in
    match List.stable_sort (fun (a, _) (b, _) -> Stdlib.compare a b) diverging with
    | [] -> Agree (List.length (List.filter keep expected.events))
    | (_, d) :: _ -> Diverge d

let report { stream; divergence = d } =
  let show = function Some e -> Event_stream.show e | None -> "(no more events)" in
  (* A stream's name holds a task's name, which may be the implementation's text. *)
  Printf.sprintf "%s, event %d: expected %s, got %s" (Event_stream.clip stream) d.index (show d.expected)
    (show d.actual)
