(* The controller around the program (doc/controller.md): the stimulus file and EIO.cfg reader,
   the world's clock, events and interrupt queue, the wall clock, and the reproducibility of a
   whole run. *)

module Io = Rapid_controller.Io_config
module W = Rapid_controller.World

let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

let parse text = Io.parse ~file:"t.io" text

let error_of text = match parse text with Error m -> m | Ok _ -> Alcotest.fail "accepted"

let stimulus_file () =
  match parse "# comment\nsignal di1 di   # trailing comment\nsignal go1 GO 7\n\nat 0.5 di1 1\nat 0.5 di1 0\n" with
  | Error m -> Alcotest.fail m
  | Ok c ->
      Alcotest.(check (list string)) "names" [ "di1"; "go1" ] (List.map (fun (s : Io.signal) -> s.name) c.signals);
      Alcotest.(check (float 0.)) "initial" 7. (List.nth c.signals 1).initial;
      Alcotest.(check int) "events" 2 (List.length c.stimuli)

let stimulus_errors () =
  let check name expected text = Alcotest.(check string) name expected (error_of text) in
  check "type" "t.io:1:13: io error: unknown signal type \"dx\" (di, do, ai, ao, gi or go)" "signal di1  dx";
  check "undeclared" "t.io:1:6: io error: the signal di9 is not declared above" "at 1 di9 1";
  check "output" "t.io:2:6: io error: do1 is an output: the outside world changes inputs only" "signal do1 do\nat 1 do1 1";
  check "order" "t.io:3:4: io error: the events are not in order of time" "signal di1 di\nat 2 di1 1\nat 1 di1 0";
  check "digital" "t.io:2:10: io error: a digital signal takes the value 0 or 1" "signal di1 di\nat 1 di1 2";
  check "twice" "t.io:2:8: io error: the signal DI1 is declared twice" "signal di1 di\nsignal DI1 do";
  check "name" "t.io:1:8: io error: \"1x\" is not a RAPID identifier (§2.3), so it cannot name a signal" "signal 1x di";
  check "entry" "t.io:1:1: io error: unknown entry \"sig\" (signal, at or system-input)" "sig di1 di";
  check "number" "t.io:2:4: io error: \"soon\" is not a decimal number (such as 1, 0.25 or 1e-3)"
    "signal di1 di\nat soon di1 1";
  Alcotest.(check string) "missing file" "no-such.io:1:1: io error: cannot read the file (no-such.io: No such file or directory)"
    (match Io.read_file "no-such.io" with Error m -> m | Ok _ -> "")

let eio_file () =
  let text = "EIO:CFG_1.0:6:1::\n#\nEIO_DEVICE:\n  -Name \"d1\" -Address 10\nEIO_SIGNAL:\n\n  -Name \"a\" -SignalType \"DI\" -Device \"d1\"\n  -Name \"b\" -SignalType \"AO\" \\\n    -Default 2.5\n#\nEIO_CROSS:\n  -Name \"x\" -SignalType \"DO\"\n" in
  match parse text with
  | Error m -> Alcotest.fail m
  | Ok c ->
      Alcotest.(check (list string)) "signals" [ "a"; "b" ] (List.map (fun (s : Io.signal) -> s.name) c.signals);
      Alcotest.(check (float 0.)) "default" 2.5 (List.nth c.signals 1).initial;
      Alcotest.(check string) "missing type" "t.io:2:1: io error: an EIO_SIGNAL entry without -SignalType"
        (error_of "EIO_SIGNAL:\n  -Name \"a\"\n")

(* R-13-speedlim1: EIO.cfg's SYSSIG_IN and a stimulus's system-input lines; LimitSpeed is active
   while its digital input is 1. A SYSSIG_IN entry of an unconfigured signal starts nothing; a
   system-input line names a declared DI. *)
let system_inputs () =
  let eio = "EIO:CFG_1.0:6:1::\nEIO_SIGNAL:\n  -Name \"diLim\" -SignalType \"DI\"\n#\nSYSSIG_IN:\n\n\
             \  -Signal \"diMotOn\" -Action \"MotorOn\"\n  -Signal \"diLim\" -Action \"LimitSpeed\" \\\n\
             \    -Arg6 \"ROB_1\"\n#\n" in
  (match parse eio with
   | Error m -> Alcotest.fail m
   | Ok c ->
       Alcotest.(check (list (pair string string))) "SYSSIG_IN" [ ("LimitSpeed", "diLim") ]
         (List.map (fun (si : Io.system_input) -> (si.action, si.input)) c.system_inputs);
       Alcotest.(check string) "-Arg6" "ROB_1" (List.hd c.system_inputs).arg6);
  (match parse "signal di_lim di\nsystem-input LimitSpeed di_lim ROB_1\nat 1 di_lim 1\n" with
   | Error m -> Alcotest.fail m
   | Ok c ->
       let w = W.create c in
       Alcotest.(check bool) "inactive at 0" false (W.system_input_active w ~action:"LimitSpeed");
       W.advance_to w 1.;
       Alcotest.(check bool) "active at 1" true (W.system_input_active w ~action:"limitspeed");
       Alcotest.(check bool) "another action" false (W.system_input_active w ~action:"MotorOn"));
  Alcotest.(check string) "undeclared" "t.io:1:25: io error: the signal di_x is not declared above"
    (error_of "system-input LimitSpeed di_x\n");
  Alcotest.(check string) "not a DI" "t.io:2:25: io error: do1 is not a digital input: a system input is one"
    (error_of "signal do1 do\nsystem-input LimitSpeed do1\n")

(* A million statements of 1 microsecond are exactly one second: the clock counts
   microseconds, not sums of floats. *)
let exact_clock () =
  let w = W.create ~statement_time:0.000001 Io.empty in
  for _ = 1 to 1_000_000 do W.statement w done;
  Alcotest.(check (float 0.)) "1 s" 1. (W.now w)

let events_in_order () =
  let io = match parse "signal di1 di\nsignal di2 di\nat 1 di1 1\nat 1 di2 1\nat 2 di1 0\n" with
    | Ok c -> c | Error m -> Alcotest.fail m in
  let w = W.create io in
  Alcotest.(check (option (float 0.))) "next" (Some 1.) (W.next_event w);
  W.advance_to w 1.5;
  let seen = List.map (function
      | W.Signal_changed { signal; value; _ } -> Printf.sprintf "%s=%g" signal value
      | _ -> "?") (W.drain w) in
  Alcotest.(check (list string)) "same time: file order" [ "di1=1"; "di2=1" ] seen;
  Alcotest.(check (option (float 0.))) "next" (Some 2.) (W.next_event w)

let queue () =
  let w = W.create Io.empty in
  let n = match W.connect w ~trap:7 with Ok n -> n | Error e -> Alcotest.fail e in
  ignore (W.order_timer w n ~period:0.1 ~single:false);
  W.disable w;
  W.advance_to w 10.;
  Alcotest.(check (option (pair int int))) "disabled" None (W.take w);
  W.enable w;
  let rec count k = match W.take w with Some (m, 7) when m = n -> count (k + 1) | _ -> k in
  Alcotest.(check int) "queue capacity" W.queue_capacity (count 0);
  let discarded = List.length (List.filter (function W.Interrupt_discarded _ -> true | _ -> false) (W.drain w)) in
  Alcotest.(check int) "discarded" (100 - W.queue_capacity) discarded;
  Alcotest.(check (result unit string)) "unknown number" (Error "ERR_UNKINO") (W.sleep w 99)

(* IDelete takes the number's occurrences out of the queue (R-8-x); ISleep refuses a safe
   interrupt (R-8-w); a time as large as a num holds never falls due (R-8-j). *)
let delete_safe_never () =
  let w = W.create Io.empty in
  let connect () = match W.connect w ~trap:7 with Ok n -> n | Error e -> Alcotest.fail e in
  let a = connect () and b = connect () in
  ignore (W.order_timer w a ~period:0.1 ~single:true);
  ignore (W.order_timer w b ~period:0.2 ~single:true);
  W.disable w;
  W.advance_to w 1.;
  ignore (W.drain w);
  W.delete w a;
  let discarded = List.filter_map (function
      | W.Interrupt_discarded { number; reason; _ } -> Some (number, reason) | _ -> None) (W.drain w) in
  Alcotest.(check (list (pair int string))) "dropped" [ (a, "deleted (IDelete)") ] discarded;
  let a' = connect () in
  Alcotest.(check int) "the freed number again" a a';
  W.enable w;
  Alcotest.(check (option (pair int int))) "only b's" (Some (b, 7)) (W.take w);
  Alcotest.(check (option (pair int int))) "then none" None (W.take w);
  W.set_safe w a' ~safe:true;
  Alcotest.(check (result unit string)) "safe" (Error "ERR_INOISSAFE") (W.sleep w a');
  W.set_safe w a' ~safe:false;
  Alcotest.(check (result unit string)) "not safe" (Ok ()) (W.sleep w a');
  Alcotest.(check bool) "never" true (W.seconds 3e38 > W.seconds 1e11 && W.seconds 3e38 = W.seconds nan);
  ignore (W.order_timer w b ~period:3e38 ~single:false);
  Alcotest.(check bool) "not due" true (match W.next_event w with Some t -> t >= 1e12 | None -> false)

let wall_clock () =
  let show t = let y, m, d, h, mi, s, wd = Rapid_installed.Io_routines.date_time t in
    Printf.sprintf "%04d-%02d-%02d %02d:%02d:%02d %d" y m d h mi s wd in
  Alcotest.(check string) "epoch" "2024-01-01 00:00:00 1" (show W.default_epoch);
  Alcotest.(check string) "1970" "1970-01-01 00:00:00 4" (show 0.);
  Alcotest.(check string) "leap day" "2024-02-29 23:59:59 4" (show (W.default_epoch +. (59. *. 86400.) +. 86399.))

(* The same program with the same stimulus gives the same events, byte for byte. *)
let reproducible_with args () =
  let run () =
    let out = Filename.temp_file "rapid-sem" ".json" in
    let command = Printf.sprintf "cd golden && %s %s --io controller-cell.io controller-cell.mod > %s"
        (Filename.quote binary) args (Filename.quote out) in
    let status = Sys.command command in
    let ic = open_in_bin out in
    let text = Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic)) in
    Sys.remove out; (status, text)
  in
  let s1, first = run () and s2, second = run () in
  Alcotest.(check int) "exit" 0 s1;
  Alcotest.(check int) "exit again" 0 s2;
  Alcotest.(check bool) "events" true (String.length first > 1000);
  Alcotest.(check string) "byte-identical" first second

(* Any text, and texts made of the files' own words: the reader answers, never raises. *)
let never_raises () =
  let words = [| "signal"; "at"; "di"; "do"; "gi"; "ai"; "x1"; "1"; "0"; "-1"; "0.5"; "1e400"; "nan";
                 "#"; "\\"; "\n"; "\r\n"; " "; "\t"; "EIO_SIGNAL:"; "EIO:CFG_1.0::"; "-Name"; "\"";
                 "-SignalType"; "\"DI\""; "-Default"; "EIO_CROSS:"; "-" |] in
  let gen = QCheck.Gen.(oneof [
      string_size ~gen:printable (0 -- 200);
      map (String.concat "") (list_size (0 -- 60) (oneofa words)) ]) in
  QCheck.Test.check_exn ~rand:(Random.State.make [| 8 |])
    (QCheck.Test.make ~count:3000 ~name:"io reader" (QCheck.make ~print:(Printf.sprintf "%S") gen)
       (fun text -> match Io.parse ~file:"f" text with
          | Ok _ -> true
          | Error m -> String.length m > 5 && String.sub m 0 2 = "f:"))

(* Issue 21, item 3: a number of the file is checked against what it feeds, at its own word
   (R-8-numbers1); before, 1e300 or 3.5e38 reached the run and ended in an internal error. *)
let numbers_checked () =
  let check name expected text = Alcotest.(check string) name expected (error_of text) in
  let beyond w = Printf.sprintf "%s is beyond the range of num (IEEE 754 single precision, at most \
                                 3.40282347E+38 in magnitude; §2.13)" w in
  check "analog initial 1e300" ("t.io:1:13: io error: " ^ beyond "1e300") "signal a ai 1e300";
  check "analog initial 3.5e38" ("t.io:1:13: io error: " ^ beyond "3.5e38") "signal a ai 3.5e38";
  check "analog value 1e300" ("t.io:2:8: io error: " ^ beyond "-1e300") "signal a ai\nat 1 a -1e300";
  check "time 1e300" ("t.io:2:4: io error: " ^ beyond "1e300") "signal a di\nat 1e300 a 1";
  check "group 1e300" ("t.io:1:13: io error: " ^ beyond "1e300") "signal g gi 1e300";
  check "group beyond 32 bits"
    "t.io:2:8: io error: 4294967296 does not fit in the group signal's 32 bits (at most 4294967295)"
    "signal g gi\nat 1 g 4294967296";
  List.iter (fun w ->
      check ("time " ^ w) (Printf.sprintf "t.io:2:4: io error: %S is not a decimal number (such as 1, 0.25 or 1e-3)" w)
        ("signal a di\nat " ^ w ^ " a 1"))
    [ "0x10"; "1_0"; "nan"; "inf"; "-inf"; "infinity"; "1e"; "."; "+"; "1e+"; "0b1"; "1.5f"; "_1" ];
  check "value nan" "t.io:2:8: io error: \"nan\" is not a decimal number (such as 1, 0.25 or 1e-3)"
    "signal a ai\nat 1 a nan";
  match parse "signal a ai 3.4e38\nsignal g gi 4294967295\nsignal b ai -0\nat 1e+06 a .5\nat 1E6 a -2.5e-3\n" with
  | Error m -> Alcotest.fail m
  | Ok c ->
      Alcotest.(check (list (float 0.))) "initial values" [ 3.4e38; 4294967295.; 0. ]
        (List.map (fun (s : Io.signal) -> s.initial) c.signals);
      Alcotest.(check bool) "-0 is 0" false (Float.sign_bit (List.nth c.signals 2).initial);
      Alcotest.(check (list (float 0.))) "times" [ 1e6; 1e6 ] (List.map (fun (s : Io.stimulus) -> s.time) c.stimuli)

let eio_numbers () =
  let check name expected text = Alcotest.(check string) name expected (error_of ("EIO_SIGNAL:\n" ^ text)) in
  check "group beyond its -DeviceMap, on the continued line"
    "t.io:3:14: io error: 16 does not fit in the group signal's 4 bits (at most 15)"
    "  -Name \"g\" -SignalType \"GI\" -DeviceMap \"0-3\" \\\n    -Default 16\n";
  check "-DeviceMap of two ranges" "t.io:2:61: io error: 256 does not fit in the group signal's 8 bits (at most 255)"
    "  -Name \"g\" -SignalType \"GO\" -DeviceMap \"0-3,8-11\" -Default 256\n";
  check "analog below -MinLog" "t.io:2:60: io error: -6 is below the signal's -MinLog -5"
    "  -Name \"b\" -SignalType \"AI\" -MinLog -5 -MaxLog 5 -Default -6\n";
  check "-Default 1e300" ("t.io:2:39: io error: 1e300 is beyond the range of num (IEEE 754 single precision, at \
                           most 3.40282347E+38 in magnitude; §2.13)")
    "  -Name \"b\" -SignalType \"AI\" -Default 1e300\n";
  check "-DeviceMap wider than 32 bits"
    "t.io:2:41: io error: -DeviceMap \"0-40\" maps 41 bits: a group signal has at most 32"
    "  -Name \"g\" -SignalType \"GI\" -DeviceMap \"0-40\"\n";
  match parse "EIO_SIGNAL:\n  -Name \"g\" -SignalType \"GI\" -DeviceMap \"0-3\" -Default 15\n\
               \  -Name \"b\" -SignalType \"AI\" -MinLog -5 -MaxLog 5 -Default -4.5\n" with
  | Error m -> Alcotest.fail m
  | Ok c ->
      Alcotest.(check (list (float 0.))) "defaults" [ 15.; -4.5 ]
        (List.map (fun (s : Io.signal) -> s.initial) c.signals)

(* What the attacker of issue 21 found after the numbers' fix (R-8-small3): a repeated
   attribute, an overlapping -DeviceMap, an empty one, -Default without a value, and num's
   largest value as --save writes it. *)
let eio_small () =
  let check name expected text = Alcotest.(check string) name expected (error_of ("EIO_SIGNAL:\n" ^ text)) in
  check "-Default twice, at the second"
    "t.io:2:43: io error: -Default is given twice in this EIO_SIGNAL entry"
    "  -Name \"ai1\" -SignalType \"AI\" -Default 1 -Default 1e300\n";
  check "-Name twice, case aside"
    "t.io:2:30: io error: -name is given twice in this EIO_SIGNAL entry"
    "  -Name \"a\" -SignalType \"AI\" -name \"b\"\n";
  check "overlapping ranges count their bits once"
    "t.io:2:60: io error: 255 does not fit in the group signal's 6 bits (at most 63)"
    "  -Name \"g\" -SignalType \"GI\" -DeviceMap \"0-3,2-5\" -Default 255\n";
  check "-DeviceMap \"\"" "t.io:2:41: io error: -DeviceMap has no value"
    "  -Name \"g\" -SignalType \"GI\" -DeviceMap \"\" -Default 1\n";
  check "-Default without a value" "t.io:2:30: io error: -Default has no value"
    "  -Name \"a\" -SignalType \"AI\" -Default\n";
  check "-Default without a value, another key after"
    "t.io:2:30: io error: -Default has no value"
    "  -Name \"a\" -SignalType \"AI\" -Default -MinLog 0\n";
  (match parse "EIO_SIGNAL:\n  -Name \"g\" -SignalType \"GI\" -DeviceMap \"0-3,2-5\" -Default 63\n\
               \  -Name \"h\" -SignalType \"GO\" -DeviceMap \"4-7,0-31,3\" -Default 4294967295\n" with
   | Error m -> Alcotest.fail m
   | Ok c -> Alcotest.(check (list (float 0.))) "within the distinct bits" [ 63.; 4294967295. ]
               (List.map (fun (s : Io.signal) -> s.initial) c.signals));
  (* num's largest value, 3.40282347E+38, has the shortest literal 3.4028235E+38, above it as a
     decimal but rounded to it as a RAPID literal is; half a unit of its last place above is not. *)
  let flt_max = Int32.float_of_bits 0x7f7fffffl in
  (match parse "signal ai1 ai 3.4028235E+38\nsignal ai2 ai -3.4028235E+38\nat 1 ai1 3.40282356E+38\n" with
   | Error m -> Alcotest.fail m
   | Ok c ->
       Alcotest.(check (list (float 0.))) "initial values" [ flt_max; -. flt_max ]
         (List.map (fun (s : Io.signal) -> s.initial) c.signals);
       Alcotest.(check (list (float 0.))) "the value" [ flt_max ]
         (List.map (fun (s : Io.stimulus) -> s.value) c.stimuli));
  Alcotest.(check string) "half a unit above"
    "t.io:1:15: io error: 3.4028236E+38 is beyond the range of num (IEEE 754 single precision, at most \
     3.40282347E+38 in magnitude; §2.13)" (error_of "signal ai1 ai 3.4028236E+38")

(* A UTF-8 byte order mark first is not an entry; the columns of line 1 count after it. *)
let byte_order_mark () =
  (match parse "\xEF\xBB\xBFsignal di1 di\nat 1 di1 1\n" with
   | Ok c -> Alcotest.(check (list string)) "signals" [ "di1" ] (List.map (fun (s : Io.signal) -> s.name) c.signals)
   | Error m -> Alcotest.fail m);
  Alcotest.(check string) "column after the mark"
    "t.io:1:12: io error: unknown signal type \"dx\" (di, do, ai, ao, gi or go)"
    (error_of "\xEF\xBB\xBFsignal di1 dx")

(* A signal named after an installed object: the checker's error at the stimulus file's line
   and column, not in the generated module of the signals. *)
let installed_name_clash () =
  match parse "# the cell\nsignal di1 di\n  signal tool0 do\n" with
  | Error m -> Alcotest.fail m
  | Ok io -> (
      match Rapid_load.Session.load_modules ~io [] with
      | Error (Static reports) ->
          let errors = List.filter (fun (r : Rapid_typing.Report.t) -> r.severity = Error) reports in
          Alcotest.(check (list string)) "at the stimulus line"
            [ "t.io:3:10: semantic error: the installed object tool0 is declared twice (§13)" ]
            (List.map Rapid_typing.Report.headline errors)
      | Error _ -> Alcotest.fail "another failure"
      | Ok _ -> Alcotest.fail "accepted")

(* Issue 21, item 9: declaring n signals takes time linear in n. 100,000 signals took minutes
   when every pair was compared (Io_config's duplicate check, Session.connect_signals). *)
let many_signals () =
  let n = 100_000 in
  let text = String.concat "" (List.init n (fun i -> Printf.sprintf "signal s%d di\n" i))
             ^ String.concat "" (List.init (n / 10) (fun i -> Printf.sprintf "at %d s%d 1\n" i (i * 10))) in
  let t0 = Sys.time () in
  let io = match parse text with Ok io -> io | Error m -> Alcotest.fail m in
  let read = Sys.time () -. t0 in
  Alcotest.(check int) "signals" n (List.length io.signals);
  (match Rapid_load.Session.load_modules ~io [] with
   | Ok _ -> () | Error _ -> Alcotest.fail "refused");
  let loaded = Sys.time () -. t0 in
  Alcotest.(check bool) (Printf.sprintf "read in %.1f s (under 5 s)" read) true (read < 5.);
  Alcotest.(check bool) (Printf.sprintf "read, checked and connected in %.1f s (under 40 s)" loaded) true (loaded < 40.)

let suite =
  ("controller", [
      Alcotest.test_case "the stimulus file" `Quick stimulus_file;
      Alcotest.test_case "errors in the stimulus file: FILE:LINE:COL" `Quick stimulus_errors;
      Alcotest.test_case "EIO.cfg: EIO_SIGNAL entries" `Quick eio_file;
      Alcotest.test_case "system inputs: SYSSIG_IN, system-input (R-13-speedlim1)" `Quick system_inputs;
      Alcotest.test_case "the io reader never raises" `Quick never_raises;
      Alcotest.test_case "numbers checked against what they feed (R-8-numbers1)" `Quick numbers_checked;
      Alcotest.test_case "EIO.cfg numbers: -DeviceMap, -MinLog/-MaxLog, at the word" `Quick eio_numbers;
      Alcotest.test_case "EIO.cfg: a repeated attribute, overlapping or empty maps, values missing; num's largest"
        `Quick eio_small;
      Alcotest.test_case "a UTF-8 byte order mark" `Quick byte_order_mark;
      Alcotest.test_case "a signal named after an installed object, at its line" `Quick installed_name_clash;
      Alcotest.test_case "100,000 signals in linear time" `Quick many_signals;
      Alcotest.test_case "the clock counts microseconds exactly" `Quick exact_clock;
      Alcotest.test_case "timed events in order" `Quick events_in_order;
      Alcotest.test_case "the interrupt queue and its capacity" `Quick queue;
      Alcotest.test_case "IDelete, safe interrupts, times that never come" `Quick delete_safe_never;
      Alcotest.test_case "the wall clock (CDate, CTime, GetTime)" `Quick wall_clock;
      Alcotest.test_case "two runs give byte-identical run --json" `Quick (reproducible_with "run --json");
      Alcotest.test_case "two traces give byte-identical jsonl" `Quick (reproducible_with "trace --format jsonl");
    ])
