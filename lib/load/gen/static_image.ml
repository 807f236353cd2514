(* A marshalled value laid out as OCaml blocks in a C array, for the linker to place in the
   executable's data (installed_image_blob.c): at start-up the value is there, with no bytes to
   read and no block to allocate, and its pages are read from the executable as they are first
   touched (bench/README.md, "Start-up: the image in the executable's data").

   The blocks are those Marshal.from_string would make, in the order it makes them (each block's
   fields read in turn, depth first), with the sharing the bytes record. The format is OCaml
   4.13's (runtime/caml/intext.h); a value the reader does not know (a custom block, a code
   pointer) stops the build rather than being laid out wrong. *)

type word =
  | Int of int64                (* a whole word: an immediate, a header, bytes or a float's bits *)
  | Pointer of int              (* the value whose header is at this word index *)
  | Atom of int                 (* the runtime's empty block of this tag, put in at start-up *)

type t = { words : word array; root : word; scanned : int list (* headers of blocks with fields *) }

exception Unknown of string

let layout (bytes : string) : t =
  let get8 i = Char.code bytes.[i] in
  let get16 i = (get8 i lsl 8) lor get8 (i + 1) in
  let get32 i = (get16 i lsl 16) lor get16 (i + 2) in
  let get64 i = Int64.logor (Int64.shift_left (Int64.of_int (get32 i)) 32) (Int64.of_int (get32 (i + 4))) in
  let signed8 i = let x = get8 i in if x >= 0x80 then x - 0x100 else x in
  let signed16 i = let x = get16 i in if x >= 0x8000 then x - 0x10000 else x in
  let signed32 i = let x = get32 i in if x >= 0x8000_0000 then x - 0x1_0000_0000 else x in
  if String.length bytes < 20 || get32 0 <> 0x8495A6BE then raise (Unknown "not a small marshalled value");
  let words = ref (Array.make 1024 (Int 0L)) and used = ref 0 in
  let reserve n =
    let at = !used in
    while at + n > Array.length !words do
      let bigger = Array.make (2 * Array.length !words) (Int 0L) in
      Array.blit !words 0 bigger 0 !used;
      words := bigger
    done;
    used := at + n;
    at in
  let set i w = !words.(i) <- w in
  let objects = ref [||] and counted = ref 0 in
  let count header =
    if !counted >= Array.length !objects then begin
      let bigger = Array.make (max 1024 (2 * !counted)) 0 in
      Array.blit !objects 0 bigger 0 !counted;
      objects := bigger
    end;
    !objects.(!counted) <- header;
    incr counted in
  let scanned = ref [] in
  let black = 3 lsl 8 in
  let header ~size ~tag = Int (Int64.of_int ((size lsl 10) lor black lor tag)) in
  (* a word of memory from its eight bytes, [byte 0] the lowest (x86-64 is little-endian) *)
  let word_of byte =
    let w = ref 0L in
    for b = 7 downto 0 do w := Int64.logor (Int64.shift_left !w 8) (Int64.of_int (byte b)) done;
    Int !w in
  (* bytes [len] from [pos] as the words of a string block (OCaml's padding: the last byte of
     the last word counts the unused bytes) *)
  let string_block pos len =
    let size = (len + 8) / 8 in
    let h = reserve (size + 1) in
    set h (header ~size ~tag:252);
    for w = 0 to size - 1 do
      set (h + 1 + w) (word_of (fun b ->
          let k = (w * 8) + b in
          if k < len then get8 (pos + k) else if k = (size * 8) - 1 then (size * 8) - 1 - len else 0))
    done;
    count h;
    Pointer h in
  let float_words ~tag pos n =
    let h = reserve (n + 1) in
    set h (header ~size:n ~tag);
    (* the doubles' bytes are marshalled as they stand in memory (CODE_DOUBLE_LITTLE) *)
    for k = 0 to n - 1 do set (h + 1 + k) (word_of (fun b -> get8 (pos + (8 * k) + b))) done;
    count h;
    Pointer h in
  let immediate n = Int (Int64.logor (Int64.shift_left (Int64.of_int n) 1) 1L) in
  (* the value at [pos]: its word and the position after it (a block's fields included) *)
  let rec item pos : word * int =
    let code = get8 pos in
    if code >= 0x80 then block ~tag:(code land 0xF) ~size:((code lsr 4) land 0x7) (pos + 1)
    else if code >= 0x40 then (immediate (code land 0x3F), pos + 1)
    else if code >= 0x20 then let len = code land 0x1F in (string_block (pos + 1) len, pos + 1 + len)
    else match code with
      | 0x00 -> (immediate (signed8 (pos + 1)), pos + 2)
      | 0x01 -> (immediate (signed16 (pos + 1)), pos + 3)
      | 0x02 -> (immediate (signed32 (pos + 1)), pos + 5)
      | 0x03 -> (Int (Int64.logor (Int64.shift_left (get64 (pos + 1)) 1) 1L), pos + 9)
      | 0x04 -> (shared (get8 (pos + 1)), pos + 2)
      | 0x05 -> (shared (get16 (pos + 1)), pos + 3)
      | 0x06 -> (shared (get32 (pos + 1)), pos + 5)
      | 0x08 -> let hd = get32 (pos + 1) in block ~tag:(hd land 0xFF) ~size:(hd lsr 10) (pos + 5)
      | 0x09 -> let len = get8 (pos + 1) in (string_block (pos + 2) len, pos + 2 + len)
      | 0x0A -> let len = get32 (pos + 1) in (string_block (pos + 5) len, pos + 5 + len)
      | 0x0C -> (float_words ~tag:253 (pos + 1) 1, pos + 9)
      | 0x0E -> let n = get8 (pos + 1) in (float_words ~tag:254 (pos + 2) n, pos + 2 + (8 * n))
      | 0x07 -> let n = get32 (pos + 1) in (float_words ~tag:254 (pos + 5) n, pos + 5 + (8 * n))
      | 0x13 ->
          let hd = Int64.to_int (get64 (pos + 1)) in
          block ~tag:(hd land 0xFF) ~size:(hd lsr 10) (pos + 9)
      | c -> raise (Unknown (Printf.sprintf "marshalling code 0x%02x" c))
  and shared offset = Pointer !objects.(!counted - offset)
  and block ~tag ~size pos =
    if size = 0 then (Atom tag, pos)
    else if tag >= 246 && tag <> 252 && tag <> 253 && tag <> 254 then
      raise (Unknown (Printf.sprintf "a block of tag %d" tag))
    else begin
      let h = reserve (size + 1) in
      set h (header ~size ~tag);
      count h;
      scanned := h :: !scanned;
      let pos = ref pos in
      for k = 0 to size - 1 do
        let w, next = item !pos in
        set (h + 1 + k) w;
        pos := next
      done;
      (Pointer h, !pos)
    end
  in
  let root, _ = item 20 in
  { words = Array.sub !words 0 !used; root; scanned = List.rev !scanned }

(* The C source: the words, the root, the blocks whose fields the collector's roots hook scans,
   and the fields that hold an empty block (the runtime's atoms are not known before it starts). *)
let to_c ~name (t : t) =
  let b = Buffer.create (32 * Array.length t.words) in
  let pr fmt = Printf.bprintf b fmt in
  pr "/* Generated by lib/load/gen/gen_installed_image.ml: do not edit. */\n";
  pr "#include <stdint.h>\n\n";
  pr "const int %s_word_count = %d;\n" name (max 1 (Array.length t.words));
  pr "uintptr_t %s_words[%d] __attribute__((aligned(4096))) = {\n" name (max 1 (Array.length t.words));
  let word = function
    | Int x -> Printf.sprintf "0x%LxU" x
    | Pointer h -> Printf.sprintf "(uintptr_t)(%s_words + %d)" name (h + 1)
    | Atom _ -> "1" (* Val_unit until start-up puts the atom in *) in
  Array.iteri (fun i w -> pr "%s,%s" (word w) (if i mod 4 = 3 then "\n" else " ")) t.words;
  if Array.length t.words = 0 then pr "0";
  pr "};\n\n";
  pr "const uintptr_t %s_root = %s;\n\n" name
    (match t.root with Atom _ -> "1" | w -> word w);
  let atoms = ref [] in
  Array.iteri (fun i w -> match w with Atom tag -> atoms := (i, tag) :: !atoms | _ -> ()) t.words;
  let atoms = List.rev !atoms in
  pr "const int %s_atom_count = %d;\n" name (List.length atoms);
  pr "const uint32_t %s_atoms[%d] = {" name (max 1 (2 * List.length atoms));
  List.iter (fun (i, tag) -> pr "%d, %d, " i tag) atoms;
  if atoms = [] then pr "0";
  pr "};\n\n";
  pr "const int %s_scanned_count = %d;\n" name (List.length t.scanned);
  pr "const uint32_t %s_scanned[%d] = {\n" name (max 1 (List.length t.scanned));
  List.iteri (fun i h -> pr "%d,%s" h (if i mod 12 = 11 then "\n" else " ")) t.scanned;
  if t.scanned = [] then pr "0";
  pr "};\n";
  Buffer.contents b
