type t = {
  text : string;
  line_starts : int array;
  byte_order_mark : bool;
  latin1 : bool;
  final_newline : bool;
  length : int;
}

(* Length of the valid UTF-8 sequence starting at [i], or 0 when it is not one. *)
let utf8_sequence s i =
  let n = String.length s in
  let byte k = if i + k < n then Char.code (String.unsafe_get s (i + k)) else -1 in
  let cont k = let b = byte k in b >= 0x80 && b < 0xC0 in
  let c = byte 0 in
  if c < 0x80 then 1
  else if c < 0xC2 then 0
  else if c < 0xE0 then if cont 1 then 2 else 0
  else if c < 0xF0 then
    let c1 = byte 1 in
    if (c = 0xE0 && c1 < 0xA0) || (c = 0xED && c1 >= 0xA0) then 0
    else if cont 1 && cont 2 then 3 else 0
  else if c < 0xF5 then
    let c1 = byte 1 in
    if (c = 0xF0 && c1 < 0x90) || (c = 0xF4 && c1 >= 0x90) then 0
    else if cont 1 && cont 2 && cont 3 then 4 else 0
  else 0

let is_utf8 s start =
  let n = String.length s in
  let rec go i = i >= n || (let k = utf8_sequence s i in k > 0 && go (i + k)) in
  go start

let latin1_to_utf8 s start =
  let b = Buffer.create (String.length s + 64) in
  for i = start to String.length s - 1 do
    let c = Char.code s.[i] in
    if c < 0x80 then Buffer.add_char b s.[i]
    else begin
      Buffer.add_char b (Char.chr (0xC0 lor (c lsr 6)));
      Buffer.add_char b (Char.chr (0x80 lor (c land 0x3F)))
    end
  done;
  Buffer.contents b

(* Line starts in characters: a UTF-8 continuation byte does not start a character. *)
let line_starts text =
  let starts = ref [ 0 ] and count = ref 1 in
  let chars = ref 0 in
  let n = String.length text in
  let i = ref 0 in
  while !i < n do
    let c = String.unsafe_get text !i in
    if Char.code c land 0xC0 <> 0x80 then incr chars;
    (match c with
     | '\n' -> starts := !chars :: !starts; incr count
     | '\r' when !i + 1 >= n || String.unsafe_get text (!i + 1) <> '\n' ->
         starts := !chars :: !starts; incr count
     | _ -> ());
    incr i
  done;
  let a = Array.make !count 0 in
  List.iteri (fun k v -> a.(!count - 1 - k) <- v) !starts;
  (a, !chars)

let decode raw =
  let bom = String.length raw >= 3 && String.sub raw 0 3 = "\xEF\xBB\xBF" in
  let start = if bom then 3 else 0 in
  let latin1 = not (is_utf8 raw start) in
  let text =
    if latin1 then latin1_to_utf8 raw start
    else if bom then String.sub raw 3 (String.length raw - 3)
    else raw
  in
  let n = String.length text in
  let final_newline = n = 0 || text.[n - 1] = '\n' || text.[n - 1] = '\r' in
  let line_starts, length = line_starts text in
  { text; line_starts; byte_order_mark = bom; latin1; final_newline; length }
