open Geom

let buf_printf = Printf.bprintf

let end_time p =
  let f = Planner.finished_by p in
  if Float.is_finite f then f
  else List.fold_left (fun acc (i : Planner.piece_info) ->
      if Float.is_finite i.t_to then Float.max acc i.t_to else acc) 0. (Planner.pieces p)

let csv_max_rows = 200_000

let csv ?(step = 0.01) p =
  let b = Buffer.create 4096 in
  (* A robot with external axes: a column for each, named as extjoint names it (law X-desc). *)
  let ext = (Kinematics.robot (Planner.kinematics p)).externals in
  Buffer.add_string b "t,x,y,z,q1,q2,q3,q4,j1,j2,j3,j4,j5,j6";
  List.iter (fun (a : Ext_axes.axis) -> Buffer.add_string b ("," ^ a.name)) ext;
  Buffer.add_char b '\n';
  let last = end_time p in
  let row t =
    let q = Planner.pose_at p t in
    buf_printf b "%.4f,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f" t q.trans.x q.trans.y q.trans.z
      q.rot.q1 q.rot.q2 q.rot.q3 q.rot.q4;
    (match Planner.joints_at p t with
     | Ok j -> Array.iter (fun a -> buf_printf b ",%.4f" a) j
     | Error _ -> Buffer.add_string b ",,,,,,");
    (match Planner.external_at p t with
     | Ok e -> List.iter (fun (a : Ext_axes.axis) -> buf_printf b ",%.4f" e.(a.index)) ext
     | Error _ -> List.iter (fun _ -> Buffer.add_char b ',') ext);
    Buffer.add_char b '\n' in
  (* At most [csv_max_rows] rows (doc/motion.md, O-output): a longer path is sampled at a
     coarser step, so that the file, and the memory that builds it, stay bounded. *)
  let most = float_of_int csv_max_rows in
  let step = if Float.is_finite last && last /. step > most then last /. most else step in
  let n = if Float.is_finite last then int_of_float (Float.floor (last /. step)) else 0 in
  for i = 0 to n do row (float_of_int i *. step) done;
  if float_of_int n *. step < last then row last;
  Buffer.contents b

let esc s =
  let b = Buffer.create (String.length s) in
  String.iter (function '<' -> Buffer.add_string b "&lt;" | '>' -> Buffer.add_string b "&gt;"
                      | '&' -> Buffer.add_string b "&amp;" | '"' -> Buffer.add_string b "&quot;"
                      | c -> Buffer.add_char b c) s;
  Buffer.contents b

(* Samples of each piece of the path: positions, and whether the piece is a corner. *)
let sampled p =
  List.filter_map (fun (i : Planner.piece_info) ->
      if not (Float.is_finite i.t_to) || i.kind = Planner.Still then None
      else
        let n = 24 in
        let pts = List.init (n + 1) (fun k ->
            (Planner.pose_at p (i.t_from +. (i.t_to -. i.t_from) *. float_of_int k /. float_of_int n)).trans) in
        Some ((match i.kind with Planner.Corner _ -> true | _ -> false), pts))
    (Planner.pieces p)

(* A "nice" tick spacing for a span: 1, 2 or 5 times a power of ten, about six ticks. *)
let tick span =
  let raw = span /. 6. in
  let m = 10. ** Float.floor (log10 raw) in
  List.fold_left (fun acc k -> if k *. m >= raw && acc = 0. then k *. m else acc) 0. [ 1.; 2.; 5.; 10. ]

let nice_axis vmax =
  let vmax = if Float.is_finite vmax && vmax > 0. then vmax else 1. in
  let m = 10. ** Float.floor (log10 vmax) in
  (* The step of 1, 2 or 5 times a power of ten that gives 4 to 8 ticks above 0 *)
  let steps = List.concat_map (fun k -> [ k *. m /. 10.; k *. m ]) [ 1.; 2.; 5. ] in
  let fits st = let n = Float.ceil (vmax /. st -. 1e-9) in n >= 4. && n <= 8. in
  let step = match List.find_opt fits (List.sort compare steps) with Some st -> st | None -> tick vmax in
  (step, step *. Float.ceil (vmax /. step -. 1e-9))

(* Text boxes for the labels, estimated from the font size (12 px sans-serif: about 7 px a
   character, 10 px above the baseline and 3 below). *)
let char_width = 7.

type box = { bx : float; by : float; bw : float; bh : float }

let overlap a b = a.bx < b.bx +. b.bw && b.bx < a.bx +. a.bw && a.by < b.by +. b.bh && b.by < a.by +. a.bh

let inside area a = a.bx >= area.bx && a.by >= area.by && a.bx +. a.bw <= area.bx +. area.bw
                    && a.by +. a.bh <= area.by +. area.bh

(* The distinct programmed points, in the order first reached: a point passed again (a loop) is
   one entry; a point is its position (to 0.1 mm) and its name. *)
type point = { number : int; name : string; at : pos; fine : bool }

let max_named = 40

let distinct_points segs =
  let seen = Hashtbl.create 64 and out = ref [] and n = ref 0 in
  List.iter (fun (sg : Planner.segment_info) ->
      let r v = Float.round (v *. 10.) in
      let key = (r sg.target.x, r sg.target.y, r sg.target.z, sg.seg_label) in
      if not (Hashtbl.mem seen key) then begin
        Hashtbl.replace seen key ();
        incr n;
        out := { number = !n; name = sg.seg_label; at = sg.target; fine = sg.seg_fine } :: !out
      end) segs;
  List.rev !out

(* A point's name on the plot: itself when short, else its number in the table beside. *)
let short_name pt = if pt.name <> "" && String.length pt.name <= 12 then pt.name else "#" ^ string_of_int pt.number

let path_svg ?(title = "TCP path") p =
  let runs = sampled p in
  let segs = Planner.segments p in
  (* For the ranges only, in no order: [@] and [List.map] overflowed the stack on long paths. *)
  (* The robot's base where the cell mounts it (law F-base), when that is not the world's origin:
     drawn in the world frame with the path, at the start's external axes. *)
  let robot = Kinematics.robot (Planner.kinematics p) in
  let base =
    if Base_frame.is_world robot.base_frame then None
    else
      let e = match Planner.external_at p 0. with Ok e -> e | Error _ -> Ext_axes.initial robot.externals in
      Option.map (fun (b : pose) -> b.trans) (Base_frame.in_world robot e) in
  let all = List.rev_append (List.rev_map (fun (s : Planner.segment_info) -> s.target) segs)
      ((Planner.pose_at p 0.).trans :: (Option.to_list base @ List.concat_map snd runs)) in
  let range f =
    List.fold_left (fun (lo, hi) q -> (Float.min lo (f q), Float.max hi (f q))) (infinity, neg_infinity) all in
  let pad (lo, hi) = let m = Float.max 10. ((hi -. lo) *. 0.08) in (lo -. m, hi +. m) in
  let xr = pad (range (fun q -> q.x)) and yr = pad (range (fun q -> q.y)) and zr = pad (range (fun q -> q.z)) in
  let points = distinct_points segs in
  let named = List.filteri (fun i _ -> i < max_named) points in
  let more = List.length points - List.length named in
  let panel = 440. in
  (* The table of the points beside the two views: number, name, position. *)
  let table_x = 2. *. panel +. 110. and table_w = 380. and row_h = 15. in
  let table_rows = List.length named + (if more > 0 then 1 else 0) in
  let height = Float.max (panel +. 110.) (70. +. row_h *. float_of_int (table_rows + 1) +. 20.) in
  let b = Buffer.create 65536 in
  buf_printf b "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" \
                font-family=\"sans-serif\" font-size=\"12\">\n"
    (table_x +. table_w) height;
  buf_printf b "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n";
  buf_printf b "<text x=\"20\" y=\"24\" font-size=\"16\" font-weight=\"bold\">%s</text>\n" (esc title);
  buf_printf b "<text x=\"20\" y=\"%.0f\" fill=\"#555\">blue: programmed segments (moving), \
                orange: corner paths of fly-by points, \
                dots: programmed points (filled: stop point, ring: fly-by)</text>\n" (panel +. 100.);
  (* One view: [h] and [v] pick the horizontal and vertical coordinates; equal scales. *)
  let view ox name hname vname h v hr vr =
    let span = Float.max (snd hr -. fst hr) (snd vr -. fst vr) in
    let s = (panel -. 60.) /. span in
    let hc = (fst hr +. snd hr) /. 2. and vc = (fst vr +. snd vr) /. 2. in
    let oy = 50. in
    let px q = ox +. 50. +. (panel -. 60.) /. 2. +. (h q -. hc) *. s in
    let py q = oy +. (panel -. 60.) /. 2. -. (v q -. vc) *. s in
    buf_printf b "<g>\n<text x=\"%.1f\" y=\"%.1f\" font-size=\"14\" font-weight=\"bold\">%s</text>\n"
      (ox +. 50.) (oy -. 10.) name;
    let area = { bx = ox +. 50.; by = oy; bw = panel -. 60.; bh = panel -. 60. } in
    buf_printf b "<rect class=\"plot-area\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" \
                  stroke=\"#999\"/>\n" area.bx area.by area.bw area.bh;
    let t = tick span in
    let lo_h = hc -. span /. 2. and lo_v = vc -. span /. 2. in
    let first lo = t *. Float.ceil (lo /. t) in
    let rec ticks a hi f = if a <= hi then (f a; ticks (a +. t) hi f) in
    ticks (first lo_h) (lo_h +. span) (fun a ->
        let x = ox +. 50. +. (a -. lo_h) *. s in
        buf_printf b "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#eee\"/>\
                      <text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" fill=\"#555\">%g</text>\n"
          x oy x (oy +. panel -. 60.) x (oy +. panel -. 45.) a);
    ticks (first lo_v) (lo_v +. span) (fun a ->
        let y = oy +. panel -. 60. -. (a -. lo_v) *. s in
        buf_printf b "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#eee\"/>\
                      <text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#555\">%g</text>\n"
          (ox +. 50.) y (ox +. panel -. 10.) y (ox +. 45.) (y +. 4.) a);
    buf_printf b "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s (mm)</text>\n"
      (ox +. 50. +. (panel -. 60.) /. 2.) (oy +. panel -. 28.) hname;
    buf_printf b "<text x=\"%.1f\" y=\"%.1f\" transform=\"rotate(-90 %.1f %.1f)\" \
                  text-anchor=\"middle\">%s (mm)</text>\n"
      (ox +. 12.) (oy +. (panel -. 60.) /. 2.) (ox +. 12.) (oy +. (panel -. 60.) /. 2.) vname;
    List.iter (fun (corner, pts) ->
        buf_printf b "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"%s\" points=\""
          (if corner then "#e67e00" else "#1f5fbf") (if corner then "3" else "1.6");
        List.iter (fun q -> buf_printf b "%.2f,%.2f " (px q) (py q)) pts;
        Buffer.add_string b "\"/>\n") runs;
    Option.iter (fun at ->
        buf_printf b "<g class=\"robot-base\"><polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"#2e7d32\"/>\
                      <text x=\"%.1f\" y=\"%.1f\" fill=\"#2e7d32\">base</text></g>\n"
          (px at) (py at -. 7.) (px at -. 6.) (py at +. 5.) (px at +. 6.) (py at +. 5.) (px at +. 8.) (py at +. 4.))
      base;
    let start = (Planner.pose_at p 0.).trans in
    buf_printf b "<rect x=\"%.1f\" y=\"%.1f\" width=\"8\" height=\"8\" fill=\"#333\"/>\n"
      (px start -. 4.) (py start -. 4.);
    (* Each distinct point once (a dot at every pass was as many dots on top of each other);
       points that fall together in this view (a vertical move seen from above) share one label. *)
    let spots = Hashtbl.create 64 and order = ref [] in
    List.iter (fun pt ->
        let key = (Float.round (px pt.at), Float.round (py pt.at)) in
        match Hashtbl.find_opt spots key with
        | Some l -> Hashtbl.replace spots key (pt :: l)
        | None -> Hashtbl.replace spots key [ pt ]; order := key :: !order) points;
    let markers = List.map (fun (x, y) -> { bx = x -. 5.; by = y -. 5.; bw = 10.; bh = 10. }) !order in
    List.iter (fun (x, y) ->
        let pts = Hashtbl.find spots (x, y) in
        if List.exists (fun pt -> pt.fine) pts then
          buf_printf b "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"#c0392b\"/>\n" x y
        else buf_printf b "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"white\" stroke=\"#c0392b\" \
                           stroke-width=\"1.5\"/>\n" x y) (List.rev !order);
    (* Labels placed around their point inside the plot area, clear of the other labels and the
       dots: the nearest free place on rings of growing radius, with a leader line beyond the
       first; where none is free, the place that overlaps least. *)
    let placed = ref [] in
    let place ?(cls = "point-label") ?(colour = "#c0392b") x y text =
      let w = char_width *. float_of_int (String.length text) +. 2. and hgt = 13. in
      let w = Float.min w area.bw in
      let candidates = List.concat_map (fun r ->
          List.map (fun (dx, dy) ->
              let cx = x +. dx *. r and cy = y +. dy *. r in
              let bx = if dx > 0.3 then cx else if dx < -0.3 then cx -. w else cx -. w /. 2. in
              let by = if dy > 0.3 then cy else if dy < -0.3 then cy -. hgt else cy -. hgt /. 2. in
              (r, { bx; by; bw = w; bh = hgt }))
            [ (0.8, -0.8); (0.8, 0.8); (-0.8, -0.8); (-0.8, 0.8); (1., 0.); (-1., 0.); (0., -1.); (0., 1.) ])
          [ 7.; 16.; 28.; 42.; 60.; 84.; 110. ] in
      let candidates = List.filter (fun (_, bx) -> inside area bx) candidates in
      let cost bx = List.length (List.filter (overlap bx) !placed)
                    + List.length (List.filter (overlap bx) markers) in
      let chosen = match List.find_opt (fun (_, bx) -> cost bx = 0) candidates with
        | Some c -> Some c
        | None ->
            List.fold_left (fun acc (r, bx) -> match acc with
                | Some (_, best) when cost best <= cost bx -> acc
                | _ -> Some (r, bx)) None candidates in
      let r, bx = match chosen with
        | Some c -> c
        | None ->
            (* No ring place inside the area (a point at a corner of a small plot): clamped in. *)
            (0., { bx = Float.min (Float.max x area.bx) (area.bx +. area.bw -. w);
                   by = Float.min (Float.max (y -. hgt) area.by) (area.by +. area.bh -. hgt); bw = w; bh = hgt }) in
      placed := bx :: !placed;
      if r > 10. then begin
        let ex = Float.min (Float.max x bx.bx) (bx.bx +. bx.bw)
        and ey = Float.min (Float.max y bx.by) (bx.by +. bx.bh) in
        buf_printf b "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"0.6\"/>\n"
          x y ex ey colour
      end;
      buf_printf b "<text class=\"%s\" x=\"%.1f\" y=\"%.1f\" fill=\"%s\" stroke=\"white\" stroke-width=\"3\" \
                    paint-order=\"stroke\">%s</text>\n" cls (bx.bx +. 1.) (bx.by +. 10.) colour (esc text) in
    place ~cls:"start-label" ~colour:"#333" (px start) (py start) "start";
    List.iter (fun (x, y) ->
        let pts = List.rev (Hashtbl.find spots (x, y)) in
        match List.filter (fun pt -> pt.number <= max_named) pts with
        | [] -> ()
        | shown ->
            let text = String.concat ", " (List.map short_name shown) in
            let text = if String.length text > 30 then
                Printf.sprintf "#%d…#%d" (List.hd shown).number (List.nth shown (List.length shown - 1)).number
              else text in
            place x y text) (List.rev !order);
    Buffer.add_string b "</g>\n" in
  view 0. "Top view (x–y)" "x" "y" (fun q -> q.x) (fun q -> q.y) xr yr;
  view (panel +. 60.) "Side view (x–z)" "x" "z" (fun q -> q.x) (fun q -> q.z) xr zr;
  buf_printf b "<g class=\"point-table\"><text x=\"%.1f\" y=\"40\" font-size=\"14\" font-weight=\"bold\">\
                Programmed points</text>\n" table_x;
  buf_printf b "<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\">#  name  (x, y, z) mm</text>\n" table_x 60.;
  List.iteri (fun i pt ->
      buf_printf b "<text x=\"%.1f\" y=\"%.1f\"><tspan fill=\"#c0392b\">#%d %s</tspan> \
                    <tspan fill=\"#555\">(%.0f, %.0f, %.0f)</tspan></text>\n"
        table_x (60. +. row_h *. float_of_int (i + 1)) pt.number
        (esc (if pt.name = "" then "(unnamed)" else pt.name)) pt.at.x pt.at.y pt.at.z) named;
  if more > 0 then
    buf_printf b "<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\">and %d more points, not named</text>\n"
      table_x (60. +. row_h *. float_of_int (List.length named + 1)) more;
  Buffer.add_string b "</g>\n</svg>\n";
  Buffer.contents b

type lane = Waits | Traps | Signals

type mark = { lane : lane; m_from : float; m_to : float; m_label : string }

let lane_row = function Waits -> 0 | Traps -> 1 | Signals -> 2

(* The TCP speed by differences of positions taken within one moving piece of the path: the TCP
   is the tool's of the move under way, so a window across the start of the first move (the
   flange with tool0 before it) or a change of tool between two moves would give a speed the
   robot never had; standing still is 0. *)
let tcp_speeds ?(samples = 600) ?until p =
  let tend = match until with Some t -> t | None -> Float.max 1e-3 (end_time p) in
  let moving = Array.of_list (List.filter (fun (i : Planner.piece_info) ->
      Float.is_finite i.t_to && i.t_to > i.t_from && i.kind <> Planner.Still) (Planner.pieces p)) in
  let dt = tend /. float_of_int samples and j = ref 0 in
  Array.init samples (fun k ->
      let t0 = float_of_int k *. dt in
      let t1 = t0 +. dt and tm = t0 +. dt /. 2. in
      while !j < Array.length moving && moving.(!j).t_to < tm do incr j done;
      let v =
        if !j >= Array.length moving || moving.(!j).t_from > tm then 0.
        else
          let pc = moving.(!j) in
          let eps = 1e-9 *. (1. +. Float.abs tm) in
          let a = Float.max t0 (pc.t_from +. eps) and b = Float.min t1 (pc.t_to -. eps) in
          if b -. a <= eps then 0.
          else distance (Planner.pose_at p a).trans (Planner.pose_at p b).trans /. (b -. a) in
      (tm, v))

let timeline_svg ?(title = "Motion timeline") ?(program = []) p =
  let pieces = List.filter (fun (i : Planner.piece_info) -> Float.is_finite i.t_to) (Planner.pieces p) in
  let segs = Array.of_list (Planner.segments p) in
  let program = List.filter (fun m -> Float.is_finite m.m_from && Float.is_finite m.m_to) program in
  let tend = Float.max 1e-3 (List.fold_left (fun t m -> Float.max t m.m_to) (end_time p) program) in
  let w = 960. and left = 90. in
  let sx t = left +. t /. tend *. (w -. left -. 30.) in
  let b = Buffer.create 65536 in
  let height = if program = [] then 330. else 440. in
  buf_printf b "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" \
                font-family=\"sans-serif\" font-size=\"12\">\n" w height;
  buf_printf b "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n";
  buf_printf b "<text x=\"20\" y=\"24\" font-size=\"16\" font-weight=\"bold\">%s</text>\n" (esc title);
  buf_printf b "<text x=\"10\" y=\"75\">moves</text><text x=\"24\" y=\"210\" text-anchor=\"middle\" \
                transform=\"rotate(-90 24 210)\">TCP speed (mm/s)</text>\n";
  let t = tick tend in
  let rec ticks a = if a <= tend +. 1e-9 then begin
      buf_printf b "<line x1=\"%.1f\" y1=\"50\" x2=\"%.1f\" y2=\"290\" stroke=\"#eee\"/>\
                    <text x=\"%.1f\" y=\"305\" text-anchor=\"middle\" fill=\"#555\">%g</text>\n"
        (sx a) (sx a) (sx a) a;
      ticks (a +. t) end in
  ticks 0.;
  buf_printf b "<text x=\"%.1f\" y=\"322\" text-anchor=\"middle\">time (s)</text>\n" (sx (tend /. 2.));
  List.iter (fun (i : Planner.piece_info) ->
      let x0 = sx i.t_from and x1 = sx i.t_to in
      let fill, label = match i.kind with
        | Planner.Segment id ->
            let s = segs.(id) in
            ("#1f5fbf",
             Printf.sprintf "%s %s" s.seg_kind (if s.seg_label = "" then "#" ^ string_of_int id else s.seg_label))
        | Planner.Corner _ -> ("#e67e00", "")
        | Planner.Still -> ("#bbbbbb", "stop") in
      buf_printf b "<rect x=\"%.2f\" y=\"55\" width=\"%.2f\" height=\"30\" fill=\"%s\" stroke=\"white\" \
                    stroke-width=\"0.5\"><title>%s %.3f–%.3f s</title></rect>\n"
        x0 (Float.max 0.5 (x1 -. x0)) fill (esc label) i.t_from i.t_to;
      if label <> "" && x1 -. x0 > 7. *. float_of_int (String.length label) then
        buf_printf b "<text x=\"%.1f\" y=\"74\" text-anchor=\"middle\" fill=\"white\">%s</text>\n"
          ((x0 +. x1) /. 2.) (esc label))
    pieces;
  (* Each move's own piece and the corner after it, found once (a search of the pieces for every
     move was quadratic in the moves); the first, as a search from the start finds. *)
  let own_piece = Hashtbl.create 64 and corner_after = Hashtbl.create 64 in
  List.iter (fun (i : Planner.piece_info) ->
      match i.kind with
      | Planner.Segment id -> if not (Hashtbl.mem own_piece id) then Hashtbl.replace own_piece id i
      | Planner.Corner (a, _) -> if not (Hashtbl.mem corner_after a) then Hashtbl.replace corner_after a i
      | Planner.Still -> ()) pieces;
  List.iter (fun (s : Planner.segment_info) ->
      if s.seg_fine then
        match Hashtbl.find_opt own_piece s.seg_id with
        | Some i -> buf_printf b "<line x1=\"%.1f\" y1=\"48\" x2=\"%.1f\" y2=\"88\" stroke=\"#c0392b\" \
                                 stroke-width=\"2\"/>\n"
                      (sx i.t_to) (sx i.t_to)
        | None -> ()) (Array.to_list segs);
  (* Each programmed point under the time it is passed: the end of its segment at a stop point,
     the middle of its corner path at a fly-by point; named as in the path's table (a long name
     by its number there), in three staggered rows, where one of them has room. *)
  let numbers = Hashtbl.create 64 in
  List.iter (fun pt ->
      let r v = Float.round (v *. 10.) in
      Hashtbl.replace numbers (r pt.at.x, r pt.at.y, r pt.at.z, pt.name) (short_name pt))
    (distinct_points (Array.to_list segs));
  let rows = Array.make 3 neg_infinity in
  Array.iter (fun (s : Planner.segment_info) ->
      let own = Hashtbl.find_opt own_piece s.seg_id and corner = Hashtbl.find_opt corner_after s.seg_id in
      let at = match corner, own with
        | Some c, _ -> Some ((c.t_from +. c.t_to) /. 2.)
        | None, Some i -> Some i.t_to
        | None, None -> None in
      match at with
      | None -> ()
      | Some t ->
          let r v = Float.round (v *. 10.) in
          let name = match Hashtbl.find_opt numbers (r s.target.x, r s.target.y, r s.target.z, s.seg_label) with
            | Some n -> n
            | None -> "#" ^ string_of_int s.seg_id in
          let x = sx t and w = 6. *. float_of_int (String.length name) in
          let row = ref 0 in
          while !row < 3 && x -. w /. 2. < rows.(!row) +. 4. do incr row done;
          buf_printf b "<line x1=\"%.1f\" y1=\"85\" x2=\"%.1f\" y2=\"91\" stroke=\"#888\" stroke-width=\"0.5\"/>\n" x x;
          if !row < 3 then begin
            rows.(!row) <- x +. w /. 2.;
            let y = 100. +. 12. *. float_of_int !row in
            buf_printf b "<text class=\"point-name\" x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"10\" \
                          fill=\"#333\">%s</text>\n" x y (esc name)
          end) segs;
  buf_printf b "<g font-size=\"11\"><rect x=\"300\" y=\"12\" width=\"12\" height=\"10\" fill=\"#1f5fbf\"/>\
<text x=\"316\" y=\"21\">move</text>\
<rect x=\"360\" y=\"12\" width=\"12\" height=\"10\" fill=\"#e67e00\"/>\
<text x=\"376\" y=\"21\">corner path (fly-by point)</text>\
<rect x=\"530\" y=\"12\" width=\"12\" height=\"10\" fill=\"#bbbbbb\"/><text x=\"546\" y=\"21\">standing still</text>\
<line x1=\"640\" y1=\"10\" x2=\"640\" y2=\"24\" stroke=\"#c0392b\" stroke-width=\"2\"/>\
<text x=\"646\" y=\"21\">stop point (fine)</text>\
<text x=\"760\" y=\"21\" fill=\"#333\">names: points (#n: the path's table)</text></g>\n";
  let speeds = tcp_speeds ~samples:600 ~until:tend p in
  let step, vtop = nice_axis (Array.fold_left (fun m (_, v) -> Float.max m v) 0. speeds) in
  let top = 140. and h = 140. in
  let vy v = top +. h -. v /. vtop *. h in
  let rec vticks v = if v <= vtop +. 1e-9 *. vtop then begin
      buf_printf b "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>\
                    <text class=\"speed-tick\" x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#555\" \
                    font-size=\"10\">%g</text>\n"
        left (vy v) (w -. 30.) (vy v) (if v = 0. then "#999" else "#eee") (left -. 4.) (vy v +. 3.) v;
      vticks (v +. step) end in
  vticks 0.;
  buf_printf b "<polyline class=\"tcp-speed\" fill=\"none\" stroke=\"#1f8f4f\" stroke-width=\"1.5\" points=\"";
  Array.iter (fun (t, v) -> buf_printf b "%.2f,%.2f " (sx t) (vy v)) speeds;
  Buffer.add_string b "\"/>\n";
  (* The program against the same time: where its pointer waited, its traps, its signals. *)
  if program <> [] then begin
    List.iteri (fun k name ->
        buf_printf b "<text x=\"10\" y=\"%.0f\">%s</text>\n" (350. +. 30. *. float_of_int k) name)
      [ "waits"; "traps"; "signals" ];
    (* A signal's name is written where the one before it in the lane leaves room. *)
    let free = ref neg_infinity in
    List.iter (fun m ->
        let y = 336. +. 30. *. float_of_int (lane_row m.lane) in
        let x0 = sx m.m_from and x1 = sx m.m_to in
        match m.lane with
        | Signals ->
            buf_printf b "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#8e44ad\" \
                          stroke-width=\"1.5\"><title>%s %.6f s</title></line>\n"
              x0 y x0 (y +. 20.) (esc m.m_label) m.m_from;
            if x0 > !free && x0 +. 6. *. float_of_int (String.length m.m_label) +. 2. < w then begin
              buf_printf b "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" fill=\"#333\">%s</text>\n"
                (x0 +. 2.) (y +. 10.) (esc m.m_label);
              free := x0 +. 6.5 *. float_of_int (String.length m.m_label) +. 8.
            end
        | Waits | Traps ->
            buf_printf b "<rect class=\"%s\" x=\"%.2f\" y=\"%.1f\" width=\"%.2f\" height=\"20\" fill=\"%s\">\
                          <title>%s %.6f–%.6f s</title></rect>\n"
              (if m.lane = Waits then "wait" else "trap")
              x0 y (Float.max 1. (x1 -. x0)) (if m.lane = Waits then "#7f8c8d" else "#c0392b")
              (esc m.m_label) m.m_from m.m_to;
            (* the whole label where it fits, else the instruction's name (before ": ") *)
            let fits l = x1 -. x0 > 6. *. float_of_int (String.length l) +. 4. in
            let short = match String.index_opt m.m_label ':' with
              | Some i -> String.sub m.m_label 0 i | None -> m.m_label in
            let shown = if fits m.m_label then Some m.m_label else if fits short then Some short else None in
            Option.iter (fun l ->
                buf_printf b "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"10\" \
                              fill=\"white\">%s</text>\n"
                  ((x0 +. x1) /. 2.) (y +. 14.) (esc l)) shown) program
  end;
  Buffer.add_string b "</svg>\n";
  Buffer.contents b
