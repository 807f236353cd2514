let hex c =
  match c with
  | '0' .. '9' -> Some (Char.code c - 48)
  | 'a' .. 'f' -> Some (Char.code c - 87)
  | 'A' .. 'F' -> Some (Char.code c - 55)
  | _ -> None

let decode s =
  let b = Buffer.create (String.length s) in
  let n = String.length s in
  let rec go i =
    if i < n then
      if s.[i] = '%' && i + 2 < n then
        match hex s.[i + 1], hex s.[i + 2] with
        | Some h, Some l -> Buffer.add_char b (Char.chr ((h * 16) + l)); go (i + 3)
        | _ -> Buffer.add_char b '%'; go (i + 1)
      else (Buffer.add_char b s.[i]; go (i + 1)) in
  go 0;
  Buffer.contents b

let prefix = "file://"

let to_path uri =
  let n = String.length prefix in
  if String.length uri >= n && String.lowercase_ascii (String.sub uri 0 n) = prefix then
    let rest = String.sub uri n (String.length uri - n) in
    (* file://host/path: only the local host (empty or localhost) names a path here *)
    let rest =
      if String.length rest > 0 && rest.[0] = '/' then Some rest
      else if String.length rest >= 10 && String.lowercase_ascii (String.sub rest 0 10) = "localhost/" then
        Some (String.sub rest 9 (String.length rest - 9))
      else None in
    Option.map decode rest
  else None

let of_path path =
  let b = Buffer.create (String.length path + 8) in
  Buffer.add_string b prefix;
  String.iter (fun c ->
      match c with
      | 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '-' | '.' | '_' | '~' | '/' -> Buffer.add_char b c
      | c -> Buffer.add_string b (Printf.sprintf "%%%02X" (Char.code c))) path;
  Buffer.contents b
