type t =
  | Value of Value.t
  | Location of Value.t array * int * Ir.reference_kind
  | Switch
  | Missing
