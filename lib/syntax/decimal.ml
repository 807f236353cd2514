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

(* Half way from num_max to 2^128: a value below it rounds to a finite single (ties to even
   would give 2^128), as a RAPID literal is rounded (Value.single_of_q), so 3.4028235E+38, the
   shortest literal of num_max that --save writes, is in range. *)
let single_overflow = Q.sub (Q.of_bigint (Z.shift_left Z.one 128)) (Q.of_bigint (Z.shift_left Z.one 103))

let read w =
  if not (is_decimal w) then Error `Not_decimal
  else
    match float_of_string_opt w with
    | Some f when Float.abs f <= num_max -> Ok (f +. 0.)
    | Some f when Float.abs f < 3.5e38 -> (
        (* Near the bound the double may round either way: the exact value decides. *)
        let unsigned = if w.[0] = '+' || w.[0] = '-' then String.sub w 1 (String.length w - 1) else w in
        match Num_literal.of_text unsigned with
        | Ok t when Q.lt (Num_literal.to_q t) single_overflow -> Ok (Float.copy_sign num_max f)
        | _ -> Error `Beyond_num)
    | _ -> Error `Beyond_num

let shown w = if String.length w <= 40 then w else String.sub w 0 40 ^ "..."
