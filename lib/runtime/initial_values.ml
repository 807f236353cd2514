(* Initial values, computed before the run with the machine's operators (§3.2, §3.3). *)

open Rapid_syntax
module V = Value
module R = Rapid_typing.Report

(* What evaluating an initial value gives: a value; [Unknown] when only the run can tell (a
   placeholder, an unknown name allowed by --allow-unknown, a function call, which a constant
   expression cannot hold anyway); [Failed] when an error was reported for it, here or in a
   constant it uses. *)
type outcome = Known of V.t | Unknown | Failed

type ctx = {
  program : Ir.program;
  mutable reports : R.t list;
  global_values : outcome option array;   (* None: not computed yet *)
}

let report ctx ~rule ~sections region message =
  ctx.reports <- { R.severity = Error; rule; sections; region; message; hint = None } :: ctx.reports

(* Ch. 12's meaning of each execution error an initial value can raise. *)
let describe = function
  | "ERR_DIVZERO" -> "division by zero"
  | "ERR_OVERFLOW" -> "a result beyond the range of its type"
  | "ERR_NOTINTVAL" -> "a value that is not an integer where an integer is required"
  | "ERR_MAXINTVAL" -> "an integer beyond the exact integer range of its type"
  | "ERR_STRTOOLNG" -> "a string longer than 80 characters"
  | "ERR_OUTOFBND" -> "an index outside the array's dimension"
  | "ERR_NOTEQDIM" -> "arrays of different dimensions"
  | _ -> "an execution error"

(* R-3.2-a: an initial value is a constant expression; an execution error of one of its
   operations is known before the run, and is a static error at that operation. *)
let execution_error ctx ~section (at : Source.region) name =
  report ctx ~rule:"constant-value" ~sections:[ "3.2"; section ] at
    (Printf.sprintf "this constant expression raises %s (%s) when it is evaluated: the initial \
                     value of data is known before the program runs" name (describe name))

(* R-2.5-c: a numeric literal that is a num must lie within single precision's range. *)
let literal_out_of_range ctx (at : Source.region) =
  report ctx ~rule:"literal-range" ~sections:[ "2.5"; "2.13" ] at
    "this numeric literal is a num here, and beyond the range of num (IEEE 754 single \
     precision, largest finite value about 3.40282347E+38)"

let integer_index f =
  if Float.is_integer f && Float.abs f < 1e9 then Some (int_of_float f) else None

(* The value of an expression of an initial value; [local] gives the value of a routine data
   slot initialised before this one. *)
let rec eval ctx ~local (e : Ir.expr) : outcome =
  match e.e with
  | Literal (V.Num x) when not (Float.is_finite x) -> Failed   (* reported by [literals] *)
  | Literal v -> Known v
  | Read p -> read ctx ~local p
  | Read_signal _ | Call _ | Placeholder | Fitted _ -> Unknown
  | Unary (op, a) -> (
      match eval ctx ~local a with
      | Known v -> (
          match Arith.unary op v with
          | Ok r -> Known r
          | Error name -> execution_error ctx ~section:"3.12" e.at name; Failed)
      | other -> other)
  | Binary (op, a, b) -> (
      match eval ctx ~local a, eval ctx ~local b with
      | Known x, Known y -> (
          match Arith.binary op x y with
          | Ok r -> Known r
          | Error name -> execution_error ctx ~section:"3.12" e.at name; Failed)
      | Failed, _ | _, Failed -> Failed
      | _ -> Unknown)
  | And (a, b) | Or (a, b) -> (
      let is_and = match e.e with And _ -> true | _ -> false in
      match eval ctx ~local a with
      | Known (V.Bool x) when x <> is_and -> Known (V.Bool x)
      | Known (V.Bool _) -> eval ctx ~local b
      | Known _ -> Unknown
      | other ->
          (* The right operand is looked at for its own errors all the same. *)
          (match eval ctx ~local b with Failed -> Failed | _ -> other))
  | Aggregate (es, kind) ->
      let outcomes = Array.map (eval ctx ~local) es in
      if Array.exists (fun o -> o = Failed) outcomes then Failed
      else if Array.for_all (function Known _ -> true | _ -> false) outcomes then
        let vs = Array.map (function Known v -> v | _ -> V.Bool false) outcomes in
        Known (match kind with Record_value -> V.Record vs | Array_value -> V.Array vs)
      else Unknown

and read ctx ~local (p : Ir.place) : outcome =
  match p with
  | Unresolved _ -> Unknown
  | Whole (Global i) -> global ctx i
  | Whole (Local i) -> local i
  | Component (inner, k) -> (
      match read ctx ~local inner with
      | Known (V.Record cs) when k < Array.length cs -> Known cs.(k)
      | Known _ -> Unknown
      | other -> other)
  | Element (inner, indexes) -> (
      let base = read ctx ~local inner in
      let idx = Array.map (eval ctx ~local) indexes in
      if base = Failed || Array.exists (fun o -> o = Failed) idx then Failed
      else
        (* §3.6: each index an integer within its dimension (R-3.6: ERR_NOTINTVAL). *)
        let rec at_index v i =
          if i >= Array.length idx then Known v
          else
            match v, idx.(i) with
            | V.Array elems, Known (V.Num f | V.Dnum f) -> (
                match integer_index f with
                | None when not (Float.is_integer f) ->
                    execution_error ctx ~section:"3.6" indexes.(i).at "ERR_NOTINTVAL"; Failed
                | Some k when k >= 1 && k <= Array.length elems -> at_index elems.(k - 1) (i + 1)
                | _ -> execution_error ctx ~section:"3.6" indexes.(i).at "ERR_OUTOFBND"; Failed)
            | _ -> Unknown
        in
        match base with Known v -> at_index v 0 | _ -> Unknown)

(* Module data is evaluated in dependency order beforehand ([order]): a global read here has
   its value already, or none (a variable without initial value is not read by a constant
   expression). *)
and global ctx i =
  match ctx.global_values.(i) with
  | Some o -> o
  | None -> (
      match ctx.program.globals.(i).g_init with
      | Init_default _ -> Unknown  (* not a constant: no constant expression reads it (§3.2) *)
      | Init_expr _ -> Unknown)

(* The globals an initial value reads, with the region of each reading, in source order. *)
let rec reads_of_expr acc (e : Ir.expr) =
  match e.e with
  | Literal _ | Call _ | Placeholder -> acc
  | Read p | Read_signal p -> reads_of_place acc e.at p
  | Unary (_, a) -> reads_of_expr acc a
  | Binary (_, a, b) | And (a, b) | Or (a, b) -> reads_of_expr (reads_of_expr acc a) b
  | Aggregate (es, _) -> Array.fold_left reads_of_expr acc es
  | Fitted (a, _) -> reads_of_expr acc a

and reads_of_place acc at (p : Ir.place) =
  match p with
  | Whole (Global i) -> (i, at) :: acc
  | Whole (Local _) | Unresolved _ -> acc
  | Component (inner, _) -> reads_of_place acc at inner
  | Element (inner, idx) -> Array.fold_left reads_of_expr (reads_of_place acc at inner) idx

(* R-3.2-b: module data in an order where each initial value comes after the constants it
   reads (a depth-first search with an explicit stack: a chain of constants may be long). A
   reading that closes a cycle is reported, and the value that reads it fails. *)
let module_data ctx ~known =
  let n = Array.length ctx.program.globals in
  let state = Array.init n (fun i -> if i < known then `Black else `White) in
  let reads i =
    match ctx.program.globals.(i).g_init with
    | Init_expr e -> List.rev (reads_of_expr [] e)
    | Init_default _ -> []
  in
  let cyclic = Array.make n false in
  let finish i =
    state.(i) <- `Black;
    ctx.global_values.(i) <-
      Some
        (match ctx.program.globals.(i).g_init with
         | Init_default _ -> Unknown  (* not a constant: no constant expression reads it (§3.2) *)
         | Init_expr _ when cyclic.(i) -> Failed
         | Init_expr e -> eval ctx ~local:(fun _ -> Unknown) e)
  in
  for root = 0 to n - 1 do
    if state.(root) = `White then begin
      state.(root) <- `Grey;
      let stack = ref [ (root, ref (reads root)) ] in
      while !stack <> [] do
        match !stack with
        | [] -> ()
        | (i, pending) :: outer -> (
            match !pending with
            | [] -> finish i; stack := outer
            | (j, at) :: more -> (
                pending := more;
                match state.(j) with
                | `White -> state.(j) <- `Grey; stack := (j, ref (reads j)) :: !stack
                | `Grey ->
                    cyclic.(i) <- true;
                    report ctx ~rule:"constant-cycle" ~sections:[ "3.2"; "2.24" ] at
                      (Printf.sprintf "the value of %s depends on itself: a constant expression \
                                       must be known before the program runs"
                         ctx.program.globals.(j).g_name)
                | `Black -> ()))
      done
    end
  done

(* Routine data: initialised in declaration order at each call (§2.21); a constant expression
   reads only module data and the routine's constants declared before. *)
let routine_data ctx (r : Ir.routine) =
  let values = Hashtbl.create 8 in
  List.iter (fun (slot, (init : Ir.init)) ->
      let o = match init with
        | Init_default _ -> Unknown  (* not a constant: no constant expression reads it (§3.2) *)
        | Init_expr e ->
            eval ctx ~local:(fun i -> Option.value (Hashtbl.find_opt values i) ~default:Unknown) e in
      Hashtbl.replace values slot o) r.local_inits

(* Every expression of the program, initial values included, for its numeric literals
   (R-2.5-c). A worklist, not recursion: an ELSEIF chain is a deep nest of IF statements. *)
let literals ctx ~globals_known ~routines_known (program : Ir.program) =
  let work = Stack.create () in
  let rec expr (e : Ir.expr) =
    match e.e with
    | Literal (V.Num x) when not (Float.is_finite x) -> literal_out_of_range ctx e.at
    | Literal _ | Placeholder -> ()
    | Read p | Read_signal p -> place p
    | Unary (_, a) -> expr a
    | Binary (_, a, b) | And (a, b) | Or (a, b) -> expr a; expr b
    | Aggregate (es, _) -> Array.iter expr es
    | Fitted (a, _) -> expr a
    | Call c -> call c
  and place (p : Ir.place) =
    match p with
    | Whole _ | Unresolved _ -> ()
    | Element (inner, idx) -> place inner; Array.iter expr idx
    | Component (inner, _) -> place inner
  and call (c : Ir.call) =
    Array.iter (function
        | Ir.By_value e -> expr e
        | By_reference (p, _) -> place p
        | Absent | Present_switch | Pass_on _ -> ()) c.arguments
  in
  let block (b : Ir.block) = Stack.push (`Block b) work in
  let statement (s : Ir.stmt) =
    match s.s with
    | Assign (p, e) -> place p; expr e
    | Call_procedure c -> call c
    | Call_late (e, args) ->
        expr e;
        Array.iter (fun (a : Ir.late_argument) ->
            match a.late_value with
            | Late_expr e -> expr e
            | Late_switch | Late_conditional _ -> ()) args
    | Return e | Raise e -> Option.iter expr e
    | Connect (p, _) -> place p
    | If (c, a, b) | Elseif (c, a, b) -> expr c; block a; block b
    | Compact_if (c, s) -> expr c; Stack.push (`Statement s) work
    | For f -> expr f.from_; expr f.to_; Option.iter expr f.step; block f.loop_body
    | While (c, b) -> expr c; block b
    | Test (e, cases, default) ->
        expr e;
        Array.iter (fun (values, b) -> Array.iter expr values; block b) cases;
        block default
    | Goto _ | Break | Continue | Exit | Retry | Trynext | Label | Placeholder_statement -> ()
  in
  let init = function Ir.Init_expr e -> expr e | Init_default _ -> () in
  Array.iteri (fun i (g : Ir.global) -> if i >= globals_known then init g.g_init) program.globals;
  Array.iteri (fun i (r : Ir.routine) -> if i >= routines_known then begin
      List.iter (fun (_, i) -> init i) r.local_inits;
      List.iter (fun b -> block b)
        (r.body :: List.filter_map (fun x -> x)
                     [ r.backward; Option.map (fun (h : Ir.error_handler) -> h.handler) r.error; r.undo ]);
      while not (Stack.is_empty work) do
        match Stack.pop work with
        | `Block (b : Ir.block) -> Array.iter statement b.body
        | `Statement s -> statement s
      done end) program.routines

(* The installed part of a program is the same for every task (Lower shares it), so what is
   computed for it here is kept from the last program that passed: the values of the leading
   globals and the leading routines that are physically those of that program. They are installed
   ones (a task's own are made anew for each task), and installed data and routines read nothing
   of the task, so their values and verdicts are the same. *)
type memo = { m_globals : Ir.global array; m_routines : Ir.routine array; m_values : outcome option array;
              m_evaluated : Ir.global array }

let last : memo option ref = ref None

let common_prefix a b =
  let n = min (Array.length a) (Array.length b) in
  let rec go i = if i < n && a.(i) == b.(i) then go (i + 1) else i in
  go 0

let evaluate (program : Ir.program) =
  let ctx = { program; reports = []; global_values = Array.make (Array.length program.globals) None } in
  let known, routines_known = match !last with
    | None -> (0, 0)
    | Some m ->
        let k = common_prefix m.m_globals program.globals in
        Array.blit m.m_values 0 ctx.global_values 0 k;
        (k, common_prefix m.m_routines program.routines) in
  (* Operands of the wrong type are excluded by the static semantics; were one to come (a name
     allowed by --allow-unknown), its value is left to the run, which reports it. *)
  (try module_data ctx ~known with V.Type_mismatch _ -> ());
  Array.iteri (fun i r -> if i >= routines_known then try routine_data ctx r with V.Type_mismatch _ -> ())
    program.routines;
  literals ctx ~globals_known:known ~routines_known program;
  match ctx.reports with
  | [] ->
      let evaluated_before i = match !last with Some m when i < known -> Some m.m_evaluated.(i) | _ -> None in
      let globals = Array.mapi (fun i (g : Ir.global) ->
          match evaluated_before i with Some e -> e | None ->
          match ctx.global_values.(i) with
          | Some (Known v) -> { g with g_init = Init_expr { e = Literal v; at = g.g_at } }
          | _ -> g) program.globals in
      last := Some { m_globals = program.globals; m_routines = program.routines; m_values = ctx.global_values;
                     m_evaluated = globals };
      Ok { program with globals }
  | reports ->
      let order (r : R.t) =
        let f = match Source.file_of r.region with Some f -> Source.name f | None -> "" in
        (f, Source.start_offset r.region) in
      Error (List.stable_sort (fun a b -> compare (order a) (order b)) (List.rev reports))

type kept = memo

let kept () = !last
let keep m = last := Some m
