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
  | Length of (Value.t -> (Value.t, string) Stdlib.result)

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

(* One array of names per routine (the last routines asked), so that the bodies' look-ups by
   name (Primitive.named_argument) find the index they kept for it; with it the bytes of each
   parameter's default, which the memory budget counts for an absent argument. *)
let names_kept = 8
let kept_parameters : Ir.parameter array array = Array.make names_kept [||]
let kept_names : string array array = Array.make names_kept [||]
let kept_bytes : int array array = Array.make names_kept [||]
let kept_copies : int array array = Array.make names_kept [||]
let next_kept = ref 0

let kept (callee : Ir.routine) =
  let rec find i =
    if i >= names_kept then begin
      let names = Array.map (fun (p : Ir.parameter) -> p.p_name) callee.parameters in
      let bytes = Array.map (fun (p : Ir.parameter) -> Value.shape_bytes p.p_default) callee.parameters in
      let copies = Array.mapi (fun i (p : Ir.parameter) ->
          match p.p_type with
          | Some { base; dims = Scalar | Sized _ }
            when (match base with Rapid_typing.Types.Anytype -> false | _ -> true) && Value.fixed_size p.p_default ->
              bytes.(i)
          | _ -> -1) callee.parameters in
      (* the slot's arrays set with nothing allocated between them: no task's thread sees a
         slot half made *)
      let j = !next_kept in
      kept_names.(j) <- names; kept_bytes.(j) <- bytes; kept_copies.(j) <- copies;
      kept_parameters.(j) <- callee.parameters;
      next_kept := (j + 1) mod names_kept;
      j
    end
    else if kept_parameters.(i) == callee.parameters then i
    else find (i + 1) in
  find 0

let parameter_names (callee : Ir.routine) =
  if Array.length callee.parameters = 0 then [||] else kept_names.(kept callee)

let default_bytes (callee : Ir.routine) =
  if Array.length callee.parameters = 0 then [||] else kept_bytes.(kept callee)

let copy_bytes (callee : Ir.routine) =
  if Array.length callee.parameters = 0 then [||] else kept_copies.(kept callee)

(* The parameters of this name, in order, by the parameters' array and the name (physically,
   the last ones asked): a move asks for its tool's, zone's and target's labels. *)
let label_slots = 16
let label_parameters : Ir.parameter array array = Array.make label_slots [||]
let label_names = Array.make label_slots ""
let label_indices : int list array = Array.make label_slots []

let matching (parameters : Ir.parameter array) name =
  let n = String.length name in
  let h = if n = 0 then 0 else (n * 5 + Char.code (String.unsafe_get name 0)) land (label_slots - 1) in
  if label_parameters.(h) == parameters && label_names.(h) == name then label_indices.(h)
  else begin
    let found = ref [] in
    for i = Array.length parameters - 1 downto 0 do
      if same parameters.(i).p_name name then found := i :: !found
    done;
    label_parameters.(h) <- parameters; label_names.(h) <- name; label_indices.(h) <- !found;
    !found
  end

let has_type_suffix name =
  let n = String.length name and k = String.length type_suffix in
  n > k
  && (let rec from i = i >= k || (name.[n - k + i] = type_suffix.[i] && from (i + 1)) in from 0)

let argument_label (program : Ir.program) (callee : Ir.routine) (arguments : Ir.argument array) name =
  if has_type_suffix name then
    let n = String.length name and k = String.length type_suffix in
    argument_type program callee arguments (String.sub name 0 (n - k))
  else
  let found = ref None in
  List.iter (fun i ->
      if i < Array.length arguments then
        match arguments.(i) with
        | Ir.By_value { e = Read (Whole (Global g)); _ } | By_reference (Whole (Global g), _) ->
            found := Some program.globals.(g).g_name
        | By_value { at; _ } -> (
            match Rapid_syntax.Source.Table.find_opt program.names.argument_texts at with
            | Some text -> found := Some text
            | None -> found := Some (Printf.sprintf "line %d" (Rapid_syntax.Source.start at).line))
        | _ -> ()) (matching callee.parameters name);
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
