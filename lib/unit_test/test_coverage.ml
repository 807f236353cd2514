module M = Rapid_semantics.Machine
module R = Rapid_semantics.Rule
module S = Rapid_syntax.Source

type key = string * int * int

let key_of region : key option =
  match S.file_of region with
  | None -> None
  | Some f -> let p = S.start region in Some (S.name f, p.line, p.col)

(* A branch point: a condition (IF, ELSEIF, compact IF, WHILE, FOR's "another round") has two
   ways, the taken one first; a TEST one per case and its DEFAULT (present or not) last. *)
type point = { at : key; ways : int; counts : int array }

type routine = { r_name : string; r_module : string; r_at : key; mutable r_entered : int }

type t = {
  statements : (key, int ref) Hashtbl.t;
  points : (key, point) Hashtbl.t;
  routines : (key, routine) Hashtbl.t;
}

let ways (s : Ir.stmt) =
  match s.s with
  | If _ | Elseif _ | Compact_if _ | While _ | For _ -> Some 2
  | Test (_, cases, _) -> Some (Array.length cases + 1)
  | _ -> None

let of_program (program : Ir.program) ~covered =
  let t = { statements = Hashtbl.create 256; points = Hashtbl.create 64; routines = Hashtbl.create 32 } in
  let rec block (b : Ir.block) = Array.iter stmt b.body
  and stmt (s : Ir.stmt) =
    match key_of s.sat with
    | None -> ()
    | Some k ->
        (match s.s with Label -> () | _ -> Hashtbl.replace t.statements k (ref 0));
        Option.iter (fun n -> Hashtbl.replace t.points k { at = k; ways = n; counts = Array.make n 0 }) (ways s);
        match s.s with
        | If (_, a, b) | Elseif (_, a, b) -> block a; block b
        | Compact_if (_, inner) -> stmt inner
        | While (_, b) -> block b
        | For f -> block f.loop_body
        | Test (_, cases, d) -> Array.iter (fun (_, b) -> block b) cases; block d
        | _ -> () in
  Array.iter (fun (r : Ir.routine) ->
      if r.primitive = None && covered r then
        match key_of r.at with
        | None -> ()
        | Some k ->
            Hashtbl.replace t.routines k { r_name = r.name; r_module = r.module_name; r_at = k; r_entered = 0 };
            block r.body;
            Option.iter block r.backward;
            Option.iter (fun (h : Ir.error_handler) -> block h.handler) r.error;
            Option.iter block r.undo) program.routines;
  t

(* By region during the run: a region is one immediate integer, cheap to count by. *)
type hits = {
  reached : (S.region, int ref) Hashtbl.t;
  taken : (S.region * int, int ref) Hashtbl.t;
  entered : (S.region, int ref) Hashtbl.t;
}

let record () = { reached = Hashtbl.create 256; taken = Hashtbl.create 64; entered = Hashtbl.create 32 }

let bump table k = match Hashtbl.find_opt table k with Some n -> incr n | None -> Hashtbl.replace table k (ref 1)

(* The way a step's rule chose, of the statement in progress before it. *)
let way rule ~test_case (s : Ir.stmt) =
  match rule, s.s with
  | (R.If_true | R.Compact_if_true | R.While_true | R.For_enter | R.For_step), _ -> Some 0
  | (R.If_false | R.Compact_if_false | R.While_false | R.For_empty | R.For_done), _ -> Some 1
  | R.Test_match, _ -> test_case
  | R.Test_default, Test (_, cases, _) -> Some (Array.length cases)
  | _ -> None

let observe h cfg step =
  (match M.focus_view cfg with Statement s -> bump h.reached s.sat | _ -> ());
  let before = M.current_statement cfg and test_case = M.test_case cfg and depth = M.depth cfg in
  let rule, events = step () in
  Option.iter (fun s -> Option.iter (fun w -> bump h.taken (s.Ir.sat, w)) (way rule ~test_case s)) before;
  if M.depth cfg > depth && M.outcome cfg = Running then bump h.entered (M.current_routine cfg).at;
  (rule, events)

type portable = {
  p_reached : (key * int) list;
  p_taken : ((key * int) * int) list;
  p_entered : (key * int) list;
}

let portable h =
  let keyed table f = Hashtbl.fold (fun r n acc -> match f r with Some k -> (k, !n) :: acc | None -> acc) table [] in
  { p_reached = keyed h.reached key_of;
    p_taken = keyed h.taken (fun (r, w) -> Option.map (fun k -> (k, w)) (key_of r));
    p_entered = keyed h.entered key_of }

let add t p =
  List.iter (fun (k, n) -> match Hashtbl.find_opt t.statements k with Some c -> c := !c + n | None -> ()) p.p_reached;
  List.iter (fun ((k, w), n) -> match Hashtbl.find_opt t.points k with
      | Some pt when w < pt.ways -> pt.counts.(w) <- pt.counts.(w) + n
      | _ -> ()) p.p_taken;
  List.iter (fun (k, n) -> match Hashtbl.find_opt t.routines k with
      | Some r -> r.r_entered <- r.r_entered + n | None -> ()) p.p_entered

(* The files, in name order; in each, its lines (the most any statement starting there was
   reached), branch points and routines, in the order of the text. *)
let files t =
  let names = Hashtbl.create 8 in
  let note (f, _, _) = Hashtbl.replace names f () in
  Hashtbl.iter (fun k _ -> note k) t.statements;
  Hashtbl.iter (fun k _ -> note k) t.routines;
  List.sort compare (Hashtbl.fold (fun f () acc -> f :: acc) names [])

let in_file f (f', _, _) = f = f'

let lines t file =
  let by_line = Hashtbl.create 64 in
  Hashtbl.iter (fun ((_, line, _) as k) n ->
      if in_file file k then
        Hashtbl.replace by_line line (max !n (Option.value (Hashtbl.find_opt by_line line) ~default:0))) t.statements;
  List.sort compare (Hashtbl.fold (fun l n acc -> (l, n) :: acc) by_line [])

let points t file =
  List.sort (fun a b -> compare a.at b.at)
    (Hashtbl.fold (fun k p acc -> if in_file file k then p :: acc else acc) t.points [])

let routines t file =
  List.sort (fun a b -> compare a.r_at b.r_at)
    (Hashtbl.fold (fun k r acc -> if in_file file k then r :: acc else acc) t.routines [])

(* A point never reached has no count of its ways: lcov's "-". *)
let reached t (p : point) = match Hashtbl.find_opt t.statements p.at with Some n -> !n > 0 | None -> false

let line_of (_, l, _) = l

let lcov t =
  let b = Buffer.create 4096 in
  List.iter (fun file ->
      Printf.bprintf b "TN:\nSF:%s\n" file;
      let rs = routines t file in
      List.iter (fun r -> Printf.bprintf b "FN:%d,%s\n" (line_of r.r_at) r.r_name) rs;
      List.iter (fun r -> Printf.bprintf b "FNDA:%d,%s\n" r.r_entered r.r_name) rs;
      Printf.bprintf b "FNF:%d\nFNH:%d\n" (List.length rs) (List.length (List.filter (fun r -> r.r_entered > 0) rs));
      let ps = points t file in
      let found = ref 0 and hit = ref 0 in
      List.iteri (fun block p ->
          Array.iteri (fun w n ->
              incr found;
              if n > 0 then incr hit;
              Printf.bprintf b "BRDA:%d,%d,%d,%s\n" (line_of p.at) block w
                (if reached t p then string_of_int n else "-")) p.counts) ps;
      Printf.bprintf b "BRF:%d\nBRH:%d\n" !found !hit;
      let ls = lines t file in
      List.iter (fun (l, n) -> Printf.bprintf b "DA:%d,%d\n" l n) ls;
      Printf.bprintf b "LF:%d\nLH:%d\nend_of_record\n" (List.length ls)
        (List.length (List.filter (fun (_, n) -> n > 0) ls)))
    (files t);
  Buffer.contents b

let totals t =
  let ls = List.concat_map (lines t) (files t) in
  let ways = List.concat_map (fun f -> List.concat_map (fun p -> Array.to_list p.counts) (points t f)) (files t) in
  (List.length (List.filter (fun (_, n) -> n > 0) ls), List.length ls,
   List.length (List.filter (fun n -> n > 0) ways), List.length ways)

let rate hit found = if found = 0 then 1. else float_of_int hit /. float_of_int found

let percent hit found = Printf.sprintf "%d/%d (%.1f%%)" hit found (100. *. rate hit found)

let summary t =
  let lh, lf, bh, bf = totals t in
  Printf.sprintf "lines: %s, branches: %s" (percent lh lf) (percent bh bf)

let cobertura t ~version =
  let x = Xml_text.escape in
  let b = Buffer.create 4096 in
  let lh, lf, bh, bf = totals t in
  let r4 v = Printf.sprintf "%.4f" v in
  Buffer.add_string b "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  Buffer.add_string b "<!DOCTYPE coverage SYSTEM \"http://cobertura.sourceforge.net/xml/coverage-04.dtd\">\n";
  Printf.bprintf b "<coverage line-rate=\"%s\" branch-rate=\"%s\" lines-covered=\"%d\" lines-valid=\"%d\" \
                    branches-covered=\"%d\" branches-valid=\"%d\" complexity=\"0\" version=\"%s\" timestamp=\"0\">\n"
    (r4 (rate lh lf)) (r4 (rate bh bf)) lh lf bh bf (x version);
  Buffer.add_string b "  <sources>\n    <source>.</source>\n  </sources>\n  <packages>\n";
  Printf.bprintf b
    "    <package name=\"rapid\" line-rate=\"%s\" branch-rate=\"%s\" complexity=\"0\">\n      <classes>\n"
    (r4 (rate lh lf)) (r4 (rate bh bf));
  List.iter (fun file ->
      let ls = lines t file and ps = points t file and rs = routines t file in
      let branch_of line = List.filter (fun p -> line_of p.at = line) ps in
      let ways ps = List.concat_map (fun p -> Array.to_list p.counts) ps in
      let line_xml indent (l, n) =
        match ways (branch_of l) with
        | [] -> Printf.bprintf b "%s<line number=\"%d\" hits=\"%d\" branch=\"false\"/>\n" indent l n
        | ws ->
            let h = List.length (List.filter (fun n -> n > 0) ws) and f = List.length ws in
            Printf.bprintf b "%s<line number=\"%d\" hits=\"%d\" branch=\"true\" condition-coverage=\"%d%% (%d/%d)\"/>\n"
              indent l n (int_of_float (100. *. rate h f)) h f in
      let fh = List.length (List.filter (fun (_, n) -> n > 0) ls) in
      let bw = ways ps in
      let module_name = match rs with r :: _ -> r.r_module | [] -> Filename.remove_extension (Filename.basename file) in
      Printf.bprintf b
        "        <class name=\"%s\" filename=\"%s\" line-rate=\"%s\" branch-rate=\"%s\" complexity=\"0\">\n"
        (x module_name) (x file) (r4 (rate fh (List.length ls)))
        (r4 (rate (List.length (List.filter (fun n -> n > 0) bw)) (List.length bw)));
      Buffer.add_string b "          <methods>\n";
      (* A routine's lines: from its declaration up to the next routine's. *)
      let rec methods = function
        | [] -> ()
        | r :: rest ->
            let first = line_of r.r_at in
            let last = match rest with n :: _ -> line_of n.r_at | [] -> max_int in
            let mine = List.filter (fun (l, _) -> l >= first && l < last) ls in
            let mh = List.length (List.filter (fun (_, n) -> n > 0) mine) in
            Printf.bprintf b "            <method name=\"%s\" signature=\"\" line-rate=\"%s\" branch-rate=\"%s\" \
                              complexity=\"0\">\n              <lines>\n"
              (x r.r_name) (r4 (rate mh (List.length mine)))
              (let ws = ways (List.filter (fun p -> line_of p.at >= first && line_of p.at < last) ps) in
               r4 (rate (List.length (List.filter (fun n -> n > 0) ws)) (List.length ws)));
            List.iter (line_xml "                ") mine;
            Buffer.add_string b "              </lines>\n            </method>\n";
            methods rest in
      methods rs;
      Buffer.add_string b "          </methods>\n          <lines>\n";
      List.iter (line_xml "            ") ls;
      Buffer.add_string b "          </lines>\n        </class>\n") (files t);
  Buffer.add_string b "      </classes>\n    </package>\n  </packages>\n</coverage>\n";
  Buffer.contents b
