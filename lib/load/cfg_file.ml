(* The RobotWare system parameter format. Lines are read one by one; an instance goes on over
   lines whose last character is a backslash. Every attribute keeps its line and column so that
   a backup's warnings and errors can name it. *)

type value = Flag | Text of string
type attribute = { key : string; value : value; line : int; col : int }
type instance = { attributes : attribute list; at_line : int }
type section = { name : string; instances : instance list; line : int }
type t = { file : string; domain : string; sections : section list }

exception Bad of int * int * string

type word = Key of string | Word of string | Quoted of string

(* The words of one line: keys (-Name), bare words and quoted strings, each with its column. A
   bare word after a dash that starts with a digit or a point is a negative number, not a key. *)
let words ln text =
  let n = String.length text and i = ref 0 and acc = ref [] in
  let blank c = c = ' ' || c = '\t' in
  while !i < n do
    if blank text.[!i] then incr i
    else begin
      let col = !i + 1 in
      if text.[!i] = '"' then begin
        let j = ref (!i + 1) in
        while !j < n && text.[!j] <> '"' do incr j done;
        if !j >= n then raise (Bad (ln, col, "a quoted value is not closed on its line"));
        acc := (Quoted (String.sub text (!i + 1) (!j - !i - 1)), col) :: !acc;
        i := !j + 1
      end else begin
        let j = ref !i in
        while !j < n && not (blank text.[!j]) do incr j done;
        let w = String.sub text !i (!j - !i) in
        let is_key = String.length w > 1 && w.[0] = '-'
                     && not (match w.[1] with '0' .. '9' | '.' -> true | _ -> false) in
        acc := ((if is_key then Key (String.sub w 1 (String.length w - 1)) else Word w), col) :: !acc;
        i := !j
      end
    end
  done;
  List.rev !acc

let attributes ln ws =
  let rec go = function
    | [] -> []
    | (Key k, col) :: (Word v, _) :: rest -> { key = k; value = Text v; line = ln; col } :: go rest
    | (Key k, col) :: (Quoted v, _) :: rest -> { key = k; value = Text v; line = ln; col } :: go rest
    | (Key k, col) :: rest -> { key = k; value = Flag; line = ln; col } :: go rest
    | (Word w, col) :: _ -> raise (Bad (ln, col, Printf.sprintf "the value %s has no -KEY before it" w))
    | (Quoted w, col) :: _ -> raise (Bad (ln, col, Printf.sprintf "the value \"%s\" has no -KEY before it" w)) in
  go ws

let is_name_char c = c = '_' || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')

(* "NAME:" or "NAME = TYPE:" at the start of a line. *)
let section_name line =
  let l = String.trim line in
  let n = String.length l in
  if n < 2 || l.[n - 1] <> ':' || not (is_name_char l.[0]) || line.[0] = ' ' || line.[0] = '\t' then None
  else
    let body = String.sub l 0 (n - 1) in
    match String.index_opt body '=' with
    | None -> if String.for_all is_name_char body then Some body else None
    | Some k ->
        let a = String.trim (String.sub body 0 k)
        and b = String.trim (String.sub body (k + 1) (String.length body - k - 1)) in
        if a <> "" && b <> "" && String.for_all is_name_char a && String.for_all is_name_char b then Some a else None

let strip_cr s = if s <> "" && s.[String.length s - 1] = '\r' then String.sub s 0 (String.length s - 1) else s

let parse_lines ~file lines =
  let sections = ref [] in
  let current = ref None in                  (* name, line, instances (reversed) *)
  let pending = ref None in                  (* the instance being read: line, attributes (reversed), goes on *)
  let finish_instance () = match !pending, !current with
    | Some (l, attrs, _), Some (name, sl, insts) ->
        current := Some (name, sl, { attributes = List.rev attrs; at_line = l } :: insts); pending := None
    | _ -> pending := None in
  let finish_section () =
    finish_instance ();
    (match !current with
     | Some (name, line, insts) -> sections := { name; line; instances = List.rev insts } :: !sections
     | None -> ());
    current := None in
  let domain = ref "" in
  List.iteri (fun i raw ->
      let ln = i + 1 in
      let raw = strip_cr raw in
      let trimmed = String.trim raw in
      let continued = trimmed <> "" && trimmed.[String.length trimmed - 1] = '\\' in
      let body = if continued then String.sub raw 0 (String.rindex raw '\\') else raw in
      if i = 0 then begin
        match String.index_opt trimmed ':' with
        | Some k when k > 0 && String.for_all is_name_char (String.sub trimmed 0 k)
                      && String.length trimmed > k + 4 && String.sub trimmed (k + 1) 4 = "CFG_" ->
            domain := String.sub trimmed 0 k
        | _ -> raise (Bad (ln, 1, "the first line is not a domain header such as SYS:CFG_1.0:5:0::"))
      end
      else match !pending with
        | Some (l, attrs, true) ->
            pending := Some (l, List.rev_append (attributes ln (words ln body)) attrs, continued)
        | _ ->
            if trimmed = "" then finish_instance ()
            else if trimmed.[0] = '#' then finish_section ()
            else match section_name raw with
              | Some name -> finish_section (); current := Some (name, ln, [])
              | None ->
                  if trimmed.[0] <> '-' then
                    let k = ref 0 in
                    while !k < String.length raw && (raw.[!k] = ' ' || raw.[!k] = '\t') do incr k done;
                    raise (Bad (ln, !k + 1, Printf.sprintf "%S is neither a section header NAME: nor an attribute -KEY"
                                              trimmed))
                  else if !current = None then
                    raise (Bad (ln, 1, "an attribute outside a section (no NAME: line before it)"))
                  else begin
                    finish_instance ();
                    pending := Some (ln, List.rev (attributes ln (words ln body)), continued)
                  end)
    lines;
  (match !pending with
   | Some (l, _, true) -> raise (Bad (l, 1, "the last instance ends in a backslash: the file is cut short"))
   | _ -> ());
  finish_section ();
  { file; domain = !domain; sections = List.rev !sections }

let without_bom text =
  if String.length text >= 3 && String.sub text 0 3 = "\xEF\xBB\xBF" then String.sub text 3 (String.length text - 3)
  else text

let parse ~file text =
  try Ok (parse_lines ~file (String.split_on_char '\n' (without_bom text)))
  with Bad (line, col, m) -> Error (Printf.sprintf "%s:%d:%d: cfg error: %s" file line col m)

let read_file file =
  match open_in_bin file with
  | exception Sys_error m -> Error (Printf.sprintf "%s:1:1: cfg error: cannot read the file (%s)" file m)
  | ic ->
      let text = Fun.protect ~finally:(fun () -> close_in_noerr ic)
          (fun () -> really_input_string ic (in_channel_length ic)) in
      parse ~file text

let same a b = String.lowercase_ascii a = String.lowercase_ascii b
let section t name = List.find_opt (fun s -> same s.name name) t.sections
let find i key = List.find_opt (fun a -> same a.key key) i.attributes
let text i key = match find i key with Some { value = Text v; _ } -> Some v | _ -> None
let flag i key = find i key <> None
let place t line = Printf.sprintf "%s:%d" t.file line
