(* The UdpUc devices and the UDP channel of an EGM process (egm_channel.mli). *)

type device = { name : string; host : string; port : int }

let split_list s = List.filter (( <> ) "") (List.map String.trim (String.split_on_char ',' s))

let loopback host =
  match List.map int_of_string_opt (String.split_on_char '.' host) with
  | [ Some 127; Some b; Some c; Some d ] -> List.for_all (fun x -> x >= 0 && x <= 255) [ b; c; d ]
  | _ -> false

let parse_devices s =
  let one item =
    match String.index_opt item '=' with
    | Some i when i > 0 -> (
        let name = String.sub item 0 i and rest = String.sub item (i + 1) (String.length item - i - 1) in
        match String.rindex_opt rest ':' with
        | None -> Error (Printf.sprintf "%s: expected NAME=HOST:PORT" item)
        | Some j ->
            let host = String.sub rest 0 j and port = String.sub rest (j + 1) (String.length rest - j - 1) in
            let host = if String.lowercase_ascii host = "localhost" then "127.0.0.1" else host in
            if not (loopback host) then Error (Printf.sprintf "%s: the sensor must be on the loopback (127.x.y.z)" item)
            else match int_of_string_opt port with
              | Some p when p >= 1 && p <= 65535 -> Ok { name; host; port = p }
              | _ -> Error (Printf.sprintf "%s: the port is not a number 1..65535" item))
    | _ -> Error (Printf.sprintf "%s: expected NAME=HOST:PORT" item) in
  List.fold_right (fun item acc -> match acc, one item with
      | Ok l, Ok x -> Ok (x :: l) | (Error _ as e), _ -> e | _, Error e -> Error e) (split_list s) (Ok [])

let find devices name =
  let base n =
    let n = String.lowercase_ascii (String.trim n) in
    if String.length n > 0 && n.[String.length n - 1] = ':' then String.sub n 0 (String.length n - 1) else n in
  List.find_opt (fun d -> base d.name = base name) devices

type t = { fd : Unix.file_descr; mutable closed : bool }

let open_channel d =
  try
    let fd = Unix.socket Unix.PF_INET Unix.SOCK_DGRAM 0 in
    (try
       Unix.set_close_on_exec fd;
       Unix.connect fd (Unix.ADDR_INET (Unix.inet_addr_of_string d.host, d.port));
       Ok { fd; closed = false }
     with Unix.Unix_error (e, _, _) -> Unix.close fd; Error (Unix.error_message e))
  with Unix.Unix_error (e, _, _) -> Error (Unix.error_message e)

(* A refused datagram (nobody listens yet) is reported by the host at a later call on the
   socket: it is no message, and no error of the channel. *)
let send t data =
  if not t.closed then
    try ignore (Unix.send_substring t.fd data 0 (String.length data) []) with Unix.Unix_error _ -> ()

let ready fd within =
  match Unix.select [ fd ] [] [] (Float.max 0. within) with
  | [], _, _ -> false
  | _ -> true
  | exception Unix.Unix_error (Unix.EINTR, _, _) -> false

let receive t ~within =
  if t.closed then None
  else begin
    let buf = Bytes.create 65536 in
    let last = ref None in
    let take () =
      match Unix.recv t.fd buf 0 (Bytes.length buf) [] with
      | n -> last := Some (Bytes.sub_string buf 0 n); true
      | exception Unix.Unix_error _ -> true in
    let start = Unix.gettimeofday () in
    let rec first () =
      let left = within -. (Unix.gettimeofday () -. start) in
      if ready t.fd left then (ignore (take ()); if !last = None then first ())
      else () in
    first ();
    (* The others already there: the newest counts. *)
    while !last <> None && ready t.fd 0. do ignore (take ()) done;
    !last
  end

let close t = if not t.closed then (t.closed <- true; try Unix.close t.fd with Unix.Unix_error _ -> ())
