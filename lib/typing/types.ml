type value_class = Value | Non_value | Semi_value

type data_type =
  | Num
  | Dnum
  | Bool
  | String
  | Installed_atomic of installed_atomic
  | Record of record_type
  | Anytype

and installed_atomic = {
  atomic_name : string;
  atomic_class : value_class;
  associated : data_type option;
}

and record_type = {
  record_id : int;
  record_name : string;
  mutable components : (string * data_type) list;
}

type dims = Scalar | Sized of int list | Conformant of int
type object_type = { base : data_type; dims : dims }

let scalar base = { base; dims = Scalar }

let name = function
  | Num -> "num"
  | Dnum -> "dnum"
  | Bool -> "bool"
  | String -> "string"
  | Installed_atomic a -> a.atomic_name
  | Record r -> r.record_name
  | Anytype -> "anytype"

let to_string { base; dims } =
  match dims with
  | Scalar -> name base
  | Sized sizes -> Printf.sprintf "%s{%s}" (name base) (String.concat "," (List.map string_of_int sizes))
  | Conformant rank -> Printf.sprintf "%s{%s}" (name base) (String.concat "," (List.init rank (fun _ -> "*")))

(* A record whose definition refers back to itself is refused before it gets here (the
   resolution of type definitions checks for cycles), so these walks terminate. Each record's
   class is computed once and kept with the component list it was computed from (records that
   share component types would otherwise be walked once per path, exponentially many). *)
(* By record id: an integer's hash and equality, a dozen look-ups a statement. *)
module By_id = Hashtbl.Make (struct type t = int let equal (a : int) b = a = b let hash (x : int) = x land max_int end)

let class_cache : ((string * data_type) list * value_class) By_id.t = By_id.create 64

let rec value_class = function
  | Num | Dnum | Bool | String -> Value
  | Installed_atomic a -> a.atomic_class
  | Anytype -> Value
  | Record r -> (
      match By_id.find_opt class_cache r.record_id with
      | Some (components, cls) when components == r.components -> cls
      | _ ->
          let classes = List.map (fun (_, t) -> value_class t) r.components in
          let cls =
            if List.mem Non_value classes then Non_value
            else if List.mem Semi_value classes then Semi_value
            else Value
          in
          By_id.replace class_cache r.record_id (r.components, cls);
          cls)

(* Saturating arithmetic: sizes beyond [max_int] are all "too large". *)
let saturating_add a b = if a > max_int - b then max_int else a + b
let saturating_mul a b = if a <> 0 && b > max_int / a then max_int else a * b

let size_cache : ((string * data_type) list * int) By_id.t = By_id.create 64

let rec data_type_size = function
  | Num | Dnum | Bool | String | Installed_atomic _ | Anytype -> 1
  | Record r -> (
      match By_id.find_opt size_cache r.record_id with
      | Some (components, n) when components == r.components -> n
      | _ ->
          let n = List.fold_left (fun acc (_, t) -> saturating_add acc (data_type_size t)) 0 r.components in
          By_id.replace size_cache r.record_id (r.components, n);
          n)

let value_size { base; dims } =
  let element = data_type_size base in
  match dims with
  | Scalar | Conformant _ -> element
  | Sized sizes -> List.fold_left saturating_mul element sizes

let same_data_type a b =
  match a, b with
  | Num, Num | Dnum, Dnum | Bool, Bool | String, String | Anytype, Anytype -> true
  | Installed_atomic x, Installed_atomic y ->
      String.lowercase_ascii x.atomic_name = String.lowercase_ascii y.atomic_name
  | Record x, Record y -> x.record_id = y.record_id
  | (Num | Dnum | Bool | String | Anytype | Installed_atomic _ | Record _), _ -> false

let associated_value_type t =
  match t with
  | Installed_atomic { atomic_class = Semi_value; associated; _ } -> associated
  | _ -> None

let same_structure a b =
  match a, b with
  | Scalar, Scalar -> true
  | Sized x, Sized y -> x = y
  | Conformant r, Sized s | Sized s, Conformant r -> List.length s = r
  | Conformant r, Conformant s -> r = s
  | (Scalar | Sized _ | Conformant _), _ -> false

let equal_types ~value_context a b =
  same_structure a.dims b.dims
  && (same_data_type a.base b.base
      || value_context
         && (match associated_value_type a.base, associated_value_type b.base with
             | Some v, None -> same_data_type v b.base
             | None, Some v -> same_data_type a.base v
             | _ -> false))

let counter = ref 0
let new_record_id () = incr counter; !counter
let record_ids_used () = !counter
let restore_record_ids n = counter := n

(* Without building lowered copies: names are compared wherever components and labels are
   looked up, thousands of times in a large record. *)
let same_name a b =
  a == b
  || (let n = String.length a in
      n = String.length b
      && (let lower c = if c >= 'A' && c <= 'Z' then Char.code c + 32 else Char.code c in
          let rec from i =
            i >= n
            || ((let x = String.unsafe_get a i and y = String.unsafe_get b i in x = y || lower x = lower y)
                && from (i + 1)) in
          from 0))

let component r name =
  List.find_map (fun (n, t) -> if same_name n name then Some t else None) r.components
