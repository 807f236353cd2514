type incoming = Message of Yojson.Safe.t | Malformed of string | End

let max_body = 64 * 1024 * 1024

let parse_error = -32700
let invalid_request = -32600
let method_not_found = -32601
let invalid_params = -32602
let internal_error = -32603
let server_not_initialized = -32002
let request_failed = -32803

(* A header line without its CR LF (a bare LF is accepted too); None at the end of input. *)
let header_line ic =
  match input_line ic with
  | exception End_of_file -> None
  | l ->
      let n = String.length l in
      Some (if n > 0 && l.[n - 1] = '\r' then String.sub l 0 (n - 1) else l)

(* The field may follow the rest of a message that came without one (a body the header did not
   measure, read as a header line): it is looked for anywhere in the line, so that the next
   message is read again from its own header. *)
let content_length fields =
  let field = "content-length:" in
  let n = String.length field in
  List.find_map (fun l ->
      let low = String.lowercase_ascii l in
      let rec find i =
        if i + n > String.length low then None
        else if String.sub low i n = field then
          int_of_string_opt (String.trim (String.sub l (i + n) (String.length l - i - n)))
        else find (i + 1) in
      find 0) fields

(* The body of a refused message is read and dropped, so that the next header is found. *)
let skip ic n =
  let chunk = Bytes.create 65536 in
  let rec go n = if n > 0 then
      match input ic chunk 0 (min n (Bytes.length chunk)) with
      | 0 -> ()
      | k -> go (n - k)
      | exception End_of_file -> () in
  go n

let read ic =
  (* The header: lines up to an empty one. Empty lines before any field are skipped (a client's
     stray line break between messages). *)
  let rec fields acc =
    match header_line ic with
    | None -> if acc = [] then None else Some (List.rev acc)
    | Some "" -> if acc = [] then fields acc else Some (List.rev acc)
    | Some l -> fields (l :: acc) in
  match fields [] with
  | None -> End
  | Some fs -> (
      match content_length fs with
      | None -> Malformed "a message header without a Content-Length field"
      | Some n when n < 0 || n > max_body ->
          skip ic n;
          Malformed (Printf.sprintf "a Content-Length of %d bytes is refused (at most %d)" n max_body)
      | Some n -> (
          match really_input_string ic n with
          | exception End_of_file -> End
          | body -> (
              match Yojson.Safe.from_string body with
              | json -> Message json
              | exception Yojson.Json_error m -> Malformed ("the body is not JSON: " ^ m))))


let frame json =
  let body = Yojson.Safe.to_string json in
  Printf.sprintf "Content-Length: %d\r\n\r\n%s" (String.length body) body

let write oc json =
  output_string oc (frame json);
  flush oc

let response id result = `Assoc [ ("jsonrpc", `String "2.0"); ("id", id); ("result", result) ]

let error_response id code message =
  `Assoc [ ("jsonrpc", `String "2.0"); ("id", id);
           ("error", `Assoc [ ("code", `Int code); ("message", `String message) ]) ]

let notification meth params = `Assoc [ ("jsonrpc", `String "2.0"); ("method", `String meth); ("params", params) ]

let request id meth params =
  `Assoc [ ("jsonrpc", `String "2.0"); ("id", id); ("method", `String meth); ("params", params) ]
