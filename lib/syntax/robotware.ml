type t = Rw7 | Rw6

let default = Rw7

let of_string s =
  let major = match String.index_opt s '.' with Some i -> String.sub s 0 i | None -> s in
  match int_of_string_opt (String.trim major) with
  | Some (5 | 6) -> Some Rw6
  | Some 7 -> Some Rw7
  | _ -> None

let reserves_loop_words = function Rw7 -> true | Rw6 -> false

let to_string = function Rw7 -> "7" | Rw6 -> "6"
