(** The native stack the closure engine recurses on ({!Closure_engine}): a budget, in units of
    routine nesting, that ends a run as resource exhaustion before the stack overflows
    (doc/semantics.md, "The second engine"; bench/README.md, "The closure engine"). *)

val routine_nest : Ir.routine -> int
(** The depth of the routine's syntax tree (statements, lists and expressions), plus its error
    and UNDO handlers, which run on top of the body: how deep one activation nests. *)

val native_stack_bytes : unit -> int
(** The soft limit of the native stack (Linux: /proc/self/limits), 8 MB when it cannot be read,
    1 GB when it is unlimited. *)

val bytes_per_nest : int
(** Native stack bytes budgeted per unit of nesting: 26, twice the 11 to 13 measured. *)

val budget : unit -> int
(** [native_stack_bytes () / bytes_per_nest], read the first time it is asked in the process. *)
