type signal_type = DI | DO | AI | AO | GI | GO

type signal = { name : string; kind : signal_type; initial : float; line : int; col : int }
type stimulus = { time : float; signal : string; value : float }
type system_input = { action : string; input : string; arg6 : string; si_line : int; si_col : int }
type t = {
  file : string; signals : signal list; stimuli : stimulus list; collisions : float list;
  system_inputs : system_input list; mechanical_units : string list;
  task_ids : string list;
}

let empty =
  { file = ""; signals = []; stimuli = []; collisions = []; system_inputs = []; mechanical_units = []; task_ids = [] }

let type_name = function
  | DI -> "signaldi" | DO -> "signaldo" | AI -> "signalai" | AO -> "signalao"
  | GI -> "signalgi" | GO -> "signalgo"

let is_input = function DI | AI | GI -> true | DO | AO | GO -> false
let is_digital = function DI | DO -> true | _ -> false

let kind_of_word w =
  match String.lowercase_ascii w with
  | "di" -> Some DI | "do" -> Some DO | "ai" -> Some AI | "ao" -> Some AO
  | "gi" -> Some GI | "go" -> Some GO | _ -> None

exception Bad of int * int * string

(* A signal becomes an installed data object of the program: its name must be a RAPID
   identifier (§2.3), at most 32 characters. *)
let check_name line col name =
  if not (Rapid_syntax.Lexer.is_ascii_name name) then
    raise (Bad (line, col, Printf.sprintf "%S is not a RAPID identifier (§2.3), so it cannot name a signal"
                             (Rapid_syntax.Decimal.shown name)));
  if Hashtbl.mem Rapid_syntax.Lexer.reserved_words (String.uppercase_ascii name) then
    raise (Bad (line, col, Printf.sprintf "%s is a reserved word (§2.4), so it cannot name a signal" name))

(* doc/controller.md: numbers are decimal; within num's range (§2.13, R-8-numbers1). *)
let number line col w =
  match Rapid_syntax.Decimal.read w with
  | Ok f -> f
  | Error `Not_decimal ->
      raise (Bad (line, col, Printf.sprintf "%S is not a decimal number (such as 1, 0.25 or 1e-3)"
                               (Rapid_syntax.Decimal.shown w)))
  | Error `Beyond_num ->
      raise (Bad (line, col, Printf.sprintf "%s is beyond the range of num (IEEE 754 single precision, \
                                             at most 3.40282347E+38 in magnitude; §2.13)"
                               (Rapid_syntax.Decimal.shown w)))

(* Words of a line with their columns (1-based), up to a comment. *)
let words line =
  let n = String.length line in
  let rec go i acc =
    if i >= n || line.[i] = '#' then List.rev acc
    else if line.[i] = ' ' || line.[i] = '\t' || line.[i] = '\r' then go (i + 1) acc
    else
      let j = ref i in
      while !j < n && not (List.mem line.[!j] [ ' '; '\t'; '\r'; '#' ]) do incr j done;
      go !j ((String.sub line i (!j - i), i + 1) :: acc)
  in
  go 0 []

(* Names declared so far, letter case aside (§2.3): one look-up per signal, so that a
   configuration of 100,000 signals is read in linear time. *)
let add_signal seen signals line col s =
  let key = String.lowercase_ascii s.name in
  if Hashtbl.mem seen key then raise (Bad (line, col, Printf.sprintf "the signal %s is declared twice" s.name));
  Hashtbl.replace seen key s;
  s :: signals

(* R-8-numbers1: a group signal is at most 32 bits wide (GInputDnum reads them all), fewer
   where an EIO.cfg gives its -DeviceMap; an analog signal stays within -MinLog .. -MaxLog
   where an EIO.cfg gives them. *)
type limits = { bits : int; low : float option; high : float option }

let default_limits = { bits = 32; low = None; high = None }
let group_max bits = Float.pow 2. (float_of_int bits) -. 1.

let check_value ?(limits = default_limits) line col kind v =
  match kind with
  | DI | DO when v <> 0. && v <> 1. ->
      raise (Bad (line, col, "a digital signal takes the value 0 or 1"))
  | GI | GO when not (Float.is_integer v) || v < 0. ->
      raise (Bad (line, col, "a group signal takes a non-negative integer value"))
  | GI | GO when v > group_max limits.bits ->
      raise (Bad (line, col, Printf.sprintf "%.0f does not fit in the group signal's %d bits (at most %.0f)"
                               v limits.bits (group_max limits.bits)))
  | AI | AO -> (
      match limits.low, limits.high with
      | Some lo, _ when v < lo -> raise (Bad (line, col, Printf.sprintf "%g is below the signal's -MinLog %g" v lo))
      | _, Some hi when v > hi -> raise (Bad (line, col, Printf.sprintf "%g is above the signal's -MaxLog %g" v hi))
      | _ -> ())
  | _ -> ()

(* A time of the stimulus: decimal, not negative, within num's range (one from 10^12 s on
   never comes, R-8-j). *)
let time_of ln (t, tc) last_time =
  let time = number ln tc t in
  if time < 0. then raise (Bad (ln, tc, "a time is not negative"));
  if time < last_time then raise (Bad (ln, tc, "the events are not in order of time"));
  time

let parse_stimulus ~file lines =
  let signals = ref [] and stimuli = ref [] and collisions = ref [] and last_time = ref 0. in
  let system_inputs = ref [] in
  let by_name = Hashtbl.create 16 in
  List.iteri (fun i line ->
      let ln = i + 1 in
      match words line with
      | [] -> ()
      | ("signal", _) :: rest -> (
          match rest with
          | (name, nc) :: (ty, tc) :: init ->
              check_name ln nc name;
              let kind = match kind_of_word ty with
                | Some k -> k
                | None -> raise (Bad (ln, tc, Printf.sprintf "unknown signal type %S (di, do, ai, ao, gi or go)"
                                          (Rapid_syntax.Decimal.shown ty))) in
              let initial = match init with
                | [] -> 0.
                | [ (w, c) ] -> let v = number ln c w in check_value ln c kind v; v
                | _ :: (_, c) :: _ -> raise (Bad (ln, c, "more than a name, a type and an initial value")) in
              signals := add_signal by_name !signals ln nc { name; kind; initial; line = ln; col = nc }
          | _ -> raise (Bad (ln, 1, "expected: signal NAME TYPE [INITIAL]")))
      | ("at", _) :: rest -> (
          match rest with
          | [ t; ("collision", _) ] ->
              (* A collision of the robot (doc/motion.md, §7.6). *)
              let time = time_of ln t !last_time in
              last_time := time;
              collisions := time :: !collisions
          | [ t; (name, nc); (v, vc) ] ->
              let time = time_of ln t !last_time in
              let s = match Hashtbl.find_opt by_name (String.lowercase_ascii name) with
                | Some s -> s
                | None -> raise (Bad (ln, nc, Printf.sprintf "the signal %s is not declared above"
                                                (Rapid_syntax.Decimal.shown name))) in
              if not (is_input s.kind) then
                raise (Bad (ln, nc, Printf.sprintf "%s is an output: the outside world changes inputs only" s.name));
              let value = number ln vc v in
              check_value ln vc s.kind value;
              last_time := time;
              stimuli := { time; signal = s.name; value } :: !stimuli
          | _ -> raise (Bad (ln, 1, "expected: at TIME NAME VALUE, or at TIME collision")))
      | ("system-input", _) :: rest -> (
          (* A system input (EIO.cfg's SYSSIG_IN): the action a digital input starts, and the
             mechanical unit it acts on (-Arg6 of LimitSpeed). *)
          match rest with
          | (action, _) :: (name, nc) :: unit_name ->
              let s = match Hashtbl.find_opt by_name (String.lowercase_ascii name) with
                | Some s -> s
                | None -> raise (Bad (ln, nc, Printf.sprintf "the signal %s is not declared above"
                                                (Rapid_syntax.Decimal.shown name))) in
              if s.kind <> DI then
                raise (Bad (ln, nc, Printf.sprintf "%s is not a digital input: a system input is one" s.name));
              let arg6 = match unit_name with
                | [] -> ""
                | [ (u, _) ] -> u
                | _ :: (_, c) :: _ -> raise (Bad (ln, c, "more than an action, a signal and a mechanical unit")) in
              system_inputs := { action; input = s.name; arg6; si_line = ln; si_col = nc } :: !system_inputs
          | _ -> raise (Bad (ln, 1, "expected: system-input ACTION SIGNAL [MECHUNIT]")))
      | (w, c) :: _ ->
          raise (Bad (ln, c, Printf.sprintf "unknown entry %S (signal, at or system-input)"
                               (Rapid_syntax.Decimal.shown w))))
    lines;
  { file; signals = List.rev !signals; stimuli = List.rev !stimuli; collisions = List.rev !collisions;
    system_inputs = List.rev !system_inputs; mechanical_units = []; task_ids = [] }

(* -DeviceMap of a group signal: bits "0-7", or a list of them "0-3,8-11"; its width is the
   number of distinct bits it maps: "0-3,2-5" maps bits 0 to 5, six bits (R-8-small3; no ABB
   text at hand refuses a map whose ranges overlap). *)
let device_map_bits ln col map =
  let bad () =
    raise (Bad (ln, col, Printf.sprintf "-DeviceMap %S: expected bits such as \"0-7\" or \"0-3,8-11\""
                           (Rapid_syntax.Decimal.shown map))) in
  let bit w = match int_of_string_opt (String.trim w) with
    | Some b when b >= 0 && b < 100_000 && String.for_all (fun c -> c = ' ' || (c >= '0' && c <= '9')) w -> b
    | _ -> bad () in
  let ranges = List.map (fun part ->
      match String.split_on_char '-' part with
      | [ b ] -> let b = bit b in (b, b)
      | [ a; b ] -> let a = bit a and b = bit b in (min a b, max a b)
      | _ -> bad ()) (String.split_on_char ',' map) in
  (* The ranges sorted and merged: each bit counted once. *)
  let width, _ = List.fold_left (fun (n, upto) (lo, hi) ->
      let lo = max lo (upto + 1) in
      if hi < lo then (n, upto) else (n + hi - lo + 1, hi)) (0, -1) (List.sort compare ranges) in
  if width > 32 then
    raise (Bad (ln, col, Printf.sprintf "-DeviceMap %S maps %d bits: a group signal has at most 32"
                           (Rapid_syntax.Decimal.shown map) width));
  width

(* EIO.cfg: sections start with a line "NAME:"; an instance is a list of "-Key value" pairs and
   goes on over lines that end with a backslash. Only EIO_SIGNAL is read. Each word keeps the
   line and column it was read at, so that an error names the word itself. *)
let eio_words ln text first_col =
  let n = String.length text and i = ref 0 and acc = ref [] in
  let skip () = while !i < n && (text.[!i] = ' ' || text.[!i] = '\t' || text.[!i] = '\r') do incr i done in
  while (skip (); !i < n) do
    let col = first_col + !i in
    if text.[!i] = '"' then begin
      let j = ref (!i + 1) in
      while !j < n && text.[!j] <> '"' do incr j done;
      acc := (`Quoted (String.sub text (!i + 1) (!j - !i - 1)), ln, col) :: !acc;
      i := min n (!j + 1)
    end else begin
      let j = ref !i in
      while !j < n && not (List.mem text.[!j] [ ' '; '\t'; '\r' ]) do incr j done;
      acc := (`Bare (String.sub text !i (!j - !i)), ln, col) :: !acc;
      i := !j
    end
  done;
  List.rev !acc

let eio_signal ~seen signals ln words =
  (* A bare word that starts with '-' is the next key, unless it is a number (-Default -5). *)
  let is_key w = String.length w > 1 && w.[0] = '-' && not (Rapid_syntax.Decimal.is_decimal w) in
  (* An attribute given twice is refused at the second (R-8-small3): the first was kept and the
     second never checked. A key with no value stands at its own place, so that a refusal of
     a missing value names the key. *)
  let given = Hashtbl.create 8 in
  let rec pairs = function
    | (`Bare word, kl, kc) :: rest when is_key word -> (
        let key = String.lowercase_ascii (String.sub word 1 (String.length word - 1)) in
        if Hashtbl.mem given key then
          raise (Bad (kl, kc, Printf.sprintf "%s is given twice in this EIO_SIGNAL entry"
                                (Rapid_syntax.Decimal.shown word)));
        Hashtbl.replace given key ();
        match rest with
        | (`Quoted v, l, c) :: rest -> (key, (v, l, c)) :: pairs rest
        | (`Bare v, l, c) :: rest when not (is_key v) -> (key, (v, l, c)) :: pairs rest
        | _ -> (key, ("", kl, kc)) :: pairs rest)
    | _ :: rest -> pairs rest
    | [] -> [] in
  let pairs = pairs words in
  (* A number or a device map with no value (-Default alone, -DeviceMap "") was read as 0 or
     as no map: refused (R-8-small3). *)
  List.iter (fun (key, (v, l, c)) ->
      if v = "" && List.mem key [ "default"; "minlog"; "maxlog"; "devicemap" ] then
        raise (Bad (l, c, Printf.sprintf "-%s has no value" (match key with
            | "default" -> "Default" | "minlog" -> "MinLog" | "maxlog" -> "MaxLog" | _ -> "DeviceMap")))) pairs;
  let get k = List.assoc_opt k pairs in
  let num k = match get k with
    | None | Some ("", _, _) -> None
    | Some (w, l, c) -> Some (number l c w, l, c) in
  match get "name", get "signaltype" with
  | Some (name, nl, nc), Some (ty, tl, tc) ->
      check_name nl nc name;
      let kind = match kind_of_word ty with
        | Some k -> k | None -> raise (Bad (tl, tc, Printf.sprintf "unknown -SignalType %S" ty)) in
      let bits = match kind, get "devicemap" with
        | (GI | GO), Some (map, l, c) -> device_map_bits l c map
        | _ -> default_limits.bits in
      let low = Option.map (fun (v, _, _) -> v) (num "minlog")
      and high = Option.map (fun (v, _, _) -> v) (num "maxlog") in
      (match low, high, get "maxlog" with
       | Some lo, Some hi, Some (_, l, c) when lo > hi ->
           raise (Bad (l, c, Printf.sprintf "-MaxLog %g is below -MinLog %g" hi lo))
       | _ -> ());
      let initial = match num "default" with
        | None -> 0.
        | Some (v, l, c) -> check_value ~limits:{ bits; low; high } l c kind v; v in
      add_signal seen signals nl nc { name; kind; initial; line = nl; col = nc }
  | None, _ -> raise (Bad (ln, 1, "an EIO_SIGNAL entry without -Name"))
  | Some _, None -> raise (Bad (ln, 1, "an EIO_SIGNAL entry without -SignalType"))

(* SYSSIG_IN: "-Signal NAME -Action ACTION [-Arg6 MECHUNIT]"; an entry that names no signal or no
   action is left out, as the controller would not start it. *)
let eio_system_input words =
  let rec get key = function
    | (`Bare w, _, _) :: ((`Quoted v | `Bare v), l, c) :: _ when String.lowercase_ascii w = key -> Some (v, l, c)
    | _ :: rest -> get key rest
    | [] -> None in
  match get "-signal" words, get "-action" words with
  | Some (input, l, c), Some (action, _, _) when input <> "" && action <> "" ->
      let arg6 = match get "-arg6" words with Some (u, _, _) -> u | None -> "" in
      Some { action; input; arg6; si_line = l; si_col = c }
  | _ -> None

let parse_eio ~file lines =
  let signals = ref [] and seen = Hashtbl.create 16 in
  let system_inputs = ref [] in
  let in_signals = ref false and in_system_inputs = ref false in
  (* the entry being read: its first line, its words, whether its last line ended in \ *)
  let pending = ref None in
  let finish () =
    match !pending with
    | None -> ()
    | Some (_, words, _) when !in_system_inputs ->
        pending := None;
        Option.iter (fun si -> system_inputs := si :: !system_inputs) (eio_system_input (List.rev words))
    | Some (ln, words, _) -> pending := None; signals := eio_signal ~seen !signals ln (List.rev words) in
  List.iteri (fun i raw ->
      let ln = i + 1 in
      let line = String.trim raw in
      let first_col =
        match String.index_opt raw (if line = "" then ' ' else line.[0]) with Some k -> k + 1 | None -> 1 in
      let ends_continued = String.length line > 0 && line.[String.length line - 1] = '\\' in
      let body = if ends_continued then String.sub line 0 (String.length line - 1) else line in
      let is_section = String.length line > 1 && line.[String.length line - 1] = ':'
                       && String.for_all
                            (fun c -> c = '_' || c = ':' || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')) line in
      match !pending with
      | Some (l, words, true) ->
          pending := Some (l, List.rev_append (eio_words ln body first_col) words, ends_continued)
      | _ ->
          if is_section then (finish (); in_signals := (line = "EIO_SIGNAL:");
                              in_system_inputs := (line = "SYSSIG_IN:"))
          else if line = "" || line.[0] = '#' then finish ()
          else if (!in_signals || !in_system_inputs) && line.[0] = '-' then
            (finish (); pending := Some (ln, List.rev (eio_words ln body first_col), ends_continued))
          else finish ())
    lines;
  finish ();
  (* A system input whose signal is not configured starts nothing. *)
  let configured si = Hashtbl.mem seen (String.lowercase_ascii si.input) in
  { file; signals = List.rev !signals; stimuli = []; collisions = [];
    system_inputs = List.filter configured (List.rev !system_inputs); mechanical_units = []; task_ids = [] }

let is_eio lines =
  List.exists (fun l ->
      let l = String.trim l in l = "EIO_SIGNAL:" || (String.length l >= 8 && String.sub l 0 8 = "EIO:CFG_")) lines

(* A UTF-8 byte order mark, which some editors write first: not part of the first line, whose
   columns count from after it. *)
let without_bom text =
  if String.length text >= 3 && String.sub text 0 3 = "\xEF\xBB\xBF" then String.sub text 3 (String.length text - 3)
  else text

let parse ~file text =
  let lines = String.split_on_char '\n' (without_bom text) in
  try Ok (if is_eio lines then parse_eio ~file lines else parse_stimulus ~file lines)
  with Bad (line, col, m) -> Error (Printf.sprintf "%s:%d:%d: io error: %s" file line col m)

let read_file file =
  match open_in_bin file with
  | exception Sys_error m -> Error (Printf.sprintf "%s:1:1: io error: cannot read the file (%s)" file m)
  | ic ->
      let text = Fun.protect ~finally:(fun () -> close_in_noerr ic)
          (fun () -> really_input_string ic (in_channel_length ic)) in
      parse ~file text
