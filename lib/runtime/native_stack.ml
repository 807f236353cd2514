(* How much of the native stack the closure engine's activations take: each activation of a
   routine nests its closures as deep as the routine's syntax tree. *)

open Ir

(* The depth of a routine's syntax tree: how deep its closures nest on the native stack. The
   static semantics bounds it (R-1.4), so these recursions are bounded too. *)
let rec expr_depth (e : Ir.expr) =
  1 + match e.e with
    | Literal _ | Placeholder -> 0
    | Read p | Read_signal p -> place_depth p
    | Unary (_, x) -> expr_depth x
    | Binary (_, x, y) | And (x, y) | Or (x, y) -> Int.max (expr_depth x) (expr_depth y)
    | Aggregate (es, _) -> exprs_depth es
    | Call c -> arguments_depth c.arguments
    | Fitted (x, _) -> expr_depth x
and exprs_depth es = Array.fold_left (fun m e -> Int.max m (expr_depth e)) 0 es
and place_depth = function
  | Whole _ | Unresolved _ -> 1
  | Element (p, es) -> 1 + Int.max (place_depth p) (exprs_depth es)
  | Component (p, _) -> 1 + place_depth p
and arguments_depth args =
  Array.fold_left (fun m -> function
      | By_value e -> Int.max m (expr_depth e)
      | By_reference (p, _) -> Int.max m (place_depth p)
      | Absent | Present_switch | Pass_on _ -> m) 0 args
and stmt_depth (s : stmt) =
  2 + match s.s with
    | Assign (p, e) -> Int.max (place_depth p) (expr_depth e)
    | Call_procedure c -> arguments_depth c.arguments
    | Call_late (e, args) ->
        Array.fold_left (fun m (a : late_argument) -> match a.late_value with
            | Late_expr e -> Int.max m (expr_depth e)
            | Late_switch | Late_conditional _ -> m) (expr_depth e) args
    | Return (Some e) | Raise (Some e) -> expr_depth e
    | Connect (p, _) -> place_depth p
    | If (c, t, e) | Elseif (c, t, e) -> Int.max (expr_depth c) (Int.max (block_depth t) (block_depth e))
    | Compact_if (c, s) -> Int.max (expr_depth c) (stmt_depth s)
    | For f ->
        Int.max (Int.max (expr_depth f.from_) (expr_depth f.to_))
          (Int.max (match f.step with Some e -> expr_depth e | None -> 0) (block_depth f.loop_body))
    | While (c, b) -> Int.max (expr_depth c) (block_depth b)
    | Test (e, cases, d) ->
        Array.fold_left (fun m (vs, b) -> Int.max m (Int.max (exprs_depth vs) (block_depth b)))
          (Int.max (expr_depth e) (block_depth d)) cases
    | Goto _ | Break | Continue | Return None | Raise None | Exit | Retry | Trynext | Label
    | Placeholder_statement -> 0
and block_depth (b : block) = 1 + Array.fold_left (fun m s -> Int.max m (stmt_depth s)) 0 b.body

let routine_nest (r : routine) =
  (* The handler runs on top of the statement that caused the error. *)
  4 + block_depth r.body
  + (match r.error with Some h -> block_depth h.handler | None -> 0)
  + (match r.undo with Some b -> block_depth b | None -> 0)

(* The soft limit of the native stack (Linux: /proc/self/limits), 8 MB when it cannot be read. *)
let native_stack_bytes () =
  let default = 8 * 1024 * 1024 in
  match open_in "/proc/self/limits" with
  | exception Sys_error _ -> default
  | ic ->
      let rec find () =
        match input_line ic with
        | exception End_of_file -> default
        | line when String.length line > 14 && String.sub line 0 14 = "Max stack size" -> (
            match List.filter (( <> ) "") (String.split_on_char ' ' (String.sub line 14 (String.length line - 14))) with
            | "unlimited" :: _ -> 1024 * 1024 * 1024
            | soft :: _ -> Option.value (int_of_string_opt soft) ~default
            | [] -> default)
        | _ -> find ()
      in
      let bytes = find () in
      close_in_noerr ic; bytes

(* Native stack bytes per unit of nesting: 11 to 13 measured where the stack overflows
   (bench/README.md, "The closure engine"), doubled. *)
let bytes_per_nest = 26

(* Read once per process: every run of the closure engine asks (a fuzzer's thousands), and the
   limit of a running process does not change unless it changes it itself, which rapid-sem never
   does. *)
let read_budget = lazy (native_stack_bytes () / bytes_per_nest)

let budget () = Lazy.force read_budget

