module O = Rapid_run.Run_options
module Setup = Rapid_run.Run_setup
module M = Rapid_semantics.Machine
module S = Rapid_syntax.Source

let ( let* ) = Result.bind

let rapid_extensions = [ ".mod"; ".sys"; ".modx"; ".sysx" ]

let is_module f = List.mem (String.lowercase_ascii (Filename.extension f)) rapid_extensions

let rec below dir =
  match Sys.readdir dir with
  | exception Sys_error m -> Error m
  | entries ->
      let entries = List.sort compare (Array.to_list entries) in
      List.fold_left (fun acc e ->
          let* acc = acc in
          let path = if dir = Filename.current_dir_name then e else Filename.concat dir e in
          if Sys.is_directory path then Result.map (fun l -> acc @ l) (below path)
          else if is_module path then Ok (acc @ [ path ]) else Ok acc) (Ok []) entries

let module_files given =
  List.fold_left (fun acc f ->
      let* acc = acc in
      if f = "-" then Error "rapid-sem: test reads its modules from files: standard input (-) is not one"
      else if Sys.file_exists f && Sys.is_directory f then
        match below f with
        | Ok [] -> Error (Printf.sprintf "rapid-sem: %s: no RAPID module (.mod, .sys, .modx, .sysx) in this folder" f)
        | Ok l -> Ok (acc @ l)
        | Error m -> Error ("rapid-sem: " ^ m)
      else Ok (acc @ [ f ])) (Ok []) given

(* The directive: a comment line "!rapid-sem: OPTIONS" anywhere in the module (before MODULE
   too, doc/dialect.md), its options as the command line spells them. *)
let directive_prefix = Str.regexp "^\\([ \t]*![ \t]*rapid-sem:\\)\\(.*\\)$"

let lines_of file =
  match open_in_bin file with
  | exception Sys_error _ -> []
  | ic ->
      let rec go n acc = match input_line ic with
        | l -> go (n + 1) ((n, l) :: acc)
        | exception End_of_file -> close_in ic; List.rev acc in
      go 1 []

let directive_options (o : O.t) file =
  let relative f =
    let dir = Filename.dirname file in
    if Filename.is_relative f && dir <> Filename.current_dir_name then Filename.concat dir f else f in
  List.fold_left (fun acc (n, line) ->
      let* (o : O.t) = acc in
      if not (Str.string_match directive_prefix line 0) then Ok o
      else
        let col = String.length (Str.matched_group 1 line) + 2 in
        let words = List.filter (( <> ) "") (String.split_on_char ' '
                      (String.map (function '\t' | '\r' -> ' ' | c -> c) (Str.matched_group 2 line))) in
        let fail m = Error (Printf.sprintf "%s:%d:%d: test directive: %s" file n col m) in
        let number opt v k = match float_of_string_opt v with
          | Some x when x >= 0. && Float.is_finite x -> k x
          | _ -> fail (Printf.sprintf "%s %s: a number of seconds, 0 or more" opt v) in
        let rec go (o : O.t) = function
          | [] -> Ok o
          | "--io" :: f :: rest -> go { o with controller = { o.controller with io = Some (relative f) } } rest
          | "--robot" :: f :: rest -> go { o with robot = Some (relative f) } rest
          | "--max-time" :: v :: rest ->
              number "--max-time" v (fun x -> go { o with controller = { o.controller with max_time = x } } rest)
          | "--statement-time" :: v :: rest ->
              number "--statement-time" v (fun x ->
                  go { o with controller = { o.controller with statement_time = x } } rest)
          | [ ("--io" | "--robot" | "--max-time" | "--statement-time") as opt ] -> fail (opt ^ " needs a value")
          | w :: _ -> fail (Printf.sprintf "%s is not an option a test module may ask for (--io, --robot, --max-time, \
                                            --statement-time)" w) in
        go o words) (Ok o) (lines_of file)

type test = { name : string; module_name : string; file : string; line : int; col : int; options : O.t }

type suite = {
  files : string list;
  tests : test list;
  test_modules : string list;
  coverage : Test_coverage.t;
  loads : (O.t * Rapid_load.Session.loaded) list;
}

let is_test_name = Rapid_load.Session.is_test_name

let file_of (r : Ir.routine) = Option.map S.name (S.file_of r.at)

let tests_of (program : Ir.program) =
  List.filter (fun (r : Ir.routine) ->
      r.kind = Procedure && Array.length r.parameters = 0 && r.primitive = None && is_test_name r.name)
    (Array.to_list program.routines)

let discover ~notify (o : O.t) files =
  let* per_file = List.fold_left (fun acc f ->
      let* acc = acc in
      Result.map (fun o' -> acc @ [ (f, o') ]) (Result.map_error (fun m -> Setup.Usage m) (directive_options o f)))
      (Ok []) files in
  (* One load per distinct set of options of the modules that declare tests (the others'
     directives name nothing of their own), the first with the warnings told. *)
  let declares_tests file =
    match Rapid_syntax.Parse.parse_file file with
    | Error _ -> true
    | Ok m -> Rapid_load.Session.declares_tests m in
  let per_file = List.filter (fun (f, _) -> declares_tests f) per_file in
  let distinct = match List.sort_uniq compare (List.map snd per_file) with [] -> [ o ] | l -> l in
  let* loads = List.fold_left (fun acc opts ->
      let* acc = acc in
      let tell = if acc = [] then notify else ignore in
      Result.map (fun (s : Setup.single) -> acc @ [ (opts, s.loaded) ])
        (Setup.single ~testing:true ~notify:tell opts files))
      (Ok []) distinct in
  let program = (snd (List.hd loads)).program in
  let tests = List.concat_map (fun (file, opts) ->
      let program = (List.assoc opts loads).program in
      List.filter_map (fun (r : Ir.routine) ->
          if file_of r = Some file then
            let at = S.start r.at in
            Some { name = r.name; module_name = r.module_name; file; line = at.line; col = at.col; options = opts }
          else None) (tests_of program)) per_file in
  let test_modules = List.sort_uniq compare (List.map (fun t -> String.lowercase_ascii t.module_name) tests) in
  let given = files in
  let covered (r : Ir.routine) =
    (match file_of r with Some f -> List.mem f given | None -> false)
    && not (List.mem (String.lowercase_ascii r.module_name) test_modules) in
  Ok { files; tests; test_modules; coverage = Test_coverage.of_program program ~covered; loads }

let filter re s =
  let matches n = match Str.search_forward re n 0 with _ -> true | exception Not_found -> false in
  { s with tests = List.filter (fun t -> matches t.name) s.tests }

type verdict = Passed | Failed of { at : string option; message : string }

type result = {
  test : test;
  verdict : verdict;
  time : float;
  output : string list;
  hits : Test_coverage.portable option;
}

let verdict (t : test) (o : Outcome.t) ~max_steps =
  let failed ?at message =
    let at = match at with
      | Some r when r <> S.no_region -> S.to_string r
      | _ -> Printf.sprintf "%s:%d:%d" t.file t.line t.col in
    Failed { at = Some at; message } in
  match o with
  | Ended -> Passed
  | Stopped { name = "ERR_ASSERT"; at; about = Some m; _ } -> failed ~at m
  | Stopped { name; at; chain; about; _ } ->
      failed ~at (Printf.sprintf "execution error %s%s: no error handler took it (%s)" name
                    (match about with Some a -> " (" ^ a ^ ")" | None -> "") (String.concat " <- " chain))
  | Resource_exhausted (m, at) -> failed ?at m
  | Deadlock m -> failed m
  | Unsupported { reason; at; _ } -> failed ~at (Outcome.unsupported_what reason)
  | Stuck m -> failed ("internal error of rapid-sem: no rule applies (" ^ m ^ ")")
  | Running -> failed (Printf.sprintf "the step limit (%d) is exhausted" max_steps)

let run_test ~coverage ~engine suite t =
  let o = t.options in
  let refused m = { test = t; verdict = Failed { at = None; message = m }; time = 0.; output = []; hits = None } in
  (* The program loaded once with these options, in a world of its own (Run_setup.fresh_world):
     both engines start it with fresh module data (§2.21). *)
  match List.assoc_opt o suite.loads, Setup.fresh_world ~notify:ignore o suite.files with
  | None, _ | _, Error _ -> refused "the task buffer does not load with this test's options"
  | Some loaded, Ok world ->
      let s = { Setup.loaded; world } in
      let output = ref [] in
      let on_event = function Event.Output l -> output := l :: !output | _ -> () in
      let finish outcome hits =
        { test = t; verdict = verdict t outcome ~max_steps:o.max_steps;
          time = Rapid_controller.World.now s.world.controller;
          output = List.rev !output; hits } in
      if coverage || engine = `Machine then
        match Setup.machine o s ~entry:t.name with
        | Error _ -> refused ("cannot start " ^ t.name)
        | Ok cfg ->
            let h = Test_coverage.record () in
            let step = if coverage then (fun () -> Test_coverage.observe h cfg (fun () -> M.step_rule cfg))
              else (fun () -> M.step_rule cfg) in
            while M.outcome cfg = Running && M.steps cfg < o.max_steps do List.iter on_event (snd (step ())) done;
            finish (M.outcome cfg) (if coverage then Some (Test_coverage.portable h) else None)
      else
        match Rapid_run.Run.Closure.run ~limits:o.limits ~fuel:o.max_steps ~stub_unmodelled:o.stub_unmodelled
                ~all_events:false ~on_event ~host:s.world.host s.loaded.program ~entry:t.name with
        | Error m -> refused m
        | Ok r -> finish r.outcome None

(* Child processes: each runs every [jobs]-th test and sends each result back as it ends
   (Marshal over a pipe); the parent hands them on in the order they come. *)
let run ?(jobs = 1) ~coverage ~engine ~on_result suite =
  let tests = Array.of_list suite.tests in
  let n = Array.length tests in
  let results = Array.make n None in
  let got i r = results.(i) <- Some r; on_result i r in
  let jobs = max 1 (min jobs n) in
  if jobs = 1 then Array.iteri (fun i t -> got i (run_test ~coverage ~engine suite t)) tests
  else begin
    flush_all ();
    let children = List.init jobs (fun j ->
        let r, w = Unix.pipe ~cloexec:true () in
        match Unix.fork () with
        | 0 ->
            Unix.close r;
            let oc = Unix.out_channel_of_descr w in
            (try
               Array.iteri (fun i t ->
                   if i mod jobs = j then begin
                     let res = run_test ~coverage ~engine suite t in
                     Marshal.to_channel oc (i, res) [];
                     flush oc
                   end) tests
             with _ -> ());
            (try close_out oc with _ -> ());
            Unix._exit 0
        | pid -> Unix.close w; (pid, Unix.in_channel_of_descr r)) in
    let rec loop live =
      if live <> [] then begin
        let fds = List.map (fun (_, ic) -> Unix.descr_of_in_channel ic) live in
        let ready, _, _ = try Unix.select fds [] [] (-1.) with Unix.Unix_error (Unix.EINTR, _, _) -> ([], [], []) in
        let live = List.filter (fun (pid, ic) ->
            if not (List.mem (Unix.descr_of_in_channel ic) ready) then true
            else match (Marshal.from_channel ic : int * result) with
              | (i, r) -> got i r; true
              | exception _ -> close_in_noerr ic; ignore (Unix.waitpid [] pid); false) live in
        loop live
      end in
    loop children
  end;
  List.mapi (fun i t -> match results.(i) with
      | Some r -> r
      | None -> { test = t; verdict = Failed { at = None; message = "the child process running it ended first" };
                  time = 0.; output = []; hits = None }) (Array.to_list tests)
