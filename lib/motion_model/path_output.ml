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

(* A "nice" tick spacing for a span. *)
let tick span =
  let raw = span /. 6. in
  let m = 10. ** Float.floor (log10 raw) in
  List.fold_left (fun acc k -> if k *. m >= raw && acc = 0. then k *. m else acc) 0. [ 1.; 2.; 5.; 10. ]

let path_svg ?(title = "TCP path") p =
  let runs = sampled p in
  let segs = Planner.segments p in
  (* For the ranges only, in no order: [@] and [List.map] overflowed the stack on long paths. *)
  let all = List.rev_append (List.rev_map (fun (s : Planner.segment_info) -> s.target) segs)
      ((Planner.pose_at p 0.).trans :: List.concat_map snd runs) in
  let range f =
    List.fold_left (fun (lo, hi) q -> (Float.min lo (f q), Float.max hi (f q))) (infinity, neg_infinity) all in
  let pad (lo, hi) = let m = Float.max 10. ((hi -. lo) *. 0.08) in (lo -. m, hi +. m) in
  let xr = pad (range (fun q -> q.x)) and yr = pad (range (fun q -> q.y)) and zr = pad (range (fun q -> q.z)) in
  let panel = 440. in
  let b = Buffer.create 65536 in
  buf_printf b "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" \
                font-family=\"sans-serif\" font-size=\"12\">\n"
    (2. *. panel +. 120.) (panel +. 110.);
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
    buf_printf b "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#999\"/>\n"
      (ox +. 50.) oy (panel -. 60.) (panel -. 60.);
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
    let start = (Planner.pose_at p 0.).trans in
    buf_printf b "<rect x=\"%.1f\" y=\"%.1f\" width=\"8\" height=\"8\" fill=\"#333\"/>\
                  <text x=\"%.1f\" y=\"%.1f\" fill=\"#333\">start</text>\n"
      (px start -. 4.) (py start -. 4.) (px start +. 7.) (py start +. 14.);
    (* Labels of points that fall together (a vertical move seen from above) are stacked. *)
    let placed = ref [] and named = Hashtbl.create 64 in
    let place x y w =
      let rec go y =
        if List.exists (fun (x', y', w') -> Float.abs (y -. y') < 13. && x < x' +. w' && x' < x +. w) !placed
        then go (y +. 14.) else y in
      let y = go y in
      placed := (x, y, w) :: !placed; y in
    List.iter (fun (sg : Planner.segment_info) ->
        let x = px sg.target and y = py sg.target in
        if sg.seg_fine then buf_printf b "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"#c0392b\"/>\n" x y
        else buf_printf b "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"white\" stroke=\"#c0392b\" \
                           stroke-width=\"1.5\"/>\n" x y;
        (* A point passed again with its name (a loop) is named once: stacking the same name
           at every pass was quadratic in the passes (and cubic to place). *)
        let key = (Float.round (x *. 10.), Float.round (y *. 10.), sg.seg_label) in
        if sg.seg_label <> "" && not (Hashtbl.mem named key) then
          let () = Hashtbl.replace named key () in
          let ly = place (x +. 6.) (y -. 6.) (7. *. float_of_int (String.length sg.seg_label)) in
          buf_printf b "<text x=\"%.1f\" y=\"%.1f\" fill=\"#c0392b\" stroke=\"white\" stroke-width=\"3\" \
                        paint-order=\"stroke\">%s</text>\n"
            (x +. 6.) ly (esc sg.seg_label)) segs;
    Buffer.add_string b "</g>\n" in
  view 0. "Top view (x–y)" "x" "y" (fun q -> q.x) (fun q -> q.y) xr yr;
  view (panel +. 60.) "Side view (x–z)" "x" "z" (fun q -> q.x) (fun q -> q.z) xr zr;
  Buffer.add_string b "</svg>\n";
  Buffer.contents b

type lane = Waits | Traps | Signals

type mark = { lane : lane; m_from : float; m_to : float; m_label : string }

let lane_row = function Waits -> 0 | Traps -> 1 | Signals -> 2

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
  buf_printf b "<text x=\"10\" y=\"75\">moves</text><text x=\"10\" y=\"175\">TCP speed</text>\n";
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
     the middle of its corner path at a fly-by point; labels in three staggered rows. *)
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
          let name = if s.seg_label = "" then "#" ^ string_of_int s.seg_id else s.seg_label in
          let x = sx t and w = 6.5 *. float_of_int (String.length name) in
          let row = ref 0 in
          while !row < 2 && x -. w /. 2. < rows.(!row) +. 4. do incr row done;
          rows.(!row) <- x +. w /. 2.;
          let y = 100. +. 12. *. float_of_int !row in
          buf_printf b "<line x1=\"%.1f\" y1=\"85\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#888\" stroke-width=\"0.5\"/>\
                        <text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"10\" fill=\"#333\">%s</text>\n"
            x x (y -. 9.) x y (esc name)) segs;
  buf_printf b "<g font-size=\"11\"><rect x=\"300\" y=\"12\" width=\"12\" height=\"10\" fill=\"#1f5fbf\"/>\
<text x=\"316\" y=\"21\">move</text>\
<rect x=\"360\" y=\"12\" width=\"12\" height=\"10\" fill=\"#e67e00\"/>\
<text x=\"376\" y=\"21\">corner path (fly-by point)</text>\
<rect x=\"530\" y=\"12\" width=\"12\" height=\"10\" fill=\"#bbbbbb\"/><text x=\"546\" y=\"21\">standing still</text>\
<line x1=\"640\" y1=\"10\" x2=\"640\" y2=\"24\" stroke=\"#c0392b\" stroke-width=\"2\"/>\
<text x=\"646\" y=\"21\">stop point (fine)</text>\
<text x=\"760\" y=\"21\" fill=\"#333\">names: programmed points</text></g>\n";
  (* TCP speed by differences of positions. *)
  let n = 600 in
  let dt = tend /. float_of_int n in
  let speeds = Array.init n (fun k ->
      let t0 = float_of_int k *. dt in
      distance (Planner.pose_at p t0).trans (Planner.pose_at p (t0 +. dt)).trans /. dt) in
  let vmax = Array.fold_left Float.max 1. speeds in
  let top = 140. and h = 140. in
  buf_printf b "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#999\"/>\n"
    left (top +. h) (w -. 30.) (top +. h);
  buf_printf b "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#555\">%.0f mm/s</text>\
                <text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#555\">0</text>\n"
    (left -. 4.) (top +. 4.) vmax (left -. 4.) (top +. h);
  buf_printf b "<polyline fill=\"none\" stroke=\"#1f8f4f\" stroke-width=\"1.5\" points=\"";
  Array.iteri (fun k v ->
      buf_printf b "%.2f,%.2f " (sx ((float_of_int k +. 0.5) *. dt)) (top +. h -. v /. vmax *. h)) speeds;
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
            if x0 > !free then begin
              buf_printf b "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" fill=\"#333\">%s</text>\n"
                (x0 +. 2.) (y +. 10.) (esc m.m_label);
              free := x0 +. 6. *. float_of_int (String.length m.m_label) +. 6.
            end
        | Waits | Traps ->
            buf_printf b "<rect x=\"%.2f\" y=\"%.1f\" width=\"%.2f\" height=\"20\" fill=\"%s\">\
                          <title>%s %.6f–%.6f s</title></rect>\n"
              x0 y (Float.max 1. (x1 -. x0)) (if m.lane = Waits then "#7f8c8d" else "#c0392b")
              (esc m.m_label) m.m_from m.m_to;
            if x1 -. x0 > 6.5 *. float_of_int (String.length m.m_label) then
              buf_printf b "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"10\" \
                            fill=\"white\">%s</text>\n"
                ((x0 +. x1) /. 2.) (y +. 14.) (esc m.m_label)) program
  end;
  Buffer.add_string b "</svg>\n";
  Buffer.contents b
