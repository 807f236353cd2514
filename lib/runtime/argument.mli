(** An argument of an installed routine as an engine passes it: one per parameter of the
    routine's declaration, in order (alternatives each in their own place). *)

type t =
  | Value of Value.t                                 (** an in parameter *)
  | Location of Value.t array * int * Ir.reference_kind
      (** an alias parameter: the container and index of the argument's location, and what it
          denotes (a variable, a persistent, ...) for IsVar and IsPers *)
  | Switch                                           (** a present switch *)
  | Missing                                          (** an absent optional parameter *)
