(* Backward execution and the debugger: the backward rules of the machine are documented in
   doc/semantics.md ("Backward execution") and each is applied in one of the debugger sessions
   of test/golden (the spec/ cases of format 3 run forward only); and the session itself on
   cases the golden transcripts do not show. *)

module M = Rapid_semantics.Machine
module D = Rapid_tools.Debugger

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

let documented_backward_rules () =
  let text = read_file "../doc/semantics.md" in
  let start = Str.search_forward (Str.regexp_string "## Backward execution") text 0 in
  (* The section runs to the next heading of its level. *)
  let stop = try Str.search_forward (Str.regexp "^## ") text (start + 1) with Not_found -> String.length text in
  let section = String.sub text start (stop - start) in
  let rec collect pos acc =
    match Str.search_forward (Str.regexp "\\*\\*\\([a-z-]+\\)\\*\\*") section pos with
    | p -> collect (p + 1) (Str.matched_group 1 section :: acc)
    | exception Not_found -> List.sort_uniq compare acc
  in
  collect 0 []

(* The machine at the start of FILEs' entry routine; the test fails when they do not load. *)
let started ?(entry = "main") files =
  match Rapid_load.Session.load files with
  | Error _ -> Alcotest.failf "%s does not load" (String.concat " " files)
  | Ok loaded -> (match M.start ~host:(Rapid_run.Run.setup ()).host loaded.program ~entry with Error m -> Alcotest.fail m | Ok cfg -> cfg)

(* A session of FILEs fed the lines of a script; its transcript and rules. *)
let session ?entry files lines =
  let cfg = started ?entry files in
  let out = Buffer.create 256 in
  let d = D.create ~max_steps:1_000_000 ~out:(fun l -> Buffer.add_string out l; Buffer.add_char out '\n') cfg in
  let rec go = function
    | [] -> ()
    | l :: more -> (match D.command d l with `Quit -> () | `Go_on -> go more) in
  go lines;
  (Buffer.contents out, D.rules d, cfg)

(* The debugger sessions of test/golden: "debug --script SCRIPT FILE...". *)
let golden_sessions () =
  Sys.readdir "golden" |> Array.to_list |> List.sort compare
  |> List.filter (fun f -> Filename.check_suffix f ".cmd")
  |> List.filter_map (fun f ->
      match String.split_on_char ' ' (String.trim (read_file (Filename.concat "golden" f))) with
      | "debug" :: "--script" :: script :: files
        when not (List.exists (fun p -> Sys.is_directory (Filename.concat "golden" p)) files) ->
          (* A backup's session (a folder, test/golden/backup-events-debug) is the command line's. *)
          let in_golden p = Filename.concat "golden" p in
          Some (List.map in_golden files,
                String.split_on_char '\n' (read_file (in_golden script)))
      | _ -> None)

let backward_rules_documented () =
  Alcotest.(check (list string)) "backward rules of doc/semantics.md"
    (List.sort compare M.backward_rule_names) (documented_backward_rules ())

let backward_rules_exercised () =
  let used = List.concat_map (fun (files, lines) -> let _, rules, _ = session files lines in rules) (golden_sessions ()) in
  let missing = List.filter (fun r -> not (List.mem r used)) M.backward_rule_names in
  Alcotest.(check (list string)) "backward rules in no debugger session" [] missing

let program text =
  let file = Filename.temp_file "debugger" ".mod" in
  let oc = open_out_bin file in
  output_string oc text; close_out oc;
  file

(* back inside an error handler is refused (§6.2), and an error in a BACKWARD handler is not
   handled even by the caller's handler (§6.1). *)
let back_in_handler () =
  let file = program {|MODULE m
  VAR num x := 0;
  PROC P()
  BACKWARD
  ENDPROC
  PROC main()
    x := 1 / x;
  ERROR
    P;
    x := 1;
    TRYNEXT;
  ENDPROC
ENDMODULE
|} in
  let text, _, _ = session [ file ] [ "step"; "step"; "back" ] in
  Alcotest.(check bool) "refused in an error handler" true
    (Str.string_match (Str.regexp ".*in an error or UNDO handler") (String.concat " " (String.split_on_char '\n' text)) 0)

(* A BACKWARD handler's routine data is initialised as for a call, and its parameters bound:
   the handler sees the argument evaluated forward (§6.1, §6.2). *)
let handler_scope () =
  let file = program {|MODULE m
  VAR num log := 0;
  FUNC num Twice(num a)
    RETURN 2 * a;
  ENDFUNC
  PROC P(num k)
    VAR num extra := 5;
    log := log + k;
  BACKWARD
    log := log * 100 + k + extra;
  ENDPROC
  PROC main()
    P Twice(3);
    log := log;
  ENDPROC
ENDMODULE
|} in
  let text, _, _ = session [ file ] [ "next"; "back"; "print log" ] in
  Alcotest.(check bool) "log = 6 * 100 + 6 + 5" true
    (List.mem "log = 611" (String.split_on_char '\n' text))

(* The breakpoints of a program that ends: continue runs to the end; a step limit ends a session
   that loops without end with a clear line. *)
let step_limit () =
  let file = program {|MODULE m
  VAR num x := 0;
  PROC main()
    WHILE TRUE DO
      x := x + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
|} in
  let cfg = started [ file ] in
  let lines = ref [] in
  let d = D.create ~max_steps:500 ~out:(fun l -> lines := l :: !lines) cfg in
  ignore (D.command d "continue");
  Alcotest.(check bool) "step limit" true (List.mem "the step limit (500) is exhausted" !lines)


(* Commands that cannot do what they ask say what exists or what the command expects, and change
   nothing: a breakpoint where no statement begins, or in a file the task does not have, could
   never stop the program pointer. *)
let malformed_commands () =
  let file = program {|MODULE m
  VAR num x := 0; VAR num a{2};
  PROC main()
    x := 1;

    x := 2;
    x := 3;
  ENDPROC
ENDMODULE
|} in
  let cfg = started [ file ] in
  let lines = ref [] in
  let d = D.create ~files:[ file ] ~out:(fun l -> lines := l :: !lines) cfg in
  let answer command = lines := []; ignore (D.command d command); List.rev !lines in
  let base = Filename.basename file in
  Alcotest.(check (list string)) "a line past the end"
    [ Printf.sprintf "break: no statement begins on line 40 of %s; statements begin on lines 4, 6-7" file ]
    (answer (Printf.sprintf "break %s:40" base));
  Alcotest.(check (list string)) "an empty line"
    [ Printf.sprintf "break: no statement begins on line 5 of %s; statements begin on lines 4, 6-7" file ]
    (answer (Printf.sprintf "break %s:5" file));
  Alcotest.(check (list string)) "a file not in the task"
    [ Printf.sprintf "break: no file other.mod in the task (its files: %s)" file ] (answer "break other.mod:4");
  Alcotest.(check (list string)) "a statement's line" [ Printf.sprintf "breakpoint 1 at %s:6" base ]
    (answer (Printf.sprintf "break %s:6" base));
  Alcotest.(check (list string)) "print alone" [ "print: print EXPR" ] (answer "print");
  Alcotest.(check (list string)) "p alone" [ "print: print EXPR" ] (answer "p  ");
  Alcotest.(check (list string)) "set without a target" [ "set: set REF := EXPR" ] (answer "set := 5");
  Alcotest.(check (list string)) "set alone" [ "set: set REF := EXPR" ] (answer "set");
  Alcotest.(check (list string)) "set of a literal"
    [ "set: set REF := EXPR: 3 is not a data object, an element or a component (§4.5)" ] (answer "set 3 := 4");
  (* An index beyond int's range is not wrapped round into the array. *)
  Alcotest.(check (list string)) "a huge index"
    [ "print: ERR_OUTOFBND: index 1.00000002e+20 is outside the array (§3.6)" ]
    (answer "print a{99999999999999999999}");
  (* tooldata has three components, as a pos: its negation is refused, not a crash. *)
  Alcotest.(check (list string)) "the negation of a tooldata"
    [ "print: no operator of §3.12 takes an operand of this type" ] (answer "print -tool0");
  Alcotest.(check (list string)) "set to the negation of a tooldata"
    [ "set: no operator of §3.12 takes an operand of this type" ] (answer "set x := -tool0");
  Alcotest.(check (list string)) "nothing changed" [ "x = 0" ] (answer "print x");
  (* The refused breakpoints took no number; the one set stops continue. *)
  Alcotest.(check (list string)) "continue" [ "m:6  x := 2;" ] (answer "continue")

(* Move instructions stepped backward (R-6.1-move): after each back the robot stands where the
   move stepped over began, having retraced it (MoveC through its circle point), at a stop point. *)
let back_moves_retrace () =
  let module MP = Rapid_installed.Motion_routines in
  let module MM = Rapid_motion_model in
  let file = "../spec/06-backward/05-back-move-instructions.mod" in
  let loaded = match Rapid_load.Session.load [ file ] with Ok l -> l | Error _ -> Alcotest.fail "does not load" in
  let motion = MP.create ~history:100_000_000 () in
  let host = (Rapid_run.Run.setup ~motion ()).host in
  let cfg = match M.start ~host loaded.program ~entry:"main" with Ok c -> c | Error m -> Alcotest.fail m in
  let d = D.create ~max_steps:1_000_000 ~out:(fun _ -> ()) cfg in
  let run l = ignore (D.command d l) in
  let p () = MP.planner motion in
  let now () = host.now () in
  let at () = (MM.Planner.pose_at (p ()) (now ())).trans in
  let close what (a : MM.Geom.pos) (x, y, z) =
    let dist = Float.sqrt (((a.x -. x) ** 2.) +. ((a.y -. y) ** 2.) +. ((a.z -. z) ** 2.)) in
    if dist > 0.05 then Alcotest.failf "%s: the robot at (%.2f, %.2f, %.2f), not (%g, %g, %g)" what a.x a.y a.z x y z in
  List.iter run [ "next"; "next"; "next"; "next" ];
  close "forward, after MoveC" (at ()) (550., 100., 300.);
  let t0 = now () in
  run "back";
  (* back over MoveC: at p2, the robot standing, having passed the circle point pCir *)
  close "back over MoveC" (at ()) (350., 100., 300.);
  if not (MM.Planner.finished_by (p ()) <= now () +. 1e-6) then Alcotest.fail "the robot still moves after back";
  let nearest = ref infinity in
  for k = 0 to 400 do
    let t = t0 +. (now () -. t0) *. float_of_int k /. 400. in
    let q = (MM.Planner.pose_at (p ()) t).trans in
    let dist = Float.sqrt (((q.x -. 450.) ** 2.) +. ((q.y -. 200.) ** 2.) +. ((q.z -. 300.) ** 2.)) in
    nearest := Float.min !nearest dist;
    (* on the circle through p2, pCir, p3: centre (450, 100, 300), radius 100 *)
    let r = Float.sqrt (((q.x -. 450.) ** 2.) +. ((q.y -. 100.) ** 2.)) in
    if Float.abs (r -. 100.) > 0.5 || Float.abs (q.z -. 300.) > 0.5 then
      Alcotest.failf "back over MoveC leaves the circle at (%.1f, %.1f, %.1f)" q.x q.y q.z
  done;
  if !nearest > 1. then Alcotest.failf "back over MoveC passes %.1f mm from the circle point" !nearest;
  let t1 = now () in
  run "back";
  (* back over MoveL p2 (a fly-by point forward): on the line to p1, ending there at a stop point *)
  close "back over MoveL" (at ()) (350., -100., 300.);
  let mid = (MM.Planner.pose_at (p ()) ((t1 +. now ()) /. 2.)).trans in
  if Float.abs (mid.x -. 350.) > 0.5 || Float.abs (mid.z -. 300.) > 0.5 then
    Alcotest.failf "back over MoveL leaves the line at (%.1f, %.1f, %.1f)" mid.x mid.y mid.z;
  run "back";
  (* back over MoveJ p1: to the axis angles it started from, jStart *)
  (match MM.Planner.joints_at (p ()) (now ()) with
   | Ok j -> Alcotest.(check (array (float 1e-3))) "back over MoveJ: at jStart" [| 0.; 0.; 0.; 0.; 30.; 0. |] j
   | Error _ -> Alcotest.fail "no axis angles");
  run "back";
  (match MM.Planner.joints_at (p ()) (now ()) with
   | Ok j -> Alcotest.(check (array (float 1e-3))) "back over MoveAbsJ: at the start (axes 0)" [| 0.; 0.; 0.; 0.; 0.; 0. |] j
   | Error _ -> Alcotest.fail "no axis angles");
  Alcotest.(check (list string)) "the rules" [ "backward-move"; "backward-end" ]
    (List.filter (fun r -> r = "backward-move" || r = "backward-end") (D.rules d) |> List.sort_uniq compare |> List.rev)

(* At the first statement of a list inside a compound statement, back refuses, saying why. *)
let back_at_top_of_inner_list () =
  let file = program {|MODULE m
  VAR num x := 0;
  PROC main()
    IF x = 0 THEN
      x := 1;
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE
|} in
  let out, _, _ = session [ file ] [ "step"; "back"; "step"; "back" ] in
  let has sub = try ignore (Str.search_forward (Str.regexp_string sub) out 0); true with Not_found -> false in
  if not (has "the first statement of a list inside a compound statement (IF, FOR, WHILE, TEST), which cannot be \
               executed backward") then Alcotest.failf "no reason given: %s" out

let suite =
  ("debugger",
   [ Alcotest.test_case "backward rules documented" `Quick backward_rules_documented;
     Alcotest.test_case "backward rules in the golden sessions" `Quick backward_rules_exercised;
     Alcotest.test_case "back in an error handler" `Quick back_in_handler;
     Alcotest.test_case "BACKWARD handler scope" `Quick handler_scope;
     Alcotest.test_case "step limit" `Quick step_limit;
     Alcotest.test_case "malformed commands say what they expect" `Quick malformed_commands;
     Alcotest.test_case "back at the top of an IF's list" `Quick back_at_top_of_inner_list;
     Alcotest.test_case "MoveC, MoveL, MoveJ, MoveAbsJ stepped backward retrace their moves" `Quick back_moves_retrace ])
