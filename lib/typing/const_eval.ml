open Rapid_syntax
open Ast

type value = Number of Q.t | Boolean of bool | Text of string

(* By the region of a constant's initial value (by its name in a tree not read from a file,
   where every region is the same): [None] while it is being evaluated. *)
type key = At of Source.region | Named of string
type cache = (key, value option option) Hashtbl.t

let create_cache () : cache = Hashtbl.create 64
let copy_cache (c : cache) : cache = Hashtbl.copy c

let integer_of = function
  | Number q when Z.equal (Q.den q) Z.one -> Some (Q.num q)
  | _ -> None

(* Truncation toward zero for DIV and MOD, the reading of doc/rulings.md R-3.12. *)
let div_trunc a b = Z.div a b
let rem_trunc a b = Z.rem a b

let same a b =
  match a, b with
  | Number x, Number y -> Some (Q.equal x y)
  | Boolean x, Boolean y -> Some (x = y)
  | Text x, Text y -> Some (String.equal x y)
  | _ -> None

(* Beyond these a value says nothing a typing rule needs: every number of RAPID (dnum: double
   precision) has fewer bits, every string at most 80 bytes (§2.13). Keeping them out bounds the
   size of every value, whatever the chain of constants that builds it. *)
let max_bits = 2200
let bounded = function
  | Number q as v when Z.numbits (Q.num q) <= max_bits && Z.numbits (Q.den q) <= max_bits -> Some v
  | Number _ -> None
  | Text s as v when String.length s <= 80 -> Some v
  | Text _ -> None
  | Boolean _ as v -> Some v

(* Constants that name constants are followed this deep at most in one go, so that the stack
   stays small: a longer chain is evaluated from the constant where the limit was reached, whose
   value is then known, and the evaluation starts again. *)
let max_depth = 1000

exception Too_deep of key * expression

let eval ?(cache = create_cache ()) ~lookup e =
  let rec eval depth (e : expression) =
    match e.it with
    | Num_literal text -> (
        match Num_literal.of_text text with Ok t -> Some (Number (Num_literal.to_q t)) | Error _ -> None)
    | String_literal s -> Some (Text s.bytes)
    | Bool_literal b -> Some (Boolean b)
    | Data_reference (Entire name) -> (
        match lookup name with
        | None -> None
        | Some (init : expression) -> (
            let key =
              if init.at = Source.no_region then Named (String.lowercase_ascii name) else At init.at in
            match Hashtbl.find_opt cache key with
            | Some known -> Option.join known   (* computed, or in progress: a cycle *)
            | None when depth >= max_depth -> raise (Too_deep (key, init))
            | None ->
                Hashtbl.replace cache key None;
                match eval (depth + 1) init with
                | v -> Hashtbl.replace cache key (Some v); v
                | exception (Too_deep _ as e) -> Hashtbl.remove cache key; raise e))
    | Data_reference _ | Function_call _ | Aggregate _ | EXP_placeholder -> None
    | Unary (op, a, at) -> (
        match op, eval depth (operand a at) with
        | Unary_plus, Some (Number q) -> Some (Number q)
        | Unary_minus, Some (Number q) -> Some (Number (Q.neg q))
        | Not, Some (Boolean b) -> Some (Boolean (not b))
        | _ -> None)
    | Binary (op, a, b) -> (
        match eval depth a, eval depth b with
        | Some x, Some y -> Option.bind (binary op x y) bounded
        | _ -> None)
  and binary op x y =
    match op, x, y with
    | Plus, Number a, Number b -> Some (Number (Q.add a b))
    | Minus, Number a, Number b -> Some (Number (Q.sub a b))
    | Mul, Number a, Number b -> Some (Number (Q.mul a b))
    | Div, Number a, Number b -> if Q.equal b Q.zero then None else Some (Number (Q.div a b))
    | (Int_div | Modulo), Number a, Number b -> (
        match integer_of (Number a), integer_of (Number b) with
        | Some a, Some b when not (Z.equal b Z.zero) ->
            Some (Number (Q.of_bigint (if op = Int_div then div_trunc a b else rem_trunc a b)))
        | _ -> None)
    | Plus, Text a, Text b ->
        if String.length a + String.length b > 80 then None else Some (Text (a ^ b))
    | Less, Number a, Number b -> Some (Boolean (Q.lt a b))
    | Less_equal, Number a, Number b -> Some (Boolean (Q.leq a b))
    | Greater, Number a, Number b -> Some (Boolean (Q.gt a b))
    | Greater_equal, Number a, Number b -> Some (Boolean (Q.geq a b))
    | Equal, a, b -> Option.map (fun eq -> Boolean eq) (same a b)
    | Not_equal, a, b -> Option.map (fun eq -> Boolean (not eq)) (same a b)
    | And, Boolean a, Boolean b -> Some (Boolean (a && b))
    | Or, Boolean a, Boolean b -> Some (Boolean (a || b))
    | Xor, Boolean a, Boolean b -> Some (Boolean (a <> b))
    | _ -> None
  in
  let rec from_scratch e =
    match eval 0 e with
    | v -> v
    | exception Too_deep (key, init) ->
        (* The constant at the limit first; each round fills [max_depth] more of the chain. *)
        Hashtbl.replace cache key None;
        let v = from_scratch init in
        Hashtbl.replace cache key (Some v);
        from_scratch e
  in
  from_scratch e
