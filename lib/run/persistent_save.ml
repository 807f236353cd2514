module V = Value
open Rapid_syntax

(* ------------------------------------------------------------------------------ literals *)

(* The exact value a numeric literal's text denotes (§2.5), rounded as the declaration's type
   rounds it; a leading minus is the unary operator. *)
let reads_as precision s =
  let negative = String.length s > 0 && s.[0] = '-' in
  let digits = if negative then String.sub s 1 (String.length s - 1) else s in
  match Num_literal.of_text digits with
  | Error _ -> None
  | Ok lit -> (
      match V.of_literal lit precision with
      | V.Num f | V.Dnum f -> Some (if negative then -.f else f)
      | _ -> None)

(* The fewest significant digits whose literal reads back as exactly [f]: checked by the
   lexer's own reading of a literal, not by the host's float_of_string, whose rounding to
   double first and then to single may differ from the literal's rounding to single. *)
let shortest precision ~max_digits f =
  if not (Float.is_finite f) then V.type_mismatch "a finite number (R-3.12-c)"
  else if Float.is_integer f && Float.abs f < 1e15 then Printf.sprintf "%.0f" f
  else
    (* RAPID writes the exponent with E (§2.5). *)
    let text p = String.map (fun c -> if c = 'e' then 'E' else c) (Printf.sprintf "%.*g" p f) in
    let rec go p =
      let s = text p in
      if p >= max_digits || reads_as precision s = Some f then s else go (p + 1) in
    go 1

(* §2.7: a string literal whose value is exactly the bytes of [s] when the literal stands in a
   file of this encoding. The lexer gives a literal's value as the UTF-8 of the characters the
   file decodes to, so a character is written as itself only when decoding it gives back the
   same bytes: in a UTF-8 file a whole UTF-8 sequence, in a Latin-1 file the one byte of a
   character U+00A0..U+00FF. Every other byte, control characters (C0, DEL, C1) included, is
   a character code \HH; a quote and a backslash are written twice. *)
let string_literal ~latin1 s =
  let b = Buffer.create (String.length s + 2) in
  let n = String.length s in
  let code i = Buffer.add_string b (Printf.sprintf "\\%02X" (Char.code s.[i])) in
  let rec go i =
    if i < n then
      match s.[i] with
      | '"' -> Buffer.add_string b "\"\""; go (i + 1)
      | '\\' -> Buffer.add_string b "\\\\"; go (i + 1)
      | c when Char.code c < 0x20 || Char.code c = 0x7F -> code i; go (i + 1)
      | c when Char.code c < 0x80 -> Buffer.add_char b c; go (i + 1)
      | _ -> (
          (* The code point of a sequence of two bytes (a longer one is beyond U+07FF). *)
          let two () = ((Char.code s.[i] land 0x1F) lsl 6) lor (Char.code s.[i + 1] land 0x3F) in
          match Utf8_text.sequence s i with
          | k when k > 0 && not latin1 && (k > 2 || two () >= 0xA0) ->
              Buffer.add_string b (String.sub s i k); go (i + k)
          | 2 when latin1 && two () >= 0xA0 && two () <= 0xFF -> Buffer.add_char b (Char.chr (two ())); go (i + 2)
          | _ -> code i; go (i + 1)) in
  Buffer.add_char b '"';
  go 0;
  Buffer.add_char b '"';
  Buffer.contents b

let rec literal_in ~latin1 = function
  | V.Num f -> shortest `Num ~max_digits:9 f
  | V.Dnum f -> shortest `Dnum ~max_digits:17 f
  | V.Bool b -> if b then "TRUE" else "FALSE"
  | V.String s -> string_literal ~latin1 s
  | V.Record cs | V.Array cs -> "[" ^ String.concat "," (Array.to_list (Array.map (literal_in ~latin1) cs)) ^ "]"
  | V.Handle _ -> V.type_mismatch "a handle has no literal"

let literal v = literal_in ~latin1:false v

(* -------------------------------------------------------------------------------- splice *)

(* Byte offset in the decoded text (UTF-8, Decode.t.text) of each character offset, the unit
   of every region of the tree (Source). *)
let text_offsets (d : Decode.t) =
  let offsets = Array.make (d.length + 1) (String.length d.text) in
  let c = ref 0 in
  String.iteri (fun i ch ->
      if Char.code ch land 0xC0 <> 0x80 && !c <= d.length then (offsets.(!c) <- i; incr c)) d.text;
  offsets

(* One replacement: the characters [start, stop) of the decoded text become [value]'s literal. *)
type edit = { start : int; stop : int; before : string; value : V.t }

let edits (d : Decode.t) offsets (m : Ast.module_declaration) current =
  let byte c = offsets.(max 0 (min c d.length)) in
  List.filter_map (fun (decl : Ast.data_declaration) ->
      match decl.it with
      | Ast.Data_declaration { storage = Pers; name = { it = Ident n; at = name_at }; initial_value; _ } -> (
          match current n with
          | None -> None
          | Some v when (match literal v with _ -> false | exception V.Type_mismatch _ -> true) ->
              (* A value without a literal (an installed object) keeps its text. *)
              None
          | Some value -> (
              match initial_value with
              | Some e -> Some { start = Source.start_offset e.at; stop = Source.stop_offset e.at; before = ""; value }
              | None ->
                  (* Before the declaration's ';'. *)
                  let first = Source.stop_offset name_at in
                  let rec semicolon c =
                    if c < first then None else if d.text.[byte c] = ';' then Some c else semicolon (c - 1) in
                  Option.map (fun c -> { start = c; stop = c; before = " := "; value })
                    (semicolon (min (Source.stop_offset decl.at) d.length - 1))))
      | _ -> None) m.data_declarations
  |> List.sort (fun a b -> compare a.start b.start)

(* [text] with the edits applied, their offsets mapped to positions of [text] by [at]. *)
let apply text at literal edits =
  let buf = Buffer.create (String.length text + 64) in
  let last = List.fold_left (fun pos e ->
      let a = at e.start in
      Buffer.add_string buf (String.sub text pos (a - pos));
      Buffer.add_string buf e.before;
      Buffer.add_string buf (literal e.value); at e.stop) 0 edits in
  Buffer.add_string buf (String.sub text last (String.length text - last));
  Buffer.contents buf

let bom = "\xEF\xBB\xBF"

(* A literal's bytes as the characters a file of that encoding reads them as, in UTF-8: the
   Latin-1 byte c is U+00c. *)
let as_characters ~latin1 s =
  if not latin1 then s
  else begin
    let b = Buffer.create (String.length s) in
    String.iter (fun c -> Buffer.add_utf_8_uchar b (Uchar.of_char c)) s;
    Buffer.contents b
  end

let splice ~original m current =
  let d = Decode.decode original in
  let offsets = text_offsets d in
  let skip = if d.byte_order_mark then 3 else 0 in
  let es = edits d offsets m current in
  (* The same characters measured in the file's own unit: a byte of a Latin-1 file is one
     character, a UTF-8 file is the decoded text itself. *)
  let raw_at c = skip + (if d.latin1 then c else offsets.(c)) in
  let in_file = literal_in ~latin1:d.latin1 in
  let spliced = apply original raw_at in_file es in
  (* What the spliced file must read as: the old text with these very literals, as characters.
     Comparing with the UTF-8 literals instead would call a Latin-1 file changed whenever a
     value holds a character beyond U+00FF, which its literal spells as \HH (R-2.23-save2n). *)
  let expected = apply d.text (fun c -> offsets.(c)) (fun v -> as_characters ~latin1:d.latin1 (in_file v)) es in
  if (Decode.decode spliced).text = expected then spliced
  else
    (* A Latin-1 file whose only bytes that are not UTF-8 stood in the replaced values would
       now read as UTF-8, and any other character above U+007F would change: the module is
       written as UTF-8 (chapter 16), every character as it was (R-2.23-save1). *)
    (if d.byte_order_mark then bom else "") ^ apply d.text (fun c -> offsets.(c)) literal es

(* -------------------------------------------------------------------------------- writing *)

(* Temporary files are named <base>.<pid>.rapid-sem.part, the process id keeping two saves
   apart. Their writer holds a lock on them (lockf) until the rename: a part file that can be
   locked is stale, left by a save killed in the middle (a killed process's locks are gone),
   whatever process has its id now. *)
let part_suffix = ".rapid-sem.part"

let part_name base pid = Printf.sprintf "%s.%d%s" base pid part_suffix

let is_part_of base f =
  let prefix = base ^ "." in
  let lp = String.length prefix and ls = String.length part_suffix and lf = String.length f in
  lf > lp + ls && String.sub f 0 lp = prefix && String.sub f (lf - ls) ls = part_suffix
  && Option.is_some (int_of_string_opt (String.sub f lp (lf - lp - ls)))

(* Removes [file] when nobody holds its lock; it is unlinked while we hold it, so that its
   writer (who checks, once it has the lock, that its name is still its file) starts again. *)
let remove_if_stale file =
  match Unix.openfile file [ Unix.O_RDWR; Unix.O_CLOEXEC ] 0 with
  | exception Unix.Unix_error _ -> ()
  | fd ->
      (match Unix.lockf fd Unix.F_TLOCK 0 with
       | () -> (try Unix.unlink file with Unix.Unix_error _ -> ())
       | exception Unix.Unix_error _ -> ());
      Unix.close fd

let remove_stale_parts path =
  let dir = Filename.dirname path and base = Filename.basename path in
  match Sys.readdir dir with
  | exception Sys_error _ -> ()
  | names -> Array.iter (fun f -> if is_part_of base f then remove_if_stale (Filename.concat dir f)) names

let fsync_dir dir =
  match Unix.openfile dir [ Unix.O_RDONLY ] 0 with
  | fd -> (try Unix.fsync fd with Unix.Unix_error _ -> ()); Unix.close fd
  | exception Unix.Unix_error _ -> ()

(* The temporary file, created and locked; a few tries when another save's cleaning removes
   it between the two. *)
let rec create_locked tmp tries =
  let fd = Unix.openfile tmp [ Unix.O_RDWR; Unix.O_CREAT; Unix.O_EXCL; Unix.O_CLOEXEC ] 0o644 in
  let mine = match Unix.lockf fd Unix.F_TLOCK 0 with
    | () -> (
        match Unix.stat tmp with
        | st -> st.Unix.st_ino = (Unix.fstat fd).Unix.st_ino
        | exception Unix.Unix_error _ -> false)
    | exception Unix.Unix_error _ -> false in
  if mine then fd
  else begin
    Unix.close fd;
    if tries <= 1 then raise (Unix.Unix_error (Unix.EAGAIN, "lockf", tmp)) else create_locked tmp (tries - 1)
  end

(* A module's temporary file, written, flushed and still locked (its fd open), waiting for its
   rename over [target]. *)
type staged = { target : string; tmp : string; fd : Unix.file_descr }

(* Unlinked while we hold its lock, then closed. *)
let discard s =
  (try Unix.unlink s.tmp with Unix.Unix_error _ -> ());
  (try Unix.close s.fd with Unix.Unix_error _ -> ())

(* Whether a file could be renamed over [target]: not a folder (rename would fail with EISDIR
   after the files before it were renamed), and its folder one we may write in. A symbolic link
   is replaced itself, whatever it points to. *)
let replaceable target =
  let dir = Filename.dirname target in
  let dir_writable () =
    match Unix.access dir [ Unix.W_OK; Unix.X_OK ] with
    | () -> Ok ()
    | exception Unix.Unix_error (e, _, _) -> Error (dir ^ ": " ^ Unix.error_message e) in
  match Unix.lstat target with
  | { Unix.st_kind = Unix.S_DIR; _ } -> Error (Unix.error_message Unix.EISDIR)
  | _ -> dir_writable ()
  | exception Unix.Unix_error (Unix.ENOENT, _, _) -> dir_writable ()
  | exception Unix.Unix_error (e, _, _) -> Error (Unix.error_message e)

(* Phase 1 for one file: [text] in its temporary file, created and locked (R-2.23-save3),
   flushed to the disk, with the permissions of the file it will replace. Nothing is renamed. *)
let stage target text =
  match replaceable target with
  | Error e -> Error e
  | Ok () -> (
      remove_stale_parts target;
      let tmp = Filename.concat (Filename.dirname target) (part_name (Filename.basename target) (Unix.getpid ())) in
      match create_locked tmp 5 with
      | exception Unix.Unix_error (e, _, _) -> Error (Unix.error_message e)
      | fd -> (
          let s = { target; tmp; fd } in
          try
            let n = String.length text in
            let rec write off = if off < n then write (off + Unix.write_substring fd text off (n - off)) in
            write 0;
            Unix.fsync fd;
            (* Keep the permissions of the file it replaces. *)
            (match Unix.stat target with st -> Unix.fchmod fd st.Unix.st_perm | exception Unix.Unix_error _ -> ());
            Ok s
          with Unix.Unix_error (e, _, _) -> discard s; Error (Unix.error_message e)))

(* Phase 1 for all: every temporary file, or none (those already written are removed) and the
   first problem, named by its destination. *)
let stage_all targets =
  let rec go acc = function
    | [] -> Ok (List.rev acc)
    | (target, text) :: rest -> (
        match stage target text with
        | Ok s -> go (s :: acc) rest
        | Error e -> List.iter discard acc; Error (target ^ ": " ^ e)) in
  go [] targets

(* Phase 2: every rename, in order, each atomic; then the folders flushed. A rename that fails
   (phase 1 checked what it could) stops the others: their temporary files are removed, and the
   message says which modules were saved and which were not. *)
let commit staged =
  let rec go saved = function
    | [] -> Ok (List.rev saved)
    | s :: rest -> (
        match Unix.rename s.tmp s.target with
        | () -> (try Unix.close s.fd with Unix.Unix_error _ -> ()); go (s.target :: saved) rest
        | exception Unix.Unix_error (e, _, _) ->
            List.iter discard (s :: rest);
            let names = function [] -> "none" | l -> String.concat ", " l in
            Error (Printf.sprintf "%s: %s (while renaming: saved %s; not saved %s)" s.target (Unix.error_message e)
                     (names (List.rev saved)) (names (List.map (fun s -> s.target) (s :: rest))))) in
  let result = go [] staged in
  List.iter fsync_dir (List.sort_uniq compare (List.map (fun s -> Filename.dirname s.target) staged));
  result

let write_atomically path text =
  match stage_all [ (path, text) ] with
  | Error e -> Error e
  | Ok staged -> Result.map (fun _ -> ()) (commit staged)

let read_bytes path =
  match open_in_bin path with
  | ic -> Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      try Ok (really_input_string ic (in_channel_length ic)) with
      | Sys_error m | Failure m -> Error m
      | End_of_file -> Error "the file changed while it was read")
  | exception Sys_error m -> Error m

(* Two files of one base name would be saved to one file, the second over the first. *)
let same_base files =
  let rec go seen = function
    | [] -> None
    | f :: rest -> (
        let base = Filename.basename f in
        match List.assoc_opt base seen with
        | Some g when g <> f -> Some (g, f, base)
        | _ -> go ((base, f) :: seen) rest) in
  go [] files

let check ~dir ~files =
  if dir = "" then Error "the folder is an empty name (for the current folder, write --save .)"
  else if Sys.file_exists dir && not (Sys.is_directory dir) then Error (dir ^ ": not a folder")
  else match same_base files with
    | Some (a, b, base) ->
        Error (Printf.sprintf "%s and %s would both be saved as %s: nothing is saved (give the files different names)"
                 a b (Filename.concat dir base))
    | None -> Ok ()

(* Whether it made [dir]. *)
let prepare_dir ~dir ~files =
  match check ~dir ~files with
  | Error m -> Error m
  | Ok () when Sys.file_exists dir -> Ok false
  | Ok () -> (
      match Unix.mkdir dir 0o755 with
      | () -> Ok true
      | exception Unix.Unix_error (e, _, _) -> Error (dir ^ ": " ^ Unix.error_message e))

(* One table for all the files: looking every declaration up in the list made a save of N
   persistents take N * N / 2 comparisons (17 s for 20,000). The first entry of a name wins,
   as the list's search did. *)
let index data =
  let key md n = (String.lowercase_ascii md, String.lowercase_ascii n) in
  let table = Hashtbl.create (max 16 (List.length data)) in
  List.iter (fun (md, n, v) -> let k = key md n in if not (Hashtbl.mem table k) then Hashtbl.add table k v) data;
  fun ~module_name name -> Hashtbl.find_opt table (key module_name name)

(* The text to write for one file, or why it cannot be saved. *)
let saved_text lookup file =
  match read_bytes file with
  | Error m -> Error m
  | Ok original -> (
      match Parse.parse_string ~name:file original with
      | Error d -> Error (Diagnostic.to_string d)
      | Ok m -> (
          let module_name = match m.module_name.it with Ast.Ident n -> n | Ast.ID_placeholder -> "" in
          let text = splice ~original m (lookup ~module_name) in
          (* Never replace a module by one that does not read back. *)
          match Parse.parse_string ~name:file text with
          | Ok _ -> Ok text
          | Error d -> Error ("the saved module would not read back: " ^ Diagnostic.to_string d)))

let save_modules ~dir ~files data =
  match prepare_dir ~dir ~files with
  | Error m -> Error m
  | Ok made -> (
      (* Every text first, then every temporary file, and only then the renames, so that a module
         that cannot be saved leaves every file as it was (doc/services.md, "--save DIR"). *)
      let lookup = index data in
      let rec texts acc = function
        | [] -> Ok (List.rev acc)
        | file :: rest -> (
            match saved_text lookup file with
            | Ok t -> texts ((Filename.concat dir (Filename.basename file), t) :: acc) rest
            | Error e -> Error (file ^ ": " ^ e)) in
      let staged = match texts [] files with Error e -> Error e | Ok ts -> stage_all ts in
      match staged with
      | Ok staged -> commit staged
      | Error e ->
          (* The folder this save made goes too, when nothing else is in it. *)
          if made then (try Unix.rmdir dir with Unix.Unix_error _ -> ());
          Error e)
