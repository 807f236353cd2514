open Rapid_syntax
open Ast

type value = Number of Q.t | Boolean of bool | Text of string

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

let eval ~lookup e =
  (* [seen]: constants being evaluated, so that a constant defined by itself has no value
     instead of looping (the judgement reports the cycle). *)
  let rec eval seen (e : expression) =
    match e.it with
    | Num_literal text -> (
        match Num_literal.of_text text with Ok t -> Some (Number (Num_literal.to_q t)) | Error _ -> None)
    | String_literal s -> Some (Text s.bytes)
    | Bool_literal b -> Some (Boolean b)
    | Data_reference (Entire name) ->
        let key = String.lowercase_ascii name in
        if List.mem key seen then None
        else Option.bind (lookup name) (eval (key :: seen))
    | Data_reference _ | Function_call _ | Aggregate _ | EXP_placeholder -> None
    | Unary (op, a, at) -> (
        match op, eval seen (operand a at) with
        | Unary_plus, Some (Number q) -> Some (Number q)
        | Unary_minus, Some (Number q) -> Some (Number (Q.neg q))
        | Not, Some (Boolean b) -> Some (Boolean (not b))
        | _ -> None)
    | Binary (op, a, b) -> (
        match eval seen a, eval seen b with
        | Some x, Some y -> binary op x y
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
    | Plus, Text a, Text b -> Some (Text (a ^ b))
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
  eval [] e
