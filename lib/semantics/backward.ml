(* Backward execution (ch. 6; doc/semantics.md, "Backward execution"): the transition taken on
   request, never by [step]. Why a module of its own: backward.mli. *)

open Configuration
open Store
module V = Value

let statement_name (s : Ir.stmt) =
  match s.s with
  | Assign _ -> "an assignment" | Call_procedure _ -> "a procedure call" | Call_late _ -> "a late-bound procedure call"
  | Goto _ -> "GOTO" | Break -> "BREAK" | Continue -> "CONTINUE" | Return _ -> "RETURN" | Raise _ -> "RAISE"
  | Exit -> "EXIT" | Retry -> "RETRY" | Trynext -> "TRYNEXT" | Connect _ -> "CONNECT"
  | If _ | Elseif _ -> "IF" | Compact_if _ -> "a compact IF" | For _ -> "FOR" | While _ -> "WHILE"
  | Test _ -> "TEST" | Label -> "a label" | Placeholder_statement -> "<SMT>"

(* The installed procedures whose backward execution rapid-sem defines: the move instructions of
   ABB's backward execution of a program stepped on the FlexPendant (§6.1: "a procedure call,
   predefined or user-defined, may have any backward behaviour ... defined in the procedure";
   doc/rulings.md R-6.1-move). *)
let backward_moves = [ "movel"; "movej"; "movec"; "moveabsj" ]

(* A move instruction stepped backward ends at a stop point: its call with the predefined zonedata
   fine for its Zone (R-6.1-move). *)
let at_stop_point cfg (call : Ir.call) (r : Ir.routine) =
  let fine = ref (-1) in
  Array.iteri (fun g (gl : Ir.global) -> if !fine < 0 && String.lowercase_ascii gl.g_name = "fine" then fine := g)
    cfg.program.globals;
  if !fine < 0 then call
  else
    let arguments = Array.mapi (fun i (a : Ir.argument) ->
        if i < Array.length r.parameters && String.lowercase_ascii r.parameters.(i).p_name = "zone" then
          match a with
          | By_value e -> Ir.By_value { e with e = Read (Whole (Global !fine)) }
          | other -> other
        else a) call.arguments in
    { call with arguments }

let not_supported why = Stdlib.Error ("backward execution is not supported: " ^ why ^ "; no step taken (§6.1)")

(* One statement backward from the program pointer (§6.1-§6.3): the statement before it in its
   statement list, which must be simple. The program pointer is then at that statement. *)
let backward cfg =
  match cfg.focus, cfg.stack with
  | F_done _, _ -> Stdlib.Error "the task is not running"
  | F_stmt cur, K_seq (b, j) :: rest when j >= 1 && j <= Array.length b.body && b.body.(j - 1) == cur ->
      if cfg.act.handling <> Body then
        (* §6.2: "the instructions of a BACKWARD handler or an error handler cannot be executed
           backward"; UNDO handlers likewise (doc/rulings.md R-6-d). *)
        not_supported "the program pointer is in an error or UNDO handler (§6.2)"
      else if cfg.backward_depth >= 0 then not_supported "backward execution cannot be nested (§6.2)"
      else if j = 1 then
        (* §6.1: "it is not possible to step backward out of a routine at the top of a statement
           list"; nor out of a compound statement's list, which cannot itself be executed
           backward (R-6-a). *)
        not_supported
          (if b == cfg.act.routine.body then
             Printf.sprintf "the program pointer is at the first statement of %s, and backward execution does \
                             not leave a routine for its caller" cfg.act.routine.name
           else "the program pointer is at the first statement of a list inside a compound statement (IF, \
                 FOR, WHILE, TEST), which cannot be executed backward")
      else begin
        let prev = b.body.(j - 2) in
        let moved () = cfg.stack <- K_seq (b, j - 1) :: rest; cfg.focus <- F_stmt prev in
        match prev.s with
        | Label | Assign _ | Connect _ ->
            (* §6.1: comments, labels, assignments and CONNECT are no-operations backward. *)
            moved (); Ok Rule.Backward_noop
        | Call_procedure ({ callee = Routine i; _ } as call) -> (
            let r = cfg.program.routines.(i) in
            match r.backward with
            | None when r.primitive <> None && List.mem (String.lowercase_ascii r.name) backward_moves ->
                (* §6.1, R-6.1-move: the move instruction runs as in a BACKWARD handler, where a move
                   retraces the newest forward move not yet retraced (R-6.3-m), to a stop point;
                   the program pointer is then at it (backward-end). *)
                cfg.stack <- K_backward_end :: K_seq (b, j - 2) :: rest;
                cfg.backward_depth <- cfg.act.call_depth + 1;
                cfg.host.set_backward true;
                cfg.focus <- F_stmt { prev with s = Call_procedure (at_stop_point cfg call r) };
                Ok Rule.Backward_move
            | None when r.primitive <> None ->
                not_supported (Printf.sprintf "the installed procedure %s has no backward execution (only MoveL, \
                                               MoveJ, MoveC and MoveAbsJ step backward, R-6.1-move)" r.name)
            | None ->
                not_supported (Printf.sprintf "the procedure %s has no BACKWARD handler (§6.2): give it one to step \
                                               back over its calls" r.name)
            | Some handler ->
                (* §6.1: the arguments are evaluated forward and bound to the parameters as in
                   forward execution; the BACKWARD handler runs in place of the body, with the
                   routine's data in its scope (§6.2). *)
                cfg.stack <- K_seq (b, j - 2) :: rest;
                push cfg (K_stmt (prev, cfg.mark)); cfg.mark <- cfg.stack;
                push cfg K_backward_end;
                cfg.backward_depth <- cfg.act.call_depth + 1;
                cfg.host.set_backward true;
                cfg.focus <- F_next;
                let callee = { r with body = handler } in
                let n = Array.length callee.parameters in
                push cfg (K_args { call; callee; args_slots = Array.make n (fresh_loc (V.Bool false));
                                   args_present = Array.make n false; args_kinds = Array.make n Ir.Ref_other;
                                   args_module_data = Array.make n false; args_memory = 0;
                                   primitive_args = Array.make n Argument.Missing; next = 0 });
                Statements.settle cfg;
                Ok Rule.Backward_call)
        | _ -> not_supported (statement_name prev ^ " cannot be executed backward")
      end
  | _ -> Stdlib.Error "the program pointer is not at a statement"

let running cfg = cfg.backward_depth >= 0
