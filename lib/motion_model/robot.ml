type axis = {
  a : float; alpha : float; d : float; offset : float;
  min : float; max : float; speed : float;
}

type t = { name : string; axes : axis array; max_tcp_speed : float; externals : Ext_axes.axis list }

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
  match float_of_string_opt w with
  | Some f when Float.is_finite f && w <> "" && (w.[0] = '-' || w.[0] = '+' || w.[0] = '.' || (w.[0] >= '0' && w.[0] <= '9')) -> f
  | _ -> raise (Bad (line, col, Printf.sprintf "%s: expected a number, found %S" what w))

(* external NAME linear|rotating MIN MAX SPEED [track DX DY DZ] (doc/motion.md, law X-desc). *)
let external_axis ln known rest =
  let fields = [ "min"; "max"; "speed" ] in
  match rest with
  | [] -> raise (Bad (ln, 1, "external: expected NAME linear|rotating MIN MAX SPEED [track DX DY DZ]"))
  | (nc, n) :: rest ->
      let index = match Array.to_list Ext_axes.names |> List.mapi (fun i x -> (i, x)) |> List.find_opt (fun (_, x) -> x = n) with
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
      let min = List.nth v 0 and max = List.nth v 1 and speed = List.nth v 2 in
      if min >= max then
        raise (Bad (ln, fst (List.nth nums 0), Printf.sprintf "%s: range min %g is not below max %g" n min max));
      if speed <= 0. then raise (Bad (ln, fst (List.nth nums 2), Printf.sprintf "%s: speed must be positive" n));
      let track = match track with
        | None -> None
        | Some (tc, _) when kind = Ext_axes.Rotating ->
            raise (Bad (ln, tc, Printf.sprintf "%s: only a linear axis can be a track" n))
        | Some (tc, dir) ->
            if List.length dir <> 3 then
              raise (Bad (ln, tc, Printf.sprintf "%s: track: expected 3 numbers (a direction DX DY DZ), found %d" n (List.length dir)));
            let d = List.map (fun w -> number ln w (n ^ " track")) dir in
            let p = { Geom.x = List.nth d 0; y = List.nth d 1; z = List.nth d 2 } in
            let l = Geom.norm p in
            if not (l > 0.) then raise (Bad (ln, tc, Printf.sprintf "%s: track: the direction is zero" n));
            if List.exists (fun (a : Ext_axes.axis) -> a.track <> None) known then
              raise (Bad (ln, tc, Printf.sprintf "%s: a second track: the robot stands on one" n));
            Some (Geom.scale (1. /. l) p) in
      { Ext_axes.name = n; index; kind; min; max; speed; track }

let structure_problem r =
  let ax i = r.axes.(i - 1) in
  let expect = [| -90.; 0.; -90.; 90.; -90.; 0. |] in
  let bad = ref None in
  Array.iteri (fun i e -> if !bad = None && Float.abs ((ax (i + 1)).alpha -. e) > 1e-9 then
                  bad := Some (i + 1, Printf.sprintf "axis %d: alpha must be %g" (i + 1) e)) expect;
  let zero what i v =
    if !bad = None && v <> 0. then bad := Some (i, Printf.sprintf "axis %d: %s must be 0" i what) in
  zero "d" 2 (ax 2).d; zero "d" 3 (ax 3).d; zero "d" 5 (ax 5).d;
  zero "a" 4 (ax 4).a; zero "a" 5 (ax 5).a; zero "a" 6 (ax 6).a;
  if !bad = None && (ax 2).a <= 0. then bad := Some (2, "axis 2: a must be positive");
  Option.map (fun (k, m) -> k, "unsupported kinematic structure (" ^ m ^ "): the inverse kinematics \
     solves arms with a spherical wrist, twists -90 0 -90 90 -90 0 (doc/motion.md)") !bad

let structure_error r = Option.map snd (structure_problem r)

let parse ~file text =
  let name = ref None and tcp = ref None in
  let axes = Array.make 6 None and axis_line = Array.make 6 1 in
  let externals = ref [] in
  let fail line col message = Error { file; line; col; message } in
  try
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
            let s = number ln v "max_tcp_speed" in
            if s <= 0. then raise (Bad (ln, fst v, "max_tcp_speed must be positive"));
            if !tcp <> None then raise (Bad (ln, 1, "max_tcp_speed given twice"));
            tcp := Some s
        | (_, "max_tcp_speed") :: _ -> raise (Bad (ln, 1, "max_tcp_speed: expected one number (mm/s)"))
        | (_, "axis") :: (nc, n) :: rest ->
            let k = match int_of_string_opt n with
              | Some k when k >= 1 && k <= 6 -> k
              | _ -> raise (Bad (ln, nc, Printf.sprintf "axis number must be 1 to 6, found %S" n)) in
            if axes.(k - 1) <> None then raise (Bad (ln, nc, Printf.sprintf "axis %d given twice" k));
            let fields = [ "a"; "alpha"; "d"; "offset"; "min"; "max"; "speed" ] in
            if List.length rest <> 7 then
              raise (Bad (ln, (match rest with [] -> nc | _ -> fst (List.nth rest (List.length rest - 1))),
                          Printf.sprintf "axis %d: expected 7 numbers (a alpha d offset min max speed), found %d"
                            k (List.length rest)));
            let v = List.map2 (fun f w -> number ln w (Printf.sprintf "axis %d %s" k f)) fields rest in
            let get i = List.nth v i in
            let ax = { a = get 0; alpha = get 1; d = get 2; offset = get 3; min = get 4; max = get 5; speed = get 6 } in
            if ax.min >= ax.max then
              raise (Bad (ln, fst (List.nth rest 4), Printf.sprintf "axis %d: range min %g is not below max %g" k ax.min ax.max));
            if ax.speed <= 0. then
              raise (Bad (ln, fst (List.nth rest 6), Printf.sprintf "axis %d: speed must be positive" k));
            axes.(k - 1) <- Some ax;
            axis_line.(k - 1) <- ln
        | (_, "external") :: rest -> externals := !externals @ [ external_axis ln !externals rest ]
        | (c, w) :: _ ->
            raise (Bad (ln, c, Printf.sprintf "unknown keyword %S (expected name, axis, external or max_tcp_speed)" w)))
      lines;
    let last = List.length lines in
    let missing = ref None in
    Array.iteri (fun i a -> if a = None && !missing = None then missing := Some (i + 1)) axes;
    match !missing, !tcp with
    | Some k, _ -> fail last 1 (Printf.sprintf "axis %d is missing" k)
    | None, None -> fail last 1 "max_tcp_speed is missing"
    | None, Some max_tcp_speed ->
        let r = { name = Option.value !name ~default:file;
                  axes = Array.map Option.get axes; max_tcp_speed; externals = !externals } in
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
