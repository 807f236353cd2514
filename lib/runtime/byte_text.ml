(* R-13-ab: ByteToStr writes the fixed widths ABB's examples show (\Hex "7A", \Okt "172",
   \Bin "01111010"); StrToByte also reads fewer digits, upper- or lower-case, since a leading
   zero changes nothing. *)

type base = Dec | Hex | Okt | Bin | Char

let base_of_switches ~hex ~okt ~bin ~char =
  if hex then Hex else if okt then Okt else if bin then Bin else if char then Char else Dec

let byte_of v =
  let x = Value.num_value v in
  if not (Float.is_integer x) then Error "ERR_NOTINTVAL"
  else if x < 0. || x > 255. then Error "ERR_ARGVALERR"
  else Ok (int_of_float x)

let binary n = String.init 8 (fun i -> if n land (1 lsl (7 - i)) <> 0 then '1' else '0')

let byte_to_str base v =
  match byte_of v with
  | Error e -> Error e
  | Ok n ->
      let s = match base with
        | Dec -> string_of_int n
        | Hex -> Printf.sprintf "%02X" n
        | Okt -> Printf.sprintf "%03o" n
        | Bin -> binary n
        | Char -> String.make 1 (Char.chr n) in
      Ok (Value.String s)

let digit base c =
  let d = match c with
    | '0' .. '9' -> Char.code c - Char.code '0'
    | 'a' .. 'f' -> Char.code c - Char.code 'a' + 10
    | 'A' .. 'F' -> Char.code c - Char.code 'A' + 10
    | _ -> 99 in
  if d < base then Some d else None

let str_to_byte base v =
  let s = Value.string_value v in
  let read radix width =
    let len = String.length s in
    if len = 0 || len > width then Error "ERR_ARGVALERR"
    else
      let rec go i acc =
        if i = len then (if acc <= 255 then Ok (Value.num (float_of_int acc)) else Error "ERR_ARGVALERR")
        else match digit radix s.[i] with
          | Some d -> go (i + 1) ((acc * radix) + d)
          | None -> Error "ERR_ARGVALERR" in
      go 0 0 in
  match base with
  | Dec -> read 10 3
  | Hex -> read 16 2
  | Okt -> read 8 3
  | Bin -> read 2 8
  | Char -> if String.length s = 1 then Ok (Value.num (float_of_int (Char.code s.[0]))) else Error "ERR_ARGVALERR"
