(* What the second real-programs campaign (doc/real-programs.md) found, pinned: the two engines
   refuse a run the same way when an initial value of module data names a data object that is
   neither declared nor installed (--allow-unknown: a module of a program whose other modules are
   missing, `VAR robtarget p := A_1;`). Reading the unknown name is ERR_REFUNKDAT (ch. 12), as
   in a statement; the machine said ERR_EXECPHR there before. A run with no entry routine is
   refused with the same words by both. *)

open Rapid_syntax
open Rapid_semantics
module M = Machine
module C = Closure_engine

let load name text =
  match Parse.parse_string ~name:(name ^ ".mod") text with
  | Error d -> Alcotest.failf "%s" (Diagnostic.to_string d)
  | Ok m -> (
      match Session.load_modules ~allow_unknown:true [ m ] with
      | Ok l -> l.program
      | Error _ -> Alcotest.failf "%s does not check with --allow-unknown" name)

let machine_refusal p ~entry =
  match M.start p ~entry with Ok _ -> "(runs)" | Error m -> m

let closure_refusal p ~entry =
  match C.events p ~entry with Ok _ -> "(runs)" | Error m -> m

let check_both what p ~entry expected =
  Alcotest.(check string) (what ^ ": machine") expected (machine_refusal p ~entry);
  Alcotest.(check string) (what ^ ": closure engine") expected (closure_refusal p ~entry)

let unknown_in_initial_value () =
  let p = load "unknown_init" {rapid|MODULE unknown_init
  VAR num a := b;
  PROC main()
    TPWrite "a" \Num:=a;
  ENDPROC
ENDMODULE|rapid} in
  check_both "whole name" p ~entry:"main" "the initial value of a: ERR_REFUNKDAT";
  let p = load "unknown_component" {rapid|MODULE unknown_component
  CONST num a := 1;
  VAR num c := q.x + a;
  PROC main()
  ENDPROC
ENDMODULE|rapid} in
  check_both "component of an unknown name" p ~entry:"main" "the initial value of c: ERR_REFUNKDAT"

let no_entry () =
  let p = load "no_entry" {rapid|MODULE no_entry
  PROC other()
  ENDPROC
ENDMODULE|rapid} in
  check_both "no main" p ~entry:"main" "no procedure main without parameters to run"

let suite =
  ( "realprog2",
    [ Alcotest.test_case "unknown name in an initial value: ERR_REFUNKDAT in both engines" `Quick unknown_in_initial_value;
      Alcotest.test_case "no entry routine: one refusal in both engines" `Quick no_entry ] )
