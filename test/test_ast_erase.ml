(* Ast_erase.equal is Ast_dump's equality (the fuzzer's round trip uses the former in place of
   the latter): on the printer tests' pairs of one tree in two spellings and of two trees
   differing in one detail, on every pair of many small generated trees, and on generated
   trees against their printed and parsed again copies. *)

open Rapid_syntax

let dump = Ast_dump.module_declaration

(* Ast_erase.equal compares without building the erased trees: it must also agree with the
   erased trees' structural equality, which it stands for. *)
let agrees name a b =
  let by_dump = dump a = dump b and by_erase = Ast_erase.equal a b in
  if by_dump <> by_erase then
    Alcotest.failf "%s: the dumps are %s, the erased trees %s" name
      (if by_dump then "equal" else "different") (if by_erase then "equal" else "different");
  let by_copies = Ast_erase.module_declaration a = Ast_erase.module_declaration b in
  if by_copies <> by_erase then
    Alcotest.failf "%s: the erased copies are %s, Ast_erase.equal says %s" name
      (if by_copies then "equal" else "different") (if by_erase then "equal" else "different")

let printer_pairs =
  Alcotest.test_case "the printer tests' pairs" `Quick (fun () ->
      let p = Test_printer.parse in
      List.iter (fun (a, b) ->
          agrees (Printf.sprintf "%S / %S" a b) (p a) (p b);
          if not (Ast_erase.equal (p a) (p b)) then Alcotest.failf "%S and %S: one tree, but not equal" a b)
        Test_printer.same_tree_spellings;
      List.iter (fun (a, b) ->
          let a = p (Test_printer.in_routine a) and b = p (Test_printer.in_routine b) in
          agrees "a different tree" a b;
          if Ast_erase.equal a b then Alcotest.failf "two trees found equal:\n%s" (dump a))
        Test_printer.different_trees)

(* A positional argument and a required one without a name are dumped alike: [P (a);] keeps the
   parentheses in the expression's region, not the argument's. *)
let argument_forms =
  Alcotest.test_case "positional and required arguments, regions" `Quick (fun () ->
      let p = Test_printer.parse in
      let m1 = p (Test_printer.in_routine "Foo (a), b;") and m2 = p (Test_printer.in_routine "Foo a, b;") in
      agrees "Foo (a) / Foo a" m1 m2;
      let m3 = p (Test_printer.in_routine "   Foo   a,b;") in
      agrees "layout" m2 m3;
      if not (Ast_erase.equal m2 m3) then Alcotest.fail "the same call in another layout differs")

(* Generated trees may hold the access mode REF, read only as the installed environment's
   modules are (as in Test_roundtrip). *)
let reparse i m =
  match Parse.parse_string ~options:{ Parse.default_options with installed = true } ~name:"erase.mod"
          (Printer.module_declaration m) with
  | Ok m' -> m'
  | Error d -> Alcotest.failf "module %d does not read back: %s" i (Diagnostic.to_string d)

(* Each generated tree (no regions) against the printed and parsed again copy (regions) of every
   other: equal on the diagonal, different elsewhere, and the two equalities agree on each. *)
let generated_pairs =
  Alcotest.test_case "every pair of generated modules and parsed copies" `Quick (fun () ->
      let st = Random.State.make [| 11 |] in
      let trees = Array.init 200 (fun _ -> Gen_ast.module_declaration ~max_size:6 () st) in
      let copies = Array.mapi reparse trees in
      let equal_pairs = ref 0 in
      Array.iteri (fun i a ->
          Array.iteri (fun j b ->
              agrees (Printf.sprintf "tree %d, copy of %d" i j) a b;
              if Ast_erase.equal a b then incr equal_pairs) copies) trees;
      if !equal_pairs < Array.length trees then
        Alcotest.failf "only %d equal pairs: a tree and its copy differ" !equal_pairs)

let round_trips =
  Alcotest.test_case "larger generated modules against their printed copies" `Quick (fun () ->
      let st = Random.State.make [| 12 |] in
      for i = 1 to 300 do
        let m = Gen_ast.module_declaration ~max_size:40 () st in
        agrees (Printf.sprintf "module %d" i) m (reparse i m)
      done)

let suite = ("ast erase", [ printer_pairs; argument_forms; generated_pairs; round_trips ])
