module T = Rapid_typing.Types

let same a b = String.lowercase_ascii a = String.lowercase_ascii b

exception Refused of string

let is_switch_type (t : T.object_type) =
  match t.base with Installed_atomic { atomic_name = "switch"; _ } -> true | _ -> false

let is_anytype (t : T.object_type) = t.base = T.Anytype

(* §3.11, §5.2: "the data type of an argument must be equal to the type of its parameter". *)
let equal_type (p : Ir.parameter) (t : T.object_type) =
  match p.p_type with
  | None -> is_switch_type t
  | Some pt -> is_anytype pt || T.equal_types ~value_context:(p.p_mode = Mode_in) pt t

(* §2.16: a non-value object has no value for an in parameter; a non-value or semi-value object
   is passed only to a VAR or REF parameter (footnote iii of the table of object references). *)
let value_class_fits (p : Ir.parameter) (t : T.object_type) =
  is_switch_type t
  || (match T.value_class t.base, p.p_mode with
      | Value, _ -> true
      | Semi_value, (Mode_in | Mode_var | Mode_ref) -> true
      | Non_value, (Mode_var | Mode_ref) -> true
      | (Semi_value | Non_value), _ -> false)

let is_num_scalar (p : Ir.parameter) =
  match p.p_type with
  | Some { base = Num | Dnum; dims = Scalar } -> true
  | Some t -> is_anytype t
  | None -> false

let is_dnum_scalar (p : Ir.parameter) =
  match p.p_type with Some { base = Dnum; dims = Scalar } -> true | _ -> false

(* The shape an aggregate must fit: it takes its parameter's type (§3.10). *)
let aggregate_shape (p : Ir.parameter) =
  match p.p_type with
  | Some t when not (is_anytype t) -> (
      match Value.shape_of_type t with s -> Some s | exception Invalid_argument _ -> None)
  | _ -> None

(* §2.3: an identifier is a letter followed by letters, digits and '_', at most 32 characters,
   and no reserved word (§2.4); the letters of §2.1 are A..Z, a..z and the Latin-1 letters
   À..Ö, Ø..ö, ø..ÿ. The bytes are read as UTF-8 where they are valid, as Latin-1 elsewhere (a
   string of a Latin-1 module, R-2.1-b). *)
let is_identifier (s : string) =
  let chars = Utf8_text.characters ~latin1:false s in
  let code c =
    match String.length c with
    | 1 -> Char.code c.[0]
    | 2 -> ((Char.code c.[0] land 0x1F) lsl 6) lor (Char.code c.[1] land 0x3F)
    | _ -> -1 in
  let letter c =
    let k = code c in
    (k >= 0x41 && k <= 0x5A) || (k >= 0x61 && k <= 0x7A)
    || (k >= 0xC0 && k <= 0xFF && k <> 0xD7 && k <> 0xF7) in
  let digit c = let k = code c in k >= 0x30 && k <= 0x39 in
  let n = Array.length chars in
  n >= 1 && n <= Rapid_syntax.Lexer.max_identifier_length
  && letter chars.(0)
  && Array.for_all (fun c -> letter c || digit c || c = "_") chars
  && not (Hashtbl.mem Rapid_syntax.Lexer.reserved_words (String.uppercase_ascii s))

(* §4.6: "name2", or "name1:name2" (procedure name2 of module name1). *)
let is_procedure_name name =
  match String.split_on_char ':' name with
  | [ p ] -> is_identifier p
  | [ m; p ] -> is_identifier m && is_identifier p
  | _ -> false

let unknown_procedure_error name = if is_procedure_name name then "ERR_REFUNKPRC" else "ERR_CALLPROC"

(* A place whose name is neither declared nor installed (--allow-unknown). *)
let rec unresolved : Ir.place -> bool = function
  | Unresolved _ -> true
  | Element (p, _) | Component (p, _) -> unresolved p
  | Whole _ -> false

let bind (r : Ir.routine) ~kind (args : Ir.late_argument array) =
  let n = Array.length r.parameters in
  let bound = Array.make n Ir.Absent in
  let given = Array.make n false in
  let conditional = Array.make n false in
  (* The access-mode errors are reported only when the arguments fit otherwise. *)
  let access_error = ref None in
  let access name = if !access_error = None then access_error := Some name in
  let callproc () = raise (Refused "ERR_CALLPROC") in
  let rec next_required i =
    if i >= n then None else if not r.parameters.(i).p_optional then Some i else next_required (i + 1) in
  let next = ref 0 in
  let value_argument (p : Ir.parameter) (a : Ir.late_argument) : Ir.argument =
    match a.late_value with
    | Late_switch -> if p.p_switch then Present_switch else callproc ()
    | Late_conditional slot -> (
        (* §3.11: a conditional argument passes on an optional parameter of the caller. *)
        if not p.p_optional then callproc ();
        (match a.late_type with Late_typed t when not (equal_type p t) -> callproc () | _ -> ());
        match slot with Some s -> Pass_on s | None -> Absent)
    | Late_expr _ when p.p_switch -> callproc ()
    | Late_expr e -> (
        let e = match a.late_type, e.e with
          | Late_typed t, _ -> if equal_type p t && value_class_fits p t then e else callproc ()
          | Late_numeric d, _ -> if not (is_num_scalar p) then callproc () else if is_dnum_scalar p then d else e
          | Late_untyped, Aggregate _ -> (
              match aggregate_shape p with
              | Some shape -> { e with e = Fitted (e, shape) }
              | None -> e)
          | Late_untyped, _ -> e in
        let reference () =
          match e.e with Read place | Read_signal place -> Some place | _ -> None in
        match p.p_mode with
        | Mode_in -> By_value e
        | Mode_ref -> (
            match reference () with
            | Some place -> By_reference (place, kind place a.late_kind)
            | None -> By_value e)
        | Mode_var | Mode_inout -> (
            (* §5.2: a variable, or a parameter bound to one; not a constant, a read-only
               variable, a persistent for VAR, nor any other expression. *)
            match reference () with
            | Some place -> (
                match kind place a.late_kind with
                | Ref_constant -> access "ERR_ARGNOTVAR"; By_value e
                | Ref_persistent when p.p_mode = Mode_var -> access "ERR_ARGNOTVAR"; By_value e
                | _ when a.late_read_only -> access "ERR_ARGNOTVAR"; By_value e
                | k -> By_reference (place, k))
            | None -> access "ERR_ARGNOTVAR"; By_value e)
        | Mode_pers -> (
            match reference () with
            | Some place when unresolved place ->
                (* R-5.2-unknown1: a name neither declared nor installed (--allow-unknown) is
                   unknown, not "not a persistent": binding it raises ERR_REFUNKDAT, as a VAR
                   parameter's would. *)
                By_reference (place, Ref_persistent)
            | Some place -> (
                match kind place a.late_kind with
                | Ref_persistent -> By_reference (place, Ref_persistent)
                | _ -> access "ERR_ARGNOTPER"; By_value e)
            | None -> access "ERR_ARGNOTPER"; By_value e))
  in
  let put i (a : Ir.late_argument) =
    let p = r.parameters.(i) in
    if given.(i) then callproc ();
    (* §5.2: of mutually exclusive optional parameters at most one is given; conditional ones
       are checked when they are passed on (ERR_ARGDUPCND). *)
    let is_conditional = match a.late_value with Late_conditional _ -> true | _ -> false in
    if p.p_group >= 0 && not is_conditional then
      Array.iteri (fun j (q : Ir.parameter) ->
          if j <> i && q.p_group = p.p_group && given.(j) && not conditional.(j) then callproc ())
        r.parameters;
    given.(i) <- true;
    conditional.(i) <- is_conditional;
    bound.(i) <- value_argument p a
  in
  try
    Array.iter (fun (a : Ir.late_argument) ->
        (* §3.11: an optional argument names its parameter, which must be an optional one; a
           required argument goes to the next required parameter, whose name it may give. *)
        let optional =
          match a.late_name with
          | Some name when a.late_optional ->
              let rec find i =
                if i >= n then None
                else if r.parameters.(i).p_optional && same r.parameters.(i).p_name name then Some i
                else find (i + 1) in
              find 0
          | _ -> None in
        match optional with
        | Some i -> put i a
        | None -> (
            match a.late_value with
            | _ when a.late_optional -> callproc ()
            | Late_switch | Late_conditional _ -> callproc ()
            | Late_expr _ -> (
                match next_required !next with
                | None -> callproc ()
                | Some i ->
                    next := i + 1;
                    (match a.late_name with
                     | Some nm when not (same nm r.parameters.(i).p_name) -> callproc ()
                     | _ -> ());
                    put i a))) args;
    if next_required !next <> None then callproc ();
    match !access_error with Some name -> Error name | None -> Ok bound
  with Refused name -> Error name
