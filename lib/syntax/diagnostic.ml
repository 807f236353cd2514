type error_class =
  | Lexical_error | Syntax_error | Semantic_error | Fatal_static_error | File_error
type t = {
  error_class : error_class;
  region : Source.region;
  message : string;
  hint : string option;
}

let make ?hint error_class region message = { error_class; region; message; hint }

let with_hint hint d = { d with hint }

let class_name = function
  | Lexical_error -> "lexical error"
  | Syntax_error -> "syntax error"
  | Semantic_error -> "semantic error"
  | Fatal_static_error -> "fatal error"
  | File_error -> "file error"

let headline d =
  Printf.sprintf "%s: %s: %s" (Source.to_string d.region) (class_name d.error_class) d.message

let hint_line hint = "  hint: " ^ hint

let to_string d =
  match d.hint with
  | None -> headline d
  | Some h -> headline d ^ "\n" ^ hint_line h

(* The sections a message cites, "§4.18" or "§5.4-§5.6", in order and without repeats. *)
let sections_of message =
  let n = String.length message in
  let rec scan i acc =
    if i >= n then List.rev acc
    else if i + 1 < n && message.[i] = '\xC2' && message.[i + 1] = '\xA7' then begin
      let j = ref (i + 2) in
      while !j < n && (match message.[!j] with '0' .. '9' | '.' -> true | _ -> false) do incr j done;
      (* a trailing full stop ends the sentence, not the section *)
      let stop = if !j > i + 2 && message.[!j - 1] = '.' then !j - 1 else !j in
      let s = String.sub message (i + 2) (stop - i - 2) in
      scan !j (if s = "" || List.mem s acc then acc else s :: acc)
    end
    else scan (i + 1) acc
  in
  scan 0 []
