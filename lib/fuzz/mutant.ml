(* Mutants work on the text, not on the generator's structure: what the checker meets in the
   field is text, and a text mutation reaches what no well-typed generator can (a token in the
   wrong place, a name of the wrong kind). *)

open Rapid_syntax

let pick rs l = List.nth l (Random.State.int rs (List.length l))
let file_name = "fuzz.mod"

(* ------------------------------------------------------------------ tokens *)

let is_ident_char c = c = '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')

(* Which bytes are name characters, looked up rather than tested (every byte of every mutant
   is). *)
let ident_table = String.init 256 (fun i -> if is_ident_char (Char.chr i) then '\001' else '\000')
let ident text i = String.unsafe_get ident_table (Char.code (String.unsafe_get text i)) = '\001'

(* The text's words (names, keywords, numbers: the longest runs of name characters), counted,
   and the k-th of them with its offset, without a list of them all: a mutation draws one or
   two words of a text of a few thousand bytes, and the list of every word, each copied, was
   most of what making a mutant cost. Drawing [Random.State.int rs (count_words text)] and
   taking that word is what picking from the list did. *)
let count_words text =
  let n = String.length text in
  let count = ref 0 and i = ref 0 in
  while !i < n do
    if ident text !i then begin
      incr count;
      while !i < n && ident text !i do incr i done
    end
    else incr i
  done;
  !count

let nth_word text k =
  let n = String.length text in
  let rec go i k =
    if i >= n then invalid_arg "Mutant.nth_word"
    else if ident text i then begin
      let j = ref i in
      while !j < n && ident text !j do incr j done;
      if k = 0 then (i, String.sub text i (!j - i)) else go !j (k - 1)
    end
    else go (i + 1) k in
  go 0 k

let replace_at text offset length by =
  String.sub text 0 offset ^ by ^ String.sub text (offset + length) (String.length text - offset - length)

let keywords = [
  "IF"; "THEN"; "ELSE"; "ELSEIF"; "ENDIF"; "FOR"; "FROM"; "TO"; "STEP"; "DO"; "ENDFOR"; "WHILE";
  "ENDWHILE"; "TEST"; "CASE"; "DEFAULT"; "ENDTEST"; "PROC"; "ENDPROC"; "FUNC"; "ENDFUNC"; "TRAP";
  "ENDTRAP"; "ERROR"; "UNDO"; "BACKWARD"; "RETURN"; "RETRY"; "TRYNEXT"; "RAISE"; "EXIT"; "GOTO";
  "CONNECT"; "WITH"; "VAR"; "PERS"; "CONST"; "INOUT"; "LOCAL"; "TASK"; "RECORD"; "ENDRECORD";
  "ALIAS"; "MODULE"; "ENDMODULE"; "NOT"; "AND"; "OR"; "XOR"; "DIV"; "MOD"; "TRUE"; "FALSE";
]

let type_names = [
  "num"; "dnum"; "bool"; "string"; "pos"; "orient"; "pose"; "robtarget"; "intnum"; "signaldo"; "errnum"; "fzpoint";
  "tooldata";
]

let tokens = [
  ";"; ":="; ","; "("; ")"; "["; "]"; "{"; "}"; "\\"; "?"; "%"; "|"; ":"; "."; "+"; "-"; "*"; "/";
  "<"; ">"; "="; "<>"; "<="; ">="; "<EXP>"; "<SMT>"; "<ARG>"; "<ID>"; "<DDN>"; "\""; "!"; "1E40";
  "9E+09"; "0x1F"; "2147483648"; "\"x\""; "[1, 2]"; "[]"; "TRUE"; "ERRNO"; "INTNO"; "main";
]

let literal_swaps = [
  "TRUE"; "FALSE"; "0"; "1.5"; "\"s\""; "[1, 2, 3]"; "[1, 0, 0, 0]"; "gpos1"; "gint"; "v100"; "<EXP>";
]

let lines text = String.split_on_char '\n' text
let unlines l = String.concat "\n" l

(* Whether the text has a word at all: what a mutation asks before drawing, when only some of its
   kinds then draw a word. *)
let has_word text =
  let n = String.length text in
  let rec go i = i < n && (ident text i || go (i + 1)) in
  go 0

(* Where each line starts, a line being a piece of [String.split_on_char '\n' text]: one more
   line than there are newlines. Line [i] ends before [starts.(i + 1) - 1], the last at the end. *)
let line_starts text =
  let n = String.length text in
  let k = ref 1 in
  for i = 0 to n - 1 do if String.unsafe_get text i = '\n' then incr k done;
  let starts = Array.make !k 0 and j = ref 1 in
  for i = 0 to n - 1 do
    if String.unsafe_get text i = '\n' then begin Array.unsafe_set starts !j (i + 1); incr j end
  done;
  starts

let line_stop text starts i =
  if i + 1 < Array.length starts then starts.(i + 1) - 1 else String.length text

(* The line operations below give what splitting the text into its lines, changing the list and
   joining it again gave (test/test_campaign.ml compares them on thousands of mutants), without
   the list: a program has some hundred lines, and the array made of them went straight to the
   major heap. *)
let one_mutation rs text =
  let n = String.length text in
  let count = lazy (count_words text) in
  let pick_word rs = nth_word text (Random.State.int rs (Lazy.force count)) in
  if n = 0 || not (has_word text) then text
  else
    match Random.State.int rs 12 with
    | 0 ->
        (* a literal or name of another type: ill-typed, mostly *)
        let off, w = pick_word rs in
        replace_at text off (String.length w) (pick rs literal_swaps)
    | 1 ->
        (* a name swapped for another word of the program: a routine for a datum, a type for a
           name, a keyword for a name *)
        let off, w = pick_word rs in
        let _, w' = pick_word rs in
        replace_at text off (String.length w) w'
    | 2 ->
        let off, w = pick_word rs in
        replace_at text off (String.length w) ""
    | 3 ->
        let off = Random.State.int rs n in
        replace_at text off 0 (" " ^ pick rs tokens ^ " ")
    | 4 ->
        let off, w = pick_word rs in
        replace_at text off (String.length w) (pick rs keywords)
    | 5 ->
        let off, w = pick_word rs in
        replace_at text off (String.length w) (pick rs type_names)
    | 6 ->
        (* a line taken out, with the newline after it (before it, for the last line) *)
        let starts = line_starts text in
        let k = Array.length starts in
        let i = Random.State.int rs k in
        if k = 1 then ""
        else if i < k - 1 then replace_at text starts.(i) (starts.(i + 1) - starts.(i)) ""
        else replace_at text (starts.(i) - 1) (n - starts.(i) + 1) ""
    | 7 ->
        let starts = line_starts text in
        let i = Random.State.int rs (Array.length starts) in
        replace_at text starts.(i) 0 (String.sub text starts.(i) (line_stop text starts i - starts.(i)) ^ "\n")
    | 8 ->
        let starts = line_starts text in
        let k = Array.length starts in
        let i = Random.State.int rs k and j = Random.State.int rs k in
        if i = j then text
        else begin
          let b = Buffer.create (n + 1) in
          for m = 0 to k - 1 do
            let from = if m = i then j else if m = j then i else m in
            Buffer.add_substring b text starts.(from) (line_stop text starts from - starts.(from));
            if m < k - 1 then Buffer.add_char b '\n'
          done;
          Buffer.contents b
        end
    | 9 ->
        (* a parameter mode, or a storage class, where it may or may not be allowed *)
        let off, w = pick_word rs in
        replace_at text off 0 (pick rs [ "VAR "; "PERS "; "INOUT "; "REF "; "\\"; "LOCAL "; "CONST " ])
        |> fun t -> ignore w; t
    | 10 ->
        (* an operator for another *)
        let ops = [ ":="; "+"; "-"; "*"; "/"; "<"; ">"; "="; ";"; "," ] in
        let rec find tries =
          if tries = 0 then text
          else
            let off = Random.State.int rs n in
            if List.mem (String.make 1 text.[off]) ops then replace_at text off 1 (pick rs ops) else find (tries - 1) in
        find 50
    | _ -> String.sub text 0 (Random.State.int rs n)

let mutate rs text =
  let rec go k t = if k = 0 then t else go (k - 1) (one_mutation rs t) in
  go (1 + Random.State.int rs 3) text

(* ------------------------------------------------------------------ hostile texts *)

(* [String.concat "" (List.init n (fun _ -> s))], without the list of n strings. *)
let repeat n s =
  let l = String.length s in
  if l = 1 then String.make n s.[0] else
  let b = Bytes.create (n * l) in
  for i = 0 to n - 1 do Bytes.blit_string s 0 b (i * l) l done;
  Bytes.unsafe_to_string b

let in_main body = Printf.sprintf "MODULE h\n  PROC main()\n%s\n  ENDPROC\nENDMODULE\n" body

(* The large texts are a function of their kind and depth, and a campaign draws each of them
   again and again (a hostile text every ten programs, some fifty of them): each is built once
   per process and the same string handed out after, which Campaign, which judges a large text
   once, then finds by its address instead of hashing and comparing up to 600 KB. Building them
   anew was 1.9 M instructions a hostile text (bench/README.md, "Fuzzing, fourth round"). The
   draws are made before the lookup, in the order they always were. *)
let built : (int * int, string) Hashtbl.t = Hashtbl.create 32

let once kind depth make =
  match Hashtbl.find_opt built (kind, depth) with
  | Some text -> text
  | None ->
      let text = make () in
      if Hashtbl.length built < 64 then Hashtbl.replace built (kind, depth) text;
      text

let hostile rs =
  let depth () = pick rs [ 100; 1000; 10_000; 100_000 ] in
  match Random.State.int rs 14 with
  | 0 -> String.init (Random.State.int rs 2000) (fun _ -> Char.chr (Random.State.int rs 256))
  | 1 -> let d = depth () in
      once 1 d (fun () -> in_main (Printf.sprintf "    x := %s1%s;" (repeat d "(") (repeat d ")")))
  | 2 -> let d = depth () in
      once 2 d (fun () -> in_main (Printf.sprintf "    x := %s1%s;" (repeat d "[") (repeat d "]")))
  | 3 -> let d = min 20_000 (depth ()) in
      once 3 d (fun () -> in_main (repeat d "IF TRUE THEN\n" ^ repeat d "ENDIF\n"))
  | 4 -> let d = depth () in once 4 d (fun () -> in_main (Printf.sprintf "    VAR num %s;" (String.make d 'a')))
  | 5 -> let d = depth () in once 5 d (fun () -> in_main (Printf.sprintf "    TPWrite \"%s\";" (String.make d 'x')))
  | 6 -> in_main (Printf.sprintf "    x := %s;"
                   (pick rs [ String.make 5000 '9'; "1E999999"; "1E-999999"; "0x" ^ String.make 100 'F';
                              "0b" ^ String.make 200 '1'; "0o" ^ String.make 100 '7'; "1.E"; ".5E+" ]))
  | 7 -> in_main "    TPWrite \"unterminated;\n" ^ pick rs [ "\""; ""; "\\" ]
  | 8 -> "\xEF\xBB\xBFMODULE m\r  PROC main()\r\r\n  ENDPROC\rENDMODULE" ^ pick rs [ ""; "\r"; "\x00"; "\xFF\xFE" ]
  | 9 -> let d = depth () in once 9 d (fun () -> in_main (repeat d "    ;\n"))
  | 10 -> let d = min 10_000 (depth ()) in
      once 10 d (fun () -> in_main (Printf.sprintf "    x := %sa%s;" (repeat d "-") ""))
  | 11 -> let d = min 50_000 (depth ()) in
      once 11 d (fun () -> in_main (Printf.sprintf "    x := 1%s;" (repeat d " + 1")))
  | 12 -> let d = min 10_000 (depth ()) in
      once 12 d (fun () ->
          Printf.sprintf "MODULE h\n%s\nENDMODULE\n"
            (String.concat "\n"
               (List.init d (fun i -> "  PROC p" ^ string_of_int i ^ "() p" ^ string_of_int (i + 1) ^ "; ENDPROC"))))
  | _ ->
      (* a valid program's words in random order *)
      let vocabulary = keywords @ tokens @ type_names @ [ "x"; "main"; "1"; "\"s\"" ] in
      String.concat " " (List.init (Random.State.int rs 300) (fun _ -> pick rs vocabulary))

(* ------------------------------------------------------------------ the property *)

(* [FILE:LINE:COL: CLASS: ...]: the place first, then a class word. *)
let well_placed headline =
  let prefix = file_name ^ ":" in
  let p = String.length prefix in
  String.length headline > p && String.sub headline 0 p = prefix &&
  (match String.split_on_char ':' (String.sub headline p (String.length headline - p)) with
   | line :: col :: cls :: _ ->
       int_of_string_opt line <> None && int_of_string_opt (String.trim col) <> None && String.trim cls <> ""
   | _ -> false)

let check_text ?(max_steps = 20_000) text =
  try
    match Parse.parse_string ~name:file_name text with
    | Error d ->
        let h = Diagnostic.headline d in
        if well_placed h then Ok () else Error ("a diagnostic without its place or class: " ^ h)
    | Ok m -> (
        match Fuzz_run.load m with
        | Error (Front_end ds) ->
            (match List.find_opt (fun d -> not (well_placed (Diagnostic.headline d))) ds with
             | Some d -> Error ("a diagnostic without its place or class: " ^ Diagnostic.headline d)
             | None -> Ok ())
        | Error (Static rs) ->
            (match List.find_opt (fun r -> not (well_placed (Rapid_typing.Report.headline r))) rs with
             | Some r -> Error ("a report without its place or class: " ^ Rapid_typing.Report.headline r)
             | None -> if List.exists (fun (r : Rapid_typing.Report.t) -> r.severity = Error) rs then Ok ()
               else Error "refused without an error")
        | Error (Internal m) -> Error ("internal: " ^ m)
        | Ok loaded ->
            let o = Fuzz_run.machine.run loaded.program ~max_steps in
            if String.length o.outcome >= 5 && String.sub o.outcome 0 5 = "stuck" then
              Error ("no rule applies: " ^ o.outcome)
            else Ok ())
  with
  | Stack_overflow -> Error "stack overflow"
  | Out_of_memory -> Error "out of memory"
  | e -> Error ("exception " ^ Printexc.to_string e)

(* ------------------------------------------------------------------ shrinking *)

(* Lines, then words, then characters: each pass deletes chunks, halving their size, while the
   text still fails. *)

let shrink_text fails text =
  (* chunks of halving sizes (and 3, the words of a small declaration), tried at every place
     when the parts are few, at every chunk boundary when they are many *)
  let rec by_chunks split join parts chunk =
    if chunk = 0 then parts
    else
      let n = List.length parts in
      let step = if n <= 300 then 1 else chunk in
      let rec try_at i parts =
        if i >= List.length parts then parts
        else
          let candidate = List.filteri (fun j _ -> j < i || j >= i + chunk) parts in
          if candidate <> [] && fails (join candidate) then try_at i candidate else try_at (i + step) parts in
      let parts' = try_at 0 parts in
      let next =
        if chunk > 4 && chunk / 2 < 3 then 3 else if chunk = 4 then 3 else if chunk = 3 then 2 else chunk / 2 in
      if List.length parts' < n then by_chunks split join parts' chunk else by_chunks split join parts' next in
  let ls = by_chunks lines unlines (lines text) (max 1 (List.length (lines text) / 2)) in
  let t = unlines ls in
  (* words next, so that a declaration goes whole from a line that holds several *)
  let words t =
    (* names and numbers whole, every other character alone, blanks kept with what precedes *)
    let n = String.length t in
    let rec go i acc =
      if i >= n then List.rev acc
      else
        let j = ref (i + 1) in
        if is_ident_char t.[i] then while !j < n && is_ident_char t.[!j] do incr j done;
        while !j < n && (t.[!j] = ' ' || t.[!j] = '\n') do incr j done;
        go !j (String.sub t i (!j - i) :: acc) in
    go 0 [] in
  let ws = words t in
  (* a routine, a record or a compound statement at once, from its keyword to its END keyword *)
  let blocks ws =
    let starts w kw = let n = String.length kw in String.length w >= n && String.sub w 0 n = kw
                                                 && (String.length w = n || not (is_ident_char w.[n])) in
    let kws = [ "PROC"; "FUNC"; "TRAP"; "RECORD"; "IF"; "FOR"; "WHILE"; "TEST" ] in
    let rec go ws =
      let a = Array.of_list ws in
      let n = Array.length a in
      let rec from i =
        if i >= n then ws
        else match List.find_opt (starts a.(i)) kws with
          | None -> from (i + 1)
          | Some kw ->
              let rec close j depth =
                if j >= n then None
                else if starts a.(j) ("END" ^ kw) then (if depth = 0 then Some j else close (j + 1) (depth - 1))
                else if starts a.(j) kw then close (j + 1) (depth + 1)
                else close (j + 1) depth in
              match close (i + 1) 0 with
              | Some j ->
                  let candidate = List.filteri (fun k _ -> k < i || k > j) ws in
                  if candidate <> [] && fails (String.concat "" candidate) then go candidate else from (i + 1)
              | None -> from (i + 1) in
      from 0 in
    go ws in
  let t = if String.length t > 20_000 then t
    else
      let ws = blocks ws in
      String.concat "" (by_chunks words (String.concat "") ws (max 1 (List.length ws / 2))) in
  if String.length t > 2000 then t
  else
    let chars = List.init (String.length t) (String.get t) in
    let join cs = String.concat "" (List.map (String.make 1) cs) in
    join (by_chunks (fun _ -> chars) join chars (max 1 (List.length chars / 2)))
