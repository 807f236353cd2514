(* The text of a step for rapid-sem trace: redexes and values in RAPID's syntax, the changes a
   step makes. Everything here runs only when tracing; the machine exposes its focus and top
   frame as views (Machine.focus_view, Machine.frame_view) for it. *)

open Rapid_syntax
module M = Machine
module V = Value

(* ------------------------------------------------------------------ values *)

(* One text per value, the one run --json writes (R-4.5-m). *)
let value = Observation.value

(* ------------------------------------------------------------------ source text *)

type source = { text : string; byte_of_char : int array }

type t = { files : (string, source option) Hashtbl.t; read : string -> string option }

let create ?(read = fun _ -> None) () = { files = Hashtbl.create 8; read }

let load t name =
  match
    match t.read name with
    | Some bytes -> bytes
    | None ->
        let ic = open_in_bin name in
        Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))
  with
  | exception Sys_error _ -> None
  | bytes ->
      let d = Rapid_syntax.Decode.decode bytes in
      let text = d.text in
      (* Regions count characters: the byte where each character of the UTF-8 text starts. *)
      let starts = ref [] and n = String.length text in
      for i = n - 1 downto 0 do
        if Char.code text.[i] land 0xC0 <> 0x80 then starts := i :: !starts
      done;
      Some { text; byte_of_char = Array.of_list (!starts @ [ n ]) }

let source_of t r =
  match Source.file_of r with
  | None -> None
  | Some f -> (
      let name = Source.name f in
      match Hashtbl.find_opt t.files name with
      | Some s -> s
      | None -> let s = load t name in Hashtbl.replace t.files name s; s)

(* On one line: line breaks, and the blanks around them, as one space; cut at [limit]. *)
let one_line ~limit raw =
  let buf = Buffer.create (String.length raw) in
  let blank = ref false in
  String.iter (fun c ->
      if c = '\n' || c = '\r' || c = ' ' || c = '\t' then blank := true
      else begin
        if !blank && Buffer.length buf > 0 then Buffer.add_char buf ' ';
        blank := false;
        Buffer.add_char buf c
      end) raw;
  let s = Buffer.contents buf in
  if String.length s > limit then String.sub s 0 (limit - 3) ^ "..." else s

(* The text of a region with sub-regions replaced (values for the expressions they hold): the
   outermost of nested replacements wins. *)
let text_with ?(limit = 72) t r (subs : (Source.region * string) list) =
  match source_of t r with
  | None -> ""
  | Some src ->
      let chars = Array.length src.byte_of_char - 1 in
      let clamp o = min chars (max 0 o) in
      let a = clamp (Source.start_offset r) and b = clamp (Source.stop_offset r) in
      if b <= a then ""
      else begin
        let subs = List.filter_map (fun (q, text) ->
            let qa = clamp (Source.start_offset q) and qb = clamp (Source.stop_offset q) in
            if Source.file_of q == Source.file_of r && qa >= a && qb <= b && qb > qa then Some (qa, qb, text) else None)
            subs in
        let subs = List.sort (fun (a1, b1, _) (a2, b2, _) -> if a1 <> a2 then compare a1 a2 else compare b2 b1) subs in
        let buf = Buffer.create 64 in
        let bytes i j = String.sub src.text src.byte_of_char.(i) (src.byte_of_char.(j) - src.byte_of_char.(i)) in
        let pos = List.fold_left (fun pos (qa, qb, text) ->
            if qa < pos then pos
            else (Buffer.add_string buf (bytes pos qa); Buffer.add_string buf text; qb)) a subs in
        Buffer.add_string buf (bytes pos b);
        one_line ~limit (Buffer.contents buf)
      end

let source_text t r = text_with t r []

(* A compound statement by its first line (IF ... THEN, WHILE ... DO), a simple one whole. *)
let statement_region (s : Ir.stmt) =
  match s.s with
  | If _ | While _ | For _ | Test _ -> (
      match Source.file_of s.sat with
      | Some f ->
          let line = (Source.start s.sat).line in
          let rec scan o =
            if o >= Source.stop_offset s.sat then o
            else if (Source.pos_of_offset f o).line <> line then o - 1 else scan (o + 1) in
          Source.region f (Source.start_offset s.sat) (scan (Source.start_offset s.sat))
      | None -> s.sat)
  | _ -> s.sat

let statement_text t s = source_text t (statement_region s)

(* ------------------------------------------------------------------ places *)

let routine_index = Observation.routine_index
let slot_name = Observation.slot_name
let component_name = Observation.component_name

(* A place as it is written, its indexes as their source text. *)
let place_text t program ri (p : Ir.place) =
  let rec go (p : Ir.place) =
    match p with
    | Whole s -> Some (s, [], slot_name program ri s)
    | Element (q, idx) ->
        Option.map (fun (s, path, text) ->
            (s, path @ List.init (Array.length idx) (fun _ -> -1),
             text ^ "{" ^ String.concat "," (Array.to_list (Array.map (fun (e : Ir.expr) -> source_text t e.at) idx))
             ^ "}"))
          (go q)
    | Component (q, k) ->
        Option.map (fun (s, path, text) -> (s, path @ [ k ], text ^ "." ^ component_name program ri s path k)) (go q)
    | Unresolved n -> Some (Ir.Global (-1), [], n)
  in
  match go p with Some (_, _, text) -> text | None -> "?"

(* A location as RAPID writes it: [a{2}.x], consecutive indexes of a two-dimensional array as
   [m{2,3}]. *)
let location_text cfg l =
  let program = M.program cfg in
  let ri = routine_index program (M.current_routine cfg) in
  match M.location_path cfg l with
  | None -> "<a value no data object holds>"
  | Some (slot, steps) ->
      let buf = Buffer.create 16 in
      Buffer.add_string buf (slot_name program ri slot);
      let rec go path open_index = function
        | [] -> if open_index then Buffer.add_char buf '}'
        | M.Index k :: rest ->
            Buffer.add_string buf (if open_index then "," else "{");
            Buffer.add_string buf (string_of_int k);
            go (path @ [ -1 ]) true rest
        | M.Component_of k :: rest ->
            if open_index then Buffer.add_char buf '}';
            Buffer.add_char buf '.';
            Buffer.add_string buf (component_name program ri slot path k);
            go (path @ [ k ]) false rest
      in
      go [] false steps;
      Buffer.contents buf

(* ------------------------------------------------------------------ operators *)

let binary_symbol op =
  match String.split_on_char ' ' (Arith.binary_name op) with
  | [ _; sym; _ ] -> sym
  | _ -> Arith.binary_name op

let unary_symbol op =
  match op with
  | Arith.Not -> "NOT "
  | Num_neg | Dnum_neg | Pos_neg -> "-"
  | Num_plus | Dnum_plus | Pos_plus -> "+"

(* ------------------------------------------------------------------ steps *)

type change =
  | Write of { place : string; value : string }
  | Output of string
  | Erase
  | Log of string
  | Raised of { name : string; number : int; at : Source.region }
  | Handled of { name : string; routine : string }
  | Retried
  | Next_tried
  | Undo_run of string
  | Routine_entered of string
  | Routine_left of string
  | Task_ended
  | Controller_event of Event.t

type step = {
  number : int;
  rule : string;
  depth : int;
  at : Source.region;
  redex : string;
  result : string option;
  changes : change list;
  statement : Ir.stmt option;
  in_statement : Ir.stmt option;
  routine : Ir.routine;
  state : string option;
}

type before = {
  focus : M.focus_view;
  frame : M.frame_view;
  b_at : Source.region;
  b_depth : int;
  b_routine : Ir.routine;
  b_redex : string;
  pure_result : string option;                 (* a read, an operation: known before the step *)
  aliases : (M.location * V.t) list;           (* a primitive's reference arguments and values *)
  b_statement : Ir.stmt option;
}

let call_text t cfg (callee : Ir.routine) (arguments : M.argument_view array) =
  let args = List.filter_map (fun x -> x) (Array.to_list (Array.mapi (fun i (a : M.argument_view) ->
      let p = callee.parameters.(i) in
      let name = (if p.p_optional then "\\" else "") ^ p.p_name in
      match a with
      | Bound_value v -> Some (name ^ " := " ^ value v)
      | Bound_alias l -> Some (name ^ " := " ^ location_text cfg l)
      | Switch_argument -> Some name
      | Absent_argument | Not_bound -> None) arguments)) in
  ignore t;
  callee.name ^ "(" ^ String.concat ", " args ^ ")"

let before t cfg =
  let focus = M.focus_view cfg and frame = M.frame_view cfg in
  let program = M.program cfg in
  let routine = M.current_routine cfg in
  let ri = lazy (routine_index program routine) in
  let redex, pure =
    (* A configuration the machine is about to find stuck must not stop the trace first. *)
    try
    match focus, frame with
    | Statement s, _ -> (statement_text t s, None)
    | Expression ({ e = Read p; _ } as e), _ ->
        (source_text t e.at, Option.map value (M.place_value cfg p))
    | Expression e, _ -> (source_text t e.at, None)
    | Place p, _ -> (place_text t program (Lazy.force ri) p, None)
    | Location l, Call_arguments { callee; next; _ } when next < Array.length callee.parameters ->
        (callee.parameters.(next).p_name ^ " := " ^ location_text cfg l, None)
    | Location l, _ -> (location_text cfg l, None)
    | Value v, Binary_right (op, a) ->
        (value a ^ " " ^ binary_symbol op ^ " " ^ value v,
         Some (match Arith.binary op a v with Ok r -> value r | Error name -> name))
    | Value v, Unary_operand op ->
        (unary_symbol op ^ value v, Some (match Arith.unary op v with Ok r -> value r | Error name -> name))
    | Value v, And_right -> (value v ^ " AND ...", None)
    | Value v, Or_right -> (value v ^ " OR ...", None)
    | Value v, Aggregate_member (kind, acc, i) ->
        let members = Array.sub acc 0 (i + 1) in
        members.(i) <- v;
        let all = Array.length acc = i + 1 in
        let text = "[" ^ String.concat "," (Array.to_list (Array.map value members)) ^ (if all then "]" else ",...]") in
        (text,
         if all then Some (value (match kind with Record_value -> V.Record members | Array_value -> V.Array members))
         else None)
    | Value v, Store (l, _) -> (location_text cfg l ^ " := " ^ value v, None)
    | Value v, Condition _ -> (value v, None)
    | Value v, For_bound (_, bounds) ->
        let words = [ "FROM"; "TO"; "STEP" ] in
        (String.concat " " (List.mapi (fun i b -> List.nth words i ^ " " ^ value b) (bounds @ [ v ])), None)
    | Value v, Test_value None -> ("TEST " ^ value v, None)
    | Value v, Test_value (Some subject) -> (value subject ^ " = " ^ value v, None)
    | Value v, Return_value -> ("RETURN " ^ value v, None)
    | Value v, Raise_value -> ("RAISE " ^ value v, None)
    | Value v, Late_name -> ("% " ^ value v ^ " %", None)
    | Value v, Element_index (l, i, n, read) ->
        let element = match M.location_value l, v with
          | (Array es, (Num k | Dnum k))
            when read && i = n - 1 && Float.is_integer k && k >= 1. && k <= float_of_int (Array.length es) ->
              Some (value es.(int_of_float k - 1))
          | _ -> None in
        (location_text cfg l ^ "{" ^ value v ^ "}", element)
    | Value v, _ -> (value v, None)
    | Next, Call_arguments { callee; arguments; next; _ } when next >= Array.length arguments ->
        (call_text t cfg callee arguments, None)
    | Next, Call_arguments { call; next; _ } -> (
        match call.arguments.(next) with
        | By_reference (p, _) -> (place_text t program (Lazy.force ri) p, None)
        | By_value e -> (source_text t e.at, None)
        | _ -> ("", None))
    | Next, Routine_end -> ("end of " ^ routine.name, None)
    | Next, While_body c -> ("WHILE " ^ source_text t c.at, None)
    | Next, For_body f -> ("FOR " ^ slot_name program (Lazy.force ri) (Local f.variable), None)
    | Next, Local_init ((slot, Init_default _) :: _) ->
        (* Settled unless the memory budget does not hold it: its value is not built. *)
        (slot_name program (Lazy.force ri) (Local slot) ^ " (its storage)", None)
    | Next, Local_init ((slot, Init_expr e) :: _) ->
        (slot_name program (Lazy.force ri) (Local slot) ^ " := " ^ source_text t e.at, None)
    | Next, Local_init [] -> ("routine data of " ^ routine.name, None)
    | Next, Other_frame "undo-end" -> ("end of the UNDO handler of " ^ routine.name, None)
    | Abandon, _ when routine.undo = None -> ("leave " ^ routine.name ^ " (no UNDO handler)", None)
    | Next, Other_frame "handler-end" -> ("end of the error handler of " ^ routine.name, None)
    | Next, Other_frame kind -> (kind, None)
    | Next, _ -> ("", None)
    | Error { name; number; _ }, _ -> (Printf.sprintf "%s (%d)" name number, None)
    | Search (Some r), _ -> ("error recovery point in " ^ r ^ "?", None)
    | Search None, _ -> ("error recovery point?", None)
    | Abandon, _ -> ("leave " ^ routine.name, None)
    | End, _ -> ("", None)
    with V.Type_mismatch _ | Invalid_argument _ | Not_found -> ("?", None)
  in
  let aliases =
    match focus, frame with
    | Next, Call_arguments { callee = { primitive = Some _; _ }; arguments; next; _ }
      when next >= Array.length arguments ->
        List.filter_map (function
            | M.Bound_alias l -> Some (l, V.copy (M.location_value l))
            | _ -> None) (Array.to_list arguments)
    | _ -> []
  in
  { focus; frame; b_at = M.focus_region cfg; b_depth = M.depth cfg; b_routine = routine;
    b_redex = redex; pure_result = pure; aliases; b_statement = M.current_statement cfg }

(* The statement in progress as it stands: its text with the values computed so far. *)
let statement_state t cfg =
  match M.current_statement cfg, M.computed_values cfg with
  | Some s, (_ :: _ as values) ->
      let now = text_with ~limit:100 t (statement_region s) (List.map (fun (r, v) -> (r, value v)) values) in
      (* A literal's value written where the literal is changes nothing worth a line. *)
      if now = text_with ~limit:100 t (statement_region s) [] then None else Some now
  | _ -> None

let event_change (e : Event.t) =
  match e with
  | Output s -> Output s
  | Erase -> Erase
  | Log s -> Log s
  | Routine_entered r -> Routine_entered r
  | Routine_left r -> Routine_left r
  | Error_raised { name; number; at } -> Raised { name; number; at }
  | Error_handled { name; routine } -> Handled { name; routine }
  | Undo_run r -> Undo_run r
  | Task_ended -> Task_ended
  | Observed (Stored { place; value }) -> Write { place; value }
  | (Controller _ | Trap_entered _ | Trap_left _ | Stubbed _ | Motion _ | Event_log _ | Observed _) as e ->
      Controller_event e

let after t (b : before) cfg (rule, events) =
  ignore t;
  let program = M.program cfg in
  let post_value () = match M.focus_view cfg with Value v -> Some (value v) | _ -> None in
  let write_slot slot =
    let ri = routine_index program (M.current_routine cfg) in
    match M.slot_value cfg slot with
    | Some v -> [ Write { place = slot_name program ri slot; value = value v } ]
    | None -> []
  in
  let result, writes =
    match rule, b.focus, b.frame with
    | ("read" | "binary" | "unary" | "aggregate" | "element"), _, _ -> (b.pure_result, [])
    | "binary-error", _, _ -> (b.pure_result, [])
    | "store", Value v, Store (l, _) -> (None, [ Write { place = location_text cfg l; value = value v } ])
    | ("for-enter" | "for-step"), _, (For_bound (f, _) | For_body f) -> (None, write_slot (Local f.variable))
    | "for-empty", _, _ -> (Some "no iteration", [])
    | "for-done", _, _ -> (Some "the loop ends", [])
    | "connect-allocate", Location l, _ ->
        (None, [ Write { place = location_text cfg l; value = value (M.location_value l) } ])
    | ("if-true" | "compact-if-true"), _, _ -> (Some "THEN", [])
    | "if-false", _, _ -> (Some "ELSE", [])
    | "compact-if-false", _, _ -> (Some "skipped", [])
    | "while-true", _, _ -> (Some "the body runs", [])
    | "while-false", _, _ -> (Some "the loop ends", [])
    | ("and-short" | "or-short"), Value v, _ -> (Some (value v), [])
    | ("and-right" | "or-right"), _, _ -> (Some "the right operand decides", [])
    | "test-match", _, _ -> (Some "this CASE", [])
    | "test-default", _, _ -> (Some "DEFAULT", [])
    | "return-function", Value v, _ -> (Some (b.b_routine.name ^ " returned " ^ value v), [])
    | ("return-procedure" | "return-entry"), _, _ -> (Some (b.b_routine.name ^ " returned"), [])
    | "call-primitive", _, Call_arguments { callee; _ } ->
        let changed = List.filter_map (fun (l, old) ->
            let now = M.location_value l in
            if V.equal old now then None else Some (Write { place = location_text cfg l; value = value now }))
            b.aliases in
        ((match callee.kind, post_value () with
            | Function, Some v -> Some (callee.name ^ " returned " ^ v)
            | _ -> None), changed)
    | "argument-alias", _, _ -> (
        match M.frame_view cfg with
        | Call_arguments { callee; arguments; next; _ } when next > 0 -> (
            match arguments.(next - 1) with
            | Bound_alias l -> (Some (callee.parameters.(next - 1).p_name ^ " is " ^ location_text cfg l), [])
            | _ -> (None, []))
        | _ -> (None, []))
    | "raise-handle", _, _ -> (Some ("handled by the error handler of " ^ (M.current_routine cfg).name), [])
    | ("raise-unhandled" | "raise-in-handler" | "raise-again-unhandled" | "handler-end" | "retry-limit"), _, _ ->
        (Some "the system error handler", [])
    | "raise-propagate", _, _ -> (Some ("none: propagated to the caller of " ^ b.b_routine.name), [])
    | "raise-again", _, _ -> (Some ("propagated from " ^ b.b_routine.name), [])
    | ("undo-done" | "abandon"), _, _ -> (Some (b.b_routine.name ^ " is left"), [])
    | ("undo-done-entry" | "abandon-entry"), _, _ -> (Some "the task ends", [])
    | "longjump-found", _, _ -> (Some "found: a long jump to it", [])
    | "longjump-search", _, _ -> (Some "not here", [])
    | "retry", _, _ -> (Some "the statement that caused the error runs again", [])
    | "trynext", _, _ -> (Some "the statement after the one that caused the error", [])
    | ("call-late-unknown" | "call-late-mismatch" | "call-unknown" | "call-unknown-function"
      | "call-primitive-error" | "index-out-of-bounds" | "index-not-integer" | "place-absent"
      | "place-unknown" | "argument-alias-refused" | "raise" | "raise-illegal" | "execute-placeholder"
      | "connect-again" | "function-no-return"), _, _ -> (
        match M.focus_view cfg with
        | Error { name; number; _ } -> (Some (Printf.sprintf "%s (%d)" name number), [])
        | _ -> (None, []))
    | "call-late", _, _ -> (None, [])
    | _ -> (None, [])
  in
  (* RETRY and TRYNEXT are the machine's events (Observation.Retried, Tried_next). *)
  let extra = [] in
  let statement = match b.focus with Statement s -> Some s | _ -> None in
  (* An interrupt is served where the program pointer is (ch. 8): the step says which, and
     which trap runs, rather than the frame it was served at. *)
  let redex, result =
    match rule, List.find_map (function Event.Trap_entered { number; trap; _ } -> Some (number, trap) | _ -> None)
                  events with
    | "interrupt-serve", Some (number, trap) ->
        (Printf.sprintf "interrupt %d" number, Some ("the trap " ^ trap ^ " runs"))
    | _ -> (b.b_redex, result) in
  { number = M.steps cfg; rule; depth = b.b_depth; at = b.b_at; redex; result;
    changes = writes @ extra @ List.map event_change events; statement;
    in_statement = b.b_statement; routine = b.b_routine; state = statement_state t cfg }

let place_of_statement _ (r : Ir.routine) (s : Ir.stmt) =
  Printf.sprintf "%s:%d" r.module_name (Source.start s.sat).line
