(* Each kind builds its modules as Program_gen programs, so that Fuzz_case.shrink can shrink a
   failing scenario statement by statement. The choices are few and deliberate: the rule a kind
   is for is reached in most of its scenarios, and the variations (handler endings, limits,
   times) are those the rule's cases in spec/ turn on. *)

open Program_gen

let pick rs l = List.nth l (Random.State.int rs (List.length l))
let chance rs p = Random.State.float rs 1. < p
let int_in rs lo hi = lo + Random.State.int rs (hi - lo + 1)
let lines = List.map (fun s -> Line s)

let proc ?(params = "") ?(data = []) ?error ?undo name body =
  { header = Printf.sprintf "PROC %s(%s)" name params; data; body = lines body;
    error = Option.map (fun e -> ("ERROR", lines e)) error; undo = Option.map lines undo; footer = "ENDPROC" }

let trap name body =
  { header = "TRAP " ^ name; data = []; body = lines body; error = None; undo = None; footer = "ENDTRAP" }

(* The stimulus: the signals of every generated program (Fuzz_run.io), the changes of di1 when
   the scenario keeps them, and its own events (a collision), in order of time. *)
let stimulus ?(changes = true) events =
  let base = [ (0.25, "di1 1"); (0.75, "di1 0"); (1.5, "di1 1") ] in
  let all = List.stable_sort (fun (a, _) (b, _) -> compare a b) ((if changes then base else []) @ events) in
  "signal di1 di\nsignal do1 do\n" ^ String.concat "" (List.map (fun (t, e) -> Printf.sprintf "at %g %s\n" t e) all)

let one ?(options = Fuzz_case.default_options) ?(io = stimulus []) ?(data = []) routines =
  { Fuzz_case.tasks = [ { task_name = "T_ROB1"; modules = [ { name = "fuzz"; module_data = data; routines } ] } ];
    io_text = io; options; schedule = None }

(* A handler's statements, ending as drawn: [""] falls off its end (the system error handler). *)
let handler_ending rs endings = match pick rs endings with "" -> [] | e -> [ e ]

(* ---------------------------------------------------------------- options *)

(* Names neither declared nor installed, allowed by --allow-unknown: reaching one raises
   ERR_REFUNKDAT, ERR_REFUNKPRC or ERR_REFUNKFUN (doc/semantics.md, place-unknown,
   call-unknown, call-unknown-function). *)
let unknown rs =
  let uses = [ "zn1 := fzunknown + 1;"; "fzunknownproc 1;"; "zn1 := fzunknownfun(2);";
               "TPWrite \"u \" \\Num:=fzunknown;";
               "fzunknown := 3;" ] in
  let body = List.init (int_in rs 1 3) (fun _ -> pick rs uses) @ [ "TPWrite \"end \" \\Num:=zn1;" ] in
  let error =
    if chance rs 0.7 then Some ("TPWrite \"handler \" \\Num:=ERRNO;" :: handler_ending rs [ "TRYNEXT;"; "RETRY;"; "" ])
    else None in
  one ~options:{ Fuzz_case.default_options with allow_unknown = true } ~data:[ "VAR num zn1 := 1;" ]
    [ proc ?error "main" body ]

(* Installed routines whose behaviour rapid-sem does not model (the stub cases of spec/11-installed):
   the run ends there, or under --stub-unmodelled they run as no-ops (R-13-i). *)
let unmodelled rs =
  let calls = [ "TPReadFK zn1, \"Go on?\", \"Yes\", \"No\", \"\", \"\", \"\";"; "zn1 := RunMode();";
                "zb1 := IsSysId(\"6400-1234\");"; "zs1 := Type(zn1);" ] in
  let body = List.concat (List.init (int_in rs 1 3) (fun _ -> [ pick rs calls; "TPWrite \"n \" \\Num:=zn1;" ])) in
  one ~options:{ Fuzz_case.default_options with stub_unmodelled = chance rs 0.6 }
    ~data:[ "VAR num zn1 := 7;"; "VAR bool zb1;"; "VAR string zs1;" ] [ proc "main" body ]

(* --max-time with what outlasts it: a long loop (time-limit), a wait whose next event lies
   beyond it (wait-time-limit), a wait nothing can end (wait-deadlock), a WaitUntil polling. *)
let time_limit rs =
  let max_time = pick rs [ 0.05; 0.2; 0.5 ] in
  let io, wait =
    match Random.State.int rs 6 with
    | 0 -> (stimulus [], [ "WHILE zn1 < 1000000 DO"; ])
    | 1 -> (stimulus [], [ Printf.sprintf "WaitTime %s;" (pick rs [ "1"; "10" ]) ])
    | 2 -> (stimulus ~changes:false (if chance rs 0.5 then [] else [ (30., "di1 1") ]), [ "WaitDI di1, 1;" ])
    | 3 ->
        (stimulus [], [ Printf.sprintf "WaitUntil zn1 < 0%s;" (pick rs [ ""; " \\PollRate:=0.05"; " \\MaxTime:=5" ]) ])
    | _ -> (stimulus [], [ "WaitTime 0.01;"; "WaitTime 0.02;" ]) in
  let body =
    match wait with
    | [ "WHILE zn1 < 1000000 DO" ] -> [ Compound ([ ("WHILE zn1 < 1000000 DO", lines [ "Incr zn1;" ]) ], "ENDWHILE") ]
    | l -> lines l in
  let main =
    { (proc "main" []) with body = Line "TPWrite \"start\";" :: body @ [ Line "TPWrite \"end \" \\Num:=zn1;" ] } in
  one ~options:{ Fuzz_case.default_options with max_time = Some max_time } ~io ~data:[ "VAR num zn1;" ] [ main ]

(* --max-memory with routine data that may not fit (Value.bytes: a num 32 bytes, an element 8
   more): memory-exhausted at the call, or at a module declaration before the first step. *)
let memory rs =
  let budget = pick rs [ 400; 1000; 2000; 5000; 20000 ] in
  let n = pick rs [ 10; 50; 100; 500 ] in
  let depth = int_in rs 1 6 in
  let fill = { (proc ~params:"num k" ~data:[ Printf.sprintf "VAR num big{%d};" n ] "fill" []) with
               body = lines [ "big{1} := k;"; "TPWrite \"k \" \\Num:=k;" ]
                      @ [ Compound ([ ("IF k > 1 THEN", lines [ "fill k - 1;" ]) ], "ENDIF") ] } in
  one ~options:{ Fuzz_case.default_options with max_memory = Some budget }
    ~data:(if chance rs 0.3 then [ Printf.sprintf "VAR string gtexts{%d};" (n / 5) ] else [])
    [ fill; proc "main" [ Printf.sprintf "fill %d;" depth; "TPWrite \"done\";" ] ]

(* --max-call-depth with recursion bounded by its argument: call-depth-exceeded when the
   argument is deeper than the limit. *)
let call_depth rs =
  let limit = int_in rs 3 12 and n = int_in rs 1 15 in
  let r = { (proc ~params:"num k" "down" []) with
            body = [ Compound ([ ("IF k > 0 THEN", lines [ "down k - 1;" ]) ], "ENDIF"); Line "Incr zn1;" ] } in
  let error = if chance rs 0.3 then Some [ "TPWrite \"handler\";"; "TRYNEXT;" ] else None in
  one ~options:{ Fuzz_case.default_options with max_call_depth = Some limit } ~data:[ "VAR num zn1;" ]
    [ r; proc ?error "main" [ Printf.sprintf "down %d;" n; "TPWrite \"depth \" \\Num:=zn1;" ] ]

(* ---------------------------------------------------------------- conditional arguments *)

(* §3.11, §5.2: conditional arguments for two alternatives of one optional parameter, each
   present when the caller's optional parameter is: both present is ERR_ARGDUPCND
   (argument-pass-on-duplicate), which the programs of Program_gen reach a few times in a
   hundred thousand. *)
let conditional rs =
  let value = chance rs 0.5 in
  let params = if value then "\\num a | num b" else "\\switch a | switch b" in
  let check = proc ~params "alt"
      [ "IF Present(a) TPWrite \"a\";"; "IF Present(b) TPWrite \"b\";" ] in
  let pass =
    proc ~params:(if value then "\\num x, \\num y" else "\\switch x, \\switch y") "pass" [ "alt \\a?x \\b?y;" ] in
  let argument p = if value then Printf.sprintf " \\%s:=%d" p (int_in rs 1 9) else " \\" ^ p in
  let call () =
    Printf.sprintf "pass%s%s;" (if chance rs 0.6 then argument "x" else "")
      (if chance rs 0.6 then argument "y" else "") in
  let error =
    if chance rs 0.6 then Some ("TPWrite \"handler \" \\Num:=ERRNO;" :: handler_ending rs [ "TRYNEXT;"; "RETURN;"; "" ])
    else None in
  one [ check; pass; proc ?error "main" (List.init (int_in rs 1 4) (fun _ -> call ()) @ [ "TPWrite \"end\";" ]) ]

(* ---------------------------------------------------------------- CONNECT *)

(* §4.15: the target of CONNECT is a variable of the module; through a VAR or INOUT parameter
   it may be routine data or a persistent: ERR_CNTNOTVAR (connect-not-variable). *)
let connect_parameter rs =
  let mode = pick rs [ "VAR"; "INOUT" ] in
  let target = pick rs ([ "zint"; "lint" ] @ if mode = "INOUT" then [ "pint" ] else []) in
  let error =
    if chance rs 0.6 then Some ("TPWrite \"handler \" \\Num:=ERRNO;" :: handler_ending rs [ "TRYNEXT;"; "RETURN;"; "" ])
    else None in
  let conn =
    proc ?error ~params:(mode ^ " intnum x") "conn"
      [ "CONNECT x WITH zztrap;"; "ITimer \\Single, 0.01, x;"; "WaitTime 0.05;" ] in
  one ~data:[ "VAR intnum zint;"; "PERS intnum pint := 0;" ]
    [ conn; trap "zztrap" [ "TPWrite \"trap \" \\Num:=INTNO;" ];
      proc ~data:[ "VAR intnum lint;" ] "main"
        [ Printf.sprintf "conn %s;" target; "IDelete zint;"; "TPWrite \"end\";" ] ]

(* ---------------------------------------------------------------- asynchronous errors *)

let targets = [
  "CONST robtarget fzq1 := [[300, -250, 300], [0, 0, 1, 0], [-1, 0, -1, 0], \
   [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];";
  "CONST robtarget fzq2 := [[300, 250, 300], [0, 0, 1, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];";
  "CONST robtarget fzq3 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];";
]

(* The handler of an asynchronous error (§7.4, §7.6): RETRY or TRYNEXT resume where the program
   pointer is, RAISE and RETURN leave, EXIT ends, and without a handler the task stops. *)
let async_handler rs =
  if chance rs 0.15 then None
  else
    let restart = if chance rs 0.7 then [ "StartMove;" ] else [] in
    Some (("TPWrite \"async \" \\Num:=ERRNO;" :: restart)
          @ handler_ending rs [ "RETRY;"; "TRYNEXT;"; "EXIT;"; "RAISE;"; "RETURN;"; "" ])

(* A robot path made by [mover], a routine [waiter] the program pointer waits in, the error
   from a collision of the stimulus or ProcerrRecovery in a trap; handlers in each routine as
   drawn. *)
let async rs =
  (* the error's source: a collision of the stimulus, or ProcerrRecovery in a timer's trap *)
  let source = pick rs [ "collision"; "\\SyncOrgMoveInst"; "\\SyncLastMoveInst"; "\\SyncLastMoveInst" ] in
  let collision = source = "collision" in
  (* slow enough that the robot still moves when the timer's trap runs *)
  (* a \SyncLastMoveInst error raised at the next move instruction (async-error-at-move) needs
     the timer's trap while the program pointer is in the waiter, past a fly-by point:
     v1000 and z10 leave the first MoveL at about 0.9 s, the timer runs out at 1.2 s or later *)
  let at_move = source = "\\SyncLastMoveInst" && chance rs 0.5 in
  let speed = if at_move then "v1000" else pick rs [ "v100"; "v200"; "v200"; "v1000" ] in
  let zone = if at_move then "z10" else pick rs [ "fine"; "z10" ] in
  let wait = if at_move then "WaitTime 2;"
    else pick rs [ "WaitTime 0.5;"; "WaitTime 2;"; "WaitUntil zn1 > 0 \\MaxTime:=1;"; "TPWrite \"no wait\";" ] in
  let waiter = proc ?error:(if chance rs 0.4 then async_handler rs else None)
      ?undo:(if chance rs 0.4 then Some [ "TPWrite \"undo waiter\";" ] else None)
      "waiter" [ "TPWrite \"waiter\";"; wait ] in
  let mover = proc ?error:(if chance rs 0.6 then async_handler rs else None)
      ?undo:(if chance rs 0.3 then Some [ "TPWrite \"undo mover\";" ] else None) "mover"
      ((if collision then []
        else [ "CONNECT gfail WITH fzfail;";
               Printf.sprintf "ITimer \\Single, %s, gfail;" (pick rs [ "0.3"; "0.8"; "1.5" ]) ])
       @ [ Printf.sprintf "MoveL fzq2, %s, %s, tool0;" speed zone; "waiter;";
           Printf.sprintf "MoveL fzq3, %s, fine, tool0;" speed; "TPWrite \"mover done\";" ]) in
  let fail = trap "fzfail"
      [ "TPWrite \"trap\";"; Printf.sprintf "ProcerrRecovery %s;" source ] in
  let main = proc ?error:(async_handler rs) "main"
      [ "MoveJ fzq1, v1000, fine, tool0;"; "mover;"; "TPWrite \"main done\";" ] in
  let io = stimulus (if collision then [ (pick rs [ 0.5; 1.; 1.5; 2.5 ], "collision") ] else []) in
  one ~io ~data:(targets @ [ "VAR intnum gfail;"; "VAR num zn1;" ])
    ([ waiter; mover ] @ (if collision then [] else [ fail ]) @ [ main ])

(* ---------------------------------------------------------------- the user level *)

(* §7.3: routines of a NOSTEPIN module below the user level, their errors handed on by
   RaiseToUser; the user's handler RETRYs or TRYNEXTs into them (resume-retry,
   resume-trynext), or leaves. Variants: the entry routine itself below the user level, a
   user routine without handler, an \ErrorNumber that is no error number, a late-bound
   RaiseToUser outside any handler. *)
let user_level rs =
  (* without a switch RaiseToUser is a static error (raise-to-user-switch) *)
  let switch = pick rs [ " \\Continue"; " \\Resume"; " \\BreakOff" ] in
  let number = pick rs [ ""; ""; " \\ErrorNumber:=gerr"; " \\ErrorNumber:=ERR_DIVZERO" ] in
  let raise_ = pick rs [ "zn1 := 10 / gdiv;"; "RAISE 7;"; "RAISE gerr;" ] in
  let inner = proc "inner" ~error:[ "TPWrite \"inner handler \" \\Num:=ERRNO;"; "RaiseToUser" ^ switch ^ number ^ ";" ]
      ?undo:(if chance rs 0.5 then Some [ "TPWrite \"inner undo\";" ] else None)
      [ "TPWrite \"inner\";"; raise_; "TPWrite \"inner goes on\";" ] in
  (* a function below the user level, whose error the user routine's RETRY evaluates again
     (spec/07-user-level/03-function-error-constant) *)
  let scaled = { header = "FUNC num scaled(num x)"; data = [];
                 body = lines [ "IF gdiv = 0 RAISE 5;"; "RETURN x * gdiv;" ];
                 error = Some ("ERROR", lines [ "RaiseToUser" ^ switch ^ number ^ ";" ]); undo = None;
                 footer = "ENDFUNC" } in
  let outer = proc "outer"
      ?error:(if chance rs 0.3 then Some [ "TPWrite \"outer handler\";"; "RAISE;" ] else None)
      ?undo:(if chance rs 0.4 then Some [ "TPWrite \"outer undo\";" ] else None)
      ((if chance rs 0.3 then [ "zn1 := scaled(3) + 1;" ] else [])
       @ [ (if chance rs 0.85 then "inner;" else "RAISE 56;"); "TPWrite \"outer goes on\";" ]) in
  let user_error =
    if chance rs 0.15 then None
    else Some ([ "TPWrite \"user handler \" \\Num:=ERRNO;" ]
               (* without the repair, RETRY meets the error again until the retry limit *)
               @ (if chance rs 0.8 then [ "gdiv := 2;"; "gerr := 5;" ] else [])
               @ handler_ending rs [ "RETRY;"; "TRYNEXT;"; "RETRY;"; "TRYNEXT;"; "RETURN;"; "RAISE;"; "" ]) in
  let misplaced = if chance rs 0.1 then [ "% \"RaiseToUser\" % \\BreakOff;" ] else [] in
  let user =
    proc ?error:user_error "work" (("TPWrite \"work\";" :: misplaced) @ [ "outer;"; "TPWrite \"work goes on\";" ]) in
  let data = [ "VAR num gdiv := 0;"; "VAR num zn1;"; Printf.sprintf "VAR num gerr := %d;" (pick rs [ 5; 95; 0 ]) ] in
  let below = chance rs 0.1 in
  let main_error = if chance rs 0.5 then Some [ "TPWrite \"main handler \" \\Num:=ERRNO;"; "TRYNEXT;" ] else None in
  let main = proc ?error:main_error "main" [ "work;"; "TPWrite \"main done\";" ] in
  (* an error recovery point above the user level: the long jump from below it is reported at
     the call (R-7.3-o) *)
  let main =
    if chance rs 0.2 then
      { main with error = Some ("ERROR (56, LONG_JMP_ALL_ERR)", lines [ "TPWrite \"recovery point\";"; "TRYNEXT;" ]) }
    else main in
  (* a NOVIEW module is below the user level too (R-9.4-a) *)
  let attribute = if chance rs 0.2 then "NOVIEW" else "NOSTEPIN" in
  let lib = { name = Printf.sprintf "fzlib (%s)" attribute; module_data = [];
              routines = [ outer; inner; scaled ] @ (if below then [ user; main ] else []) } in
  let app = { name = "fuzz"; module_data = data; routines = (if below then [] else [ user; main ]) } in
  { Fuzz_case.tasks = [ { task_name = "T_ROB1"; modules = [ app; lib ] } ];
    io_text = stimulus []; options = Fuzz_case.default_options; schedule = None }

(* ---------------------------------------------------------------- several tasks *)

(* Two tasks on one clock (ch. 14): a system-global persistent one sets and the other waits
   for, a synchronisation point, a semaphore; some never meet (wait-deadlock, or the time
   limit). *)
let tasks rs =
  let a_steps = ref [] and b_steps = ref [] in
  let add_a l = a_steps := !a_steps @ l and add_b l = b_steps := !b_steps @ l in
  for _ = 1 to int_in rs 1 3 do
    match Random.State.int rs 6 with
    | 0 ->
        add_a [ Printf.sprintf "WaitTime %s;" (pick rs [ "0.1"; "0.5" ]); "fzflag := fzflag + 1;" ];
        add_b [ Printf.sprintf "WaitUntil fzflag > %d%s;" (int_in rs 0 1)
                  (pick rs [ ""; " \\MaxTime:=1"; " \\PollRate:=0.05" ]);
                "TPWrite \"B sees \" \\Num:=fzflag;" ]
    | 1 -> add_a [ "WaitSyncTask fzmeet, fzboth;" ]; add_b [ "WaitSyncTask fzmeet, fzboth;" ]
    | 2 -> add_a [ "WaitSyncTask fzmeet, fzboth \\TimeOut:=0.5;" ]
    | 3 -> add_a [ "WaitTestAndSet fzlock;"; "TPWrite \"A holds\";"; "WaitTime 0.1;"; "fzlock := FALSE;" ];
           add_b [ "WaitTestAndSet fzlock;"; "TPWrite \"B holds\";"; "fzlock := FALSE;" ]
    | 4 ->
        (* a semaphore never given back: the second task waits for what no task can change *)
        add_a [ "WaitTestAndSet fzlock;"; "TPWrite \"A keeps\";" ];
        add_b [ "WaitTestAndSet fzlock;"; "TPWrite \"B keeps\";" ]
    | _ -> add_b [ Printf.sprintf "WaitTime %s;" (pick rs [ "0.05"; "0.2" ]); "fzflag := fzflag + 1;" ];
           add_a [ "WaitUntil fzflag > 0 \\MaxTime:=0.5;" ]
  done;
  let handler = if chance rs 0.5 then Some [ "TPWrite \"timeout \" \\Num:=ERRNO;"; "TRYNEXT;" ] else None in
  let a = { name = "fuzz_a";
            module_data = [ "PERS num fzflag := 0;"; "PERS bool fzlock := FALSE;"; "VAR syncident fzmeet;";
                            "PERS tasks fzboth{2} := [[\"T_ROB1\"], [\"T_B\"]];" ];
            routines = [ proc ?error:handler "main" (("TPWrite \"A\";" :: !a_steps) @ [ "TPWrite \"A ends\";" ]) ] } in
  let b = { name = "fuzz_b";
            module_data = [ "PERS num fzflag;"; "PERS bool fzlock;"; "VAR syncident fzmeet;"; "PERS tasks fzboth{2};" ];
            routines = [ proc ?error:handler "main" (("TPWrite \"B\";" :: !b_steps) @ [ "TPWrite \"B ends\";" ]) ] } in
  { Fuzz_case.tasks = [ { task_name = "T_ROB1"; modules = [ a ] }; { task_name = "T_B"; modules = [ b ] } ];
    io_text = stimulus [];
    (* a WaitUntil that nothing ends polls until the time limit: a short one *)
    options = { Fuzz_case.default_options with max_time = Some (pick rs [ 0.3; 2.; 5. ]) };
    schedule = (if chance rs 0.7 then Some (Random.State.int rs 1000) else None) }

let table = [
  ("unknown", unknown); ("unmodelled", unmodelled); ("time-limit", time_limit); ("memory", memory);
  ("call-depth", call_depth); ("conditional", conditional); ("connect-parameter", connect_parameter);
  ("async", async); ("async", async);
  ("user-level", user_level); ("user-level", user_level); ("user-level", user_level); ("tasks", tasks);
]

let kinds = List.sort_uniq compare (List.map fst table)

(* Three scenarios in ten of one task also hold a program of Program_gen, its main renamed
   fzgen and called at the end of the scenario's main: the scenario's options, stimulus and
   handlers then meet every statement form too. The scenarios' names (z..., fz...) are apart
   from the program's (g..., p<n>, f<n>, fztrap, fzrec). *)
let with_program rs (c : Fuzz_case.t) =
  match c.tasks with
  | [ ({ modules = app :: rest; _ } as t) ]
    when List.exists (fun (r : routine) -> r.header = "PROC main()") app.routines ->
      let g = Program_gen.generate rs in
      let renamed = List.map (fun (r : routine) ->
          if r.header = "PROC main()" then { r with header = "PROC fzgen()" } else r) g.routines in
      (* its RECORD first: type definitions come before data declarations (§9.2) *)
      let app = { app with module_data = g.module_data @ app.module_data;
                           routines = List.map (fun (r : routine) ->
                               if r.header = "PROC main()" then { r with body = r.body @ [ Line "fzgen;" ] } else r)
                               app.routines @ renamed } in
      { c with tasks = [ { t with modules = app :: rest } ] }
  | _ -> c

let generate rs =
  let c = (snd (pick rs table)) rs in
  if chance rs 0.3 then with_program rs c else c

let generate_kind kind rs =
  match List.assoc_opt kind table with
  | Some g -> g rs
  | None -> invalid_arg ("Scenario_gen.generate_kind: no kind " ^ kind)
