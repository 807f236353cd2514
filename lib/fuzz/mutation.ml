module Ir = Rapid_runtime.Ir

type t = Trynext_as_retry | For_skips_last

let all = [ Trynext_as_retry; For_skips_last ]
let name = function Trynext_as_retry -> "trynext-as-retry" | For_skips_last -> "for-skips-last"
let of_string s = List.find_opt (fun m -> name m = s) all

(* The statement, broken; the rewriting goes through every statement list of every routine. *)
let rec stmt m (s : Ir.stmt) : Ir.stmt =
  let desc : Ir.stmt_desc =
    match s.s, m with
    | Trynext, Trynext_as_retry -> Retry
    | For f, For_skips_last ->
        let step = match f.step with
          | Some e -> e
          | None -> { e = Literal (Rapid_runtime.Value.Num 1.); at = f.to_.at } in
        For { f with to_ = { e = Binary (Num_sub, f.to_, step); at = f.to_.at }; loop_body = block m f.loop_body }
    | For f, _ -> For { f with loop_body = block m f.loop_body }
    | If (c, a, b), _ -> If (c, block m a, block m b)
    | Elseif (c, a, b), _ -> Elseif (c, block m a, block m b)
    | Compact_if (c, s'), _ -> Compact_if (c, stmt m s')
    | While (c, b), _ -> While (c, block m b)
    | Test (e, cases, d), _ -> Test (e, Array.map (fun (vs, b) -> (vs, block m b)) cases, block m d)
    | d, _ -> d in
  { s with s = desc }

and block m (b : Ir.block) = { b with body = Array.map (stmt m) b.body }

let apply m (p : Ir.program) =
  let routine (r : Ir.routine) =
    { r with body = block m r.body; backward = Option.map (block m) r.backward;
             error = Option.map (fun (h : Ir.error_handler) -> { h with handler = block m h.handler }) r.error;
             undo = Option.map (block m) r.undo } in
  { p with routines = Array.map routine p.routines }

let engine m (e : Fuzz_run.engine) =
  { Fuzz_run.engine_name = e.engine_name ^ "+" ^ name m; run = (fun p ~max_steps -> e.run (apply m p) ~max_steps) }
