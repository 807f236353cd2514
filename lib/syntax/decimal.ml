let is_decimal w =
  let n = String.length w and i = ref 0 in
  let digits () =
    let from = !i in
    while !i < n && w.[!i] >= '0' && w.[!i] <= '9' do incr i done;
    !i - from in
  let sign () = if !i < n && (w.[!i] = '+' || w.[!i] = '-') then incr i in
  sign ();
  let whole = digits () in
  let fraction = if !i < n && w.[!i] = '.' then (incr i; digits ()) else 0 in
  let exponent_ok =
    if !i < n && (w.[!i] = 'e' || w.[!i] = 'E') then (incr i; sign (); digits () > 0) else true in
  whole + fraction > 0 && exponent_ok && !i = n

let num_max = Int32.float_of_bits 0x7f7fffffl

let read w =
  if not (is_decimal w) then Error `Not_decimal
  else
    match float_of_string_opt w with
    | Some f when Float.abs f <= num_max -> Ok (f +. 0.)
    | _ -> Error `Beyond_num

let shown w = if String.length w <= 40 then w else String.sub w 0 40 ^ "..."
