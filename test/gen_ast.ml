(* QCheck generators of syntax trees that chapter 10 derives (with the parser's reading of
   §2.10 comments and of TASK and switch), for the round-trip property: every tree built here
   is the tree of some module text, so printing it and parsing the text must give it back.

   "Derivable" decides where each constructor may stand:
   - placeholders only where §2.9 and chapter 10 put them: <EXP> only where the grammar says
     <expression> (never inside parentheses, aggregates, index lists, function arguments or as
     an operand), <VAR> only as an assignment target, connect target or conditional procedure
     argument (§4.5, §4.15, §4.6), <ARG> only among procedure arguments (§4.6), <ID> only where
     the grammar says <identifier> and not <ident> (§3.6, §3.11, §7.2);
   - comments (§2.10): a type or data declaration comment is followed by an item of its own
     list (otherwise it belongs to the next list); in a record, a comment follows the record's
     name or a component, except as the last item, and a record has a component (§2.14);
   - LOCAL and TASK only on module-level items, TASK not on CONST (§2.18); BACKWARD only in a
     procedure (§5.4); a compact IF holds a simple statement or <SMT> (§4.17); module
     attributes in the order of §9.2, at most once each, with its exclusions;
   - no parameter typed "switch" with no access mode and no array part: that is how a switch
     parameter is written (§5.2).
   Every region is [Source.no_region].

   Each generator takes a fuel [n] that bounds the size of what it builds; lists share their
   parent's fuel. *)

open Rapid_syntax
open Ast

type 'a gen = 'a QCheck.Gen.t

let loc it = { it; at = Source.no_region }

let int st bound = Random.State.int st bound
let chance st p = Random.State.float st 1.0 < p
let pick st l = List.nth l (int st (List.length l))

(* [weighted st cases]: one of the thunks, chosen with the given weights. *)
let weighted st (cases : (int * (unit -> 'a)) list) =
  let total = List.fold_left (fun acc (w, _) -> acc + w) 0 cases in
  let rec go k = function
    | [] -> invalid_arg "Gen_ast.weighted: no case"
    | [ (_, f) ] -> f ()
    | (w, f) :: rest -> if k < w then f () else go (k - w) rest
  in
  go (int st total) cases

(* A list of at most [max] elements that share the fuel [n]. *)
let list_of st ?(min = 0) max n (f : int -> 'a) =
  let k = min + int st (max - min + 1) in
  let each = if k = 0 then 0 else (n - 1) / k in
  List.init k (fun _ -> f each)

(* ------------------------------------------------------------------ lexical elements *)

(* §2.4, and the two words that are not reserved but that the grammar names (§2.18, §5.2). *)
let reserved =
  [ "ALIAS"; "AND"; "BACKWARD"; "BREAK"; "CASE"; "CONNECT"; "CONST"; "CONTINUE"; "DEFAULT";
    "DIV"; "DO"; "ELSE"; "ELSEIF"; "ENDFOR"; "ENDFUNC"; "ENDIF"; "ENDMODULE"; "ENDPROC";
    "ENDRECORD"; "ENDTEST"; "ENDTRAP"; "ENDWHILE"; "ERROR"; "EXIT"; "FALSE"; "FOR"; "FROM";
    "FUNC"; "GOTO"; "IF"; "INOUT"; "LOCAL"; "MOD"; "MODULE"; "NOSTEPIN"; "NOT"; "NOVIEW"; "OR";
    "PERS"; "PROC"; "RAISE"; "READONLY"; "RECORD"; "RETRY"; "RETURN"; "STEP"; "SYSMODULE";
    "TEST"; "THEN"; "TO"; "TRAP"; "TRUE"; "TRYNEXT"; "UNDO"; "VAR"; "VIEWONLY"; "WHILE";
    "WITH"; "XOR";
    (* REF is a word of the installed environment (ch. 11), which the round trip reads. *)
    "REF" ]

let is_reserved s = List.mem (String.uppercase_ascii s) reserved

(* §2.1 letters, as UTF-8: ASCII letters and the Latin-1 letters À..Ö Ø..ö ø..ÿ. *)
let utf8_of_code c =
  if c < 0x80 then String.make 1 (Char.chr c)
  else
    String.init 2 (fun i -> Char.chr (if i = 0 then 0xC0 lor (c lsr 6) else 0x80 lor (c land 0x3F)))

let latin1_letters =
  List.filter (fun c -> c <> 0xD7 && c <> 0xF7) (List.init (0x100 - 0xC0) (fun i -> 0xC0 + i))
  |> List.map utf8_of_code |> Array.of_list

let ascii_letter st =
  let c = int st 52 in
  String.make 1 (Char.chr (if c < 26 then 65 + c else 97 + c - 26))

let letter st =
  if chance st 0.1 then latin1_letters.(int st (Array.length latin1_letters)) else ascii_letter st

(* §2.3: a letter, then letters, digits and '_', 32 characters at most, not a reserved word. *)
let rec ident_string st =
  let length = if chance st 0.05 then 1 + int st 32 else 1 + int st 8 in
  let b = Buffer.create 32 in
  Buffer.add_string b (letter st);
  for _ = 2 to length do
    Buffer.add_string b
      (weighted st
         [ (6, fun () -> letter st);
           (2, fun () -> String.make 1 (Char.chr (48 + int st 10)));
           (1, fun () -> "_") ])
  done;
  let s = Buffer.contents b in
  if is_reserved s then ident_string st
  else
    (* TASK and switch are identifiers (§2.4 does not list them): use them now and then. *)
    weighted st [ (40, fun () -> s); (1, fun () -> pick st [ "task"; "TASK"; "switch"; "Switch" ]) ]

let name st : name = loc (ident_string st)

(* <identifier> ::= <ident> | <ID> (§2.3) *)
let identifier st : identifier =
  if chance st 0.05 then loc ID_placeholder else loc (Ident (ident_string st))

(* Where the grammar says <ident>. *)
let ident_only st : identifier = loc (Ident (ident_string st))

let digits st ~min ~max =
  String.init (min + int st (max - min + 1)) (fun _ -> Char.chr (48 + int st 10))

(* §2.5, every form, within the range of IEEE 754 double precision: at most 7 significant
   digits and exponents below 100 keep every value far from both bounds. *)
let num_literal st : num_literal =
  let exponent () =
    pick st [ "E"; "e" ] ^ pick st [ ""; "+"; "-" ]
    ^ (if chance st 0.2 then "0" else "") ^ string_of_int (int st 100)
  in
  let opt_exponent () = if chance st 0.3 then exponent () else "" in
  let based prefix digit_chars max =
    let n = 1 + int st max in
    prefix ^ String.init n (fun _ -> digit_chars.[int st (String.length digit_chars)])
  in
  weighted st
    [ (6, fun () -> digits st ~min:1 ~max:4);
      (2, fun () -> digits st ~min:1 ~max:3 ^ exponent ());
      (1, fun () -> "0" ^ pick st [ "D"; "d" ] ^ digits st ~min:1 ~max:5 ^ opt_exponent ());
      (1, fun () -> based ("0" ^ pick st [ "X"; "x" ]) "0123456789ABCDEFabcdef" 8);
      (1, fun () -> based ("0" ^ pick st [ "O"; "o" ]) "01234567" 8);
      (1, fun () -> based ("0" ^ pick st [ "B"; "b" ]) "01" 16);
      (2, fun () ->
          digits st ~min:1 ~max:3 ^ "."
          ^ (if chance st 0.5 then digits st ~min:1 ~max:3 else "") ^ opt_exponent ());
      (1, fun () ->
          (if chance st 0.5 then digits st ~min:1 ~max:3 else "") ^ "."
          ^ digits st ~min:1 ~max:3 ^ opt_exponent ()) ]

let hex_digit st = "0123456789ABCDEFabcdef".[int st 22]

let printable_ascii st ~except =
  let rec go () =
    let c = Char.chr (32 + int st 95) in
    if String.contains except c then go () else String.make 1 c
  in
  go ()

let multibyte st = pick st [ "é"; "Ü"; "ß"; "€"; "中"; "😀"; "\xC2\xA0" ]

(* §2.7: the raw text of a string literal: characters, "" and \\ for the quote and the
   backslash, \hh character codes, UTF-8; its value at most 80 bytes (§2.13). *)
let string_literal st : string_literal =
  let raw = Buffer.create 80 and bytes = Buffer.create 80 in
  let pieces = if chance st 0.1 then 80 else int st 12 in
  let rec add k =
    if k > 0 then begin
      let r, v =
        weighted st
          [ (10, fun () -> let s = printable_ascii st ~except:"\"\\" in (s, s));
            (1, fun () -> ("\"\"", "\""));
            (1, fun () -> ("\\\\", "\\"));
            (1, fun () ->
                let h1 = hex_digit st and h2 = hex_digit st in
                let s = Printf.sprintf "%c%c" h1 h2 in
                ("\\" ^ s, String.make 1 (Char.chr (int_of_string ("0x" ^ s)))));
            (1, fun () -> ("\t", "\t"));
            (2, fun () -> let s = multibyte st in (s, s)) ]
      in
      if Buffer.length bytes + String.length v <= 80 then begin
        Buffer.add_string raw r; Buffer.add_string bytes v
      end;
      add (k - 1)
    end
  in
  add pieces;
  { raw = Buffer.contents raw; bytes = Buffer.contents bytes }

(* §2.10: the text after '!', up to the end of its line. *)
let comment_text st =
  let n = if chance st 0.1 then 0 else int st 30 in
  String.concat ""
    (List.init n (fun _ ->
         weighted st
           [ (12, fun () -> printable_ascii st ~except:"");
             (1, fun () -> "\t");
             (2, fun () -> multibyte st) ]))

(* The lines of a %%% header block (doc/dialect.md): any line but one that closes the block. *)
let header_line st =
  let rec go () =
    let s =
      weighted st
        [ (2, fun () -> pick st [ "VERSION:1"; "LANGUAGE:ENGLISH"; "  VERSION:2"; "" ]);
          (1, fun () -> String.concat "" (List.init (int st 20) (fun _ -> printable_ascii st ~except:"")));
          (1, fun () -> pick st [ "%%% x"; "%%%%"; " %% %" ]) ]
    in
    let stripped =
      String.concat "" (String.split_on_char ' ' (String.concat "" (String.split_on_char '\t' s)))
    in
    if stripped = "%%%" then go () else s
  in
  go ()

(* ------------------------------------------------------------------ expressions *)

let unary_operator st = pick st [ Unary_plus; Unary_minus; Not ]

let binary_operator st =
  pick st [ Mul; Div; Int_div; Modulo; Plus; Minus; Less; Less_equal; Equal; Greater;
            Greater_equal; Not_equal; And; Or; Xor ]

let literal st =
  weighted st
    [ (3, fun () -> Num_literal (num_literal st));
      (2, fun () -> String_literal (string_literal st));
      (1, fun () -> Bool_literal (chance st 0.5)) ]

(* [expression ~top n]: [top] where the grammar says <expression>, which alone may be <EXP>. *)
let rec expression ?(top = false) n st : expression =
  if n <= 1 then
    weighted st
      [ (4, fun () -> loc (literal st));
        (4, fun () -> loc (Data_reference (Entire (name st).it)));
        ((if top then 1 else 0), fun () -> loc EXP_placeholder) ]
  else
    weighted st
      [ (3, fun () -> loc (literal st));
        (3, fun () -> loc (Data_reference (data_reference n st).it));
        (2, fun () -> loc (Function_call (function_call n st)));
        (1, fun () -> loc (aggregate (list_of st ~min:1 4 n (fun m -> expression m st))));
        (3, fun () -> let e = expression (n - 1) st in loc (Unary (unary_operator st, e.it, e.at)));
        (6, fun () ->
            let op = binary_operator st in
            let l = expression (n / 2) st in
            loc (Binary (op, l, expression (n / 2) st)));
        ((if top then 1 else 0), fun () -> loc EXP_placeholder) ]

(* §3.6: <VAR> is not built here; see [target]. *)
and data_reference n st : data_reference =
  if n <= 1 then loc (Entire (name st).it)
  else
    weighted st
      [ (3, fun () -> loc (Entire (name st).it));
        (2, fun () -> let nm = name st in loc (Element (nm, list_of st ~min:1 3 n (fun m -> expression m st))));
        (2, fun () -> let r = data_reference (n - 1) st in loc (Component (r, name st))) ]

(* §3.11: names are <ident>, values <expr>, no <ARG>, no <VAR>. *)
and function_call n st : function_call =
  let func = identifier st in
  let arguments =
    list_of st 4 n (fun m ->
        weighted st
          [ (4, fun () ->
                let nm = if chance st 0.2 then Some (ident_only st) else None in
                let e = expression m st in
                loc (required_argument nm e Source.no_region));
            (2, fun () ->
                let nm = ident_only st in
                loc (Optional_argument (nm, if chance st 0.5 then Some (expression m st) else None)));
            (1, fun () ->
                let nm = ident_only st in
                loc (Conditional_argument (nm, data_reference m st))) ])
  in
  let (arguments, argument_regions) = argument_arrays arguments in
  { func; arguments; argument_regions }

(* §4.6: names are <identifier>, values <expression>; <ARG> and, in a conditional argument,
   <VAR> are allowed. *)
let procedure_arguments n st : argument list =
  list_of st 4 n (fun m ->
      weighted st
        [ (5, fun () ->
              let nm = if chance st 0.2 then Some (identifier st) else None in
              let e = expression ~top:true m st in
              loc (required_argument nm e Source.no_region));
          (2, fun () ->
              let nm = identifier st in
              loc (Optional_argument
                     (nm, if chance st 0.5 then Some (expression ~top:true m st) else None)));
          (2, fun () ->
              let nm = identifier st in
              let r = if chance st 0.2 then loc VAR_placeholder else data_reference m st in
              loc (Conditional_argument (nm, r)));
          (1, fun () -> loc ARG_placeholder) ])

(* §4.5, §4.15: a data object or <VAR>. *)
let target n st = if chance st 0.1 then loc VAR_placeholder else data_reference n st

(* ------------------------------------------------------------------ statements *)

let optional st p f = if chance st p then Some (f ()) else None

(* §4.1 <simple statement> *)
let simple_statement n st : statement =
  let e () = expression ~top:true (n - 1) st in
  loc
    (weighted st
       [ (6, fun () -> let t = target (n / 2) st in Assignment (t, expression ~top:true (n / 2) st));
         (5, fun () ->
             let p =
               if chance st 0.15 then Late_bound (expression ~top:true (n / 2) st)
               else Procedure_name (identifier st)
             in
             let (args, regions) = argument_arrays (procedure_arguments (n / 2) st) in
             Procedure_call (p, args, regions));
         (1, fun () -> Goto (identifier st));
         (1, fun () -> Break);
         (1, fun () -> Continue);
         (1, fun () -> Return (optional st 0.6 e));
         (1, fun () -> Raise (optional st 0.5 e));
         (1, fun () -> Exit);
         (1, fun () -> Retry);
         (1, fun () -> Trynext);
         (1, fun () -> let t = target (n - 1) st in Connect (t, identifier st)) ])

let rec statement n st : statement =
  let cond () = expression ~top:true (n / 3) st in
  let body () = statements (n / 2) st in
  weighted st
    [ (10, fun () -> simple_statement n st);
      (1, fun () -> loc (Label (identifier st)));
      (2, fun () -> loc (Statement_comment (comment_text st)));
      (1, fun () -> loc SMT_placeholder);
      ((if n > 2 then 2 else 0), fun () ->
          let c = cond () in
          let s = if chance st 0.1 then loc SMT_placeholder else simple_statement (n / 2) st in
          loc (Compact_if (c, s)));
      ((if n > 2 then 2 else 0), fun () ->
          let condition = cond () in
          let then_branch = body () in
          let elseifs =
            list_of st 2 (n / 2) (fun m ->
                if chance st 0.2 then loc EIT_placeholder
                else
                  let c = expression ~top:true (m / 2) st in
                  loc (Elseif (c, statements (m / 2) st)))
          in
          let else_branch = optional st 0.5 body in
          loc (If { condition; then_branch; elseifs; else_branch }));
      ((if n > 2 then 1 else 0), fun () ->
          let loop_variable = identifier st in
          let from_ = cond () in
          let to_ = cond () in
          let step = optional st 0.4 cond in
          loc (For { loop_variable; from_; to_; step; body = body () }));
      ((if n > 2 then 1 else 0), fun () -> let c = cond () in loc (While (c, body ())));
      ((if n > 2 then 1 else 0), fun () ->
          let test_expression = cond () in
          let cases =
            list_of st 3 (n / 2) (fun m ->
                if chance st 0.2 then loc CSE_placeholder
                else
                  let values = list_of st ~min:1 3 (m / 2) (fun k -> expression ~top:true k st) in
                  loc (Case (values, statements (m / 2) st)))
          in
          let default = optional st 0.4 body in
          loc (Test { test_expression; cases; default })) ]

and statements n st = list_of st 5 n (fun m -> statement m st)

(* ------------------------------------------------------------------ declarations *)

(* [drop_trailing is_comment l]: §2.10 files comments that no item of their list
   follows with the next list, so a derivable list of type definitions or data declarations
   does not end with a comment. *)
let rec drop_trailing is_comment l =
  match List.rev l with
  | x :: rest when is_comment x -> drop_trailing is_comment (List.rev rest)
  | _ -> l

(* §2.18 - §2.24; [module_level]: LOCAL and TASK are allowed. *)
let data_declaration ~module_level n st : data_declaration =
  weighted st
    [ (8, fun () ->
          let storage = pick st [ Var; Pers; Const ] in
          let scope =
            if not module_level then Global
            else
              weighted st
                [ (4, fun () -> Global);
                  (1, fun () -> Local);
                  ((if storage = Const then 0 else 1), fun () -> Task) ]
          in
          let data_type = identifier st in
          let name = identifier st in
          let dims = if chance st 0.3 then list_of st ~min:1 3 (n / 2) (fun m -> expression ~top:true m st) else [] in
          let initial_value =
            if storage = Const || chance st 0.6 then Some (expression ~top:true (n / 2) st) else None
          in
          loc (Data_declaration { scope; storage; data_type; name; dims; initial_value }));
      (2, fun () -> loc (Declaration_comment (comment_text st)));
      (1, fun () -> loc DDN_placeholder) ]

let is_declaration_comment (d : data_declaration) =
  match d.it with Declaration_comment _ -> true | _ -> false

let data_declarations ~module_level n st =
  drop_trailing is_declaration_comment
    (list_of st 4 n (fun m -> data_declaration ~module_level m st))

(* §2.14 with §2.10: a comment follows the record's name or a component, or is the last item. *)
let record_components st : record_component list =
  let k = 1 + int st 4 in
  let component () = loc (Record_component (identifier st, identifier st)) in
  let comment () = loc (Component_comment (comment_text st)) in
  let rec build i acc =
    if i = k then
      (* A comment on the line of the last component, and one more on the last line. *)
      let acc = if chance st 0.3 then comment () :: acc else acc in
      let acc = if chance st 0.2 then comment () :: acc else acc in
      List.rev acc
    else
      (* A comment before component [i] follows the record's name or component [i - 1]. *)
      let acc = if chance st 0.3 then comment () :: acc else acc in
      build (i + 1) (component () :: acc)
  in
  build 0 []

let type_definition st : type_definition =
  weighted st
    [ (4, fun () ->
          let local = chance st 0.3 in
          let name = identifier st in
          loc (Record_definition { local; name; components = record_components st }));
      (3, fun () ->
          let local = chance st 0.3 in
          let base = identifier st in
          loc (Alias_definition { local; base; name = identifier st }));
      (2, fun () -> loc (Type_comment (comment_text st)));
      (1, fun () -> loc TDN_placeholder) ]

let is_type_comment (t : type_definition) =
  match t.it with Type_comment _ -> true | _ -> false

(* ------------------------------------------------------------------ routines *)

(* §5.2 <parameter declaration> *)
let parameter_declaration st : parameter_declaration =
  if chance st 0.15 then loc (Switch (identifier st))
  else
    let mode = pick st [ In; In; Var_mode; Pers_mode; Inout; Ref_mode ] in
    let data_type = identifier st in
    let name = identifier st in
    let array =
      weighted st
        [ (5, fun () -> Not_array); (2, fun () -> Conformant (1 + int st 3)); (1, fun () -> DIM_placeholder) ]
    in
    (* [switch name] with no access mode and no array part is a switch parameter (§5.2). *)
    let mode =
      match mode, data_type.it, array with
      | In, Ident s, Not_array when String.lowercase_ascii s = "switch" -> Inout
      | _ -> mode
    in
    loc (Parameter { mode; data_type; name; array })

let parameters st : parameter list =
  list_of st 4 4 (fun _ ->
      weighted st
        [ (4, fun () -> loc (Required_parameter (parameter_declaration st)));
          (2, fun () ->
              let alts =
                list_of st ~min:1 3 3 (fun _ ->
                    if chance st 0.15 then loc ALT_placeholder
                    else loc (Alternative (parameter_declaration st)))
              in
              loc (Optional_parameter alts));
          (1, fun () -> loc PAR_placeholder) ])

(* §7.2 *)
let recovery_error_number st : recovery_error_number =
  if chance st 0.5 then loc (Error_number_literal (num_literal st))
  else loc (Error_number_name (name st))

(* §5.4 - §5.6; [procedure]: BACKWARD is allowed. *)
let routine_body ~procedure n st : routine_body =
  let declarations = data_declarations ~module_level:false (n / 4) st in
  let statements_ = statements (n / 2) st in
  let part p = optional st p (fun () -> statements (n / 6) st) in
  let backward = if procedure then part 0.2 else None in
  let error =
    optional st 0.3 (fun () ->
        let error_numbers =
          optional st 0.4 (fun () -> list_of st ~min:1 3 3 (fun _ -> recovery_error_number st))
        in
        { error_numbers; handler = statements (n / 6) st })
  in
  let undo = part 0.2 in
  { declarations; statements = statements_; backward; error; undo }

let routine_declaration n st : routine_declaration =
  weighted st
    [ (6, fun () ->
          let local = chance st 0.2 in
          let name = identifier st in
          let parameters = parameters st in
          loc (Procedure_declaration { local; name; parameters; body = routine_body ~procedure:true n st }));
      (3, fun () ->
          let local = chance st 0.2 in
          let return_type = identifier st in
          let name = identifier st in
          let parameters = parameters st in
          loc (Function_declaration
                 { local; return_type; name; parameters; body = routine_body ~procedure:false n st }));
      (2, fun () ->
          let local = chance st 0.2 in
          let name = identifier st in
          loc (Trap_declaration { local; name; body = routine_body ~procedure:false n st }));
      (2, fun () -> loc (Routine_comment (comment_text st)));
      (1, fun () -> loc RDN_placeholder) ]

(* §9.2: in the list's order, each at most once, NOVIEW excluding NOSTEPIN, VIEWONLY and
   READONLY, VIEWONLY and READONLY excluding each other. *)
let module_attributes st : module_attribute list =
  let sys = chance st 0.3 in
  let noview = chance st 0.2 in
  let nostepin = (not noview) && chance st 0.3 in
  let viewonly = (not noview) && chance st 0.2 in
  let readonly = (not noview) && (not viewonly) && chance st 0.2 in
  List.filter_map (fun (present, a) -> if present then Some (loc a) else None)
    [ (sys, SYSMODULE); (noview, NOVIEW); (nostepin, NOSTEPIN); (viewonly, VIEWONLY);
      (readonly, READONLY) ]

let module_declaration_sized n st : module_declaration =
  let header = optional st 0.2 (fun () -> List.init (int st 4) (fun _ -> header_line st)) in
  (* comment lines before MODULE (doc/dialect.md) *)
  let prologue_comments = if chance st 0.2 then List.init (1 + int st 3) (fun _ -> comment_text st) else [] in
  let module_name = identifier st in
  let attributes = module_attributes st in
  let type_definitions =
    drop_trailing is_type_comment (List.init (int st 4) (fun _ -> type_definition st))
  in
  let data_declarations = data_declarations ~module_level:true (n / 3) st in
  let routine_declarations = list_of st 4 n (fun m -> routine_declaration m st) in
  { header; prologue_comments; module_name; attributes; type_definitions; data_declarations;
    routine_declarations; module_region = Source.no_region }

(* A module of size at most about [max_size] nodes of fuel. *)
let module_declaration ?(max_size = 60) () : module_declaration gen =
  QCheck.Gen.(int_range 1 max_size >>= fun n -> module_declaration_sized n)
