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

(* Speed (bench/README.md): modules are mostly ASCII, so the scans below step over ASCII bytes
   in a tight loop and look at sequences only where a byte is 0x80 or above. *)
let is_utf8 s start =
  let n = String.length s in
  let i = ref start and ok = ref true in
  while !ok && !i < n do
    if Char.code (String.unsafe_get s !i) < 0x80 then incr i
    else begin
      let k = utf8_sequence s !i in
      if k = 0 then ok := false else i := !i + k
    end
  done;
  !ok

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

(* Line starts in characters: a UTF-8 continuation byte does not start a character. A first
   pass counts the lines so that the starts go straight into an array of the right size. *)
let is_line_break text n i =
  match String.unsafe_get text i with
  | '\n' -> true
  | '\r' -> i + 1 >= n || String.unsafe_get text (i + 1) <> '\n'
  | _ -> false

let line_starts text =
  let n = String.length text in
  let count = ref 1 in
  for i = 0 to n - 1 do if is_line_break text n i then incr count done;
  let starts = Array.make !count 0 in
  let line = ref 1 and chars = ref 0 in
  for i = 0 to n - 1 do
    if Char.code (String.unsafe_get text i) land 0xC0 <> 0x80 then incr chars;
    if is_line_break text n i then begin
      Array.unsafe_set starts !line !chars;
      incr line
    end
  done;
  (starts, !chars)

(* The common case in one pass: [raw] from [start] is ASCII, so characters are bytes. Eight
   bytes at a time are stepped over when none is a line break or above 0x7F (the test for a
   zero byte in a word is the classic (x - 0x01..01) land (lnot x) land 0x80..80). [None] as
   soon as a byte above 0x7F appears: the general path takes over. *)
let ascii_line_starts raw start =
  let n = String.length raw in
  let starts = ref (Array.make 256 0) and count = ref 1 in
  let add offset =
    if !count = Array.length !starts then begin
      let bigger = Array.make (2 * !count) 0 in
      Array.blit !starts 0 bigger 0 !count;
      starts := bigger
    end;
    Array.unsafe_set !starts !count offset;
    incr count
  in
  let i = ref start and ascii = ref true in
  while !ascii && !i < n do
    let skip =
      !i + 8 <= n
      && (let w = String.get_int64_le raw !i in
          let x = Int64.logxor w 0x0A0A0A0A0A0A0A0AL and y = Int64.logxor w 0x0D0D0D0D0D0D0D0DL in
          Int64.logand
            (Int64.logor w
               (Int64.logor
                  (Int64.logand (Int64.sub x 0x0101010101010101L) (Int64.lognot x))
                  (Int64.logand (Int64.sub y 0x0101010101010101L) (Int64.lognot y))))
            0x8080808080808080L = 0L)
    in
    if skip then i := !i + 8
    else begin
      (* the eight bytes one by one: tried again at the next byte, the word would fail the test
         again until past its line end *)
      let stop = Int.min n (!i + 8) in
      while !ascii && !i < stop do
        (match String.unsafe_get raw !i with
         | '\n' -> add (!i + 1 - start)
         | '\r' -> if !i + 1 >= n || String.unsafe_get raw (!i + 1) <> '\n' then add (!i + 1 - start)
         | c -> if Char.code c >= 0x80 then ascii := false);
        incr i
      done
    end
  done;
  if !ascii then Some (Array.sub !starts 0 !count, n - start) else None

let decode raw =
  let bom = String.length raw >= 3 && String.sub raw 0 3 = "\xEF\xBB\xBF" in
  let start = if bom then 3 else 0 in
  let ascii = ascii_line_starts raw start in
  let latin1 = Option.is_none ascii && not (is_utf8 raw start) in
  let text =
    if latin1 then latin1_to_utf8 raw start
    else if bom then String.sub raw 3 (String.length raw - 3)
    else raw
  in
  let n = String.length text in
  let final_newline = n = 0 || text.[n - 1] = '\n' || text.[n - 1] = '\r' in
  let line_starts, length =
    match ascii with Some starts -> starts | None -> line_starts text in
  { text; line_starts; byte_order_mark = bom; latin1; final_newline; length }
