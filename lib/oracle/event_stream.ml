type event = Yojson.Safe.t
type t = { schema : string option; events : event list }

let max_depth = 100
let max_events = 1_000_000
let max_values = 8_000_000
let shown_bytes = 300

let kind = function
  | `Assoc fields -> (match List.assoc_opt "event" fields with Some (`String k) -> k | _ -> "")
  | _ -> ""

(* Two implementations may write an object's fields in any order: the comparison and the
   report see them sorted, so that only a difference of content counts. The maps are tail
   recursive: a line of 1 MiB may hold half a million items. *)
let rec canonical : Yojson.Safe.t -> Yojson.Safe.t = function
  | `Assoc fields ->
      let fields = List.rev (List.rev_map (fun (k, v) -> (k, canonical v)) fields) in
      `Assoc (List.sort (fun (a, _) (b, _) -> compare a b) fields)
  | `List items -> `List (List.rev (List.rev_map canonical items))
  | other -> other

let to_string e = Yojson.Safe.to_string (canonical e)

(* The length of the well-formed UTF-8 sequence at [i] (1 to 4), or 0: a byte that begins
   none, a sequence cut short, an overlong form, a surrogate or a code point past U+10FFFF. *)
let utf8_length s i =
  let n = String.length s in
  let byte k = if i + k < n then Char.code s.[i + k] else -1 in
  let cont k = let b = byte k in b >= 0x80 && b <= 0xBF in
  let in_range k lo hi = let b = byte k in b >= lo && b <= hi in
  match byte 0 with
  | b when b < 0x80 -> 1
  | b when b >= 0xC2 && b <= 0xDF -> if cont 1 then 2 else 0
  | 0xE0 -> if in_range 1 0xA0 0xBF && cont 2 then 3 else 0
  | 0xED -> if in_range 1 0x80 0x9F && cont 2 then 3 else 0
  | b when b >= 0xE1 && b <= 0xEF -> if cont 1 && cont 2 then 3 else 0
  | 0xF0 -> if in_range 1 0x90 0xBF && cont 2 && cont 3 then 4 else 0
  | b when b >= 0xF1 && b <= 0xF3 -> if cont 1 && cont 2 && cont 3 then 4 else 0
  | 0xF4 -> if in_range 1 0x80 0x8F && cont 2 && cont 3 then 4 else 0
  | _ -> 0

(* The text is another implementation's: written to a terminal as it is, its ESC and other
   control bytes would drive that terminal, and its invalid UTF-8 would make the report invalid
   too. So each control character (C0, DEL, and C1, which is U+0080 to U+009F) and each byte
   that begins no well-formed sequence is shown as \XX, its bytes in hexadecimal; a line break
   is a space, the report being one line; and the cut at [shown_bytes] falls between characters. *)
let clip s =
  let n = String.length s in
  let b = Buffer.create (min n shown_bytes + 16) in
  let hex c = Buffer.add_string b (Printf.sprintf "\\%02X" (Char.code c)) in
  let rec go i =
    if i < n then
      let len = utf8_length s i in
      if i + max len 1 > shown_bytes then
        Buffer.add_string b (Printf.sprintf "... (%d bytes)" n)
      else begin
        (match len, s.[i] with
         | 1, ('\n' | '\r') -> Buffer.add_char b ' '
         | 1, c when Char.code c < 0x20 || Char.code c = 0x7F -> hex c
         | 1, c -> Buffer.add_char b c
         | 0, c -> hex c
         | 2, c when c = '\xC2' && Char.code s.[i + 1] < 0xA0 -> hex c; hex s.[i + 1]
         | _ -> Buffer.add_string b (String.sub s i len));
        go (i + max len 1)
      end
  in
  go 0;
  Buffer.contents b

let show e = clip (to_string e)

(* One pass over a line before yojson sees it: [None] when its brackets and braces nest deeper
   than [max_depth] outside strings (yojson's reader recurses once per level, so a line of a
   million brackets would exhaust the stack before it said a word), else [Some n], [n] the
   values and names it holds (each begins a line or follows a bracket, a brace, a colon or a
   comma), which bound what its tree takes in memory. *)
let scan line =
  let n = String.length line in
  let rec go i depth in_string values =
    if i >= n then Some values
    else
      let c = line.[i] in
      if in_string then
        if c = '\\' then go (i + 2) depth true values
        else go (i + 1) depth (c <> '"') values
      else
        match c with
        | '"' -> go (i + 1) depth true values
        | '[' | '{' -> if depth + 1 > max_depth then None else go (i + 1) (depth + 1) false (values + 1)
        | ']' | '}' -> go (i + 1) (depth - 1) false values
        | ':' | ',' -> go (i + 1) depth false (values + 1)
        | _ -> go (i + 1) depth false values
  in
  go 0 0 false 1

type reader = {
  mutable first : event option;
  mutable rest : event list;
  mutable count : int;
  mutable values : int;
}

let reader () = { first = None; rest = []; count = 0; values = 0 }

let is_blank line = String.trim line = ""

let read_line r n line =
  if is_blank line then Ok None
  else if r.count >= max_events then
    Error (Printf.sprintf "line %d: more than %d events" n max_events)
  else
    match scan line with
    | None -> Error (Printf.sprintf "line %d: nested deeper than %d arrays and objects" n max_depth)
    | Some v when r.values + v > max_values ->
        Error (Printf.sprintf "line %d: more than %d JSON values in all" n max_values)
    | Some v -> (
        match Yojson.Safe.from_string line with
        | `Assoc _ as obj ->
            r.count <- r.count + 1;
            r.values <- r.values + v;
            Ok (Some (canonical obj))
        | _ -> Error (Printf.sprintf "line %d: not a JSON object" n)
        | exception Yojson.Json_error m -> Error (Printf.sprintf "line %d: not JSON (%s)" n (clip m)))

let add_line r n line =
  match read_line r n line with
  | Ok (Some e) ->
      (match r.first with None -> r.first <- Some e | Some _ -> r.rest <- e :: r.rest);
      Ok ()
  | Ok None -> Ok ()
  | Error m -> Error m

let contents r =
  let rest = List.rev r.rest in
  match r.first with
  | Some (`Assoc f as first) when kind first = "start" ->
      let schema = match List.assoc_opt "schema" f with Some (`String s) -> Some s | _ -> None in
      { schema; events = rest }
  | Some first -> { schema = None; events = first :: rest }
  | None -> { schema = None; events = [] }
