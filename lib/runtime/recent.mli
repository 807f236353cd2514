(** The last [n] pairs added, newest first, in a ring: adding one allocates nothing and costs
    the same however many were added before (the moves' owners, §7.4, both engines). *)

type ('k, 'v) t

val create : int -> ('k, 'v) t
(** Keeps the last [n] pairs ([n] at least 1). *)

val add : ('k, 'v) t -> 'k -> 'v -> unit

val find_opt : ('k, 'v) t -> 'k -> 'v option
(** The value of the newest pair kept with this key ([=]), as [List.assoc_opt] on the list of
    the pairs kept, newest first. *)
