(* The generator keeps, for the statement list it is filling, what is in scope: which data objects
   of which type can be read or written, which routines can be called and with what, whether an
   error handler or a loop encloses the point. Every choice is made so that the program passes
   the static semantics; run-time errors are left to chance on purpose. *)

type stmt = Line of string | Compound of (string * stmt list) list * string

type routine = {
  header : string;
  data : string list;
  body : stmt list;
  error : (string * stmt list) option;
  undo : stmt list option;
  footer : string;
}

type program = { name : string; module_data : string list; routines : routine list }

type options = {
  mismatching : bool; max_routines : int; max_statements : int; controller : bool; signal_stores : bool }

let default_options =
  { mismatching = true; max_routines = 5; max_statements = 5; controller = true; signal_stores = true }

(* pos and orient for their rows of §3.12 (vector and rotation arithmetic). *)
type ty = Num | Dnum | Bool | Str | Pos | Orient

let type_name = function
  | Num -> "num" | Dnum -> "dnum" | Bool -> "bool" | Str -> "string" | Pos -> "pos" | Orient -> "orient"

(* How a data object may be used: read only (CONST, IN parameters, loop variables), or also
   written; persistents matter for INOUT arguments. *)
type kind = Constant | Variable | Persistent | Readonly

type data = { name : string; ty : ty; kind : kind }

type mode = In | Var_mode | Inout

type param = {
  p_name : string;
  p_ty : ty;
  p_mode : mode;
  p_optional : bool;
  p_switch : bool;
  p_group : int;                     (* mutually exclusive alternatives share a group > 0 *)
}

type signature = { r_name : string; result : ty option; params : param list }

type scope = {
  rs : Random.State.t;
  opts : options;
  data : data list;
  array_ : string;                   (* the module's num array, 5 elements *)
  record_ : string;                  (* the module's record variable *)
  callable : signature list;
  optionals : param list;            (* the current routine's optional parameters *)
  depth : int;
  in_loop : bool;
  in_function : ty option;
  controller : bool;                 (* this program uses the controller: waits, signals,
                                        interrupts, moves (chapters 8 and 14 of the manual) *)
  counters : string list ref;        (* WHILE counters the routine must declare *)
  loop_vars : int ref;
  labels : string list ref;          (* labels placed at the end of the routine body *)
}

let pick rs l = List.nth l (Random.State.int rs (List.length l))
let chance rs p = Random.State.float rs 1. < p
let int_in rs lo hi = lo + Random.State.int rs (hi - lo + 1)

let readable sc ty = List.filter (fun d -> d.ty = ty) sc.data
let writable sc ty = List.filter (fun d -> d.ty = ty && (d.kind = Variable || d.kind = Persistent)) sc.data

let string_literals = [ "\"\""; "\"a\""; "\"rapid\""; "\"x y\""; "\"0123456789012345678901234567890123456789\"" ]

(* ------------------------------------------------------------------ expressions *)

(* A data object of a record type, whose component an expression reads. *)
let sub_place sc ty =
  match readable sc ty with [] -> (match ty with Pos -> "gpos1" | _ -> "gor1") | l -> (pick sc.rs l).name

let rec expr sc ty depth =
  let rs = sc.rs in
  let leaf () =
    let vars = readable sc ty in
    if vars <> [] && chance rs 0.6 then (pick rs vars).name
    else
      match ty with
      | Num ->
          pick rs [ string_of_int (int_in rs 0 9); string_of_int (int_in rs 0 9); "2.5"; "0.1"; "1E20"; "(-3)" ]
      | Dnum -> pick rs [ string_of_int (int_in rs 0 9); "1.5"; "4294967296" ]
      | Bool -> pick rs [ "TRUE"; "FALSE" ]
      | Str -> pick rs string_literals
      (* no aggregate here: an aggregate takes its type from its context (§3.10), which an
         operand of an operator does not give *)
      | Pos -> pick rs [ "gpos1"; "gpos2" ]
      | Orient -> pick rs [ "gor1"; "gor2" ]
  in
  if depth <= 0 then leaf ()
  else
    let sub t = expr sc t (depth - 1) in
    let calls = List.filter (fun s -> s.result = Some ty) sc.callable in
    let choices =
      [ (3, leaf) ]
      @ (if calls <> [] then [ (1, fun () -> function_call sc (pick rs calls) (depth - 1)) ] else [])
      @
      match ty with
      | Num ->
          [ (2, fun () -> Printf.sprintf "(%s %s %s)" (sub Num) (pick rs [ "+"; "-"; "*"; "/" ]) (sub Num));
            (* A constant operand of DIV or MOD that is not an integer is a static error
               (§3.12): the operands are variables, integers, or Trunc of anything. *)
            (1, fun () ->
                let operand () =
                  let vars = readable sc Num in
                  match Random.State.int rs 3 with
                  | 0 when vars <> [] -> (pick rs vars).name
                  | 1 -> string_of_int (int_in rs 0 7)
                  | _ -> Printf.sprintf "Trunc(%s)" (sub Num) in
                Printf.sprintf "(%s %s %s)" (operand ()) (pick rs [ "DIV"; "MOD" ]) (operand ()));
            (1, fun () -> Printf.sprintf "(%s%s)" (pick rs [ "-"; "+" ]) (sub Num));
            (1, fun () -> Printf.sprintf "%s.%s" (sub_place sc Pos) (pick rs [ "x"; "y"; "z" ]));
            (1, fun () -> Printf.sprintf "%s.%s" (sub_place sc Orient) (pick rs [ "q1"; "q2"; "q3"; "q4" ]));
            (1, fun () ->
                let index =
                  if chance rs 0.8 then string_of_int (int_in rs 1 5) else Printf.sprintf "Trunc(%s)" (sub Num) in
                Printf.sprintf "%s{%s}" sc.array_ index);
            (1, fun () -> Printf.sprintf "%s.%s" sc.record_ (pick rs [ "x"; "y" ]));
            (1, fun () -> Printf.sprintf "Abs(%s)" (sub Num));
            (1, fun () -> Printf.sprintf "StrLen(%s)" (sub Str));
            (1, fun () -> Printf.sprintf "Dim(%s, 1)" sc.array_) ]
          @ (if sc.controller then
               (* a signal's value (§2.16: a semi-value object read in value context) *)
               [ (1, fun () -> pick rs [ "DOutput(do1)"; "di1"; "(di1 + do1)" ]) ]
             else [])
      | Dnum ->
          [ (2, fun () -> Printf.sprintf "(%s %s %s)" (sub Dnum) (pick rs [ "+"; "-"; "*"; "/" ]) (sub Dnum));
            (* DIV and MOD on dnum want natural operands (§3.12, note c): a constant one that is
               not is a static error, a variable's value is checked when it runs *)
            (1, fun () ->
                let operand () =
                  if chance rs 0.5 then "gd1" else string_of_int (int_in rs 0 7) in
                Printf.sprintf "(%s %s %s)" (operand ()) (pick rs [ "DIV"; "MOD" ]) (operand ()));
            (1, fun () -> Printf.sprintf "(%s%s)" (pick rs [ "-"; "+" ]) (sub Dnum)) ]
      | Pos ->
          [ (2, fun () -> Printf.sprintf "(%s %s %s)" (sub Pos) (pick rs [ "+"; "-"; "*" ]) (sub Pos));
            (1, fun () -> Printf.sprintf "(%s * %s)" (sub Num) (sub Pos));
            (1, fun () -> Printf.sprintf "(%s %s %s)" (sub Pos) (pick rs [ "*"; "/" ]) (sub Num));
            (1, fun () -> Printf.sprintf "(%s%s)" (pick rs [ "-"; "+" ]) (sub Pos)) ]
      | Orient -> [ (2, fun () -> Printf.sprintf "(%s * %s)" (sub Orient) (sub Orient)) ]
      | Bool ->
          [ (2, fun () ->
                Printf.sprintf "(%s %s %s)" (sub Num) (pick rs [ "<"; "<="; "="; "<>"; ">"; ">=" ]) (sub Num));
            (1, fun () -> Printf.sprintf "(%s %s %s)" (sub Str) (pick rs [ "="; "<>" ]) (sub Str));
            (1, fun () ->
                Printf.sprintf "(%s %s %s)" (sub Dnum) (pick rs [ "<"; "<="; "="; "<>"; ">"; ">=" ]) (sub Dnum));
            (1, fun () -> Printf.sprintf "(%s %s %s)" (sub Bool) (pick rs [ "="; "<>" ]) (sub Bool));
            (* = and <> on any value type (§3.12): pos, orient, a record, an array *)
            (1, fun () ->
                let op = pick rs [ "="; "<>" ] in
                match Random.State.int rs 4 with
                | 0 -> Printf.sprintf "(%s %s %s)" (sub Pos) op (sub Pos)
                | 1 -> Printf.sprintf "(%s %s %s)" (sub Orient) op (sub Orient)
                | 2 -> Printf.sprintf "(%s %s %s)" sc.record_ op sc.record_
                | _ -> Printf.sprintf "(%s %s %s)" sc.array_ op sc.array_);
            (1, fun () -> Printf.sprintf "(NOT %s)" (sub Bool));
            (2, fun () -> Printf.sprintf "(%s %s %s)" (sub Bool) (pick rs [ "AND"; "OR"; "XOR" ]) (sub Bool)) ]
          @ (if sc.optionals <> [] then
               [ (1, fun () -> Printf.sprintf "Present(%s)" (pick rs sc.optionals).p_name) ]
             else [])
      | Str ->
          [ (2, fun () -> Printf.sprintf "(%s + %s)" (sub Str) (sub Str));
            (1, fun () -> Printf.sprintf "NumToStr(%s, %d)" (sub Num) (int_in rs 0 3)) ]
    in
    QCheck.Gen.frequency (List.map (fun (w, f) -> (w, fun _ -> f ())) choices) rs

(* The arguments of a call: required ones in order, optional ones sometimes, at most one of a
   group of alternatives, sometimes conditional on an optional parameter of the caller (§3.11). *)
and arguments sc (s : signature) depth =
  let rs = sc.rs in
  let used_groups = ref [] and conditional_groups = ref [] in
  List.filter_map (fun p ->
      if p.p_optional then begin
        let taken = p.p_group > 0 && List.mem p.p_group !used_groups in
        let conditional =
          List.filter (fun (q : param) -> q.p_ty = p.p_ty && q.p_switch = p.p_switch && p.p_mode = In) sc.optionals in
        if taken && List.mem p.p_group !conditional_groups && conditional <> [] && chance rs 0.3 then
          (* two alternatives, each conditional: allowed by the static semantics, and
             ERR_ARGDUPCND when both are present (§3.11, ch. 12) *)
          Some (`Optional (Printf.sprintf "\\%s?%s" p.p_name (pick rs conditional).p_name))
        else if taken || chance rs 0.5 then None
        else begin
          if p.p_group > 0 then used_groups := p.p_group :: !used_groups;
          let conditional =
            List.filter (fun (q : param) -> q.p_ty = p.p_ty && q.p_switch = p.p_switch && p.p_mode = In) sc.optionals in
          if conditional <> [] && chance rs 0.3 then begin
            if p.p_group > 0 then conditional_groups := p.p_group :: !conditional_groups;
            Some (`Optional (Printf.sprintf "\\%s?%s" p.p_name (pick rs conditional).p_name)) end
          else if p.p_switch then Some (`Optional ("\\" ^ p.p_name))
          else Some (`Optional (Printf.sprintf "\\%s:=%s" p.p_name (argument sc p depth)))
        end
      end
      else Some (`Required (argument sc p depth))) s.params

and argument sc p depth =
  match p.p_mode with
  | In -> expr sc p.p_ty depth
  | Var_mode | Inout ->
      let targets =
        List.filter (fun d -> d.kind = Variable || (p.p_mode = Inout && d.kind = Persistent)) (writable sc p.p_ty) in
      (* an element of the module's array: located by the place rules (argument-reference) *)
      if p.p_ty = Num && chance sc.rs 0.25 then
        Printf.sprintf "%s{%s}" sc.array_ (if chance sc.rs 0.8 then string_of_int (int_in sc.rs 1 5) else "gn1")
      else (match targets with [] -> assert false | l -> (pick sc.rs l).name)

and function_call sc s depth =
  let args = arguments sc s depth in
  let text = List.mapi (fun i a ->
      match a with
      | `Required t -> if i = 0 then t else ", " ^ t
      | `Optional t -> " " ^ t) args in
  Printf.sprintf "%s(%s)" s.r_name (String.trim (String.concat "" text))

(* What needs the controller: waits, signals, interrupts (ch. 8), moves. Both engines run it in
   the same world (doc/semantics.md, "The second engine"), so it is compared as the rest. *)
let controller_statement sc =
  let rs = sc.rs in
  let time () = pick rs [ "0"; "0.05"; "0.1"; "0.3"; "1" ] in
  let target () =
    if chance rs 0.5 then pick rs [ "fzp1"; "fzp2" ]
    else Printf.sprintf "Offs(%s, %d, %d, %d)" (pick rs [ "fzp1"; "fzp2" ])
        (int_in rs (-50) 50) (int_in rs (-50) 50) (int_in rs (-50) 50) in
  pick rs [
    (fun () -> "CONNECT gint WITH fztrap;");
    (fun () ->
        if sc.opts.signal_stores then Printf.sprintf "do1 := %s;" (pick rs [ "1"; "0"; "2"; "gn1" ])
        else Printf.sprintf "SetDO do1, %s;" (pick rs [ "1"; "0" ]));
    (fun () ->
        pick rs ([ "SetDO gsig, 1;"; "TPWrite \"u \" \\Num:=gsig;" ]
                 @ if sc.opts.signal_stores then [ "gsig := 1;" ] else []));
    (fun () -> Printf.sprintf "ITimer \\Single, %s, gint;" (pick rs [ "0.05"; "0.1"; "0.2" ]));
    (fun () -> Printf.sprintf "ITimer %s, gint;" (pick rs [ "0.1"; "0.25" ]));
    (fun () -> pick rs [ "ISleep gint;"; "IWatch gint;"; "IDelete gint;"; "IDisable;"; "IEnable;" ]);
    (fun () ->
        Printf.sprintf "ISignalDI %sdi1, %d, gint;" (if chance rs 0.5 then "\\Single, " else "") (int_in rs 0 1));
    (fun () -> Printf.sprintf "ISignalDO do1, %d, gint;" (int_in rs 0 1));
    (fun () -> Printf.sprintf "WaitTime %s;" (time ()));
    (fun () ->
        Printf.sprintf "WaitUntil %s \\MaxTime:=%s;" (pick rs [ "di1 = 1"; "gb1"; "gn2 > 0" ])
          (pick rs [ "0.1"; "0.5"; "2" ]));
    (fun () -> Printf.sprintf "WaitDI di1, %d%s;" (int_in rs 0 1) (if chance rs 0.7 then " \\MaxTime:=0.5" else ""));
    (fun () -> Printf.sprintf "SetDO do1, %d;" (int_in rs 0 1));
    (fun () -> pick rs [ "Set do1;"; "Reset do1;"; "PulseDO \\PLength:=0.1, do1;" ]);
    (fun () -> Printf.sprintf "TPWrite \"di \" \\Num:=%s;" (pick rs [ "di1"; "DOutput(do1)" ]));
    (fun () ->
        Printf.sprintf "MoveJ %s, v%d, %s, tool0;" (target ()) (pick rs [ 100; 500; 1000 ])
          (pick rs [ "fine"; "z10" ]));
    (fun () ->
        Printf.sprintf "MoveL %s, v%d, %s, tool0;" (target ()) (pick rs [ 100; 500 ])
          (pick rs [ "fine"; "z10"; "z50" ]));
  ] ()

(* Statement sequences that reach rules one statement rarely does. *)
let controller_scenario sc =
  let rs = sc.rs in
  let lines l = List.map (fun s -> Line s) l in
  match Random.State.int rs 3 with
  | 0 ->
      (* an interrupt that is taken: connected, ordered, and waited for *)
      lines [ "CONNECT gint WITH fztrap;"; Printf.sprintf "ITimer \\Single, %s, gint;" (pick rs [ "0.05"; "0.1" ]);
              "WaitTime 0.2;" ]
  | 1 -> lines [ "CONNECT gint WITH fztrap;"; "ISignalDI di1, 1, gint;"; "WaitTime 0.3;" ]
  | _ ->
      (* beyond 100 interrupt numbers in the task: ERR_INOMAX (§4.15) *)
      [ Compound ([ ("FOR k FROM 1 TO 101 DO", lines [ "CONNECT gints{k} WITH fztrap;" ]) ], "ENDFOR") ]

let procedure_arguments sc s =
  let args = arguments sc s 2 in
  let first = ref true in
  String.concat "" (List.map (fun a ->
      let t = match a with
        | `Required t -> if !first then " " ^ t else ", " ^ t
        | `Optional t -> " " ^ t in
      first := false; t) args)

(* A routine can be called only when the caller has a variable for each VAR or INOUT
   parameter. *)
let can_call sc s =
  List.for_all (fun p -> p.p_optional || p.p_mode = In || writable sc p.p_ty <> []) s.params

(* ------------------------------------------------------------------ statements *)

let rec statements sc n =
  List.init (int_in sc.rs 1 (max 1 n)) (fun _ -> statement sc) |> List.concat

and simple sc =
  let rs = sc.rs in
  let procs = List.filter (fun s -> s.result = None && can_call sc s) sc.callable in
  let assignable = List.filter (fun t -> writable sc t <> []) [ Num; Dnum; Bool; Str ] in
  let choices =
    [ (4, fun () ->
          match assignable with
          | [] -> Printf.sprintf "TPWrite %s;" (expr sc Str 2)
          | ts ->
              let t = pick rs ts in
              Printf.sprintf "%s := %s;" (pick rs (writable sc t)).name (expr sc t 3));
      (1, fun () -> Printf.sprintf "%s{%s} := %s;" sc.array_
            (if chance rs 0.85 then string_of_int (int_in rs 1 5)
             else if chance rs 0.5 then Printf.sprintf "Trunc(%s)" (expr sc Num 1)
             else "(gn1 / 2)" (* not an integer when gn1 is odd: ERR_NOTINTVAL (R-3.6) *))
            (expr sc Num 2));
      (1, fun () -> Printf.sprintf "%s.%s := %s;" sc.record_ (pick rs [ "x"; "y" ]) (expr sc Num 2));
      (1, fun () -> Printf.sprintf "%s := [%s, %s];" sc.record_ (expr sc Num 1) (expr sc Num 1));
      (1, fun () -> Printf.sprintf "%s := [%s];" sc.array_ (String.concat ", " (List.init 5 (fun _ -> expr sc Num 1))));
      (1, fun () -> Printf.sprintf "gmat{%d, %s} := %s;" (int_in rs 1 2)
            (if chance rs 0.8 then string_of_int (int_in rs 1 3) else Printf.sprintf "Trunc(%s)" (expr sc Num 1))
            (expr sc Num 2));
      (1, fun () -> Printf.sprintf "TPWrite \"m \" \\Num:=gmat{%d, %d};" (int_in rs 1 2) (int_in rs 1 3));
      (3, fun () -> Printf.sprintf "TPWrite \"n \" \\Num:=%s;" (expr sc Num 3));
      (1, fun () -> Printf.sprintf "TPWrite \"d \" \\Dnum:=%s;" (expr sc Dnum 2));
      (1, fun () -> Printf.sprintf "TPWrite \"b \" \\Bool:=%s;" (expr sc Bool 2));
      (1, fun () -> Printf.sprintf "TPWrite \"p \" \\Pos:=%s;" (expr sc Pos 2));
      (1, fun () -> Printf.sprintf "TPWrite \"o \" \\Orient:=%s;" (expr sc Orient 2));
      (1, fun () ->
          match Random.State.int rs 4 with
          | 0 -> Printf.sprintf "gpos1 := [%s, %s, %s];" (expr sc Num 1) (expr sc Num 1) (expr sc Num 1)
          | 1 -> Printf.sprintf "%s := %s;" (pick rs [ "gpos1"; "gpos2" ]) (expr sc Pos 2)
          | 2 -> Printf.sprintf "gpos1.%s := %s;" (pick rs [ "x"; "y"; "z" ]) (expr sc Num 2)
          | _ -> if chance rs 0.5 then Printf.sprintf "gor1 := %s;" (expr sc Orient 2)
                 else Printf.sprintf "gor1 := [%s, 0, 0, %s];" (expr sc Num 1) (expr sc Num 1));
      (2, fun () -> Printf.sprintf "TPWrite %s;" (expr sc Str 2));
      (1, fun () ->
          Printf.sprintf "Incr %s;" (match writable sc Num with [] -> sc.array_ ^ "{1}" | l -> (pick rs l).name)) ]
    @ (if procs <> [] then
         [ (3, fun () -> let s = pick rs procs in Printf.sprintf "%s%s;" s.r_name (procedure_arguments sc s));
           (1, fun () ->
               let s = pick rs procs in
               let name = if chance rs 0.5 then Printf.sprintf "\"%s\"" s.r_name
                 else Printf.sprintf "\"%s\" + \"%s\"" (String.sub s.r_name 0 1)
                     (String.sub s.r_name 1 (String.length s.r_name - 1)) in
               Printf.sprintf "%% %s %%%s;" name (procedure_arguments sc s)) ]
       else [])
    @ (if sc.opts.mismatching && procs <> [] then
         [ (1, fun () ->
               let s = pick rs procs in
               Printf.sprintf "%% \"%s\" %%%s;" s.r_name
                 (pick rs [ " 1, 2, 3, 4, 5"; " \"text\""; " \\nosuch:=1"; "" ])) ]
       else [])
    @ (let parameterless =
         List.filter (fun s -> s.result = None && (s.params = [] || sc.opts.mismatching)) sc.callable in
       if parameterless <> [] then
         [ (1, fun () ->
               (* CallByVar "p", n calls the procedure p<n> (ch. 13). *)
               let s = pick rs parameterless in
               let digits = String.sub s.r_name 1 (String.length s.r_name - 1) in
               Printf.sprintf "CallByVar \"p\", %s;"
                 (if chance rs 0.8 then digits else string_of_int (int_in rs 0 9))) ]
       else [])
    @ (match sc.optionals with
       | [] -> []
       | l -> [ (1, fun () ->
             (* Using an absent optional parameter's value is ERR_NOTPRES (§5.2). *)
             let p = pick rs l in
             Printf.sprintf "TPWrite \"opt \" \\%s:=%s;"
               (match p.p_ty with
                | Num -> "Num" | Dnum -> "Dnum" | Bool -> "Bool" | Str -> "Num" | Pos -> "Pos" | Orient -> "Orient")
               (if p.p_ty = Str then Printf.sprintf "StrLen(%s)" p.p_name else p.p_name)) ])
    @ (if sc.controller then [ (3, fun () -> controller_statement sc) ] else [])
    @ [ (1, fun () ->
          (* an aggregate argument of a late-bound call takes its parameter's type when its
             structure fits (§3.10, §4.6), else the call raises ERR_CALLPROC *)
          let e () = expr sc Num 1 in
          match Random.State.int rs 4 with
          | 0 | 1 -> Printf.sprintf "%% \"fzrec\" %% [%s, %s];" (e ()) (e ())
          | 2 -> Printf.sprintf "%% \"fzrec\" %% [%s, %s, %s];" (e ()) (e ()) (e ())
          | _ -> Printf.sprintf "%% \"fzrec\" %% [%s, %s];" (expr sc Str 1) (e ())) ]
    @ [ (1, fun () -> Printf.sprintf "RAISE %d;" (int_in rs 1 90));
        (1, fun () -> Printf.sprintf "RAISE Trunc(%s);" (expr sc Num 1));
        (1, fun () -> Printf.sprintf "%% \"nosuch%d\" %%;" (int_in rs 1 9));
        (* a placeholder (§2.9) passes the static semantics and raises ERR_EXECPHR when run *)
        (1, fun () -> if chance rs 0.2 then "<SMT>" else "Incr gn2;") ]
  in
  QCheck.Gen.frequency (List.map (fun (w, f) -> (w, fun _ -> f ())) choices) rs

and statement sc : stmt list =
  let rs = sc.rs in
  let inner = { sc with depth = sc.depth + 1 } in
  let block sc = statements sc (sc.opts.max_statements - sc.depth) in
  let compound =
    if sc.depth >= 3 then []
    else
      [ (2, fun () ->
            let elseifs = List.init (int_in rs 0 2) (fun _ ->
                (Printf.sprintf "ELSEIF %s THEN" (expr sc Bool 2), block inner)) in
            let else_ = if chance rs 0.5 then [ ("ELSE", block inner) ] else [] in
            [ Compound ((Printf.sprintf "IF %s THEN" (expr sc Bool 2), block inner) :: elseifs @ else_, "ENDIF") ]);
        (1, fun () -> [ Line (Printf.sprintf "IF %s %s" (expr sc Bool 2) (simple sc)) ]);
        (2, fun () ->
            incr sc.loop_vars;
            let v = Printf.sprintf "i%d" !(sc.loop_vars) in
            let body_scope = { inner with in_loop = true;
                                          data = { name = v; ty = Num; kind = Readonly } :: inner.data } in
            let step = if chance rs 0.3 then Printf.sprintf " STEP %s" (pick rs [ "2"; "-1"; "0.5"; "-2" ]) else "" in
            [ Compound ([ (Printf.sprintf "FOR %s FROM %d TO %d%s DO" v (int_in rs (-1) 3) (int_in rs (-1) 4) step,
                           block body_scope) ], "ENDFOR") ]);
        (1, fun () ->
            let c = Printf.sprintf "w%d" (List.length !(sc.counters) + 1) in
            sc.counters := c :: !(sc.counters);
            let body = block { inner with in_loop = true } in
            [ Line (Printf.sprintf "%s := 0;" c);
              Compound ([ (Printf.sprintf "WHILE %s < %d AND %s DO" c (int_in rs 1 3) (expr sc Bool 1),
                           Line (Printf.sprintf "%s := %s + 1;" c c) :: body) ], "ENDWHILE") ]);
        (1, fun () ->
            let values = List.init (int_in rs 1 3) (fun _ -> string_of_int (int_in rs 0 5)) in
            let cases = List.map (fun v -> (Printf.sprintf "CASE %s:" v, block inner)) values in
            let default = if chance rs 0.5 then [ ("DEFAULT:", block inner) ] else [] in
            [ Compound ((Printf.sprintf "TEST %s" (expr sc Num 2), []) :: cases @ default, "ENDTEST") ]) ]
  in
  let control =
    (if sc.in_loop then [ (1, fun () -> [ Line (pick rs [ "BREAK;"; "CONTINUE;" ]) ]) ] else [])
    @ [ (1, fun () ->
            let l = Printf.sprintf "lab%d" (List.length !(sc.labels) + 1) in
            sc.labels := l :: !(sc.labels);
            [ Line (Printf.sprintf "GOTO %s;" l) ]) ]
    @ (if sc.controller then [ (1, fun () -> controller_scenario sc) ] else [])
    @ (match sc.in_function with
       | Some t -> [ (1, fun () -> [ Line (Printf.sprintf "RETURN %s;" (expr sc t 2)) ]) ]
       | None -> [ (1, fun () -> [ Line "RETURN;" ]) ])
    @ [ (1, fun () -> if chance rs 0.2 then [ Line (pick rs [ "EXIT;"; "Stop;" ]) ] else [ Line (simple sc) ]) ]
  in
  QCheck.Gen.frequency
    (List.map (fun (w, f) -> (w, fun _ -> f ())) ((10, fun () -> [ Line (simple sc) ]) :: compound @ control)) rs

(* ------------------------------------------------------------------ routines *)

let handler sc =
  let rs = sc.rs in
  let ending =
    match sc.in_function with
    | Some t -> pick rs [ "RETRY;"; "TRYNEXT;"; "RAISE;"; Printf.sprintf "RETURN %s;" (expr sc t 1); "" ]
    | None -> pick rs [ "RETRY;"; "TRYNEXT;"; "RAISE;"; "RETURN;"; ""; "TRYNEXT;" ]
  in
  let body = [ Line "TPWrite \"handler \" \\Num:=ERRNO;" ] @ (if ending = "" then [] else [ Line ending ]) in
  let header =
    if chance rs 0.25 then pick rs [ "ERROR (LONG_JMP_ALL_ERR)"; "ERROR (ERR_DIVZERO, ERR_OUTOFBND)"; "ERROR (7)" ]
    else "ERROR" in
  (header, body)

let gen_params rs sc_data =
  let n = int_in rs 0 4 in
  let group = ref 0 in
  List.concat (List.init n (fun i ->
      let ty = pick rs [ Num; Num; Bool; Str; Dnum ] in
      let name = Printf.sprintf "a%d" (i + 1) in
      let has_var = List.exists (fun d -> d.ty = ty && d.kind = Variable) sc_data in
      match Random.State.int rs 5 with
      | 0 when has_var ->
          [ { p_name = name; p_ty = ty; p_mode = Var_mode; p_optional = false; p_switch = false; p_group = 0 } ]
      | 1 when has_var ->
          [ { p_name = name; p_ty = ty; p_mode = Inout; p_optional = false; p_switch = false; p_group = 0 } ]
      | 2 -> [ { p_name = name; p_ty = ty; p_mode = In; p_optional = true; p_switch = false; p_group = 0 } ]
      | 3 when chance rs 0.5 ->
          [ { p_name = name; p_ty = Num; p_mode = In; p_optional = true; p_switch = true; p_group = 0 } ]
      | 3 ->
          incr group;
          [ { p_name = name ^ "x"; p_ty = ty; p_mode = In; p_optional = true; p_switch = false; p_group = !group };
            { p_name = name ^ "y"; p_ty = Num; p_mode = In; p_optional = true; p_switch = false; p_group = !group } ]
      | _ -> [ { p_name = name; p_ty = ty; p_mode = In; p_optional = false; p_switch = false; p_group = 0 } ]))

let param_text params =
  let rec go first = function
    | [] -> []
    | p :: q :: rest when p.p_group > 0 && p.p_group = q.p_group ->
        let one p = Printf.sprintf "%s %s" (type_name p.p_ty) p.p_name in
        ((if first then "\\" else ", \\") ^ one p ^ " | " ^ one q) :: go false rest
    | p :: rest ->
        let mode = match p.p_mode with In -> "" | Var_mode -> "VAR " | Inout -> "INOUT " in
        let text =
          if p.p_switch then "\\switch " ^ p.p_name
          else Printf.sprintf "%s%s%s %s" (if p.p_optional then "\\" else "") mode (type_name p.p_ty) p.p_name in
        ((if first then "" else ", ") ^ text) :: go false rest
  in
  String.concat "" (go true params)

let routine rs opts ~controller ~module_data ~callable ~name ~result ~params =
  let params_data = List.filter_map (fun p ->
      if p.p_optional || p.p_switch then None
      else Some { name = p.p_name; ty = p.p_ty; kind = (match p.p_mode with In -> Readonly | _ -> Variable) }) params in
  let locals = List.init (int_in rs 0 2) (fun i ->
      { name = Printf.sprintf "%s_l%d" name (i + 1); ty = pick rs [ Num; Bool; Str ]; kind = Variable }) in
  let initial = List.map (fun d ->
      if chance rs 0.5 then ""
      else match d.ty with
        | Num -> " := " ^ string_of_int (int_in rs 0 9) | Bool -> " := TRUE" | _ -> " := \"i\"") locals in
  let sc = {
    rs; opts; data = params_data @ locals @ module_data; array_ = "garr"; record_ = "gpt"; callable;
    optionals = List.filter (fun p -> p.p_optional && not p.p_switch) params;
    depth = 0; in_loop = false; in_function = result; controller; counters = ref []; loop_vars = ref 0; labels = ref [];
  } in
  let body = statements sc opts.max_statements in
  let body = match result with
    | Some t -> body @ [ Line (Printf.sprintf "RETURN %s;" (expr sc t 2)) ]
    | None -> body in
  let labels = List.rev_map (fun l -> Line (l ^ ":")) !(sc.labels) in
  let error = if chance rs 0.6 then Some (handler sc) else None in
  let undo = if chance rs 0.3 then Some [ Line (Printf.sprintf "TPWrite \"undo %s\";" name) ] else None in
  let data =
    List.map2 (fun d init -> Printf.sprintf "VAR %s %s%s;" (type_name d.ty) d.name init) locals initial
    @ List.rev_map (fun c -> Printf.sprintf "VAR num %s;" c) !(sc.counters) in
  let header, footer =
    match result with
    | Some t -> (Printf.sprintf "FUNC %s %s(%s)" (type_name t) name (param_text params), "ENDFUNC")
    | None -> (Printf.sprintf "PROC %s(%s)" name (param_text params), "ENDPROC")
  in
  (* Labels stand at the end of the body, where every GOTO of the routine can reach them
     (§4.7: a label in the same or an enclosing statement list). *)
  { header; data; body = body @ labels; error; undo; footer },
  { r_name = name; result; params }

let module_data_decls = [
  "VAR num gn1 := 1;"; "VAR num gn2;"; "VAR dnum gd1 := 2;"; "VAR bool gb1 := TRUE;";
  "VAR string gs1 := \"s\";"; "PERS num gp1 := 3;"; "CONST num gc1 := 4;";
  "VAR num garr{5} := [1, 2, 3, 4, 5];"; "VAR num gmat{2, 3};"; "VAR fzpoint gpt := [1, 2];"; "VAR intnum gint;";
  "VAR pos gpos1 := [1, 2, 3];"; "PERS pos gpos2 := [0, 1, 0.5];";
  "VAR intnum gints{101};"; "VAR signaldo gsig;" (* a signal variable connected to no signal *);
  "VAR orient gor1 := [1, 0, 0, 0];"; "CONST orient gor2 := [0.7071068, 0.7071068, 0, 0];";
  "CONST robtarget fzp1 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];";
  "VAR robtarget fzp2 := [[250, -250, 350], [0, 0, 1, 0], [-1, 0, -1, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];";
]

let module_data_objects = [
  { name = "gn1"; ty = Num; kind = Variable }; { name = "gn2"; ty = Num; kind = Variable };
  { name = "gd1"; ty = Dnum; kind = Variable }; { name = "gb1"; ty = Bool; kind = Variable };
  { name = "gs1"; ty = Str; kind = Variable }; { name = "gp1"; ty = Num; kind = Persistent };
  { name = "gc1"; ty = Num; kind = Constant };
  { name = "gpos1"; ty = Pos; kind = Variable }; { name = "gpos2"; ty = Pos; kind = Persistent };
  { name = "gor1"; ty = Orient; kind = Variable }; { name = "gor2"; ty = Orient; kind = Constant };
]

let generate ?(options = default_options) rs =
  let controller = options.controller && chance rs 0.3 in
  let n = int_in rs 0 options.max_routines in
  let rec build i callable acc =
    if i > n then (List.rev acc, callable)
    else
      let result = if chance rs 0.5 then Some (pick rs [ Num; Num; Bool; Str; Dnum ]) else None in
      let name = Printf.sprintf "%s%d" (match result with Some _ -> "f" | None -> "p") i in
      let params = gen_params rs module_data_objects in
      let r, s = routine rs options ~controller ~module_data:module_data_objects ~callable ~name ~result ~params in
      build (i + 1) (callable @ [ s ]) (r :: acc)
  in
  let routines, callable = build 1 [] [] in
  let main, _ =
    routine rs options ~controller ~module_data:module_data_objects ~callable ~name:"main" ~result:None ~params:[] in
  let main =
    if chance rs 0.2 then
      { main with body = Line "CONNECT gint WITH fztrap;" :: main.body }
    else main in
  let trap_body =
    Line "TPWrite \"trap \" \\Num:=INTNO;"
    :: (if controller then
          Line "Incr gn2;"
          (* an error leaving a trap goes to the system error handler (R-8-e) *)
          :: (if chance rs 0.2 then [ Line "IF gn2 > 1 RAISE 7;" ] else [])
        else []) in
  let trap = { header = "TRAP fztrap"; data = []; body = trap_body; error = None; undo = None;
               footer = "ENDTRAP" } in
  (* the target of late-bound calls with an aggregate argument *)
  let fzrec = { header = "PROC fzrec(fzpoint r)"; data = []; body = [ Line "TPWrite \"r \" \\Num:=r.x + r.y;" ];
                error = None; undo = None; footer = "ENDPROC" } in
  { name = "fuzz"; module_data = "RECORD fzpoint num x; num y; ENDRECORD" :: module_data_decls;
    routines = routines @ [ fzrec; trap; main ] }

(* ------------------------------------------------------------------ text *)

let to_source (p : program) =
  let b = Buffer.create 4096 in
  let line indent s = Buffer.add_string b (String.make indent ' '); Buffer.add_string b s; Buffer.add_char b '\n' in
  let rec stmts indent l = List.iter (stmt indent) l
  and stmt indent = function
    | Line s -> line indent s
    | Compound (parts, close) ->
        List.iter (fun (h, body) -> line indent h; stmts (indent + 2) body) parts;
        line indent close
  in
  line 0 ("MODULE " ^ p.name);
  List.iter (line 2) p.module_data;
  List.iter (fun (r : routine) ->
      line 2 r.header;
      List.iter (line 4) r.data;
      stmts 4 r.body;
      (match r.error with Some (h, body) -> line 2 h; stmts 4 body | None -> ());
      (match r.undo with Some body -> line 2 "UNDO"; stmts 4 body | None -> ());
      line 2 r.footer) p.routines;
  line 0 "ENDMODULE";
  Buffer.contents b

let rec count l = List.fold_left (fun n s -> n + match s with
    | Line _ -> 1
    | Compound (parts, _) -> 1 + List.fold_left (fun n (_, b) -> n + count b) 0 parts) 0 l

let size (p : program) = List.fold_left (fun n (r : routine) -> n + count r.body) 0 p.routines

(* Every way of making one statement list smaller by one step. *)
let rec shrink_list (l : stmt list) : stmt list Seq.t =
  match l with
  | [] -> Seq.empty
  | s :: rest ->
      let without = Seq.return rest in
      let flattened = match s with
        | Compound (parts, _) -> List.to_seq (List.map (fun (_, b) -> b @ rest) parts)
        | Line _ -> Seq.empty in
      let inside = match s with
        | Compound (parts, close) ->
            List.mapi (fun i (h, body) -> Seq.map (fun body' ->
                Compound (List.mapi (fun j part -> if i = j then (h, body') else part) parts, close) :: rest)
                (shrink_list body)) parts
            |> List.to_seq |> Seq.flat_map (fun x -> x)
        | Line _ -> Seq.empty in
      let later = Seq.map (fun rest' -> s :: rest') (shrink_list rest) in
      Seq.append without (Seq.append flattened (Seq.append inside later))

let shrink (p : program) =
  let without i l = List.filteri (fun j _ -> j <> i) l in
  (* Whole routines first (not main: the entry routine), then module data, then routine data:
     a candidate whose names no longer resolve is refused by the checker, and skipped by the
     caller. *)
  let routines = List.to_seq (List.filter_map (fun (i, (r : routine)) ->
      if r.header = "PROC main()" then None else Some { p with routines = without i p.routines })
      (List.mapi (fun i r -> (i, r)) p.routines)) in
  let module_data = Seq.map (fun i -> { p with module_data = without i p.module_data })
      (List.to_seq (List.init (List.length p.module_data) (fun i -> i))) in
  let per_routine = List.mapi (fun i (r : routine) ->
      let with_routine r' = { p with routines = List.mapi (fun j x -> if i = j then r' else x) p.routines } in
      let bodies = Seq.map (fun body -> with_routine { r with body }) (shrink_list r.body) in
      let no_error =
        match r.error with Some _ -> Seq.return (with_routine { r with error = None }) | None -> Seq.empty in
      let no_undo = match r.undo with Some _ -> Seq.return (with_routine { r with undo = None }) | None -> Seq.empty in
      let data = Seq.map (fun k -> with_routine { r with data = without k r.data })
          (List.to_seq (List.init (List.length r.data) (fun k -> k))) in
      Seq.append no_error (Seq.append no_undo (Seq.append bodies data))) p.routines
    |> List.to_seq |> Seq.flat_map (fun x -> x) in
  Seq.append routines (Seq.append module_data per_routine)
