type token = Number of float * string | Name of string | Text of string

type answer = { line : int; routine : string; tokens : token list }

type t = { file : string; answers : answer array; mutable next : int }

let is_name_char c = match c with 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_' -> true | _ -> false

(* The tokens of one line after its routine's name; a '#' outside a string ends the line. *)
let tokens_of line =
  let n = String.length line in
  let rec go i acc =
    if i >= n || line.[i] = '#' then Ok (List.rev acc)
    else match line.[i] with
      | ' ' | '\t' | '\r' -> go (i + 1) acc
      | '"' ->
          let b = Buffer.create 16 in
          let rec str j =
            if j >= n then Error "a string without its closing quote"
            else if line.[j] = '"' then
              if j + 1 < n && line.[j + 1] = '"' then (Buffer.add_char b '"'; str (j + 2))
              else go (j + 1) (Text (Buffer.contents b) :: acc)
            else (Buffer.add_char b line.[j]; str (j + 1)) in
          str (i + 1)
      | _ ->
          let j = ref i in
          while !j < n && not (List.mem line.[!j] [ ' '; '\t'; '\r'; '#'; '"' ]) do incr j done;
          let word = String.sub line i (!j - i) in
          let token = match float_of_string_opt word with
            | Some f when Float.is_finite f && String.contains "0123456789-+." word.[0] ->
                Ok (Number (f, word))
            | _ when String.for_all is_name_char word && not (match word.[0] with '0' .. '9' -> true | _ -> false) ->
                Ok (Name word)
            | _ -> Error (Printf.sprintf "%S is neither a number, a name nor a string" word) in
          Result.bind token (fun t -> go !j (t :: acc)) in
  go 0 []

let of_text ~file text =
  let lines = String.split_on_char '\n' text in
  let rec read k acc = function
    | [] -> Ok { file; answers = Array.of_list (List.rev acc); next = 0 }
    | line :: rest -> (
        let at m = Error (Printf.sprintf "%s:%d: %s" file k m) in
        match tokens_of line with
        | Error m -> at m
        | Ok [] -> read (k + 1) acc rest
        | Ok (Name routine :: (_ :: _ as tokens)) -> read (k + 1) ({ line = k; routine; tokens } :: acc) rest
        | Ok [ Name routine ] -> at (Printf.sprintf "%s without an answer" routine)
        | Ok _ -> at "expected ROUTINE ANSWER, the name of the dialogue's routine first")
  in
  read 1 [] lines

let of_file path =
  match open_in_bin path with
  | exception Sys_error m -> Error m
  | ic ->
      let read () = really_input_string ic (in_channel_length ic) in
      let text = Fun.protect ~finally:(fun () -> close_in_noerr ic) read in
      of_text ~file:path text

let place t a = Printf.sprintf "%s:%d" t.file a.line

let remaining t = Array.length t.answers - t.next

let take t ~routine =
  if t.next >= Array.length t.answers then
    Error (Printf.sprintf "the operator script %s has no answer left for %s (its %d answers are used)" t.file routine
             (Array.length t.answers))
  else
    let a = t.answers.(t.next) in
    if String.lowercase_ascii a.routine = String.lowercase_ascii routine then (t.next <- t.next + 1; Ok a)
    else Error (Printf.sprintf "the operator script's next answer (%s) is for %s, and the program asks %s" (place t a)
                  a.routine routine)
