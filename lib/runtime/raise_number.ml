(* §4.11: "错误编号 … 必须表示为处于1至90范围内的一个整数值" (the error number must be an integer
   of 1 to 90); R-4.11-b adds the numbers BookErrNo booked. *)
let legal ~booked x = Float.is_integer x && ((x >= 1. && x <= 90.) || booked (int_of_float x))

(* R-4.11-raise1: an ERR_ constant of the system is the system's to raise; the program passes
   one on with RAISE; in its handler, or raises an error of its own. *)
let refusal (program : Ir.program) ~in_handler x =
  let shown = if Float.is_integer x && Float.abs x < 1e15 then Printf.sprintf "%.0f" x else Printf.sprintf "%g" x in
  let named =
    if Float.is_integer x then
      List.find_map (fun (name, n) -> if float_of_int n = x then Some name else None) program.error_numbers
    else None in
  let raised = match named with
    | Some name -> Printf.sprintf "RAISE %s (%s)" name shown
    | None -> "RAISE " ^ shown in
  let system = match named with
    | Some name -> Printf.sprintf "; %s is an error of the system, which only the system raises" name
    | None -> "" in
  let instead =
    if in_handler then
      "; write RAISE; without a number to pass on the error in hand (ERRNO), or book an error \
       number of the program's own with BookErrNo and raise that"
    else "; book an error number of the program's own with BookErrNo and raise that" in
  Printf.sprintf "%s%s: RAISE raises only an error number of 1 to 90 or one BookErrNo booked (§4.11)%s%s"
    raised (if in_handler then " in an error handler" else "") system instead
