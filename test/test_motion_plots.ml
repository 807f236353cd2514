(* The plots of rapid-sem motion as a robot programmer reads them (doc/motion.md, "Output"): one
   label per distinct point, every label inside its plot area, points of an expression named by
   what the program wrote, the TCP speed the move's own, the waits row only the program's waits.
   The SVG is read with xmlm, as a browser would read it, not searched as text. *)

module MM = Rapid_motion_model
module MP = Rapid_installed.Motion_routines

let write_temp text =
  let f = Filename.temp_file "plots" ".mod" in
  let oc = open_out_bin f in
  output_string oc text; close_out oc; f

(* A run of a module to its end; the planner with its history. *)
let planner_of text =
  let file = write_temp text in
  match Rapid_load.Session.load ~allow_unknown:false ~io:Rapid_controller.Io_config.empty [ file ] with
  | Error _ -> Alcotest.fail "the module does not load"
  | Ok loaded -> (
      let world = Rapid_controller.World.create ~statement_time:0. ~max_time:3600. Rapid_controller.Io_config.empty in
      let motion = MP.create ~history:100_000_000 ~robot:MM.Robot.irb120 () in
      let module M = Rapid_semantics.Machine in
      match M.start ~host:(Rapid_run.Run.setup ~controller:world ~motion ()).host loaded.program ~entry:"main" with
      | Error m -> Alcotest.fail m
      | Ok cfg ->
          while M.outcome cfg = Rapid_runtime.Outcome.Running && M.steps cfg < 2_000_000 do ignore (M.step cfg) done;
          (match M.outcome cfg with
           | Rapid_runtime.Outcome.Ended -> ()
           | _ -> Alcotest.fail "the run did not complete");
          MP.planner motion)

(* The SVG as a tree of elements: name, attributes, children; text as [Text]. *)
type node = El of string * (string * string) list * node list | Text of string

let parse svg =
  let input = Xmlm.make_input ~strip:false (`String (0, svg)) in
  let el ((_, name), attrs) children = El (name, List.map (fun ((_, k), v) -> (k, v)) attrs, children) in
  match Xmlm.input_doc_tree ~el ~data:(fun s -> Text s) input with
  | _, tree -> tree
  | exception Xmlm.Error ((l, c), e) -> Alcotest.failf "not well-formed XML at %d:%d: %s" l c (Xmlm.error_message e)

let attr k attrs = match List.assoc_opt k attrs with Some v -> v | None -> Alcotest.failf "no attribute %s" k
let num k attrs = float_of_string (attr k attrs)
let rec text_of = function Text s -> s | El (_, _, ch) -> String.concat "" (List.map text_of ch)
let children = function El (_, _, ch) -> ch | Text _ -> []
let has_class c = function El (_, attrs, _) -> List.assoc_opt "class" attrs = Some c | Text _ -> false

let rec find_all p node = (if p node then [ node ] else []) @ List.concat_map (find_all p) (children node)

(* The number of characters, for the width of a label: UTF-8 continuation bytes not counted. *)
let chars s = String.fold_left (fun n c -> if Char.code c land 0xC0 = 0x80 then n else n + 1) 0 s

(* A module that passes pHome, pPick and the point above pPick five times, with a 200 mm tool. *)
let loop_module = {|MODULE Plots
  PERS tooldata tLong := [TRUE,[[0,0,200],[1,0,0,0]],[1,[0,0,100],[1,0,0,0],0,0,0]];
  CONST robtarget pHome := [[400,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPick := [[350,-80,250],[0,0,1,0],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    FOR i FROM 1 TO 5 DO
      MoveJ pHome, v500, z10, tLong;
      MoveL Offs(pPick, 0, 0, 100), v200, z10, tLong;
      MoveL pPick, v100, fine, tLong;
      MoveL Offs(pPick, 0, 0, 100), v200, z10, tLong;
    ENDFOR
  ENDPROC
ENDMODULE
|}

let labels_once_inside () =
  let svg = MM.Path_output.path_svg (planner_of loop_module) in
  let tree = parse svg in
  let views = find_all (fun n -> match n with
      | El ("g", _, ch) -> List.exists (has_class "plot-area") ch | _ -> false) tree in
  Alcotest.(check int) "two views" 2 (List.length views);
  let names_in_view = List.map (fun g ->
      let area = match List.find (has_class "plot-area") (children g) with
        | El (_, a, _) -> a | Text _ -> assert false in
      let ax = num "x" area and ay = num "y" area and aw = num "width" area and ah = num "height" area in
      let labels = find_all (has_class "point-label") g in
      List.map (fun l ->
          let a = match l with El (_, a, _) -> a | Text _ -> assert false in
          let x = num "x" a and y = num "y" a and t = text_of l in
          (* the label's box: 7 px a character, 10 px above the baseline, 3 below *)
          let w = 7. *. float_of_int (chars t) in
          if x < ax || x +. w > ax +. aw +. 1. || y -. 10. < ay || y +. 3. > ay +. ah then
            Alcotest.failf "label %S at (%.1f, %.1f) outside the plot area (%.1f, %.1f, %.1f x %.1f)" t x y ax ay aw ah;
          t) labels) views in
  (* Top view: pPick and the point above it fall together, one label for both. *)
  (match names_in_view with
   | [ top; side ] ->
       let sorted l = List.sort compare l in
       Alcotest.(check (list string)) "top view: one label per spot" (sorted [ "pHome"; "#2, pPick" ]) (sorted top);
       Alcotest.(check (list string)) "side view: one label per point" (sorted [ "pHome"; "#2"; "pPick" ]) (sorted side)
   | _ -> Alcotest.fail "two views");
  let table = List.map text_of (find_all (fun n -> match n with El ("text", _, _) -> true | _ -> false)
                                  (List.hd (find_all (has_class "point-table") tree))) in
  let row sub = List.exists (fun t -> try ignore (Str.search_forward (Str.regexp_string sub) t 0); true
                                      with Not_found -> false) table in
  Alcotest.(check bool) "the table names the point by the expression" true (row "#2 Offs(pPick, 0, 0, 100) (350, -80, 350)");
  Alcotest.(check int) "three distinct points in the table (and its two headings)" 5 (List.length table)

(* Labels stay inside the area however many points crowd one corner. *)
let crowded_labels () =
  let kin = MM.Kinematics.create MM.Robot.irb120 in
  let p = MM.Planner.create ~joints:[| 0.; 20.; 10.; 0.; 60.; 0. |] kin in
  let find t n = Option.get (MM.Motion_data.find t n) in
  (MM.Planner.settings p).conf_l <- false;
  let now = ref 0. in
  for i = 0 to 59 do
    let rt = { MM.Frames.pose = { trans = { x = 300. +. float_of_int (i mod 6); y = float_of_int (i / 6); z = 300. };
                                  rot = { q1 = 0.; q2 = 0.; q3 = 1.; q4 = 0. } };
               conf = { cf1 = 0; cf4 = 0; cf6 = 0; cfx = 0 } } in
    let m = MM.Planner.move ~label:(Printf.sprintf "pCrowded%d" i) (find MM.Motion_data.speeddata "v1000")
        (find MM.Motion_data.zonedata "fine") (Linear rt) in
    match MM.Planner.plan p ~now:!now m with
    | Ok r -> now := r.ready_time
    | Error e -> Alcotest.fail (MM.Motion_error.name e)
  done;
  let tree = parse (MM.Path_output.path_svg p) in
  List.iter (fun g ->
      match List.find_opt (has_class "plot-area") (children g) with
      | None -> ()
      | Some (El (_, area, _)) ->
          List.iter (function
              | El (_, a, _) as l ->
                  let x = num "x" a and y = num "y" a in
                  let w = 7. *. float_of_int (chars (text_of l)) in
                  if x < num "x" area || x +. w > num "x" area +. num "width" area +. 1. || y -. 10. < num "y" area
                     || y +. 3. > num "y" area +. num "height" area then
                    Alcotest.failf "label %S outside its plot area" (text_of l)
              | Text _ -> ()) (find_all (has_class "point-label") g)
      | Some (Text _) -> ())
    (find_all (function El (n, _, _) -> n = "g" | Text _ -> false) tree)

(* A 100 mm/s move with a 200 mm tool from the start: the speed curve shows 100 mm/s, not the
   jump from the flange (tool0) to the tool's TCP at the first sample. *)
let speed_of_the_move () =
  let p = planner_of {|MODULE Speed
  PERS tooldata tLong := [TRUE,[[0,0,200],[1,0,0,0]],[1,[0,0,100],[1,0,0,0],0,0,0]];
  PROC main()
    MoveL [[400,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tLong;
    MoveL [[400,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tLong;
  ENDPROC
ENDMODULE
|} in
  let speeds = MM.Path_output.tcp_speeds p in
  let vmax = Array.fold_left (fun m (_, v) -> Float.max m v) 0. speeds in
  if vmax > 100. *. 1.02 then Alcotest.failf "the curve reaches %.1f mm/s on a 100 mm/s move" vmax;
  if vmax < 95. then Alcotest.failf "the curve reaches only %.1f mm/s on a 100 mm/s move" vmax;
  (* The axis: nice numbers, 4 to 8 ticks above 0. *)
  let tree = parse (MM.Path_output.timeline_svg p) in
  let ticks = List.map (fun n -> float_of_string (text_of n)) (find_all (has_class "speed-tick") tree) in
  let n = List.length ticks - 1 in
  if n < 4 || n > 8 then Alcotest.failf "%d ticks above 0" n;
  List.iter (fun v ->
      let m = 10. ** Float.floor (log10 (Float.max v 1.)) in
      let d = v /. m in
      if not (List.exists (fun k -> Float.abs (d -. k) < 1e-9) [ 0.; 1.; 2.; 3.; 4.; 5.; 6.; 7.; 8.; 9.; 10. ]) then
        Alcotest.failf "tick %g" v) ticks;
  let top = List.fold_left Float.max 0. ticks in
  if top < vmax *. (1. -. 1e-6) then Alcotest.failf "top tick %g under the curve's %g (%s)" top vmax (String.concat " " (List.map string_of_float ticks))

let nice_axis () =
  List.iter (fun (vmax, step, top) ->
      let s, t = MM.Path_output.nice_axis vmax in
      Alcotest.(check (pair (float 1e-9) (float 1e-9))) (Printf.sprintf "axis to %g" vmax) (step, top) (s, t))
    [ (100., 20., 100.); (1100., 200., 1200.); (25320., 5000., 30000.); (0., 0.2, 1.); (7., 1., 7.); (3.1, 0.5, 3.5) ]

(* rapid-sem motion's waits row: the WaitTime and the WaitUntil (which times out), not the moves'
   stop points. *)
let waits_row () =
  let file = write_temp {|MODULE Waits
  VAR num n := 0;
  VAR bool flag;
  PROC main()
    MoveL [[400,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
    WaitTime 1;
    MoveL [[400,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
    MoveL [[400,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
    WaitUntil n = 1 \MaxTime:=0.5 \TimeFlag:=flag;
  ENDPROC
ENDMODULE
|} in
  let timeline = Filename.temp_file "plots" ".svg" in
  let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe" in
  let status = Sys.command (Printf.sprintf "%s motion %s --timeline %s > /dev/null 2>&1" (Filename.quote binary)
                              (Filename.quote file) (Filename.quote timeline)) in
  Alcotest.(check int) "exit 0" 0 status;
  let svg = let ic = open_in_bin timeline in
    Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic)) in
  let waits = List.map (fun n -> String.trim (text_of n)) (find_all (has_class "wait") (parse svg)) in
  let starts p s = String.length s >= String.length p && String.sub s 0 (String.length p) = p in
  match waits with
  | [ a; b ] when starts "WaitTime: time" a && starts "WaitUntil" b -> ()
  | _ -> Alcotest.failf "waits: %s" (String.concat " | " waits)

let suite =
  ( "motion plots",
    [ Alcotest.test_case "path: one label per distinct point, inside the plot, Offs by its text" `Quick
        labels_once_inside;
      Alcotest.test_case "path: crowded labels stay inside" `Quick crowded_labels;
      Alcotest.test_case "timeline: the speed of a 100 mm/s move with a 200 mm tool, its axis" `Quick speed_of_the_move;
      Alcotest.test_case "timeline: the speed axis's ticks" `Quick nice_axis;
      Alcotest.test_case "timeline: the waits row holds the waiting instructions only" `Quick waits_row ] )
