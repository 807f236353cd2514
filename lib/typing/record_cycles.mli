(** Which nodes of a directed graph lie on a cycle: used for records that contain themselves
    (§2.14). Linear in the nodes and edges, and without recursion, so that a chain of any length
    is safe. *)

val on_cycle : id:('a -> int) -> successors:('a -> int list) -> 'a list -> int -> bool
(** [on_cycle ~id ~successors nodes] is the test "the node of this id lies on a cycle" (a node
    with an edge to itself included). Successor ids that name no node of [nodes] are ignored. *)
