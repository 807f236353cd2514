type file = { id : int; name : string; line_starts : int array }
type pos = { line : int; col : int }

(* Layout of a packed region, low bits first: file id, start offset, length.
   63-bit ints give 10 + 28 + 24 bits: 1023 files, 268M characters, spans of 16M characters. *)
type region = int

let file_bits = 10
let start_bits = 28
let length_bits = 24
let max_files = (1 lsl file_bits) - 1
let max_start = (1 lsl start_bits) - 1
let max_length = (1 lsl length_bits) - 1

(* File id 0 is reserved for "no file". Index i of the table holds file id i. *)
let files : file option array ref = ref (Array.make 16 None)
let file_count = ref 0

(* Ids up to [kept] are never reused: the installed modules are parsed once per process and their
   regions key tables of every later check (a literal's kind, a name's declaration); a new file
   with one of their ids would make its regions equal to theirs. *)
let kept = ref 0
let keep () = if !file_count < max_files - 64 then kept := max !kept !file_count

(* Until [keep] has kept any, ids are reused from [max_files - 96] on, so that the files parsed
   just before it (the installed modules, first needed after any number of other files) end
   below its limit: otherwise whether they keep their ids depended on where the count stood. *)
let register ~name ~line_starts =
  let limit = if !kept = 0 then max_files - 96 else max_files in
  if !file_count >= limit then file_count := !kept;
  incr file_count;
  let id = !file_count in
  if id >= Array.length !files then begin
    let bigger = Array.make (2 * Array.length !files) None in
    Array.blit !files 0 bigger 0 (Array.length !files);
    files := bigger
  end;
  let f = { id; name; line_starts } in
  !files.(id) <- Some f;
  f

let name f = f.name
let no_region = 0

(* The elaboration's and the lowering's tables are keyed by region, a hundred look-ups a
   statement: an integer's hash and equality without the runtime's generic ones. The file is
   in the low bits, the same for every region of a file: the start (and the length) are mixed
   down into the bits a table's index takes. *)
module Table = Hashtbl.Make (struct
    type t = region
    let equal (a : int) b = a = b
    let hash r =
      let s = r lsr file_bits in
      (s lxor (s lsr 25) lxor ((r land max_files) lsl 15)) land max_int
  end)

(* The table of files as one value, for an environment computed at build time (its regions name
   its files' ids) and restored at start-up before any other file is registered. *)
type registry = { r_files : file option array; r_count : int; r_kept : int }

let registered () = !file_count
let registered_in r = r.r_count

let registry () = { r_files = Array.copy !files; r_count = !file_count; r_kept = !kept }

let restore_registry r =
  files := Array.copy r.r_files;
  file_count := r.r_count;
  kept := r.r_kept

(* Every node of the tree takes a region: the clamps compare ints directly, since Stdlib's
   [min] and [max] are polymorphic and cost a call to the runtime's generic comparison. *)
let clamp (lo : int) (hi : int) (x : int) = if x < lo then lo else if x > hi then hi else x

let region f start stop =
  let start = clamp 0 max_start start in
  let length = clamp 0 max_length (stop - start) in
  f.id lor (start lsl file_bits) lor (length lsl (file_bits + start_bits))

let file_id r = r land max_files
let file_of r = let id = file_id r in if id = 0 then None else !files.(id)
let start_offset r = (r lsr file_bits) land max_start
let stop_offset r = start_offset r + ((r lsr (file_bits + start_bits)) land max_length)

(* Binary search for the last line starting at or before [offset]. *)
let pos_of_offset f offset =
  let starts = f.line_starts in
  let lo = ref 0 and hi = ref (Array.length starts - 1) in
  while !lo < !hi do
    let mid = (!lo + !hi + 1) / 2 in
    if starts.(mid) <= offset then lo := mid else hi := mid - 1
  done;
  { line = !lo + 1; col = offset - starts.(!lo) + 1 }

let pos_at r offset =
  match file_of r with
  | None -> { line = 0; col = 0 }
  | Some f -> pos_of_offset f offset

let start r = pos_at r (start_offset r)
let stop r = pos_at r (stop_offset r)

let span a b =
  match file_of a, file_of b with
  | Some f, Some g when f.id = g.id -> region f (start_offset a) (stop_offset b)
  | Some _, _ -> a
  | None, _ -> b

let file_name r = match file_of r with None -> "<generated>" | Some f -> f.name

let to_string r =
  let p = start r in
  Printf.sprintf "%s:%d:%d" (file_name r) p.line p.col

let to_range_string r =
  let p = start r and q = stop r in
  Printf.sprintf "%s:%d:%d-%d:%d" (file_name r) p.line p.col q.line q.col
