type axis = {
  a : float; alpha : float; d : float; offset : float;
  min : float; max : float; speed : float;
}

type structure = Serial | Coupled_axis3 | Palletiser | Delta | Scara

let structure_names =
  [ ("serial", Serial); ("coupled-axis3", Coupled_axis3); ("palletiser", Palletiser); ("delta", Delta);
    ("scara", Scara) ]

(* A palletiser has axes 1, 2, 3 and 6 (ABB numbers them so), a delta and a SCARA 1 to 4; the
   others stand still at 0. *)
let absent_axes = function Palletiser -> [ 4; 5 ] | Delta | Scara -> [ 5; 6 ] | Serial | Coupled_axis3 -> []

let structure_word = function
  | Palletiser -> "palletiser" | Delta -> "delta" | Scara -> "SCARA" | Serial | Coupled_axis3 -> "serial arm"

let absent_axis = { a = 0.; alpha = 0.; d = 0.; offset = 0.; min = 0.; max = 0.; speed = 1. }

type t = {
  name : string; structure : structure; axes : axis array; max_tcp_speed : float; externals : Ext_axes.axis list;
  reach : float option; base_frame : Geom.pose;
}

type error = { file : string; line : int; col : int; message : string }

let error_to_string e =
  Printf.sprintf "%s:%d:%d: robot description error: %s" e.file e.line e.col e.message

(* installed-facts.md §3: d1 290, a2 270, a3 70, d4 302, d6 72 (CORROBORATED); ranges and speeds
   UNCERTAIN. The twists and joint offsets are the usual DH reading that puts axis 2 vertical and
   axis 3 horizontal at all angles 0, tool0 pointing along +X with its x axis down, the flange at
   [374, 0, 630] (installed-facts.md: "about x = 374, z = 630"). The maximum TCP speed is ABB's
   product specification figure for the IRB 120, 6.2 m/s (UNCERTAIN, from memory). *)
let irb120_text = {|# ABB IRB 120 (installed-facts.md, "A default robot for the kinematic model")
name "ABB IRB 120"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1      0        -90        290       0          -165   165      250
axis 2      270        0          0     -90          -110   110      250
axis 3      70       -90          0       0          -110    70      250
axis 4      0         90        302       0          -160   160      320
axis 5      0        -90          0       0          -120   120      320
axis 6      0          0         72     180          -400   400      420
max_tcp_speed 6200
|}

exception Bad of int * int * string

(* Words of a line with their 1-based columns; a quoted name is one word; '#' starts a comment. *)
let words line_no line =
  let n = String.length line in
  let rec go i acc =
    if i >= n || line.[i] = '#' then List.rev acc
    else if line.[i] = ' ' || line.[i] = '\t' || line.[i] = '\r' then go (i + 1) acc
    else if line.[i] = '"' then
      match String.index_from_opt line (i + 1) '"' with
      | None -> raise (Bad (line_no, i + 1, "unterminated name: a closing \" is missing"))
      | Some j -> go (j + 1) ((i + 1, "\"" ^ String.sub line (i + 1) (j - i - 1)) :: acc)
    else
      let j = ref i in
      while !j < n && not (List.mem line.[!j] [ ' '; '\t'; '\r'; '#' ]) do incr j done;
      go !j ((i + 1, String.sub line i (!j - i)) :: acc)
  in
  go 0 []

let number line (col, w) what =
  match Rapid_syntax.Decimal.read w with
  | Ok f -> f
  | Error `Not_decimal ->
      raise (Bad (line, col, Printf.sprintf "%s: expected a number, found %S" what (Rapid_syntax.Decimal.shown w)))
  | Error `Beyond_num ->
      raise (Bad (line, col, Printf.sprintf "%s: %s is beyond the range of num (at most 3.40282347E+38, §2.13)"
                               what (Rapid_syntax.Decimal.shown w)))

(* R-2.13-numbers2: what the model takes. Lengths up to 100 m, a non-zero one from 1 µm (the
   inverse kinematics divides by them); twists and joint offsets within a turn either way;
   axis limits within 100,000 degrees (axis 6 of ABB's arms turns up to ±242 revolutions) or
   100 m; speeds from 0.001 to 100,000 units a second (a slower axis would take centuries to
   move, beyond the clock of R-8-j). Every figure of the model then stays far inside num. *)
let max_length = 100_000.
let min_length = 0.001
let max_turn = 360.
let max_limit = 100_000.
let min_speed = 0.001
let max_speed = 100_000.

let within line (col, w) what ~low ~high ~unit v =
  if v < low || v > high then
    raise (Bad (line, col, Printf.sprintf "%s: %s is outside %g .. %g %s, the range of the model (doc/motion.md)"
                             what (Rapid_syntax.Decimal.shown w) low high unit))

let length line cw what v =
  within line cw what ~low:(-. max_length) ~high:max_length ~unit:"mm" v;
  if v <> 0. && Float.abs v < min_length then
    raise (Bad (line, fst cw, Printf.sprintf "%s: %s is below 0.001 mm, the model's resolution (0 or at least 0.001)"
                                what (Rapid_syntax.Decimal.shown (snd cw))));
  v

(* A speed: positive (its own message, the common mistake), then within the model's range. *)
let speed line cw what ~unit ~positive v =
  if v <= 0. then raise (Bad (line, fst cw, positive));
  within line cw what ~low:min_speed ~high:max_speed ~unit v;
  v

(* external NAME linear|rotating MIN MAX SPEED [track DX DY DZ] (doc/motion.md, law X-desc). *)
let external_axis ln known rest =
  let fields = [ "min"; "max"; "speed" ] in
  match rest with
  | [] -> raise (Bad (ln, 1, "external: expected NAME linear|rotating MIN MAX SPEED [track DX DY DZ]"))
  | (nc, n) :: rest ->
      let index =
        match Array.to_list Ext_axes.names |> List.mapi (fun i x -> (i, x)) |> List.find_opt (fun (_, x) -> x = n) with
        | Some (i, _) -> i
        | None -> raise (Bad (ln, nc, Printf.sprintf "external axis name must be eax_a to eax_f, found %S" n)) in
      if List.exists (fun (a : Ext_axes.axis) -> a.index = index) known then
        raise (Bad (ln, nc, Printf.sprintf "external axis %s given twice" n));
      let kind, rest = match rest with
        | (_, "linear") :: r -> (Ext_axes.Linear, r)
        | (_, "rotating") :: r -> (Ext_axes.Rotating, r)
        | (c, w) :: _ -> raise (Bad (ln, c, Printf.sprintf "%s: expected linear or rotating, found %S" n w))
        | [] -> raise (Bad (ln, nc, Printf.sprintf "%s: expected linear or rotating" n)) in
      let nums, track = match rest with
        | a :: b :: c :: (tc, "track") :: dir -> ([ a; b; c ], Some (tc, dir))
        | _ -> (rest, None) in
      if List.length nums <> 3 then
        raise (Bad (ln, (match List.rev rest with (c, _) :: _ -> c | [] -> nc),
                    Printf.sprintf "%s: expected 3 numbers (min max speed), found %d" n (List.length nums)));
      let v = List.map2 (fun f w -> number ln w (Printf.sprintf "%s %s" n f)) fields nums in
      let unit = if kind = Ext_axes.Linear then "mm" else "degrees" in
      List.iteri (fun i w -> if i < 2 then
                     within ln w (Printf.sprintf "%s %s" n (List.nth fields i))
                       ~low:(-. max_limit) ~high:max_limit ~unit (List.nth v i)) nums;
      let min = List.nth v 0 and max = List.nth v 1 in
      if min >= max then
        raise (Bad (ln, fst (List.nth nums 0), Printf.sprintf "%s: range min %g is not below max %g" n min max));
      let speed = speed ln (List.nth nums 2) (n ^ " speed") ~unit:(unit ^ "/s")
          ~positive:(Printf.sprintf "%s: speed must be positive" n) (List.nth v 2) in
      let track = match track with
        | None -> None
        | Some (tc, _) when kind = Ext_axes.Rotating ->
            raise (Bad (ln, tc, Printf.sprintf "%s: only a linear axis can be a track" n))
        | Some (tc, dir) ->
            if List.length dir <> 3 then
              raise (Bad (ln, tc, Printf.sprintf "%s: track: expected 3 numbers (a direction DX DY DZ), found %d"
                                    n (List.length dir)));
            let d = List.map (fun w ->
                let v = number ln w (n ^ " track") in
                within ln w (n ^ " track") ~low:(-. max_length) ~high:max_length ~unit:"(a direction)" v; v) dir in
            let p = { Geom.x = List.nth d 0; y = List.nth d 1; z = List.nth d 2 } in
            let l = Geom.norm p in
            if not (l > 0.) then raise (Bad (ln, tc, Printf.sprintf "%s: track: the direction is zero" n));
            if List.exists (fun (a : Ext_axes.axis) -> a.track <> None) known then
              raise (Bad (ln, tc, Printf.sprintf "%s: a second track: the robot stands on one" n));
            Some (Geom.scale (1. /. l) p) in
      { Ext_axes.name = n; index; kind; min; max; speed; track }

(* The first problem a structure's checks find: each check says (axis, message) through [say]. *)
let first_problem checks =
  let bad = ref None in
  let say k m = if !bad = None then bad := Some (k, m) in
  List.iter (fun check -> check say) checks;
  !bad

(* Axes that turn about parallel vertical axes: no twist, no offset. *)
let untwisted structure ks r say =
  List.iter (fun k -> let ax = r.axes.(k - 1) in
              if ax.alpha <> 0. || ax.offset <> 0. then
                say k (Printf.sprintf "axis %d: a %s's alpha and offset must be 0 (doc/motion.md)" k structure)) ks

let palletiser_problem r =
  first_problem [
    untwisted "palletiser" [ 1; 2; 3; 6 ] r;
    (fun say -> List.iter (fun k ->
         if r.axes.(k - 1).a <= 0. then
           say k (Printf.sprintf "axis %d: a palletiser's arm length a must be positive" k)) [ 2; 3 ]) ]

let delta_problem r =
  let ax k = r.axes.(k - 1) in
  first_problem [
    untwisted "delta" [ 1; 2; 3; 4 ] r;
    (fun say -> List.iter (fun k -> if (ax k).a <> (ax 1).a || (ax k).d <> (ax 1).d then
                              say k (Printf.sprintf "axis %d: a delta's three arms have axis 1's a and d" k)) [ 2; 3 ]);
    (fun say -> if (ax 1).a <= 0. || (ax 1).d <= 0. then
        say 1 "axis 1: a delta's upper arm a and rod d must be positive");
    (fun say -> if (ax 4).a < 0. || (ax 4).d < 0. then say 4 "axis 4: a delta's a and d must not be negative") ]

(* A SCARA (IRB 910SC): axes 1 and 2 turn the two arms about vertical axes, axis 3 moves the
   quill up and down (mm), axis 4 turns the flange; only axis 1's d (the flange's height at axis
   3 = 0) and the two arms' a are lengths. *)
let scara_problem r =
  let ax k = r.axes.(k - 1) in
  first_problem [
    untwisted "SCARA" [ 1; 2; 3; 4 ] r;
    (fun say -> List.iter (fun k ->
         if (ax k).a <= 0. then say k (Printf.sprintf "axis %d: a SCARA's arm length a must be positive" k)) [ 1; 2 ]);
    (fun say -> List.iter (fun k ->
         if (ax k).d <> 0. then say k (Printf.sprintf "axis %d: a SCARA's d must be 0 (axis 1's d is the height)" k))
        [ 2; 3; 4 ]);
    (fun say -> List.iter (fun k -> if (ax k).a <> 0. then say k (Printf.sprintf "axis %d: a SCARA's a must be 0" k))
        [ 3; 4 ]) ]

let structure_problem r =
  match r.structure with
  | Palletiser -> palletiser_problem r
  | Delta -> delta_problem r
  | Scara -> scara_problem r
  | Serial | Coupled_axis3 ->
  let ax i = r.axes.(i - 1) in
  let expect = [| -90.; 0.; -90.; 90.; -90.; 0. |] in
  let bad = ref None in
  Array.iteri (fun i e -> if !bad = None && Float.abs ((ax (i + 1)).alpha -. e) > 1e-9 then
                  bad := Some (i + 1, Printf.sprintf "axis %d: alpha must be %g" (i + 1) e)) expect;
  let zero what i v =
    if !bad = None && v <> 0. then bad := Some (i, Printf.sprintf "axis %d: %s must be 0" i what) in
  zero "d" 2 (ax 2).d; zero "d" 3 (ax 3).d; zero "d" 5 (ax 5).d;
  (* axis 5's a may be given: an offset wrist (CRB 15000), solved numerically *)
  zero "a" 4 (ax 4).a; zero "a" 6 (ax 6).a;
  if !bad = None && (ax 2).a <= 0. then bad := Some (2, "axis 2: a must be positive");
  Option.map (fun (k, m) -> k, "unsupported kinematic structure (" ^ m ^ "): the inverse kinematics \
     solves arms with twists -90 0 -90 90 -90 0 (doc/motion.md)") !bad

let structure_error r = Option.map snd (structure_problem r)

let present r k = not (List.mem k (absent_axes r.structure))

let parse ~file text =
  let name = ref None and tcp = ref None and reach = ref None and structure = ref None in
  let axes = Array.make 6 None and axis_line = Array.make 6 1 in
  let externals = ref [] in
  let fail line col message = Error { file; line; col; message } in
  try
    (* a UTF-8 byte order mark, which some editors write first, is not part of line 1 *)
    let text = if String.length text >= 3 && String.sub text 0 3 = "\xEF\xBB\xBF"
      then String.sub text 3 (String.length text - 3) else text in
    let lines = String.split_on_char '\n' text in
    List.iteri (fun i line ->
        let ln = i + 1 in
        match words ln line with
        | [] -> ()
        | [ (_, "name"); (c, w) ] ->
            if String.length w = 0 || w.[0] <> '"' then raise (Bad (ln, c, "name: expected a quoted name"));
            if !name <> None then raise (Bad (ln, 1, "name given twice"));
            name := Some (String.sub w 1 (String.length w - 1))
        | (_, "name") :: _ -> raise (Bad (ln, 1, "name: expected one quoted name"))
        | [ (_, "max_tcp_speed"); v ] ->
            let s = speed ln v "max_tcp_speed" ~unit:"mm/s" ~positive:"max_tcp_speed must be positive"
                (number ln v "max_tcp_speed") in
            if !tcp <> None then raise (Bad (ln, 1, "max_tcp_speed given twice"));
            tcp := Some s
        | (_, "max_tcp_speed") :: _ -> raise (Bad (ln, 1, "max_tcp_speed: expected one number (mm/s)"))
        | [ (_, "structure"); (c, w) ] ->
            (match List.assoc_opt w structure_names with
             | None -> raise (Bad (ln, c, Printf.sprintf
                                    "structure: expected serial, coupled-axis3, palletiser, delta or scara, found %S"
                                    (Rapid_syntax.Decimal.shown w)))
             | Some k ->
                 if !structure <> None then raise (Bad (ln, 1, "structure given twice"));
                 structure := Some k)
        | (_, "structure") :: _ -> raise (Bad (ln, 1, "structure: expected one word"))
        | [ (_, "reach"); v ] ->
            (* informative: the reach of the wrist centre a product specification gives *)
            let l = length ln v "reach" (number ln v "reach") in
            if l <= 0. then raise (Bad (ln, fst v, "reach must be positive"));
            if !reach <> None then raise (Bad (ln, 1, "reach given twice"));
            reach := Some l
        | (_, "reach") :: _ -> raise (Bad (ln, 1, "reach: expected one number (mm)"))
        | (_, "axis") :: (nc, n) :: rest ->
            (* int_of_string would take 0x1 and 1_ too *)
            let k = match n with
              | "1" | "2" | "3" | "4" | "5" | "6" -> int_of_string n
              | _ -> raise (Bad (ln, nc, Printf.sprintf "axis number must be 1 to 6, found %S" n)) in
            if axes.(k - 1) <> None then raise (Bad (ln, nc, Printf.sprintf "axis %d given twice" k));
            let fields = [ "a"; "alpha"; "d"; "offset"; "min"; "max"; "speed" ] in
            if List.length rest <> 7 then
              raise (Bad (ln, (match rest with [] -> nc | _ -> fst (List.nth rest (List.length rest - 1))),
                          Printf.sprintf "axis %d: expected 7 numbers (a alpha d offset min max speed), found %d"
                            k (List.length rest)));
            (* the texts for errors by concatenation: Printf for each of the default robot's 42 numbers
               was a tenth of an empty run's start *)
            let axis_k = "axis " ^ string_of_int k in
            let v = List.map2 (fun f w -> number ln w (axis_k ^ " " ^ f)) fields rest in
            let get i = List.nth v i and word i = List.nth rest i in
            let what i = axis_k ^ " " ^ List.nth fields i in
            let len i = length ln (word i) (what i) (get i) in
            let turn i = within ln (word i) (what i) ~low:(-. max_turn) ~high:max_turn ~unit:"degrees" (get i); get i in
            let limit i =
              within ln (word i) (what i) ~low:(-. max_limit) ~high:max_limit ~unit:"degrees" (get i); get i in
            (* in the order of the line, so that the first bad word is the one reported *)
            let a = len 0 in let alpha = turn 1 in let d = len 2 in let offset = turn 3 in
            let min = limit 4 in let max = limit 5 in
            let ax = { a; alpha; d; offset; min; max; speed = get 6 } in
            if ax.min >= ax.max then
              raise (Bad (ln, fst (List.nth rest 4),
                          Printf.sprintf "axis %d: range min %g is not below max %g" k ax.min ax.max));
            let ax = { ax with speed = speed ln (word 6) (what 6) ~unit:"degrees/s"
                                   ~positive:(axis_k ^ ": speed must be positive") ax.speed } in
            axes.(k - 1) <- Some ax;
            axis_line.(k - 1) <- ln
        | (_, "external") :: rest -> externals := !externals @ [ external_axis ln !externals rest ]
        | (c, w) :: _ ->
            raise (Bad (ln, c, Printf.sprintf
                                 "unknown keyword %S (expected name, structure, axis, external, max_tcp_speed or reach)"
                                 (Rapid_syntax.Decimal.shown w))))
      lines;
    let last = List.length lines in
    let kind = Option.value !structure ~default:Serial in
    let absent = absent_axes kind in
    List.iter (fun k -> if axes.(k - 1) <> None then
                  raise (Bad (axis_line.(k - 1), 1, Printf.sprintf
                                "axis %d: a %s has no axis %d (its axes are %s)" k
                                (structure_word kind) k
                                (if kind = Palletiser then "1, 2, 3 and 6" else "1 to 4")))) absent;
    List.iter (fun k -> axes.(k - 1) <- Some absent_axis) absent;
    let missing = ref None in
    Array.iteri (fun i a -> if a = None && !missing = None then missing := Some (i + 1)) axes;
    match !missing, !tcp with
    | Some k, _ -> fail last 1 (Printf.sprintf "axis %d is missing" k)
    | None, None -> fail last 1 "max_tcp_speed is missing"
    | None, Some max_tcp_speed ->
        let r = { name = Option.value !name ~default:file; structure = kind;
                  axes = Array.map Option.get axes; max_tcp_speed; externals = !externals;
                  reach = !reach; base_frame = Geom.identity } in
        (match structure_problem r with
         | Some (k, m) -> fail axis_line.(k - 1) 1 m
         | None -> Ok r)
  with Bad (line, col, message) -> fail line col message

let load path =
  match
    let ic = open_in_bin path in
    Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))
  with
  | text -> parse ~file:path text
  | exception Sys_error m -> Error { file = path; line = 1; col = 1; message = "cannot read: " ^ m }

let irb120 =
  match parse ~file:"irb120" irb120_text with
  | Ok r -> r
  | Error e -> failwith (error_to_string e)
