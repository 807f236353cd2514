(* What the engines keep between runs (bench/README.md, "Fuzzing throughput"): the machine's
   routine table, kept for the last program and started from the installed routines' table
   for the next, must be the table of the program run. Two programs over one installed
   environment whose user routines take the same numbers under different names, run one after
   the other by both engines: each finds its own routines by name, and not the other's. *)

let program_a = {|MODULE a
  PROC foo()
    TPWrite "foo of a";
  ENDPROC
  PROC main()
    %"foo"%;
    %"bar"%;
  ERROR
    TPWrite "no such procedure " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
|}

let program_b = {|MODULE b
  PROC bar()
    TPWrite "bar of b";
  ENDPROC
  PROC main()
    %"bar"%;
    %"foo"%;
  ERROR
    TPWrite "no such procedure " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
|}

let outputs text =
  let m = match Rapid_syntax.Parse.parse_string ~name:"sharing.mod" text with
    | Ok m -> m | Error _ -> Alcotest.fail "the program does not parse" in
  let program = match Rapid_fuzz.Fuzz_run.load m with
    | Ok l -> l.program | Error _ -> Alcotest.fail "the program does not check" in
  List.map (fun (e : Rapid_fuzz.Fuzz_run.engine) ->
      let o = e.run program ~max_steps:10_000 in
      (e.engine_name, List.filter (fun l -> String.length l > 7 && String.sub l 0 7 = "output ") o.events))
    [ Rapid_fuzz.Fuzz_run.machine; Rapid_fuzz.Fuzz_run.closure ]

let starts prefix l = String.length l >= String.length prefix && String.sub l 0 (String.length prefix) = prefix

(* [own] written by the program's own routine, then the handler's line for the other name
   (ERR_REFUNKPRC, §4.6), by both engines. *)
let expect name own got =
  List.iter (fun (engine, lines) ->
      match lines with
      | [ first; second ] when first = own && starts "output no such procedure " second -> ()
      | _ -> Alcotest.failf "%s, %s: %s" name engine (String.concat " | " lines)) got

let test =
  Alcotest.test_case "each program finds its own routines by name" `Quick (fun () ->
      let first_a = outputs program_a in
      let first_b = outputs program_b in
      let again_a = outputs program_a in
      let again_b = outputs program_b in
      expect "a" "output foo of a" first_a;
      expect "b" "output bar of b" first_b;
      expect "a again" "output foo of a" again_a;
      expect "b again" "output bar of b" again_b)

let suite = ("engine start sharing", [ test ])
