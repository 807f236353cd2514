type expectation =
  | Accepted
  | Refused of { error_class : string; line : int; col : int }

type t = {
  path : string;
  sections : string list;
  expectation : expectation option;
  strict : bool;
  description : string option;
  problems : string list;
}

let error_classes = [ "lexical-error"; "syntax-error"; "fatal-error" ]

let expectation_to_string = function
  | Accepted -> "ok"
  | Refused { error_class; line; col } -> Printf.sprintf "%s %d:%d" error_class line col

(* A directive is a line whose first non-blank characters are '!', optional blanks, '@'. *)
let directive line =
  let n = String.length line in
  let i = ref 0 in
  let skip_blanks () = while !i < n && (line.[!i] = ' ' || line.[!i] = '\t') do incr i done in
  skip_blanks ();
  if !i < n && line.[!i] = '!' then begin
    incr i;
    skip_blanks ();
    if !i < n && line.[!i] = '@' then begin
      let rest = String.sub line (!i + 1) (n - !i - 1) in
      let rest = String.trim rest in
      match String.index_opt rest ' ' with
      | None -> Some (rest, "")
      | Some k -> Some (String.sub rest 0 k, String.trim (String.sub rest k (String.length rest - k)))
    end
    else None
  end
  else None

let parse_expect value =
  match String.split_on_char ' ' value |> List.filter (( <> ) "") with
  | [ "ok" ] -> Ok Accepted
  | [ error_class; position ] when List.mem error_class error_classes -> (
      match String.split_on_char ':' position with
      | [ l; c ] -> (
          match int_of_string_opt l, int_of_string_opt c with
          | Some line, Some col when line > 0 && col > 0 -> Ok (Refused { error_class; line; col })
          | _ -> Error (Printf.sprintf "bad position %S in @expect" position))
      | _ -> Error (Printf.sprintf "bad position %S in @expect" position))
  | _ -> Error (Printf.sprintf "cannot read @expect %S" value)

let read path =
  let empty = { path; sections = []; expectation = None; strict = false; description = None;
                problems = [] } in
  match In_channel_compat.read_lines path with
  | Error message -> { empty with problems = [ message ] }
  | Ok lines ->
      let case = List.fold_left (fun case line ->
          match directive line with
          | None -> case
          | Some ("section", v) when v <> "" -> { case with sections = case.sections @ [ v ] }
          | Some ("expect", v) -> (
              match parse_expect v, case.expectation with
              | Ok e, None -> { case with expectation = Some e }
              | Ok _, Some _ -> { case with problems = case.problems @ [ "more than one @expect" ] }
              | Error m, _ -> { case with problems = case.problems @ [ m ] })
          | Some ("options", "strict") -> { case with strict = true }
          | Some ("description", v) -> { case with description = Some v }
          | Some (key, v) ->
              { case with problems = case.problems @ [ Printf.sprintf "unknown directive @%s %s" key v ] })
          empty lines
      in
      let case = if case.expectation = None then { case with problems = case.problems @ [ "no @expect directive" ] } else case in
      if case.sections = [] then { case with problems = case.problems @ [ "no @section directive" ] } else case
