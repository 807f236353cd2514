type t = { max_call_depth : int; retry_limit : int; max_memory : int }

let default = { max_call_depth = 10_000; retry_limit = 4; max_memory = 256 * 1024 * 1024 }

let memory_exhausted_by limits what at =
  Outcome.Resource_exhausted
    (Printf.sprintf "%s: %s goes beyond the memory budget of %d bytes for RAPID data (--max-memory)"
       (Rapid_syntax.Source.to_string at) what limits.max_memory, Some at)

let call_depth_exceeded limits =
  Outcome.Resource_exhausted
    (Printf.sprintf "call depth beyond %d (resource exhaustion, §1.4; --max-call-depth)" limits.max_call_depth, None)

let move_owners = 64

(* A controller runs a bounded number of tasks (R-14-cli3); each task's RAPID data counts in the
   one budget of --max-memory, split evenly so that every task has its share whatever the others
   do and whatever the turns: N tasks never hold more than the budget together. *)
let for_tasks limits ~count = { limits with max_memory = limits.max_memory / max 1 count }
