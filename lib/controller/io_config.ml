type signal_type = DI | DO | AI | AO | GI | GO

type signal = { name : string; kind : signal_type; initial : float }
type stimulus = { time : float; signal : string; value : float }
type t = { signals : signal list; stimuli : stimulus list; collisions : float list }

let empty = { signals = []; stimuli = []; collisions = [] }

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
  let ok_char = function 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_' -> true | _ -> false in
  if name = "" || String.length name > 32
     || not (match name.[0] with 'A' .. 'Z' | 'a' .. 'z' -> true | _ -> false)
     || not (String.for_all ok_char name)
  then raise (Bad (line, col, Printf.sprintf "%S is not a RAPID identifier (§2.3), so it cannot name a signal" name));
  if Hashtbl.mem Rapid_syntax.Lexer.reserved_words (String.uppercase_ascii name) then
    raise (Bad (line, col, Printf.sprintf "%s is a reserved word (§2.4), so it cannot name a signal" name))

let number line col w =
  match float_of_string_opt w with
  | Some f when Float.is_finite f && String.length w > 0 && w.[0] <> '_' -> f
  | _ -> raise (Bad (line, col, Printf.sprintf "%S is not a number" w))

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

let add_signal signals line col s =
  if List.exists (fun (o : signal) -> String.lowercase_ascii o.name = String.lowercase_ascii s.name) signals then
    raise (Bad (line, col, Printf.sprintf "the signal %s is declared twice" s.name));
  s :: signals

let check_value line col kind v =
  match kind with
  | DI | DO when v <> 0. && v <> 1. ->
      raise (Bad (line, col, "a digital signal takes the value 0 or 1"))
  | GI | GO when not (Float.is_integer v) || v < 0. ->
      raise (Bad (line, col, "a group signal takes a non-negative integer value"))
  | _ -> ()

let parse_stimulus lines =
  let signals = ref [] and stimuli = ref [] and collisions = ref [] and last_time = ref 0. in
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
                | None -> raise (Bad (ln, tc, Printf.sprintf "unknown signal type %S (di, do, ai, ao, gi or go)" ty)) in
              let initial = match init with
                | [] -> 0.
                | [ (w, c) ] -> let v = number ln c w in check_value ln c kind v; v
                | _ :: (_, c) :: _ -> raise (Bad (ln, c, "more than a name, a type and an initial value")) in
              signals := add_signal !signals ln nc { name; kind; initial };
              Hashtbl.replace by_name (String.lowercase_ascii name) (List.hd !signals)
          | _ -> raise (Bad (ln, 1, "expected: signal NAME TYPE [INITIAL]")))
      | ("at", _) :: rest -> (
          match rest with
          | [ (t, tc); ("collision", _) ] ->
              (* A collision of the robot (doc/motion.md, §7.6). *)
              let time = number ln tc t in
              if time < 0. then raise (Bad (ln, tc, "a time is not negative"));
              if time < !last_time then raise (Bad (ln, tc, "the events are not in order of time"));
              last_time := time;
              collisions := time :: !collisions
          | [ (t, tc); (name, nc); (v, vc) ] ->
              let time = number ln tc t in
              if time < 0. then raise (Bad (ln, tc, "a time is not negative"));
              let s = match Hashtbl.find_opt by_name (String.lowercase_ascii name) with
                | Some s -> s
                | None -> raise (Bad (ln, nc, Printf.sprintf "the signal %s is not declared above" name)) in
              if not (is_input s.kind) then
                raise (Bad (ln, nc, Printf.sprintf "%s is an output: the outside world changes inputs only" s.name));
              let value = number ln vc v in
              check_value ln vc s.kind value;
              (match !stimuli with
               | last :: _ when last.time > time -> raise (Bad (ln, tc, "the events are not in order of time"))
               | _ -> ());
              if time < !last_time then raise (Bad (ln, tc, "the events are not in order of time"));
              last_time := time;
              stimuli := { time; signal = s.name; value } :: !stimuli
          | _ -> raise (Bad (ln, 1, "expected: at TIME NAME VALUE, or at TIME collision")))
      | (w, c) :: _ -> raise (Bad (ln, c, Printf.sprintf "unknown entry %S (signal or at)" w)))
    lines;
  { signals = List.rev !signals; stimuli = List.rev !stimuli; collisions = List.rev !collisions }

(* EIO.cfg: sections start with a line "NAME:"; an instance is a list of "-Key value" pairs and
   goes on over lines that end with a backslash. Only EIO_SIGNAL is read. *)
let parse_eio lines =
  let signals = ref [] in
  let in_signals = ref false in
  let pending = ref None in
  let finish () =
    match !pending with
    | None -> ()
    | Some (ln, text) ->
        pending := None;
        let n = String.length text in
        let pairs = ref [] in
        let i = ref 0 in
        let skip () = while !i < n && (text.[!i] = ' ' || text.[!i] = '\t' || text.[!i] = '\r') do incr i done in
        let token () =
          skip ();
          if !i < n && text.[!i] = '"' then begin
            let j = ref (!i + 1) in
            while !j < n && text.[!j] <> '"' do incr j done;
            let s = String.sub text (!i + 1) (!j - !i - 1) in
            i := min n (!j + 1); s
          end else begin
            let j = ref !i in
            while !j < n && not (List.mem text.[!j] [ ' '; '\t'; '\r' ]) do incr j done;
            let s = String.sub text !i (!j - !i) in i := !j; s
          end in
        while (skip (); !i < n) do
          let key = token () in
          if String.length key > 1 && key.[0] = '-' then begin
            skip ();
            let value = if !i < n && text.[!i] <> '-' then token () else "" in
            pairs := (String.lowercase_ascii (String.sub key 1 (String.length key - 1)), value) :: !pairs
          end
        done;
        let get k = List.assoc_opt k !pairs in
        match get "name", get "signaltype" with
        | Some name, Some ty ->
            check_name ln 1 name;
            let kind = match kind_of_word ty with
              | Some k -> k | None -> raise (Bad (ln, 1, Printf.sprintf "unknown -SignalType %S" ty)) in
            let initial = match get "default" with None | Some "" -> 0. | Some d -> number ln 1 d in
            check_value ln 1 kind initial;
            signals := add_signal !signals ln 1 { name; kind; initial }
        | None, _ -> raise (Bad (ln, 1, "an EIO_SIGNAL entry without -Name"))
        | Some _, None -> raise (Bad (ln, 1, "an EIO_SIGNAL entry without -SignalType"))
  in
  List.iteri (fun i raw ->
      let ln = i + 1 in
      let line = String.trim raw in
      let is_section = String.length line > 1 && line.[String.length line - 1] = ':'
                       && String.for_all (fun c -> c = '_' || c = ':' || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')) line in
      let continued = match !pending with Some (_, t) -> String.length t > 0 && t.[String.length t - 1] = '\\' | None -> false in
      if continued then begin
        match !pending with
        | Some (l, t) -> pending := Some (l, String.sub t 0 (String.length t - 1) ^ " " ^ line)
        | None -> ()
      end
      else if is_section then (finish (); in_signals := (line = "EIO_SIGNAL:"))
      else if line = "" || line.[0] = '#' then finish ()
      else if !in_signals && line.[0] = '-' then (finish (); pending := Some (ln, line))
      else finish ())
    lines;
  finish ();
  { signals = List.rev !signals; stimuli = []; collisions = [] }

let is_eio lines =
  List.exists (fun l -> let l = String.trim l in l = "EIO_SIGNAL:" || (String.length l >= 8 && String.sub l 0 8 = "EIO:CFG_")) lines

let parse ~file text =
  let lines = String.split_on_char '\n' text in
  try Ok (if is_eio lines then parse_eio lines else parse_stimulus lines)
  with Bad (line, col, m) -> Error (Printf.sprintf "%s:%d:%d: io error: %s" file line col m)

let read_file file =
  match open_in_bin file with
  | exception Sys_error m -> Error (Printf.sprintf "%s:1:1: io error: cannot read the file (%s)" file m)
  | ic ->
      let text = Fun.protect ~finally:(fun () -> close_in_noerr ic)
          (fun () -> really_input_string ic (in_channel_length ic)) in
      parse ~file text
