(* The length of the valid UTF-8 sequence at [i], or 0. Overlong forms, surrogates and code
   points beyond U+10FFFF are not valid. *)
let sequence s i =
  let n = String.length s in
  let byte k = if i + k < n then Char.code s.[i + k] else -1 in
  let cont k = let b = byte k in b >= 0x80 && b <= 0xBF in
  let c = byte 0 in
  if c < 0x80 then 1
  else if c >= 0xC2 && c <= 0xDF then (if cont 1 then 2 else 0)
  else if c >= 0xE0 && c <= 0xEF then
    let b1 = byte 1 in
    let ok1 = (c = 0xE0 && b1 >= 0xA0 && b1 <= 0xBF) || (c = 0xED && b1 >= 0x80 && b1 <= 0x9F)
              || (c <> 0xE0 && c <> 0xED && cont 1) in
    if ok1 && cont 2 then 3 else 0
  else if c >= 0xF0 && c <= 0xF4 then
    let b1 = byte 1 in
    let ok1 = (c = 0xF0 && b1 >= 0x90 && b1 <= 0xBF) || (c = 0xF4 && b1 >= 0x80 && b1 <= 0x8F)
              || (c > 0xF0 && c < 0xF4 && cont 1) in
    if ok1 && cont 2 && cont 3 then 4 else 0
  else 0

let is_utf8 s =
  let rec go i = i >= String.length s || (let k = sequence s i in k > 0 && go (i + k)) in
  go 0

let latin1_char b c =
  let c = Char.code c in
  if c < 0x80 then Buffer.add_char b (Char.chr c)
  else (Buffer.add_char b (Char.chr (0xC0 lor (c lsr 6))); Buffer.add_char b (Char.chr (0x80 lor (c land 0x3F))))

let of_bytes s =
  if is_utf8 s then s
  else begin
    let b = Buffer.create (String.length s + 16) in
    let rec go i =
      if i < String.length s then
        match sequence s i with
        | 0 -> latin1_char b s.[i]; go (i + 1)
        | k -> Buffer.add_string b (String.sub s i k); go (i + k) in
    go 0;
    Buffer.contents b
  end

let characters ~latin1 s =
  let out = ref [] in
  let rec go i =
    if i < String.length s then
      let k = if latin1 then 0 else sequence s i in
      if k = 0 then begin
        let b = Buffer.create 2 in
        latin1_char b s.[i]; out := Buffer.contents b :: !out; go (i + 1)
      end
      else (out := String.sub s i k :: !out; go (i + k)) in
  go 0;
  Array.of_list (List.rev !out)
