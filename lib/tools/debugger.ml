(* The stepping session of doc/debugger.md. The machine reduces one redex per step; the session
   groups steps into statements: the program pointer is at a statement when the machine's focus
   is one (Machine.pointer_statement). *)

open Rapid_syntax
module M = Machine

type t = {
  cfg : M.config;
  out : string -> unit;
  max_steps : int;
  mutable breakpoints : (int * string * int) list;   (* number, file, line *)
  mutable next_breakpoint : int;
  sources : (string, string array) Hashtbl.t;
  rules_seen : (string, unit) Hashtbl.t;
  mutable rules_order : string list;
  hidden : string -> bool;                            (* NOSTEPIN and NOVIEW modules, by name *)
  routine_data : Ir.routine -> string list;            (* names of its routine data, in order *)
  type_of : Ir.routine -> string -> (Rapid_typing.Types.object_type * bool) option;
      (* a name's declared type in a routine's scope, and whether it may be written *)
  statement_lines : (string * int list) list;
      (* the task's files and the lines a statement begins on, where a breakpoint can stop *)
  events : (string * string list) list;
      (* a controller backup's event routines that the commands make happen, by event (R-bk-11) *)
  mutable started : bool;                             (* a command has run the program *)
}

let config s = s.cfg
let rules s = List.rev s.rules_order

let note_rule s rule =
  if not (Hashtbl.mem s.rules_seen rule) then (Hashtbl.add s.rules_seen rule (); s.rules_order <- rule :: s.rules_order)

let source_lines s file =
  match Hashtbl.find_opt s.sources file with
  | Some l -> l
  | None ->
      let lines =
        try
          let ic = open_in_bin file in
          Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
              Array.of_list (String.split_on_char '\n' (really_input_string ic (in_channel_length ic))))
        with Sys_error _ -> [||] in
      Hashtbl.add s.sources file lines; lines

let file_name region = match Source.file_of region with Some f -> Source.name f | None -> ""

(* The text of the source line a region starts on, without its indentation. *)
let line_text s region =
  let line = (Source.start region).line in
  let lines = source_lines s (file_name region) in
  if line >= 1 && line <= Array.length lines then
    String.trim (Text_format.display (String.trim lines.(line - 1)))
  else ""

let place s (r : Ir.routine) region =
  Printf.sprintf "%s:%d  %s" r.module_name (Source.start region).line (line_text s region)

let show_pointer s =
  match M.outcome s.cfg with
  | Outcome.Running -> s.out (place s (M.current_routine s.cfg) (M.focus_region s.cfg))
  | _ -> ()

let outcome_text = function
  | Outcome.Running -> "running"
  | Ended -> "the task ended"
  | Stopped { name; at; about; _ } ->
      Printf.sprintf "%s: execution error: %s%s: the system error handler stopped the task"
        (Source.to_string at) name (match about with Some a -> " (" ^ a ^ ")" | None -> "")
  | Resource_exhausted (m, _) -> "resource exhausted: " ^ m
  | Unsupported { reason; at; _ } -> Printf.sprintf "%s: %s" (Source.to_string at) (Outcome.unsupported_what reason)
  | Deadlock m -> m
  | Stuck m -> "internal error: no rule applies (" ^ m ^ ")"

let show_events s events =
  List.iter (function
      | Event.Output line -> s.out ("tp> " ^ Text_format.display line)
      | Log line -> s.out ("log> " ^ Text_format.display line)
      | Event_log (Err_log { id; kind; arguments }) ->
          s.out (Printf.sprintf "log> %s %d: %s" kind id (String.concat " | " (List.map Text_format.display arguments)))
      | Event_log Skip_warning -> s.out "log> SkipWarn"
      | Error_raised { name; number; at } ->
          s.out (Printf.sprintf "error> %s (%d) at %s" name number (Source.to_string at))
      | Error_handled { name; routine } -> s.out (Printf.sprintf "error> %s handled by %s" name routine)
      | Observed (Propagated { name; number; routine; caller }) ->
          s.out (Printf.sprintf "error> %s (%d) propagated from %s to %s" name number routine caller)
      | Trap_entered { trap; number; _ } -> s.out (Printf.sprintf "trap> %s (interrupt %d)" trap number)
      | _ -> ()) events

(* §9.4: stepping does not enter the routines of a NOSTEPIN module; the program pointer is never
   shown inside one, nor inside a NOVIEW module, whose code cannot be viewed (doc/rulings.md
   R-9.4-a). *)
let visible s = not (s.hidden (M.current_routine s.cfg).module_name)

(* Runs the machine until [stop] holds at a statement, the task ends, or the step budget is
   spent. At least one step is taken. *)
let run_until s stop =
  let rec go first =
    match M.outcome s.cfg with
    | Outcome.Running when M.steps s.cfg >= s.max_steps ->
        s.out (Printf.sprintf "the step limit (%d) is exhausted" s.max_steps)
    | Outcome.Running ->
        if (not first) && M.pointer_statement s.cfg <> None && visible s && stop () then ()
        else begin
          let rule, events = M.step s.cfg in
          note_rule s rule;
          (* What happens to errors inside NOSTEPIN code is not shown (§9.4): the user sees them
             when they reach the user level, at the call (§7.3, R-7.3-o). What it writes is. *)
          let events = if visible s then events
            else List.filter (function Event.Error_raised _ | Event.Error_handled _ -> false | _ -> true) events in
          show_events s events;
          go false
        end
    | o -> s.out (outcome_text o)
  in
  go true

(* R-bk-11: the event routines the task runs before it stands at its entry routine (POWER_ON,
   RESET), or that a command made happen, run to their end, what they write shown. *)
let run_events ?until s =
  let until = match until with Some f -> f | None -> fun () -> not (M.in_event_routine s.cfg) in
  while M.outcome s.cfg = Outcome.Running && not (until ()) && M.steps s.cfg < s.max_steps do
    let rule, events = M.step s.cfg in
    note_rule s rule;
    show_events s events
  done;
  match M.outcome s.cfg with Outcome.Running -> () | o -> s.out (outcome_text o)

(* R-bk-11: a command makes the event happen: START (the first continue), RESTART (a continue
   after a stop), STEP (a step forward or backward), STOP (a continue that stopped at a
   breakpoint); its routines run where the program pointer is, which then stays there. *)
let event s name =
  match List.assoc_opt name s.events with
  | None | Some [] -> ()
  | Some routines when M.outcome s.cfg = Outcome.Running -> (
      let depth = M.interposed s.cfg in
      match M.interpose s.cfg routines with
      | Error m -> s.out ("event routines: " ^ m)
      | Ok events -> show_events s events; run_events ~until:(fun () -> M.interposed s.cfg <= depth) s)
  | Some _ -> ()

(* The program pointer stops only at a statement (doc/debugger.md), on the line it begins on: a
   breakpoint on any other line could never stop [continue]. Every statement list of every
   routine of the task's [files] (all files without them), handlers included. *)
let statement_lines ?files (program : Ir.program) =
  let table = Hashtbl.create 8 in
  let add region =
    let file = file_name region in
    let lines = Option.value ~default:[] (Hashtbl.find_opt table file) in
    Hashtbl.replace table file ((Source.start region).line :: lines) in
  let rec stmt (st : Ir.stmt) =
    add st.sat;
    match st.s with
    | If (_, a, b) | Elseif (_, a, b) -> block a; block b
    | Compact_if (_, inner) -> stmt inner
    | For f -> block f.loop_body
    | While (_, b) -> block b
    | Test (_, cases, default) -> Array.iter (fun (_, b) -> block b) cases; block default
    | _ -> ()
  and block (b : Ir.block) = Array.iter stmt b.body in
  Array.iter (fun (r : Ir.routine) ->
      if r.primitive = None then begin
        block r.body; Option.iter block r.backward; Option.iter block r.undo;
        Option.iter (fun (h : Ir.error_handler) -> block h.handler) r.error
      end) program.routines;
  let named = match files with
    | Some fs -> List.map (fun f -> (f, Option.value ~default:[] (Hashtbl.find_opt table f))) fs
    | None -> Hashtbl.fold (fun f lines acc -> if f = "" then acc else (f, lines) :: acc) table [] in
  List.sort compare (List.map (fun (f, lines) -> (f, List.sort_uniq compare lines)) named)

let create ?(max_steps = 100_000_000) ?(hidden = fun _ -> false) ?(routine_data = fun _ -> [])
    ?(type_of = fun _ _ -> None) ?files ?(events = []) ~out cfg =
  let s = { cfg; out; max_steps; breakpoints = []; next_breakpoint = 1; sources = Hashtbl.create 4;
            rules_seen = Hashtbl.create 64; rules_order = []; hidden; routine_data; type_of;
            statement_lines = statement_lines ?files (M.program cfg); events; started = false } in
  (* A backup's POWER_ON and RESET routines first (R-bk-11): the session begins at main. *)
  run_events s;
  (* The machine starts settled, at the entry routine's first statement when it has one. *)
  if M.outcome cfg = Outcome.Running && not (M.pointer_statement cfg <> None && visible s) then
    run_until s (fun () -> true);
  show_pointer s;
  s

let running s =
  match M.outcome s.cfg with
  | Outcome.Running -> true
  | o -> s.out ("the task is not running: " ^ outcome_text o); false

(* A breakpoint's file names a file of the task as given or by its base name: one test, for the
   stop at a breakpoint and for the refusal of one that names no file of the task. *)
let same_file f file = f = file || Filename.basename f = Filename.basename file

let at_breakpoint s =
  let r = M.focus_region s.cfg in
  let file = file_name r and line = (Source.start r).line in
  List.exists (fun (_, f, l) -> l = line && same_file f file) s.breakpoints

(* --- data: the names an expression of print and set reads (doc/debugger.md) *)

let lower = String.lowercase_ascii

(* The names of the current routine's slots (parameters, routine data, FOR loop variables) are
   the ones the lowering keeps for the trace (Ir.names). *)
let find_data s name =
  let cfg = s.cfg in
  let r = M.current_routine cfg in
  let program = M.program cfg in
  let n = lower name in
  let same (q : Ir.routine) = q.name = r.name && q.module_name = r.module_name in
  let rec index i =
    if i >= Array.length program.routines then None else if same program.routines.(i) then Some i else index (i + 1) in
  let local =
    match index 0 with
    | Some i when i < Array.length program.names.local_names ->
        let names = program.names.local_names.(i) in
        let rec find j = if j >= Array.length names then None
          else if lower names.(j) = n then Some (Ir.Local j) else find (j + 1) in
        find 0
    | _ -> None in
  match local with Some slot -> Some slot | None -> M.global_slot cfg n

let value_text v = try Text_format.value_text v with Value.Type_mismatch _ -> "<object>"

(* The data objects an expression names (Debug_expr): found as [find_data] finds them, typed by
   the session's [type_of] for their components. *)
(* A semi-value data object (a signal, §2.16) is read as its value, as in value context in a
   program: the handle itself says nothing to the programmer. *)
let signal_type known =
  match known with
  | Some ({ Rapid_typing.Types.base = Installed_atomic { atomic_class = Semi_value; atomic_name; _ };
            dims = Scalar }, _) -> Some atomic_name
  | _ -> None

let env s name =
  let signal_value slot =
    match M.read_data s.cfg slot with
    | Some (Value.Handle _ as h) -> Some ((M.host s.cfg).read_signal h)
    | _ -> None in
  match find_data s name with
  | None -> Error (Printf.sprintf "no data object %s in the scope of %s" name (M.current_routine s.cfg).name)
  | Some slot when (match signal_value slot with Some (Ok _) -> true | _ -> false) ->
      (* a signal connected to one of the I/O configuration (declared, or made by --io) *)
      Ok { Debug_expr.value = Option.map Result.get_ok (signal_value slot); typ = None; write = None }
  | Some slot when signal_type (s.type_of (M.current_routine s.cfg) name) <> None ->
      let kind = Option.get (signal_type (s.type_of (M.current_routine s.cfg) name)) in
      let err = match signal_value slot with Some (Error e) -> e | _ -> "ERR_NO_ALIASIO_DEF" in
      Error (Printf.sprintf "%s is a %s not connected to a signal of the I/O configuration (%s): give the \
                             signal in the --io file, or connect it with AliasIO" name kind err)
  | Some slot ->
      let known = s.type_of (M.current_routine s.cfg) name in
      (* ERRNO and INTNO are the system's (ch. 12), known as such to the program itself. *)
      let system = match slot with
        | Ir.Global i ->
            let p = M.program s.cfg in
            i = p.errno || i = p.intno || p.globals.(i).g_read_only
        | Ir.Local _ -> false in
      let writable = (not system) && (match known with Some (_, w) -> w | None -> true) in
      Ok { Debug_expr.value = M.read_data s.cfg slot; typ = Option.map fst known;
           write = (if writable then Some (fun v -> M.write_data s.cfg slot v) else None) }

let print_ s text =
  if String.trim text = "" then s.out "print: print EXPR" else
  match Debug_expr.parse_expression text with
  | Error m -> s.out ("print: " ^ m)
  | Ok e -> (
      match Debug_expr.eval (env s) e with
      | Ok v -> s.out (Printf.sprintf "%s = %s" (String.trim text) (value_text v))
      | Error m -> s.out ("print: " ^ m))

(* The position of the first ":=" of a set command's text. *)
let contains_assign text =
  let n = String.length text in
  let rec go i = if i + 1 >= n then None else if text.[i] = ':' && text.[i + 1] = '=' then Some i else go (i + 1) in
  go 0

let set_ s text =
  let target_missing = match contains_assign text with
    | Some i -> String.trim (String.sub text 0 i) = ""
    | None -> true in
  let root = let t = String.trim text in
    let rec go i = if i < String.length t && (match t.[i] with
        | 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_' -> true | _ -> false) then go (i + 1) else i in
    String.sub t 0 (go 0) in
  let signal = match if root = "" then None else find_data s root with
    | None -> None
    | Some slot -> (
        match signal_type (s.type_of (M.current_routine s.cfg) root), M.read_data s.cfg slot with
        | Some kind, _ -> Some ("a signal (" ^ kind ^ ")")
        | None, Some (Value.Handle _ as h) when Result.is_ok ((M.host s.cfg).read_signal h) -> Some "a signal"
        | _ -> None) in
  if target_missing then s.out "set: set REF := EXPR" else
  match signal with
  | Some kind ->
      s.out (Printf.sprintf "set: %s is %s: the debugger does not set signals; the program sets its \
                             outputs (SetDO, SetAO, SetGO), the stimulus file (--io) its inputs" root kind)
  | None ->
  match Debug_expr.parse_assignment text with
  | Error m -> s.out ("set: " ^ m)
  | Ok (target, e) -> (
      match Debug_expr.assign (env s) target e with
      | Ok v ->
          let t = match String.index_opt text ':' with Some i -> String.sub text 0 i | None -> text in
          s.out (Printf.sprintf "%s = %s" (String.trim t) (value_text v))
      | Error m -> s.out ("set: " ^ m))

let where s =
  List.iteri (fun i ((r : Ir.routine), region) ->
      s.out (Printf.sprintf "#%d %s  %s" i r.name (place s r region))) (M.call_chain_view s.cfg)

let back s =
  if running s then
    match M.backward s.cfg with
    | Error m -> s.out m
    | Ok rule ->
        note_rule s rule;
        if rule = "backward-call" || rule = "backward-move" then begin
          (* The BACKWARD handler, or the move instruction stepped backward, runs to its end:
             breakpoints in it do not stop it, so that backward execution is never nested (§6.2). *)
          let d = M.depth s.cfg in
          run_until s (fun () -> M.depth s.cfg <= d && not (M.backward_running s.cfg))
        end;
        show_pointer s

(* Lines as ranges: "3-5, 9, 12-14". *)
let ranges lines =
  let rec go acc = function
    | [] -> List.rev acc
    | l :: rest ->
        let rec extend last = function
          | m :: more when m = last + 1 -> extend m more
          | more -> (last, more) in
        let last, more = extend l rest in
        go ((if last = l then string_of_int l else Printf.sprintf "%d-%d" l last) :: acc) more in
  go [] lines

(* A breakpoint that could never stop the program pointer is refused, saying where one can:
   the task's files, or the lines of FILE a statement begins on (around LINE, for a long file). *)
let breakable s file line =
  match List.filter (fun (f, _) -> same_file f file) s.statement_lines with
  | [] ->
      Error (Printf.sprintf "no file %s in the task (its files: %s)" file
               (String.concat ", " (List.map fst s.statement_lines)))
  | found when List.exists (fun (_, lines) -> List.mem line lines) found -> Ok ()
  | (f, lines) :: _ ->
      let shown = ranges lines in
      let shown =
        if List.length shown <= 12 then String.concat ", " shown
        else
          let before = List.filter (fun l -> l < line) lines and after = List.filter (fun l -> l > line) lines in
          let last k l = List.filteri (fun i _ -> i >= List.length l - k) l in
          let first k l = List.filteri (fun i _ -> i < k) l in
          String.concat ", " ((if List.length before > 5 then [ "..." ] else []) @ ranges (last 5 before)
                              @ ranges (first 5 after) @ (if List.length after > 5 then [ "..." ] else [])) in
      Error (if lines = [] then Printf.sprintf "%s has no statement" f
             else Printf.sprintf "no statement begins on line %d of %s; statements begin on lines %s" line f shown)

(* R-bk-11: a step forward or backward makes the STEP event happen; the program has run. *)
let step_event s = event s "STEP"; s.started <- true

let words line =
  List.filter (fun w -> w <> "") (String.split_on_char ' ' (String.trim line))

let count_arg = function
  | [] -> Some 1
  | [ n ] -> (match int_of_string_opt n with Some k when k >= 1 -> Some k | _ -> None)
  | _ -> None

let command s line =
  let line = String.trim line in
  let verb, rest =
    match String.index_opt line ' ' with
    | Some i -> (String.sub line 0 i, String.trim (String.sub line (i + 1) (String.length line - i - 1)))
    | None -> (line, "") in
  match lower verb with
  | "" -> `Go_on
  | "#" -> `Go_on
  | _ when line.[0] = '#' -> `Go_on
  | "quit" -> `Quit
  | "step" | "s" -> (
      match count_arg (words rest) with
      | None -> s.out "step: step [N], N at least 1"; `Go_on
      | Some n ->
          let rec go k =
            if k > 0 && running s then begin
              step_event s;
              if M.outcome s.cfg = Outcome.Running then run_until s (fun () -> true);
              show_pointer s; go (k - 1)
            end in
          go n; `Go_on)
  | "next" | "n" ->
      if running s then begin
        step_event s;
        let d = M.depth s.cfg in
        if M.outcome s.cfg = Outcome.Running then run_until s (fun () -> M.depth s.cfg <= d);
        show_pointer s
      end; `Go_on
  | "finish" ->
      if running s then begin
        step_event s;
        let d = M.depth s.cfg in
        if M.outcome s.cfg = Outcome.Running then run_until s (fun () -> M.depth s.cfg < d);
        show_pointer s
      end; `Go_on
  | "continue" | "c" ->
      if running s then begin
        event s (if s.started then "RESTART" else "START");
        s.started <- true;
        if M.outcome s.cfg = Outcome.Running then begin
          run_until s (fun () -> at_breakpoint s);
          (* At a breakpoint the program stops: the STOP routines (its end ran them already). *)
          if M.outcome s.cfg = Outcome.Running then event s "STOP"
        end;
        show_pointer s
      end; `Go_on
  | "back" | "b" -> if running s then step_event s; back s; `Go_on
  | "break" -> (
      match String.rindex_opt rest ':' with
      | Some i when i > 0 && (match int_of_string_opt (String.sub rest (i + 1) (String.length rest - i - 1)) with
          | Some l -> l >= 1 | None -> false) ->
          let file = String.sub rest 0 i and l = int_of_string (String.sub rest (i + 1) (String.length rest - i - 1)) in
          (match breakable s file l with
           | Error m -> s.out ("break: " ^ m)
           | Ok () ->
               let n = s.next_breakpoint in
               s.next_breakpoint <- n + 1;
               s.breakpoints <- s.breakpoints @ [ (n, file, l) ];
               s.out (Printf.sprintf "breakpoint %d at %s:%d" n file l));
          `Go_on
      | _ -> s.out "break: break FILE:LINE"; `Go_on)
  | "delete" -> (
      match words rest with
      | [] -> s.breakpoints <- []; s.out "all breakpoints deleted"; `Go_on
      | [ n ] when int_of_string_opt n <> None ->
          let k = int_of_string n in
          if List.exists (fun (m, _, _) -> m = k) s.breakpoints then begin
            s.breakpoints <- List.filter (fun (m, _, _) -> m <> k) s.breakpoints;
            s.out (Printf.sprintf "breakpoint %d deleted" k)
          end else s.out (Printf.sprintf "delete: no breakpoint %d" k);
          `Go_on
      | _ -> s.out "delete: delete [N]"; `Go_on)
  | "print" | "p" -> if running s then print_ s rest; `Go_on
  | "set" -> if running s then set_ s rest; `Go_on
  | "where" -> if running s then where s; `Go_on
  | _ ->
      s.out (Printf.sprintf "unknown command %S \
                             (step, next, finish, back, continue, break, delete, print, set, where, quit)" verb);
      `Go_on
