(* No internal error and bounded resources, on the static side: long lists go through every phase
   (parse, print, dump, check, lower, run) without recursion that grows with their length; long
   chains of types and constants are checked in time linear in their length; initial values are
   known before the run (doc/rulings.md R-3.2-a, R-3.2-b, R-2.5-c), so a program that passes the
   static semantics never meets their errors when it runs; the conformance runner reports what it
   cannot read. The generated programs are built here, not committed. *)

open Rapid_syntax
module M = Rapid_semantics.Machine
module S = Rapid_load.Session

let repeat n f =
  let b = Buffer.create (n * 24) in
  for i = 0 to n - 1 do Buffer.add_string b (f i) done;
  Buffer.contents b

let parse name text =
  match Parse.parse_string ~name:"long.mod" text with
  | Ok m -> m
  | Error d -> Alcotest.failf "%s: %s" name (Diagnostic.to_string d)

let reports rs = String.concat "\n" (List.map Rapid_typing.Report.to_string rs)

let load name m =
  match S.load_modules [ m ] with
  | Ok loaded -> loaded.program
  | Error (Static rs) -> Alcotest.failf "%s: refused:\n%s" name (reports rs)
  | Error (Front_end ds) -> Alcotest.failf "%s: %s" name (Diagnostic.to_string (List.hd ds))
  | Error (Internal m) -> Alcotest.failf "%s: %s" name m

(* Runs main; the output lines, or a failure unless the task ends. *)
let run ?(max_steps = 20_000_000) name program =
  match M.start ~host:(Rapid_run.Run.setup ()).host program ~entry:"main" with
  | Error m -> Alcotest.failf "%s: cannot run: %s" name m
  | Ok cfg ->
      let output = ref [] in
      while M.outcome cfg = Running && M.steps cfg < max_steps do
        let _, events = M.step cfg in
        List.iter (function Rapid_runtime.Event.Output s -> output := s :: !output | _ -> ()) events
      done;
      (match M.outcome cfg with
       | Ended -> ()
       | Stopped { name = e; _ } -> Alcotest.failf "%s: stopped by %s" name e
       | Stuck m -> Alcotest.failf "%s: stuck: %s" name m
       | Running | Resource_exhausted _ | Unsupported _ | Deadlock _ -> Alcotest.failf "%s: did not end" name);
      List.rev !output

(* Every phase on one program: printed and read back to the same tree, dumped, checked, lowered,
   its initial values evaluated, and run to [expected]. *)
let every_phase ?(read_back = true) name text expected =
  let m = parse name text in
  let dump = Ast_dump.module_declaration m in
  let printed = Printer.module_declaration m in
  if read_back && Ast_dump.module_declaration (parse (name ^ ", printed") printed) <> dump then
    Alcotest.failf "%s: printing changed the tree" name;
  Alcotest.(check (list string)) name expected (run name (load name m))

let in_main ?(declarations = "") ?(routines = "") body =
  "MODULE long\n" ^ declarations ^ "  PROC main()\n" ^ body ^ "  ENDPROC\n" ^ routines ^ "ENDMODULE\n"

(* Checking time, against a bound far above a linear checker's and far below a cubic one's
   (2,000 chained records took 17 s before). *)
let quickly name seconds f =
  let t0 = Unix.gettimeofday () in
  f ();
  let t = Unix.gettimeofday () -. t0 in
  if t > seconds then Alcotest.failf "%s took %.1f s" name t

let long_lists () =
  let n = 200_000 in
  every_phase ~read_back:false "200,000 ELSEIF clauses"
    (in_main
       ("    VAR num x := 1000;\n    IF x = 0 THEN\n      x := -1;\n"
        ^ repeat n (fun i -> Printf.sprintf "    ELSEIF x = %d THEN\n      x := %d;\n" (i + 1) (-i - 2))
        ^ "    ELSE\n      x := 0;\n    ENDIF\n    TPWrite \"x=\" \\Num:=x;\n"))
    [ "x=-1001" ];
  let n = 300_000 in
  every_phase ~read_back:false "300,000 values in one CASE"
    (in_main
       ("    VAR num x := 1000;\n    TEST x\n    CASE "
        ^ String.concat ", " (List.init n string_of_int)
        ^ ":\n      TPWrite \"hit\";\n    DEFAULT:\n      TPWrite \"miss\";\n    ENDTEST\n"))
    [ "hit" ];
  let n = 10_000 in
  every_phase "10,000 CASE clauses in one TEST"
    (in_main
       ("    VAR num x := " ^ string_of_int (n - 1) ^ ";\n    TEST x\n"
        ^ repeat n (fun i -> Printf.sprintf "    CASE %d:\n      x := %d;\n" i (i + 1))
        ^ "    ENDTEST\n    TPWrite \"x=\" \\Num:=x;\n"))
    [ Printf.sprintf "x=%d" n ];
  (* Long statement lists: test_semantics.ml runs 500,000 statements, test_fuzz.ml parses 1,000,000. *)
  let n = 10_000 in
  quickly "10,000 labels and GOTOs" 5.0 (fun () ->
      every_phase "10,000 labels and GOTOs"
        (in_main
           ("    VAR num x := 0;\n"
            ^ repeat n (fun i -> Printf.sprintf "  l%d:\n    x := x + 1;\n" i)
            ^ repeat n (fun i -> Printf.sprintf "    IF x < 0 GOTO l%d;\n" i)
            ^ "    TPWrite \"x=\" \\Num:=x;\n"))
        [ Printf.sprintf "x=%d" n ]);
  let n = 5_000 in
  every_phase "a call with 5,000 arguments"
    (in_main
       ~routines:("  PROC many(" ^ String.concat ", " (List.init n (Printf.sprintf "num a%d"))
                  ^ ")\n    TPWrite \"last=\" \\Num:=a" ^ string_of_int (n - 1) ^ ";\n  ENDPROC\n")
       ("    many " ^ String.concat ", " (List.init n string_of_int) ^ ";\n"))
    [ Printf.sprintf "last=%d" (n - 1) ];
  every_phase "a constant array of 50,000 members"
    (in_main
       ~declarations:("  CONST num a{50000} := [" ^ String.concat "," (List.init 50_000 string_of_int) ^ "];\n")
       "    TPWrite \"a=\" \\Num:=a{50000};\n")
    [ "a=49999" ]

let accepted name text = ignore (load name (parse name text))

let chains_of_types () =
  let n = 2000 in
  quickly "2,000 chained records" 3.0 (fun () ->
      accepted "2,000 chained records"
        ("MODULE chain\n  RECORD r0\n    num a;\n  ENDRECORD\n"
         ^ repeat (n - 1) (fun i -> Printf.sprintf "  RECORD r%d\n    r%d a;\n  ENDRECORD\n" (i + 1) i)
         ^ Printf.sprintf "  VAR r%d v;\n  PROC main()\n    v.a.a.a := v.a.a.a;\n  ENDPROC\nENDMODULE\n" (n - 1)));
  quickly "2,000 records chained through aliases" 3.0 (fun () ->
      accepted "2,000 records chained through aliases"
        ("MODULE chain\n  RECORD r0\n    num a;\n  ENDRECORD\n  ALIAS r0 t0;\n"
         ^ repeat (n - 1) (fun i ->
             Printf.sprintf "  RECORD r%d\n    t%d a;\n  ENDRECORD\n  ALIAS r%d t%d;\n" (i + 1) i (i + 1) (i + 1))
         ^ Printf.sprintf "  VAR t%d v;\n  PROC main()\n  ENDPROC\nENDMODULE\n" (n - 1)));
  (* Each record has two components of the one before: 2^59 paths to r0 in r59, whose values
     are too large to build (R-1.4-c); r10's are not. *)
  let dag uses =
    "MODULE dag\n  RECORD r0\n    num a;\n  ENDRECORD\n"
    ^ repeat 59 (fun i -> Printf.sprintf "  RECORD r%d\n    r%d a;\n    r%d b;\n  ENDRECORD\n" (i + 1) i i)
    ^ uses ^ "  PROC main()\n  ENDPROC\nENDMODULE\n" in
  quickly "60 records, each of two of the one before" 3.0 (fun () ->
      accepted "60 records of two" (dag "  FUNC r7 inner(r10 x)\n    RETURN x.a.b.a;\n  ENDFUNC\n"));
  List.iter (fun (what, uses, line) ->
      quickly what 3.0 (fun () ->
          match S.load_modules [ parse what (dag uses) ] with
          | Error (Static (r :: _)) ->
              Alcotest.(check (pair string int)) what ("value-too-large", line)
                (r.rule, (Source.start r.region).line)
          | _ -> Alcotest.failf "%s: accepted" what))
    [ ("a variable of 2^59 components", "  VAR r59 v;\n", 241);
      ("a parameter of 2^59 components", "  PROC p(r59 x)\n  ENDPROC\n", 241);
      ("a function result of 2^41 components", "  FUNC r41 f()\n  ENDFUNC\n", 241) ];
  (* Below 2^40 the static semantics accepts: what a run's memory cannot hold is the memory
     budget's (R-1.4-b, spec/05-run/22-routine-data-beyond-memory), and nothing is built before
     the run. *)
  List.iter (fun (what, uses) ->
      quickly what 3.0 (fun () ->
          match S.load_modules [ parse what (dag uses) ] with
          | Ok _ -> ()
          | Error _ -> Alcotest.failf "%s: refused" what))
    [ ("a function result of 2^30 components", "  FUNC r30 f()\n  ENDFUNC\n");
      ("an array of 10^9 components", "  VAR num a{1000, 1000, 1000};\n") ];
  (* A cycle in a long chain is found, once per record on it. *)
  let m = parse "cycle" ("MODULE cycle\n  RECORD r0\n    r1999 a;\n  ENDRECORD\n"
                         ^ repeat (n - 1) (fun i -> Printf.sprintf "  RECORD r%d\n    r%d a;\n  ENDRECORD\n" (i + 1) i)
                         ^ "  PROC main()\n  ENDPROC\nENDMODULE\n") in
  quickly "a cycle of 2,000 records" 3.0 (fun () ->
      match S.load_modules [ m ] with
      | Error (Static rs) ->
          let cycles = List.filter (fun (r : Rapid_typing.Report.t) -> r.rule = "record-recursive") rs in
          Alcotest.(check int) "records reported on the cycle" n (List.length cycles)
      | _ -> Alcotest.fail "a cycle of records accepted")

let chains_of_constants () =
  let n = 5_000 in
  quickly "5,000 chained constants" 10.0 (fun () ->
      let text =
        "MODULE chain\n  CONST num c0 := 1;\n"
        ^ repeat (n - 1) (fun i -> Printf.sprintf "  CONST num c%d := c%d + 1;\n" (i + 1) i)
        ^ Printf.sprintf "  VAR num v{c%d};\n  PROC main()\n    TPWrite \"n=\" \\Num:=Dim(v, 1);\n  ENDPROC\nENDMODULE\n" (n - 1) in
      Alcotest.(check (list string)) "dimension" [ Printf.sprintf "n=%d" n ] (run "chain" (load "chain" (parse "chain" text))));
  (* The same chain declared backwards: each constant names the next one. *)
  quickly "5,000 constants, each naming the next" 10.0 (fun () ->
      let text =
        "MODULE chain\n"
        ^ repeat (n - 1) (fun i -> Printf.sprintf "  CONST num c%d := c%d + 1;\n" i (i + 1))
        ^ Printf.sprintf "  CONST num c%d := 1;\n  VAR num v{c0};\n  PROC main()\n    TPWrite \"n=\" \\Num:=c0;\n  ENDPROC\nENDMODULE\n" (n - 1) in
      Alcotest.(check (list string)) "value" [ Printf.sprintf "n=%d" n ] (run "chain" (load "chain" (parse "chain" text))));
  (* Each constant twice the one before, through both operands: one evaluation each. *)
  quickly "constants using the one before twice" 3.0 (fun () ->
      let text =
        "MODULE doubling\n  CONST num c0 := 1;\n"
        ^ repeat 200 (fun i -> Printf.sprintf "  CONST num c%d := c%d + c%d - c%d;\n" (i + 1) i i i)
        ^ "  VAR num v{c200 * 3};\n  PROC main()\n    VAR num x := 7 DIV c200;\n    TPWrite \"x=\" \\Num:=x;\n  ENDPROC\nENDMODULE\n" in
      Alcotest.(check (list string)) "value" [ "x=7" ] (run "doubling" (load "doubling" (parse "doubling" text))));
  (* Values that grow without bound in exact arithmetic are no trouble either. *)
  quickly "constants squaring the one before" 3.0 (fun () ->
      let m = parse "squares"
          ("MODULE squares\n  CONST num c0 := 3;\n"
           ^ repeat 200 (fun i -> Printf.sprintf "  CONST num c%d := c%d * c%d;\n" (i + 1) i i)
           ^ "  VAR num v{c200 DIV 2};\n  PROC main()\n  ENDPROC\nENDMODULE\n") in
      match S.load_modules [ m ] with
      | Error (Static (_ :: _)) -> ()
      | _ -> Alcotest.fail "an overflowing constant accepted")

(* ---------------------------------------------------------------- generated constants *)

(* Programs of constants and initialised variables, at module and routine level: chains, cycles,
   divisions by zero, overflow, numbers beyond num. Whatever they are, the static semantics
   answers without an exception, either with errors at places of the file, or by accepting; an
   accepted program runs to its end (its initial values cannot fail any more). *)
let constant_program =
  let open QCheck.Gen in
  (* Mostly harmless numbers, sometimes one at an edge of num. *)
  let literal = frequency [ (12, map string_of_int (int_range 0 9)); (1, return "0.5");
                            (1, oneofl [ "3E38"; "1E39"; "1E-50"; "16777216"; "8388608" ]) ] in
  let operator = frequency [ (4, oneofl [ "+"; "-"; "*" ]); (1, oneofl [ "/"; "DIV"; "MOD" ]) ] in
  (* A name, or an element of the constant array t (index possibly not an integer, or outside). *)
  let operand names depth expr =
    if depth > 0 then frequency [ (12, oneofl names); (1, map (Printf.sprintf "t{%s}") (expr names (depth - 1))) ]
    else oneofl names
  in
  let rec expr names depth =
    if depth = 0 || names = [] then
      if names = [] then literal else frequency [ (2, literal); (3, oneofl names) ]
    else
      frequency
        [ (2, literal); (3, operand names depth expr);
          (4, map3 (fun a op b -> Printf.sprintf "(%s %s %s)" a op b)
               (expr names (depth - 1)) operator
               (expr names (depth - 1)));
          (1, map (fun a -> "(-" ^ a ^ ")") (expr names (depth - 1))) ]
  in
  (* Strings: concatenations of constants that may pass 80 bytes. *)
  let text = oneofl [ "\"\""; "\"abc\""; "\"" ^ String.make 40 'x' ^ "\""; "\"" ^ String.make 79 'y' ^ "\"" ] in
  let rec string_expr names depth =
    if depth = 0 || names = [] then (if names = [] then text else frequency [ (1, text); (2, oneofl names) ])
    else
      frequency [ (1, text); (2, oneofl names);
                  (2, map2 (Printf.sprintf "%s + %s") (string_expr names (depth - 1)) (string_expr names (depth - 1))) ]
  in
  int_range 1 4 >>= fun k ->
  let module_names = List.init k (Printf.sprintf "c%d") in
  (* Module constants name mostly the ones before them, sometimes any: later ones, themselves
     (cycles). *)
  let rec module_constants i acc =
    if i = k then return (List.rev acc)
    else
      frequency [ (6, expr (List.filteri (fun j _ -> j < i) module_names) 2); (1, expr module_names 2) ]
      >>= fun e -> module_constants (i + 1) (e :: acc)
  in
  module_constants 0 [] >>= fun module_inits ->
  list_repeat 3 (expr module_names 1) >>= fun table ->
  int_range 0 2 >>= fun m ->
  let string_names = List.init m (Printf.sprintf "s%d") in
  let rec string_constants i acc =
    if i = m then return (List.rev acc)
    else
      frequency [ (4, string_expr (List.filteri (fun j _ -> j < i) string_names) 2); (1, string_expr string_names 2) ]
      >>= fun e -> string_constants (i + 1) (e :: acc)
  in
  string_constants 0 [] >>= fun string_inits ->
  int_range 0 3 >>= fun r ->
  let routine_names = List.init r (Printf.sprintf "v%d") in
  (* Routine data may name module constants and routine data declared before. *)
  let rec routine i acc =
    if i = r then return (List.rev acc)
    else
      expr (module_names @ List.filteri (fun j _ -> j < i) routine_names) 2 >>= fun e ->
      bool >>= fun const -> routine (i + 1) ((const, e) :: acc)
  in
  routine 0 [] >>= fun routine_inits ->
  return
    ("MODULE gen\n"
     ^ String.concat "" (List.mapi (fun i e -> Printf.sprintf "  CONST num c%d := %s;\n" i e) module_inits)
     ^ Printf.sprintf "  CONST num t{3} := [%s];\n" (String.concat ", " table)
     ^ String.concat "" (List.mapi (fun i e -> Printf.sprintf "  CONST string s%d := %s;\n" i e) string_inits)
     ^ "  PROC main()\n"
     ^ String.concat "" (List.mapi (fun i (const, e) ->
         Printf.sprintf "    %s num v%d := %s;\n" (if const then "CONST" else "VAR") i e) routine_inits)
     ^ String.concat "" (List.map (fun n -> Printf.sprintf "    TPWrite \"%s=\" \\Num:=%s;\n" n n)
                           (module_names @ routine_names))
     ^ String.concat "" (List.map (fun n -> Printf.sprintf "    TPWrite %s;\n" n) string_names)
     ^ "  ENDPROC\nENDMODULE\n")

let accepted_runs = ref 0 and refusals = ref 0

let answer text =
  match Parse.parse_string ~name:"gen.mod" text with
  | Error d -> QCheck.Test.fail_reportf "does not parse: %s" (Diagnostic.to_string d)
  | Ok m -> (
      match S.load_modules [ m ] with
      | exception e -> QCheck.Test.fail_reportf "the static semantics raised %s" (Printexc.to_string e)
      | Error (Static rs) ->
          List.iter (fun (r : Rapid_typing.Report.t) ->
              match Source.file_of r.region with
              | Some f when Source.name f = "gen.mod" && (Source.start r.region).line >= 1 -> ()
              | _ -> QCheck.Test.fail_reportf "a report without a place: %s" (Rapid_typing.Report.to_string r)) rs;
          if not (List.exists (fun (r : Rapid_typing.Report.t) -> r.severity = Error) rs) then
            QCheck.Test.fail_report "refused without an error";
          incr refusals;
          true
      | Error (Front_end _ | Internal _) -> QCheck.Test.fail_report "refused by the front end"
      | Ok loaded -> (
          match M.start ~host:(Rapid_run.Run.setup ()).host loaded.program ~entry:"main" with
          | Error m -> QCheck.Test.fail_reportf "cannot start: %s" m
          | Ok cfg -> (
              match
                while M.outcome cfg = Running && M.steps cfg < 100_000 do ignore (M.step cfg) done
              with
              | exception e -> QCheck.Test.fail_reportf "the run raised %s" (Printexc.to_string e)
              | () -> (
                  match M.outcome cfg with
                  | Ended -> incr accepted_runs; true
                  | Stopped { name; _ } -> QCheck.Test.fail_reportf "accepted, but stopped by %s" name
                  | Stuck m -> QCheck.Test.fail_reportf "stuck: %s" m
                  | Running | Resource_exhausted _ | Unsupported _ | Deadlock _ ->
                      QCheck.Test.fail_report "accepted, but did not end"))))

let generated_constants () =
  QCheck.Test.check_exn ~rand:(Random.State.make [| 20261123 |])
    (QCheck.Test.make ~count:300 ~name:"generated constants"
       (QCheck.make ~print:(fun s -> s) constant_program) answer);
  (* The generator reaches both answers, often. *)
  if !accepted_runs < 30 || !refusals < 30 then
    Alcotest.failf "%d programs accepted and run, %d refused: the generator misses one side"
      !accepted_runs !refusals

(* ---------------------------------------------------------------- no infinity at run time *)

(* R-3.12-c: no operator and no installed function makes an infinity or a NaN out of finite
   arguments, at the edges of num and dnum either: each gives a finite value or an error. *)
let rec finite (v : Rapid_runtime.Value.t) =
  match v with
  | Num x | Dnum x -> Float.is_finite x
  | Record a | Array a -> Array.for_all finite a
  | Bool _ | String _ | Handle _ -> true

let no_infinity () =
  let module V = Rapid_runtime.Value in
  let max_single = Int32.float_of_bits 0x7f7fffffl and min_single = Int32.float_of_bits 1l in
  let singles = [ 0.; -0.; 1.; -1.; 0.5; 90.; 360.; 8388608.; 16777216.; 1e30; -1e30;
                  max_single; -.max_single; min_single ] in
  let doubles = [ 0.; 1.; -1.; 0.5; 4503599627370496.; 1e300; -1e300; max_float; -.max_float; 4.9e-324 ] in
  let edges = [ 0.; 1.; max_single; -.max_single ] in
  let pos = List.concat_map (fun x -> List.concat_map (fun y -> List.map (fun z ->
      V.Record [| Num x; Num y; Num z |]) edges) edges) edges in
  let orients = List.map (fun (a, b, c, d) -> V.Record [| Num a; Num b; Num c; Num d |])
      [ (1., 0., 0., 0.); (max_single, 0., 0., max_single); (0.5, 0.5, 0.5, 0.5); (min_single, 0., 0., 0.) ] in
  let values = List.map (fun x -> V.Num x) singles @ List.map (fun x -> V.Dnum x) doubles @ pos @ orients in
  let check what r =
    match r with
    | Ok v when not (finite v) -> Alcotest.failf "%s gave %s" what (V.to_debug_string v)
    | Ok _ | Error _ -> ()
  in
  let apply what f = match f () with r -> check what r | exception V.Type_mismatch _ -> () in
  List.iter (fun (name, arity, f) ->
      let rec args k acc =
        if k = 0 then
          apply name (fun () ->
              let given = List.rev_map Option.some acc in
              f (Array.of_list (given @ List.init (arity - List.length given) (fun _ -> None))))
        else List.iter (fun v -> args (k - 1) (v :: acc)) (if arity > 2 then List.filteri (fun i _ -> i mod 3 = 0) values else values)
      in
      args (min arity 3) []) Rapid_installed.Library.functions;
  let ops = Rapid_runtime.Arith.[ Num_add; Num_sub; Num_mul; Num_div; Num_intdiv; Num_mod;
                                    Dnum_add; Dnum_sub; Dnum_mul; Dnum_div; Dnum_intdiv; Dnum_mod;
                                    Pos_add; Pos_sub; Num_pos_mul; Pos_num_mul; Pos_cross; Pos_num_div; Orient_mul ] in
  List.iter (fun op -> List.iter (fun a -> List.iter (fun b ->
      apply (Rapid_runtime.Arith.binary_name op) (fun () -> Rapid_runtime.Arith.binary op a b)) values) values) ops;
  (* Were an infinity to reach the formatting, it would be refused, not loop. *)
  (match Rapid_runtime.Text_format.num_text infinity with
   | exception V.Type_mismatch _ -> ()
   | s -> Alcotest.failf "an infinity written as %s" s);
  Alcotest.(check bool) "NumToStr of an infinity" true
    (Rapid_installed.Library.num_to_str (V.Num infinity) (V.Num 2.) ~exp:false = Error "ERR_OVERFLOW")

(* ---------------------------------------------------------------- the conformance runner *)

let runner () =
  let dir = Filename.concat (Filename.get_temp_dir_name ())
      (Printf.sprintf "rapid-sem-runner-%d" (Unix.getpid ())) in
  let ( / ) = Filename.concat in
  let write path text = let oc = open_out_bin path in output_string oc text; close_out oc in
  Unix.mkdir dir 0o755;
  Unix.mkdir (dir / "a") 0o755;
  write (dir / "a" / "ok.mod")
    "MODULE ok\n! @section 1.2\n! @expect ok\n  PROC main()\n  ENDPROC\nENDMODULE\n";
  Unix.symlink ".." (dir / "a" / "loop");
  Unix.symlink "self.mod" (dir / "self.mod");
  Unix.mkfifo (dir / "fifo.mod") 0o644;
  (* A file that cannot be read (not for root, who reads everything). *)
  let unreadable = Unix.geteuid () <> 0 in
  if unreadable then begin
    write (dir / "locked.mod") "MODULE locked\nENDMODULE\n";
    Unix.chmod (dir / "locked.mod") 0
  end;
  Unix.mkdir (dir / "b.task") 0o755;
  Unix.mkfifo (dir / "b.task" / "m.mod") 0o644;
  let cleanup () = ignore (Sys.command ("rm -rf " ^ Filename.quote dir)) in
  Fun.protect ~finally:cleanup (fun () ->
      let cases, errors = Rapid_conformance.Spec_runner.collect dir in
      let names l = List.sort compare (List.map (fun p -> String.sub p (String.length dir + 1) (String.length p - String.length dir - 1)) l) in
      Alcotest.(check (list string)) "cases" [ "a/ok.mod"; "b.task" ] (names cases);
      Alcotest.(check (list string)) "runner errors"
        ([ "a/loop"; "fifo.mod" ] @ (if unreadable then [ "locked.mod" ] else []) @ [ "self.mod" ])
        (names (List.map fst errors));
      (* The .task folder's FIFO is a problem of that case, found without opening it. *)
      let case = Rapid_conformance.Spec_case.read (dir / "b.task") in
      Alcotest.(check bool) "the FIFO in a task is a problem" true
        (List.exists (fun p -> String.length p > 0) case.problems);
      let buffer = Buffer.create 256 in
      let passed, failed = Rapid_conformance.Spec_runner.run (Format.formatter_of_buffer buffer) dir in
      Alcotest.(check (pair int int)) "passed, failed" (1, if unreadable then 5 else 4) (passed, failed))

let suite =
  ( "robustness",
    [ Alcotest.test_case "long lists through every phase" `Quick long_lists;
      Alcotest.test_case "chains of record and alias types" `Quick chains_of_types;
      Alcotest.test_case "chains of constants" `Quick chains_of_constants;
      Alcotest.test_case "generated constants: a static error at a place, or a run that ends" `Quick generated_constants;
      Alcotest.test_case "no infinity from finite numbers (R-3.12-c)" `Quick no_infinity;
      Alcotest.test_case "the conformance runner reports what it cannot read" `Quick runner ] )
