open Rapid_syntax

type t = {
  text : string;            (* UTF-8 *)
  line_chars : int array;   (* character offset of each line's start *)
  line_bytes : int array;   (* byte offset of each line's start *)
  length : int;             (* characters *)
}

type position = { line : int; character : int }

(* The length of the UTF-8 sequence that begins with byte [c] (Decode gives valid UTF-8). *)
let width c = if c < 0x80 then 1 else if c < 0xE0 then 2 else if c < 0xF0 then 3 else 4

let of_bytes raw =
  let d = Decode.decode raw in
  let text = d.text in
  let n = String.length text in
  let line_bytes = Array.make (Array.length d.line_starts) 0 in
  (* Walk the text once, character by character, noting the byte at which each line starts. *)
  let line = ref 1 and chars = ref 0 and i = ref 0 in
  while !i < n && !line < Array.length d.line_starts do
    if !chars = d.line_starts.(!line) then (line_bytes.(!line) <- !i; incr line)
    else begin
      i := !i + width (Char.code text.[!i]);
      incr chars
    end
  done;
  while !line < Array.length d.line_starts do line_bytes.(!line) <- n; incr line done;
  { text; line_chars = d.line_starts; line_bytes; length = d.length }

let text t = t.text
let length t = t.length

(* The line that holds the character offset [o]: the last whose start is at most [o]. *)
let line_of t o =
  let lo = ref 0 and hi = ref (Array.length t.line_chars - 1) in
  while !lo < !hi do
    let mid = (!lo + !hi + 1) / 2 in
    if t.line_chars.(mid) <= o then lo := mid else hi := mid - 1
  done;
  !lo

let clamp t o = max 0 (min o t.length)

let byte_of_offset t o =
  let o = clamp t o in
  let l = line_of t o in
  let b = ref t.line_bytes.(l) in
  for _ = 1 to o - t.line_chars.(l) do b := !b + width (Char.code t.text.[!b]) done;
  !b

let position_of_offset t o =
  let o = clamp t o in
  let l = line_of t o in
  let b = ref t.line_bytes.(l) and units = ref 0 in
  for _ = 1 to o - t.line_chars.(l) do
    let w = width (Char.code t.text.[!b]) in
    units := !units + (if w = 4 then 2 else 1);
    b := !b + w
  done;
  { line = l; character = !units }

(* Where the line's text ends: before its line break (LF, CRLF or CR). *)
let line_end_offset t l =
  if l + 1 >= Array.length t.line_chars then t.length
  else
    let next = t.line_chars.(l + 1) and nb = t.line_bytes.(l + 1) in
    if nb >= 2 && t.text.[nb - 1] = '\n' && t.text.[nb - 2] = '\r' then next - 2 else next - 1

let offset_of_position t p =
  if p.line < 0 then 0
  else if p.line >= Array.length t.line_chars then t.length
  else
    let stop = line_end_offset t p.line in
    let o = ref t.line_chars.(p.line) and b = ref t.line_bytes.(p.line) and units = ref 0 in
    while !o < stop && !units < p.character do
      let w = width (Char.code t.text.[!b]) in
      units := !units + (if w = 4 then 2 else 1);
      b := !b + w;
      incr o
    done;
    !o

let slice t a b =
  let a = clamp t a and b = clamp t b in
  if b <= a then "" else
    let ba = byte_of_offset t a and bb = byte_of_offset t b in
    String.sub t.text ba (bb - ba)

let apply_change t range new_text =
  match range with
  | None -> of_bytes new_text
  | Some (a, b) ->
      let oa = offset_of_position t a and ob = offset_of_position t b in
      let oa, ob = if oa <= ob then (oa, ob) else (ob, oa) in
      let ba = byte_of_offset t oa and bb = byte_of_offset t ob in
      let n = String.length t.text in
      of_bytes (String.sub t.text 0 ba ^ new_text ^ String.sub t.text bb (n - bb))

let json_position p = `Assoc [ ("line", `Int p.line); ("character", `Int p.character) ]

let position_of_json (j : Yojson.Safe.t) =
  match j with
  | `Assoc fields -> (
      match List.assoc_opt "line" fields, List.assoc_opt "character" fields with
      | Some (`Int line), Some (`Int character) -> Some { line; character }
      | _ -> None)
  | _ -> None

let json_range t a b =
  `Assoc [ ("start", json_position (position_of_offset t a)); ("end", json_position (position_of_offset t b)) ]
