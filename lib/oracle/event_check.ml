(* The implementation's side of the oracle in memory bounded by one line: each event is compared
   as it comes with rapid-sem's event at that place and dropped; only the first that differs is
   kept, as text. A million events, or a hundred lines of 80,000 values each, held as trees took
   hundreds of megabytes (issue 21); rapid-sem's own events are held as the text of each. *)

type verdict = Agree of int | Diverge of Event_diff.divergence | Broken of string

type t = {
  ignore : string list;
  context : int;
  reader : Event_stream.reader;
  mutable reference : Event_stream.t option;   (* until the implementation's first line *)
  mutable started : bool;
  mutable v1 : bool;
  mutable broken : string option;
  mutable expected : string array;             (* rapid-sem's events, prepared, as text *)
  mutable total : int;                         (* rapid-sem's events counted by Agree *)
  mutable cursor : int;                        (* the events agreed so far *)
  mutable diverged : (int * string option) option;
}

let create ?(ignore = []) ?(context = 3) ~expected () =
  { ignore; context; reader = Event_stream.reader (); reference = Some expected; started = false;
    v1 = false; broken = None; expected = [||]; total = 0; cursor = 0; diverged = None }

let text e = Event_stream.to_string (Event_diff.strip e)

(* The implementation's first line names its schema: it says which of rapid-sem's streams, /2
   or /2 read as /1 says it (Schema_compat), its events are compared with. *)
let decide t schema =
  t.started <- true;
  match t.reference with
  | None -> ()
  | Some reference ->
      t.reference <- None;
      let v1 = schema = Some "rapid-sem/1" && reference.schema = Some Schema_compat.current in
      if schema <> reference.schema && not v1 then
        t.broken <- Some (Printf.sprintf "the implementation's first line names the schema %s; expected %s"
                            (Event_stream.clip (Option.value schema ~default:"(none)"))
                            (String.concat " or " Schema_compat.accepted))
      else begin
        let events = if v1 then Schema_compat.to_v1 reference.events else reference.events in
        t.v1 <- v1;
        t.total <- List.length events;
        let kept = List.filter (fun e -> not (List.mem (Event_stream.kind e) t.ignore)) events in
        t.expected <- Array.map text (Array.of_list kept)
      end

let compare_event t e =
  let k = Event_stream.kind e in
  if t.broken = None && t.diverged = None && not (List.mem k t.ignore) && not (t.v1 && k = "task-ended") then
    let a = text e in
    if t.cursor < Array.length t.expected && String.equal t.expected.(t.cursor) a then t.cursor <- t.cursor + 1
    else t.diverged <- Some (t.cursor + 1, Some a)

let add_line t n line =
  match Event_stream.read_line t.reader n line with
  | Error m -> Error m
  | Ok None -> Ok ()
  | Ok (Some e) ->
      if t.started then compare_event t e
      else if Event_stream.kind e = "start" then
        decide t (match e with `Assoc f -> (match List.assoc_opt "schema" f with
            | Some (`String s) -> Some s | _ -> None) | _ -> None)
      else (decide t None; compare_event t e);
      Ok ()

let region_of = function `Assoc f -> List.assoc_opt "at" f | _ -> None

(* The divergence at [index] (1-based) as Event_diff.compare gives it: the few events the report
   shows are parsed again from their text. *)
let divergence t index actual =
  let event i = Yojson.Safe.from_string t.expected.(i) in
  let expected = if index - 1 < Array.length t.expected then Some (event (index - 1)) else None in
  let first = max 0 (index - 1 - t.context) in
  let before = List.init (index - 1 - first) (fun k -> event (first + k)) in
  let rec nearest i =
    if i < 0 then None else match region_of (event i) with Some r -> Some r | None -> nearest (i - 1) in
  let at = match Option.bind expected region_of with Some r -> Some r | None -> nearest (index - 2) in
  { Event_diff.index; expected; actual = Option.map Yojson.Safe.from_string actual; before; at }

let finish t =
  if not t.started then decide t None;
  match t.broken, t.diverged with
  | Some m, _ -> Broken m
  | None, Some (i, a) -> Diverge (divergence t i a)
  | None, None ->
      if t.cursor < Array.length t.expected then Diverge (divergence t (t.cursor + 1) None) else Agree t.total
