type handle = { kind : string; id : int }

type t =
  | Num of float
  | Dnum of float
  | Bool of bool
  | String of string
  | Record of t array
  | Array of t array
  | Handle of handle

exception Type_mismatch of string

let type_mismatch what = raise (Type_mismatch what)

(* ------------------------------------------------------------------------------ numbers *)

(* The conversion to the bits of a single is the C cast, which rounds to nearest with ties to
   even under the default rounding mode and overflows to an infinity. *)
let to_single x = Int32.float_of_bits (Int32.bits_of_float x)

let num x = Num (to_single x)
let dnum x = Dnum x

let pow2 e = if e >= 0 then Q.mul_2exp Q.one e else Q.div_2exp Q.one (-e)

(* Rounds |q| > 0 to [bits] significant bits with the exponent range of IEEE 754 (normal
   exponents emin..emax), ties to even. The unit in the last place is 2^k with
   k = max(e, emin) - (bits - 1), e = floor(log2 |q|): below 2^emin the spacing stays that of
   the subnormals. *)
let round_q ~bits ~emin ~emax q =
  match Q.sign q with
  | 0 -> 0.0
  | sign ->
      let a = Q.abs q in
      (* 2^(e-1) < a < 2^(e+1) for e the difference of the bit lengths. *)
      let e = Z.numbits (Q.num a) - Z.numbits (Q.den a) in
      let e = if Q.lt a (pow2 e) then e - 1 else e in
      let k = max e emin - (bits - 1) in
      let scaled = if k >= 0 then Q.div_2exp a k else Q.mul_2exp a (-k) in
      let quotient, remainder = Z.ediv_rem (Q.num scaled) (Q.den scaled) in
      let c = Z.compare (Z.shift_left remainder 1) (Q.den scaled) in
      let m = if c > 0 || (c = 0 && Z.is_odd quotient) then Z.succ quotient else quotient in
      let magnitude =
        if Z.numbits m + k > emax + 1 then infinity
        else (* m has at most bits + 1 bits: exact as a double, and ldexp is exact. *)
          ldexp (Z.to_float m) k
      in
      if sign < 0 then -.magnitude else magnitude

let single_of_q q = round_q ~bits:24 ~emin:(-126) ~emax:127 q
let double_of_q q = round_q ~bits:53 ~emin:(-1022) ~emax:1023 q

let of_literal lit precision =
  let q = Rapid_syntax.Num_literal.to_q lit in
  match precision with `Num -> Num (single_of_q q) | `Dnum -> Dnum (double_of_q q)

let num_value = function Num x | Dnum x -> x | _ -> type_mismatch "a num or dnum"
let bool_value = function Bool b -> b | _ -> type_mismatch "a bool"
let string_value = function String s -> s | _ -> type_mismatch "a string"
let components = function Record a | Array a -> a | _ -> type_mismatch "a record or an array"

(* ------------------------------------------------------------------------------ handles *)

let make_handle ~kind id = { kind; id }
let handle_kind h = h.kind
let handle_id h = h.id

(* ------------------------------------------------------------------------------ value semantics *)

let rec copy = function
  | Record a -> Record (copy_parts a)
  | Array a -> Array (copy_parts a)
  | (Num _ | Dnum _ | Bool _ | String _ | Handle _) as v -> v

(* The small ones (pos, orient, confdata...) built in place: Array.map is a call to the runtime.
   A scalar part is itself, without a call; the test is written out at each part, since a local
   function for it would be a closure allocated at every copy. *)
and copy_parts a =
  match Array.length a with
  | 1 -> let x = a.(0) in [| (match x with Record _ | Array _ -> copy x | _ -> x) |]
  | 2 ->
      let x = a.(0) and y = a.(1) in
      [| (match x with Record _ | Array _ -> copy x | _ -> x); (match y with Record _ | Array _ -> copy y | _ -> y) |]
  | 3 ->
      let x = a.(0) and y = a.(1) and z = a.(2) in
      [| (match x with Record _ | Array _ -> copy x | _ -> x); (match y with Record _ | Array _ -> copy y | _ -> y);
         (match z with Record _ | Array _ -> copy z | _ -> z) |]
  | 4 ->
      let x = a.(0) and y = a.(1) and z = a.(2) and w = a.(3) in
      [| (match x with Record _ | Array _ -> copy x | _ -> x); (match y with Record _ | Array _ -> copy y | _ -> y);
         (match z with Record _ | Array _ -> copy z | _ -> z); (match w with Record _ | Array _ -> copy w | _ -> w) |]
  | _ -> Array.map copy a

let rec equal a b =
  match a, b with
  (* IEEE equality, not Float.equal: 0 = -0 (no num result is NaN). *)
  | Num x, Num y | Dnum x, Dnum y -> x = (y : float)
  | Bool x, Bool y -> x = y
  | String x, String y -> String.equal x y
  | Record x, Record y | Array x, Array y ->
      Array.length x = Array.length y
      && (let rec from i = i >= Array.length x || (equal x.(i) y.(i) && from (i + 1)) in
          from 0)
  | Handle x, Handle y -> x.id = y.id && String.equal x.kind y.kind
  | _ -> type_mismatch "two values of equal types (§3.12 =)"

let rec same_dimensions a b =
  match a, b with
  | Array x, Array y ->
      Array.length x = Array.length y
      && (Array.length x = 0 || same_dimensions x.(0) y.(0))
  | Array _, _ | _, Array _ -> false
  | _ -> true

(* ------------------------------------------------------------------------------ initial values *)

type shape =
  | S_num
  | S_dnum
  | S_bool
  | S_string
  | S_handle of string
  | S_record of shape array
  | S_array of int * shape

let rec default_of = function
  | S_num -> Num 0.0
  | S_dnum -> Dnum 0.0
  | S_bool -> Bool false
  | S_string -> String ""
  | S_handle kind -> Handle { kind; id = 0 }
  | S_record c -> (
      (* the small ones built in place, as in [copy_parts] *)
      match Array.length c with
      | 3 -> Record [| default_of c.(0); default_of c.(1); default_of c.(2) |]
      | 4 -> Record [| default_of c.(0); default_of c.(1); default_of c.(2); default_of c.(3) |]
      | _ -> Record (Array.map default_of c))
  | S_array (n, element) -> Array (Array.init n (fun _ -> default_of element))

(* ------------------------------------------------------------------------------ memory *)

let add_sat a b = if a > max_int - b then max_int else a + b
let mul_sat n a = if n > 0 && a > max_int / n then max_int else n * a

(* Shapes share their record nodes (shape_of_data_type): each node's size is computed once. *)
let shape_bytes shape =
  let known = ref [] in
  let rec go s =
    match s with
    | S_num | S_dnum | S_bool | S_handle _ -> 32
    | S_string -> 32
    | S_record cs -> (
        match List.assq_opt s !known with
        | Some n -> n
        | None ->
            let n = Array.fold_left (fun acc c -> add_sat acc (add_sat 8 (go c))) 16 cs in
            known := (s, n) :: !known; n)
    | S_array (n, e) -> add_sat 16 (mul_sat n (add_sat 8 (go e)))
  in
  go shape

let rec fixed_size = function
  | S_string -> false
  | S_num | S_dnum | S_bool | S_handle _ -> true
  | S_record cs -> Array.for_all fixed_size cs
  | S_array (_, c) -> fixed_size c

let rec bytes = function
  | Num _ | Dnum _ | Bool _ | Handle _ -> 32
  | String s -> 32 + String.length s
  | Record a | Array a ->
      (* a loop, not a fold: a record argument's bytes are counted at every call *)
      let acc = ref 16 in
      for k = 0 to Array.length a - 1 do
        let b = match a.(k) with Num _ | Dnum _ | Bool _ | Handle _ -> 32 | c -> bytes c in
        acc := add_sat !acc (add_sat 8 b)
      done;
      !acc

let rec conform shape v =
  let all shapes vs =
    let out = Array.map2 conform shapes vs in
    if Array.for_all Option.is_some out then Some (Array.map Option.get out) else None in
  match shape, v with
  | S_num, Num _ | S_dnum, Dnum _ | S_bool, Bool _ | S_string, String _ -> Some v
  | S_dnum, Num x -> Some (Dnum x)
  | S_handle k, Handle h when h.kind = k -> Some v
  | S_record cs, (Record a | Array a) when Array.length cs = Array.length a ->
      Option.map (fun a -> Record a) (all cs a)
  | S_array (n, e), Array a when Array.length a = n -> Option.map (fun a -> Array a) (all (Array.make n e) a)
  | _ -> None

(* One shape per record type within a call: records whose components share a record type share
   its shape, so a record of two components of a record of two … 40 levels down is a shape of 40
   nodes, not 2^40 (R-1.4-c). *)
let shape_of_data_type (t : Rapid_typing.Types.data_type) =
  let memo = Hashtbl.create 8 in
  let rec go (t : Rapid_typing.Types.data_type) =
    match t with
    | Num -> S_num
    | Dnum -> S_dnum
    | Bool -> S_bool
    | String -> S_string
    | Installed_atomic a -> S_handle a.atomic_name
    | Record r -> (
        match Hashtbl.find_opt memo r.record_id with
        | Some s -> s
        | None ->
            let s = S_record (Array.of_list (List.map (fun (_, c) -> go c) r.components)) in
            Hashtbl.replace memo r.record_id s; s)
    | Anytype -> invalid_arg "Value.shape_of_type: anytype has no values of its own"
  in
  go t

let shape_of_type (t : Rapid_typing.Types.object_type) =
  let element = shape_of_data_type t.base in
  match t.dims with
  | Scalar -> element
  | Sized sizes -> List.fold_right (fun n s -> S_array (n, s)) sizes element
  | Conformant _ -> invalid_arg "Value.shape_of_type: {*} array without sizes"

let pos_shape = S_record [| S_num; S_num; S_num |]
let orient_shape = S_record [| S_num; S_num; S_num; S_num |]
let pose_shape = S_record [| pos_shape; orient_shape |]

let pos x y z = Record [| num x; num y; num z |]
let orient a b c d = Record [| num a; num b; num c; num d |]
let pose trans rot = Record [| trans; rot |]

let rec to_debug_string = function
  | Num x -> Printf.sprintf "%.9g" x
  | Dnum x -> Printf.sprintf "%.17gD" x
  | Bool b -> if b then "TRUE" else "FALSE"
  | String s -> Printf.sprintf "%S" s
  | Record a -> "[" ^ String.concat "," (Array.to_list (Array.map to_debug_string a)) ^ "]"
  | Array a -> "{" ^ String.concat "," (Array.to_list (Array.map to_debug_string a)) ^ "}"
  | Handle h -> Printf.sprintf "<%s %d>" h.kind h.id
