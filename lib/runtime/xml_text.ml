(* XML 1.0 text (§2.2): the bytes made UTF-8 as JSON's are (an implementation's output may be
   anything), the markup characters as entities, the characters XML forbids (C0 controls but
   tab, newline and carriage return; U+FFFE, U+FFFF) as \HH or U+FFFD, the three it allows as
   references, which an attribute would otherwise turn into spaces. *)
let escape s =
  let s = Utf8_text.of_bytes s in
  let b = Buffer.create (String.length s) in
  let n = String.length s in
  let rec go i =
    if i < n then
      match s.[i] with
      | '<' -> Buffer.add_string b "&lt;"; go (i + 1)
      | '>' -> Buffer.add_string b "&gt;"; go (i + 1)
      | '&' -> Buffer.add_string b "&amp;"; go (i + 1)
      | '"' -> Buffer.add_string b "&quot;"; go (i + 1)
      | ('\n' | '\t' | '\r') as c -> Printf.bprintf b "&#%d;" (Char.code c); go (i + 1)
      | c when Char.code c < 32 -> Printf.bprintf b "\\%02X" (Char.code c); go (i + 1)
      | '\xEF' when i + 2 < n && s.[i + 1] = '\xBF' && (s.[i + 2] = '\xBE' || s.[i + 2] = '\xBF') ->
          Buffer.add_string b "\xEF\xBF\xBD"; go (i + 3)
      | c -> Buffer.add_char b c; go (i + 1) in
  go 0;
  Buffer.contents b

