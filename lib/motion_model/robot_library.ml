(* A library entry: the file's identity from its name, irbMODEL-PAYLOAD-REACH.robot. *)
type entry = { name : string; model : string; payload : float; reach : float; file_text : string }

let number s = match float_of_string_opt s with
  | Some f when String.length s > 0 && String.for_all (fun c -> (c >= '0' && c <= '9') || c = '.') s -> Some f
  | _ -> None

let strip_product_prefix m =
  let m = String.uppercase_ascii m in
  let n = String.length m in
  if n > 3 && (String.sub m 0 3 = "IRB" || String.sub m 0 3 = "CRB") then String.sub m 3 (n - 3) else m

let entry_of (file, file_text) =
  let name = Filename.remove_extension file in
  match String.split_on_char '-' name with
  | [ model; payload; reach ] ->
      (match number payload, number reach with
       | Some payload, Some reach -> { name; model = strip_product_prefix model; payload; reach; file_text }
       | _ -> failwith ("robot library: file name not MODEL-PAYLOAD-REACH: " ^ file))
  | _ -> failwith ("robot library: file name not MODEL-PAYLOAD-REACH: " ^ file)

let entries = lazy (List.map entry_of Robot_files.files)

let names () = List.map (fun e -> e.name) (Lazy.force entries)

let entry name = List.find_opt (fun e -> e.name = name) (Lazy.force entries)

let text name = Option.map (fun e -> e.file_text) (entry name)

(* The shortest decimal of a figure: 1.5, not 1.500000. *)
let figure f = if Float.is_integer f then Printf.sprintf "%.0f" f else Printf.sprintf "%g" f

let type_of e = Printf.sprintf "ROB1_%s_%s_%s" e.model (figure e.reach) (figure e.payload)

let robot_type name = Option.map type_of (entry name)

(* Parsed once: a description of the library that does not parse is a build's mistake, and the
   test "the robot library" parses them all. *)
let parsed = Hashtbl.create 16

let robot e =
  match Hashtbl.find_opt parsed e.name with
  | Some r -> r
  | None ->
      let r = Result.map_error Robot.error_to_string (Robot.parse ~file:("robots/" ^ e.name ^ ".robot") e.file_text) in
      Hashtbl.replace parsed e.name r; r

let known () =
  String.concat ", " (List.map (fun e -> Printf.sprintf "%s (%s)" (type_of e) e.name) (Lazy.force entries))

(* A MOC.cfg robot type: ROBn_ (optional), the model, variant words, the reach, the payload. *)
let read_type s =
  let tokens = List.filter (( <> ) "") (String.split_on_char '_' (String.trim s)) in
  let is_rob t = let t = String.uppercase_ascii t in
    String.length t > 3 && String.sub t 0 3 = "ROB"
    && String.for_all (fun c -> c >= '0' && c <= '9') (String.sub t 3 (String.length t - 3)) in
  let tokens = match tokens with t :: rest when is_rob t -> rest | l -> l in
  match tokens with
  | [] -> None
  | model :: rest ->
      let model, rest = match rest with
        | id :: rest when String.uppercase_ascii id = "ID" -> (model ^ "ID", rest)
        | _ -> (model, rest) in
      let rec numbers = function
        | "0" :: frac :: rest when String.for_all (fun c -> c >= '0' && c <= '9') frac ->
            numbers (("0." ^ frac) :: rest)
        | t :: rest -> (match number t with Some f -> f :: numbers rest | None -> numbers rest)
        | [] -> [] in
      (match numbers rest with
       | [ reach; payload ] -> Some (strip_product_prefix model, reach, payload)
       | _ -> None)

let same a b = Float.abs (a -. b) < 1e-6

let find s =
  let all = Lazy.force entries in
  let s' = String.trim s in
  let base = if Filename.check_suffix s' ".robot" then Filename.chop_suffix s' ".robot" else s' in
  match entry base with
  | Some e -> robot e
  | None ->
      let model = strip_product_prefix (String.concat "" (String.split_on_char ' ' base)) in
      match List.filter (fun e -> e.model = model) all with
      | [ e ] -> robot e
      | _ :: _ as several ->
          Error (Printf.sprintf "robot %S: the library has several %s: %s; name one" s model
                   (String.concat ", " (List.map (fun e -> e.name) several)))
      | [] ->
          match read_type s with
          | None -> Error (Printf.sprintf "robot %S: neither a library name nor a robot type \
                                           ROBn_MODEL_REACH_PAYLOAD; the library knows %s" s (known ()))
          | Some (model, reach, payload) ->
              match List.find_opt (fun e -> e.model = model && same e.reach reach && same e.payload payload) all with
              | Some e -> robot e
              | None -> Error (Printf.sprintf "robot type %S (IRB %s, reach %s m, payload %s kg) is not in the \
                                               library; it knows %s" s model (figure reach) (figure payload) (known ()))

let load s =
  if Sys.file_exists s && not (Sys.is_directory s) then Result.map_error Robot.error_to_string (Robot.load s)
  else match find s with
    | Ok _ as ok -> ok
    | Error m -> Error (Printf.sprintf "%s (and no file %s exists)" m s)
