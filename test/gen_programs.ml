(* Random RAPID modules that pass the static semantics and end, for the differential test of the
   two engines (test_engines.ml): num data, every statement form but GOTO, calls without
   recursion (a routine calls only routines declared after it), errors that arise by chance
   (division by zero, an index out of bounds, RAISE, a function without RETURN), and error and
   UNDO handlers that end by TRYNEXT, RETRY, RAISE;, RETURN or their end. Loops run at most three
   times, so every program ends well within the budgets. *)

let pick rs l = List.nth l (Random.State.int rs (List.length l))
let chance rs p = Random.State.float rs 1. < p

(* Routine 0 is main; 1 and 2 are procedures, 3 and 4 functions. *)
let routines = [| "main"; "p1"; "p2"; "f3"; "f4" |]
let is_function i = i >= 3

type scope = {
  routine : int;
  loops : string list;          (* loop variables in scope *)
  in_loop : bool;
  depth : int;
}

let globals = [ "x0"; "x1"; "x2"; "x3" ]

(* An expression's text, and whether it is constant: the static semantics evaluates constant
   expressions (§3.2) and refuses DIV of 1/2 or an index out of bounds there, so an operation on
   two constants gets a variable. *)
let rec expr_c rs sc d : string * bool =
  let leaf () =
    match Random.State.int rs 8 with
    | 0 | 5 -> let n = Random.State.int rs 8 - 2 in ((if n < 0 then Printf.sprintf "(%d)" n else string_of_int n), true)
    | 1 when chance rs 0.3 -> ("h", false)
    | 2 when sc.loops <> [] -> (pick rs sc.loops, false)
    | 3 when sc.routine = 2 || sc.routine = 3 -> ("a", false)
    | 4 -> ("l0", false)
    | _ -> (pick rs globals, false)
  in
  if d <= 0 then leaf ()
  else
    match Random.State.int rs 9 with
    | 0 | 1 | 2 -> leaf ()
    | 3 -> (Printf.sprintf "arr{%s + %s}" (pick rs globals) (expr rs sc (d - 1)), false)
    | 4 when sc.routine < 3 -> (Printf.sprintf "f3(%s)" (expr rs sc (d - 1)), false)
    | 5 when sc.routine < 4 -> ("f4()", false)
    | _ ->
        let l, lc = expr_c rs sc (d - 1) and r, rc = expr_c rs sc (d - 1) in
        let l = if lc && rc then Printf.sprintf "(%s + %s)" (pick rs globals) l else l in
        (Printf.sprintf "(%s %s %s)" l (pick rs [ "+"; "+"; "-"; "-"; "*"; "/"; "DIV"; "MOD" ]) r, false)

and expr rs sc d = fst (expr_c rs sc d)

let rec condition rs sc d =
  match Random.State.int rs (if d <= 0 then 1 else 4) with
  | 0 -> Printf.sprintf "%s %s %s" (expr rs sc 1) (pick rs [ "<"; "<="; "="; "<>"; ">"; ">=" ]) (expr rs sc 1)
  | 1 -> Printf.sprintf "(%s) AND (%s)" (condition rs sc (d - 1)) (condition rs sc (d - 1))
  | 2 -> Printf.sprintf "(%s) OR (%s)" (condition rs sc (d - 1)) (condition rs sc (d - 1))
  | _ -> Printf.sprintf "(NOT (%s))" (condition rs sc (d - 1))

let indent n = String.make (2 * n + 4) ' '

let call rs sc =
  let callable = List.filter (fun j -> j > sc.routine && not (is_function j)) [ 1; 2 ] in
  match callable with
  | [] -> None
  | _ -> (
      match pick rs callable with
      | 1 -> Some "p1;"
      | _ -> Some (Printf.sprintf "p2 %s, %s;" (expr rs sc 1) (pick rs globals)))

let rec statement rs sc =
  let i = indent sc.depth in
  let simple () =
    match Random.State.int rs 12 with
    | 0 | 1 | 2 -> Printf.sprintf "%s := %s;" (pick rs ("l0" :: globals)) (expr rs sc 2)
    | 3 -> Printf.sprintf "arr{%s + %s} := %s;" (pick rs globals) (expr rs sc 1) (expr rs sc 1)
    | 4 | 5 -> Printf.sprintf "TPWrite \"%s\" \\Num:=%s;" routines.(sc.routine) (expr rs sc 2)
    | 6 -> Printf.sprintf "Incr %s;" (pick rs globals)
    | 7 -> Printf.sprintf "RAISE %d;" (1 + Random.State.int rs 5)
    | 8 when sc.in_loop -> pick rs [ "BREAK;"; "CONTINUE;" ]
    | 9 when chance rs 0.3 ->
        if is_function sc.routine then Printf.sprintf "RETURN %s;" (expr rs sc 1) else "RETURN;"
    | _ -> ( match call rs sc with Some c -> c | None -> "x0 := x0 + 1;")
  in
  if sc.depth >= 3 then i ^ simple () ^ "\n"
  else
    let inner = { sc with depth = sc.depth + 1 } in
    match Random.State.int rs 10 with
    | 0 ->
        Printf.sprintf "%sIF %s THEN\n%s%sELSE\n%s%sENDIF\n" i (condition rs sc 1) (block rs inner) i
          (block rs inner) i
    | 1 -> Printf.sprintf "%sIF %s %s\n" i (condition rs sc 1) (simple ())
    | 2 ->
        let k = Printf.sprintf "k%d" sc.depth in
        Printf.sprintf "%sFOR %s FROM %d TO %d DO\n%s%sENDFOR\n" i k (Random.State.int rs 3)
          (Random.State.int rs 3) (block rs { inner with loops = k :: sc.loops; in_loop = true }) i
    | 3 ->
        let c = Printf.sprintf "c%d" sc.depth in
        Printf.sprintf "%s%s := 0;\n%sWHILE %s < %d DO\n%s  %s := %s + 1;\n%s%sENDWHILE\n" i c i c
          (1 + Random.State.int rs 3) i c c (block rs { inner with in_loop = true }) i
    | 4 ->
        Printf.sprintf "%sTEST %s\n%sCASE 0, 1:\n%s%sCASE 2:\n%s%sDEFAULT:\n%s%sENDTEST\n" i
          (expr rs sc 1) i (block rs inner) i (block rs inner) i (block rs inner) i
    | _ -> i ^ simple () ^ "\n"

and block rs sc =
  String.concat "" (List.init (1 + Random.State.int rs 3) (fun _ -> statement rs sc))

let handler rs r =
  let sc = { routine = r; loops = []; in_loop = false; depth = 0 } in
  let b = Buffer.create 128 in
  if chance rs (if r = 0 then 0.9 else 0.6) then begin
    Buffer.add_string b "  ERROR\n";
    Buffer.add_string b (Printf.sprintf "    TPWrite \"%s handler \" \\Num:=ERRNO;\n" routines.(r));
    Buffer.add_string b
      (match Random.State.int rs (if r = 0 then 4 else 6) with
       | 0 | 1 | 5 -> "    TRYNEXT;\n"
       | 2 -> "    l0 := l0 + 1;\n    RETRY;\n"
       | 3 when r > 0 -> "    RAISE;\n"
       | 4 -> if is_function r then Printf.sprintf "    RETURN %s;\n" (expr rs sc 1) else "    RETURN;\n"
       | _ -> "")
  end;
  if r > 0 && chance rs 0.4 then
    Buffer.add_string b (Printf.sprintf "  UNDO\n    TPWrite \"%s undo\";\n" routines.(r));
  Buffer.contents b

let routine rs r =
  let header = match r with
    | 0 -> "PROC main()" | 1 -> "PROC p1()" | 2 -> "PROC p2(num a, INOUT num b)"
    | 3 -> "FUNC num f3(num a)" | _ -> "FUNC num f4()" in
  let sc = { routine = r; loops = []; in_loop = false; depth = 0 } in
  let body = block rs sc in
  let body =
    (* Functions mostly return; one that does not raises ERR_FNCNORET (R-5.5). *)
    if is_function r && chance rs 0.85 then body ^ Printf.sprintf "    RETURN %s;\n" (expr rs sc 1)
    else if r = 2 then body ^ "    b := b + 1;\n"
    else body in
  Printf.sprintf "  %s\n    VAR num c0;\n    VAR num c1;\n    VAR num c2;\n    VAR num l0 := 1;\n%s%s  %s\n"
    header body (handler rs r) (if is_function r then "ENDFUNC" else "ENDPROC")

let program rs =
  "MODULE generated\n  VAR num h := 0.5;\n  VAR num x0 := 1;\n  VAR num x1 := 2;\n  VAR num x2;\n  VAR num x3 := -1;\n\
  \  VAR num arr{4} := [1, 2, 3, 4];\n"
  ^ String.concat "" (List.init (Array.length routines) (routine rs))
  ^ "ENDMODULE\n"

let gen : string QCheck.Gen.t = fun rs -> program rs
