type context = {
  parameters : string array;
  argument_label : string -> string option;
  book_error : unit -> int;
  error_number : string -> int;
}

type result =
  | Returned of Value.t option
  | Failed of { error : string; at_move : bool }
  | Call_by_name of string
  | Stop_requested
  | Exit_cycle_requested
  | Not_modelled
  | Wait of { wait : Rapid_observable.Wait.t; first_poll : float option }
  | Retry_requested
  | History_exhausted of string
  | Assertion_failed of string
  | Unanswered of string

type outcome = { result : result; events : Event.t list; new_move : int option }

type reach = Values | World | Moves

type fixed =
  | One of (Value.t -> (Value.t, string) Stdlib.result)
  | Two of (Value.t -> Value.t -> (Value.t, string) Stdlib.result)
  | Three of (Value.t -> Value.t -> Value.t -> (Value.t, string) Stdlib.result)

type entry = {
  name : string;
  reach : reach;
  condition : string option;
  call : context -> Argument.t array -> outcome;
  values : (Value.t option array -> (Value.t, string) Stdlib.result) option;
  fixed : fixed option;
}

let returned v = { result = Returned v; events = []; new_move = None }

let same = Rapid_typing.Types.same_name  (* without lowered copies *)

let type_suffix = ":type"

(* [P:type]: the static type the lowering recorded for the argument of the anytype parameter P
   (Ir.Argument_types). *)
let argument_type (program : Ir.program) (callee : Ir.routine) arguments name =
  match Ir.Argument_types.find_opt program.argument_types arguments with
  | None -> None
  | Some types ->
      let found = ref None in
      Array.iteri (fun i (p : Ir.parameter) ->
          if same p.p_name name && i < Array.length types then found := types.(i)) callee.parameters;
      !found

let argument_label (program : Ir.program) (callee : Ir.routine) (arguments : Ir.argument array) name =
  let n = String.length name and k = String.length type_suffix in
  if n > k && String.sub name (n - k) k = type_suffix then
    argument_type program callee arguments (String.sub name 0 (n - k))
  else
  let found = ref None in
  Array.iteri (fun i (p : Ir.parameter) ->
      if same p.p_name name && i < Array.length arguments then
        match arguments.(i) with
        | Ir.By_value { e = Read (Whole (Global g)); _ } | By_reference (Whole (Global g), _) ->
            found := Some program.globals.(g).g_name
        | By_value { at; _ } -> (
            match Hashtbl.find_opt program.names.argument_texts at with
            | Some text -> found := Some text
            | None -> found := Some (Printf.sprintf "line %d" (Rapid_syntax.Source.start at).line))
        | _ -> ()) callee.parameters;
  !found

let condition_argument entry (callee : Ir.routine) (arguments : Ir.argument array) =
  match entry.condition with
  | None -> None
  | Some name ->
      let found = ref None in
      Array.iteri (fun i (p : Ir.parameter) ->
          if same p.p_name name && i < Array.length arguments then
            match arguments.(i) with Ir.By_value e -> found := Some e | _ -> ()) callee.parameters;
      !found

let stub_value (callee : Ir.routine) = Value.default_of (Option.value callee.stub_result ~default:Value.S_num)
