module V = Value
open Rapid_syntax

(* The fewest significant digits that read back as the same number of this precision. *)
let shortest ~round ~max_digits f =
  if Float.is_integer f && Float.abs f < 1e15 then Printf.sprintf "%.0f" f
  else
    let rec go p =
      let s = Printf.sprintf "%.*g" p f in
      if p >= max_digits || round (float_of_string s) = f then s else go (p + 1) in
    let s = go 1 in
    (* RAPID writes the exponent with E (§2.5). *)
    String.map (fun c -> if c = 'e' then 'E' else c) s

let rec literal = function
  | V.Num f -> shortest ~round:V.to_single ~max_digits:9 f
  | V.Dnum f -> shortest ~round:(fun x -> x) ~max_digits:17 f
  | V.Bool b -> if b then "TRUE" else "FALSE"
  | V.String s -> Format.string_literal s
  | V.Record cs | V.Array cs -> "[" ^ String.concat "," (Array.to_list (Array.map literal cs)) ^ "]"
  | V.Handle _ -> V.type_mismatch "a handle has no literal"

(* Byte offset in the file of each character offset of the decoded text. *)
let byte_offsets original (d : Decode.t) =
  let n = d.length in
  let offsets = Array.make (n + 1) 0 in
  if d.latin1 then Array.iteri (fun i _ -> offsets.(i) <- i) offsets
  else begin
    let b = ref (if d.byte_order_mark then 3 else 0) in
    for i = 0 to n do
      offsets.(i) <- !b;
      if !b < String.length original then begin
        let c = Char.code original.[!b] in
        (* A CR LF is one line break but two characters of the decoded text? The decoder keeps
           them as they are: one character per code point. *)
        b := !b + (if c < 0x80 then 1 else if c < 0xE0 then 2 else if c < 0xF0 then 3 else 4)
      end
    done
  end;
  offsets

(* Text for a Latin-1 file: the UTF-8 of a literal as ISO 8859-1 bytes. *)
let to_latin1 s =
  let b = Buffer.create (String.length s) in
  let n = String.length s in
  let rec go i =
    if i < n then begin
      let c = Char.code s.[i] in
      let len = if c < 0x80 then 1 else if c < 0xE0 then 2 else if c < 0xF0 then 3 else 4 in
      (if len = 1 then Buffer.add_char b s.[i]
       else if len = 2 && i + 1 < n then
         let u = ((c land 0x1F) lsl 6) lor (Char.code s.[i + 1] land 0x3F) in
         Buffer.add_char b (if u < 256 then Char.chr u else '?')
       else Buffer.add_char b '?');
      go (i + len)
    end in
  go 0; Buffer.contents b

let splice ~original (m : Ast.module_declaration) current =
  let d = Decode.decode original in
  let offsets = byte_offsets original d in
  let byte c = offsets.(max 0 (min c (Array.length offsets - 1))) in
  let edits = List.filter_map (fun (decl : Ast.data_declaration) ->
      match decl.it with
      | Ast.Data_declaration { storage = Pers; name = { it = Ident n; at = name_at }; initial_value; _ } -> (
          match current n with
          | None -> None
          | Some v when (match literal v with _ -> false | exception V.Type_mismatch _ -> true) ->
              (* A value without a literal (an installed object) keeps its text. *)
              None
          | Some v ->
              let text = literal v in
              let text = if d.latin1 then to_latin1 text else text in
              match initial_value with
              | Some e -> Some (byte (Source.start_offset e.at), byte (Source.stop_offset e.at), text)
              | None ->
                  (* Before the declaration's ';'. *)
                  let stop = byte (Source.stop_offset decl.at) in
                  let semi = try String.rindex_from original (stop - 1) ';' with Not_found | Invalid_argument _ -> -1 in
                  if semi >= byte (Source.stop_offset name_at) then Some (semi, semi, " := " ^ text) else None)
      | _ -> None) m.data_declarations in
  let edits = List.sort (fun (a, _, _) (b, _, _) -> compare a b) edits in
  let buf = Buffer.create (String.length original + 64) in
  let last = List.fold_left (fun pos (a, b, text) ->
      Buffer.add_string buf (String.sub original pos (a - pos));
      Buffer.add_string buf text; b) 0 edits in
  Buffer.add_string buf (String.sub original last (String.length original - last));
  Buffer.contents buf

let write_atomically path text =
  let dir = Filename.dirname path in
  match Filename.temp_file ~temp_dir:dir (Filename.basename path ^ ".") ".part" with
  | exception Sys_error m -> Error m
  | tmp -> (
      try
        let fd = Unix.openfile tmp [ Unix.O_WRONLY; Unix.O_TRUNC ] 0o644 in
        Fun.protect ~finally:(fun () -> Unix.close fd) (fun () ->
            let b = Bytes.of_string text in
            let rec write off = if off < Bytes.length b then write (off + Unix.write fd b off (Bytes.length b - off)) in
            write 0;
            Unix.fsync fd);
        (* Keep the permissions of the file it replaces. *)
        (match Unix.stat path with st -> Unix.chmod tmp st.Unix.st_perm | exception Unix.Unix_error _ -> ());
        Unix.rename tmp path;
        Ok ()
      with Unix.Unix_error (e, _, _) -> (try Sys.remove tmp with Sys_error _ -> ()); Error (Unix.error_message e))

let read_bytes path =
  match open_in_bin path with
  | ic -> Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      try Ok (really_input_string ic (in_channel_length ic)) with Sys_error m | Failure m -> Error m)
  | exception Sys_error m -> Error m

let save_modules ~dir ~files data =
  let same a b = String.lowercase_ascii a = String.lowercase_ascii b in
  let rec go written = function
    | [] -> Ok (List.rev written)
    | file :: rest -> (
        match read_bytes file with
        | Error m -> Error m
        | Ok original -> (
            match Parse.parse_string ~name:file original with
            | Error d -> Error (Diagnostic.to_string d)
            | Ok m ->
                let module_name = match m.module_name.it with Ast.Ident n -> n | Ast.ID_placeholder -> "" in
                let current name =
                  List.find_map (fun (md, n, v) -> if same md module_name && same n name then Some v else None) data in
                let target = Filename.concat dir (Filename.basename file) in
                match write_atomically target (splice ~original m current) with
                | Ok () -> go (target :: written) rest
                | Error e -> Error (target ^ ": " ^ e))) in
  go [] files
