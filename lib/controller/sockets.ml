type status = Created | Bound | Listening | Connected | Closed

type socket = { fd : Unix.file_descr; udp : bool; mutable status : status }

type t = {
  table : (int, socket) Hashtbl.t;
  mutable next : int;
  allowed : (string * int option) list;
  mapping : (string * string) list;
}

let status_number = function
  | Created -> 1 | Connected -> 2 | Bound -> 3 | Listening -> 4 | Closed -> 5

let max_sockets = 32

let create ?(allowed = []) ?(mapping = []) () =
  { table = Hashtbl.create 8; next = 1; allowed; mapping }

let split_list s = List.filter (( <> ) "") (List.map String.trim (String.split_on_char ',' s))

let parse_allowed s =
  let one item =
    match String.rindex_opt item ':' with
    | None -> Error (Printf.sprintf "%s: expected HOST:PORT or HOST:*" item)
    | Some i ->
        let host = String.sub item 0 i and port = String.sub item (i + 1) (String.length item - i - 1) in
        if host = "" then Error (Printf.sprintf "%s: no host" item)
        else if port = "*" then Ok (host, None)
        else match int_of_string_opt port with
          | Some p when p >= 0 && p <= 65535 -> Ok (host, Some p)
          | _ -> Error (Printf.sprintf "%s: the port is not a number 0..65535" item) in
  List.fold_right (fun item acc -> match acc, one item with
      | Ok l, Ok x -> Ok (x :: l) | (Error _ as e), _ -> e | _, Error e -> Error e) (split_list s) (Ok [])

let parse_mapping s =
  let one item =
    match String.index_opt item '=' with
    | Some i when i > 0 && i < String.length item - 1 ->
        Ok (String.sub item 0 i, String.sub item (i + 1) (String.length item - i - 1))
    | _ -> Error (Printf.sprintf "%s: expected FROM=TO" item) in
  List.fold_right (fun item acc -> match acc, one item with
      | Ok l, Ok x -> Ok (x :: l) | (Error _ as e), _ -> e | _, Error e -> Error e) (split_list s) (Ok [])

(* A dotted IPv4 address, each part 0..255: RAPID addresses are written so. *)
let ipv4 s =
  match List.map int_of_string_opt (String.split_on_char '.' s) with
  | [ Some a; Some b; Some c; Some d ] when List.for_all (fun x -> x >= 0 && x <= 255) [ a; b; c; d ] ->
      (try Some (Unix.inet_addr_of_string s) with Failure _ -> None)
  | _ -> None

(* The host address of a RAPID address: mapped, then a dotted address or "localhost"; only
   the loopback unless allowed. *)
let address t s port =
  let s = match List.assoc_opt s t.mapping with Some m -> m | None -> s in
  let s = if String.lowercase_ascii s = "localhost" then "127.0.0.1" else s in
  match ipv4 s with
  | None -> Error "ERR_SOCK_ADDR_INVALID"
  | Some a ->
      let loopback = String.length s >= 4 && String.sub s 0 4 = "127." in
      let permitted = loopback || List.exists (fun (h, p) -> h = s && (p = None || p = Some port)) t.allowed in
      if not permitted then Error "ERR_SOCK_ADDR_INVALID"
      else if port < 0 || port > 65535 then Error "ERR_SOCK_ADDR_INVALID"
      else Ok (Unix.ADDR_INET (a, port))

let find t id = match Hashtbl.find_opt t.table id with
  | Some s when s.status <> Closed -> Ok s
  | _ -> Error "ERR_SOCK_CLOSED"

let add t fd ~udp status =
  let id = t.next in
  t.next <- t.next + 1;
  Hashtbl.replace t.table id { fd; udp; status };
  id

let open_count t = Hashtbl.fold (fun _ s n -> if s.status <> Closed then n + 1 else n) t.table 0

let socket t ~udp =
  (* A peer that closes while we write must give ERR_SOCK_CLOSED, not end the process. *)
  (try Sys.set_signal Sys.sigpipe Sys.Signal_ignore with Invalid_argument _ -> ());
  if open_count t >= max_sockets then Error "ERR_SOCK_UNSPEC"
  else match Unix.socket Unix.PF_INET (if udp then Unix.SOCK_DGRAM else Unix.SOCK_STREAM) 0 with
    | fd ->
        Unix.set_close_on_exec fd;
        Ok (add t fd ~udp Created)
    | exception Unix.Unix_error _ -> Error "ERR_SOCK_UNSPEC"

let status t id = match Hashtbl.find_opt t.table id with Some s -> s.status | None -> Closed

let error_of = function
  | Unix.EADDRINUSE -> "ERR_SOCK_ADDR_INUSE"
  | Unix.EADDRNOTAVAIL | Unix.EINVAL | Unix.EAFNOSUPPORT -> "ERR_SOCK_ADDR_INVALID"
  | Unix.ENETUNREACH | Unix.EHOSTUNREACH -> "ERR_SOCK_NET_UNREACH"
  | Unix.ENOTCONN -> "ERR_SOCK_NOT_CONN"
  | Unix.EISCONN -> "ERR_SOCK_IS_CONN"
  | Unix.EPIPE | Unix.ECONNRESET | Unix.ECONNREFUSED | Unix.ECONNABORTED -> "ERR_SOCK_CLOSED"
  | _ -> "ERR_SOCK_UNSPEC"

let bind t id addr port =
  match find t id with
  | Error e -> Error e
  | Ok s when s.status <> Created -> Error "ERR_SOCK_IS_BOUND"
  | Ok s -> (
      match address t addr port with
      | Error e -> Error e
      | Ok a -> (
          try
            Unix.setsockopt s.fd Unix.SO_REUSEADDR true;
            Unix.bind s.fd a; s.status <- Bound; Ok ()
          with Unix.Unix_error (e, _, _) -> Error (error_of e)))

(* SocketListen names no queue length (ABB's pages are silent): the host's largest, so that
   clients connecting at once are queued by the kernel while the program accepts them one by one,
   instead of having their SYNs dropped and retried a second or more later (R-13-cli1). The
   kernel caps it at net.core.somaxconn. *)
let listen_backlog = 4096

let listen t id =
  match find t id with
  | Error e -> Error e
  | Ok s when s.udp -> Error "ERR_SOCK_UNSPEC"
  | Ok s when s.status <> Bound -> Error "ERR_SOCK_NOT_BOUND"
  | Ok s ->
      (try Unix.listen s.fd listen_backlog; s.status <- Listening; Ok ()
       with Unix.Unix_error (e, _, _) -> Error (error_of e))

(* Waits until the descriptor is readable (or writable), at most [timeout] host seconds. *)
let wait_for ?(write = false) fd timeout =
  let start = Unix.gettimeofday () in
  let rec go () =
    let left = timeout -. (Unix.gettimeofday () -. start) in
    if left <= 0. then false
    else match Unix.select (if write then [] else [ fd ]) (if write then [ fd ] else []) [] left with
      | [], [], _ -> go ()
      | _ -> true
      | exception Unix.Unix_error (Unix.EINTR, _, _) -> go () in
  let ready = go () in
  (ready, Unix.gettimeofday () -. start)

(* R-14-n: whether a blocking call on the socket would go on at once, looking for at most
   [within] host seconds; a socket no call can wait on (closed, not connected, ...) counts as
   ready, so that the call itself reports why. *)
let readable t id ~within =
  match find t id with
  | Error _ -> true
  | Ok s when s.status = Listening || s.status = Connected || (s.udp && s.status = Bound) ->
      if within > 0. then fst (wait_for s.fd within)
      else (match Unix.select [ s.fd ] [] [] 0. with
          | [], _, _ -> false
          | _ -> true
          | exception Unix.Unix_error _ -> true)
  | Ok _ -> true

let text_of = function Unix.ADDR_INET (a, _) -> Unix.string_of_inet_addr a | Unix.ADDR_UNIX p -> p

let accept t id ~timeout =
  match find t id with
  | Error e -> (Error e, 0.)
  | Ok s when s.status <> Listening -> (Error "ERR_SOCK_NOT_BOUND", 0.)
  | Ok s ->
      let ready, waited = wait_for s.fd timeout in
      if not ready then (Error "ERR_SOCK_TIMEOUT", waited)
      else if open_count t >= max_sockets then (Error "ERR_SOCK_UNSPEC", waited)
      else (match Unix.accept ~cloexec:true s.fd with
          | fd, peer -> (Ok (add t fd ~udp:false Connected, text_of peer), waited)
          | exception Unix.Unix_error (e, _, _) -> (Error (error_of e), waited))

let connect t id addr port ~timeout =
  match find t id with
  | Error e -> (Error e, 0.)
  | Ok s when s.status = Connected -> (Error "ERR_SOCK_IS_CONN", 0.)
  | Ok s when s.status = Listening -> (Error "ERR_SOCK_UNSPEC", 0.)
  | Ok s -> (
      match address t addr port with
      | Error e -> (Error e, 0.)
      | Ok a ->
          if s.udp then (try Unix.connect s.fd a; s.status <- Connected; (Ok (), 0.)
                         with Unix.Unix_error (e, _, _) -> (Error (error_of e), 0.))
          else begin
            Unix.set_nonblock s.fd;
            let finish r w = (try Unix.clear_nonblock s.fd with Unix.Unix_error _ -> ()); (r, w) in
            match Unix.connect s.fd a with
            | () -> s.status <- Connected; finish (Ok ()) 0.
            | exception Unix.Unix_error ((Unix.EINPROGRESS | Unix.EWOULDBLOCK | Unix.EAGAIN), _, _) -> (
                let ready, waited = wait_for ~write:true s.fd timeout in
                if not ready then finish (Error "ERR_SOCK_TIMEOUT") waited
                else match Unix.getsockopt_error s.fd with
                  | None -> s.status <- Connected; finish (Ok ()) waited
                  | Some e -> finish (Error (error_of e)) waited)
            | exception Unix.Unix_error (e, _, _) -> finish (Error (error_of e)) 0.
          end)

let rec write_all fd b off len =
  if len > 0 then
    let n = Unix.write fd b off len in
    write_all fd b (off + n) (len - n)

let send t id data =
  match find t id with
  | Error e -> Error e
  | Ok s when s.status <> Connected -> Error "ERR_SOCK_NOT_CONN"
  | Ok s -> (
      try write_all s.fd (Bytes.of_string data) 0 (String.length data); Ok ()
      with Unix.Unix_error (e, _, _) -> Error (error_of e))

let send_to t id addr port data =
  match find t id with
  | Error e -> Error e
  | Ok s when not s.udp -> Error "ERR_SOCK_UNSPEC"
  | Ok s -> (
      match address t addr port with
      | Error e -> Error e
      | Ok a -> (
          try ignore (Unix.sendto s.fd (Bytes.of_string data) 0 (String.length data) [] a); Ok ()
          with Unix.Unix_error (e, _, _) -> Error (error_of e)))

let receive t id ~max ~exact ~timeout =
  match find t id with
  | Error e -> (Error e, 0.)
  | Ok s when s.status <> Connected && not (s.udp && s.status = Bound) -> (Error "ERR_SOCK_NOT_CONN", 0.)
  | Ok s ->
      let buf = Buffer.create max and chunk = Bytes.create (Stdlib.max max 1) in
      let rec go waited =
        let ready, w = wait_for s.fd (timeout -. waited) in
        let waited = waited +. w in
        if not ready then (Error "ERR_SOCK_TIMEOUT", waited)
        else match Unix.read s.fd chunk 0 (max - Buffer.length buf) with
          | 0 -> (Error "ERR_SOCK_CLOSED", waited)
          | n ->
              Buffer.add_subbytes buf chunk 0 n;
              if exact && Buffer.length buf < max then go waited else (Ok (Buffer.contents buf), waited)
          | exception Unix.Unix_error (e, _, _) -> (Error (error_of e), waited) in
      if max <= 0 then (Ok "", 0.) else go 0.

let receive_from t id ~max ~timeout =
  match find t id with
  | Error e -> (Error e, 0.)
  | Ok s when not s.udp -> (Error "ERR_SOCK_UNSPEC", 0.)
  | Ok s when s.status = Created -> (Error "ERR_SOCK_NOT_BOUND", 0.)
  | Ok s ->
      let ready, waited = wait_for s.fd timeout in
      if not ready then (Error "ERR_SOCK_TIMEOUT", waited)
      else
        let chunk = Bytes.create 65536 in
        match Unix.recvfrom s.fd chunk 0 65536 [] with
        | n, Unix.ADDR_INET (a, p) ->
            (Ok (Bytes.sub_string chunk 0 (min n max), Unix.string_of_inet_addr a, p), waited)
        | _, Unix.ADDR_UNIX _ -> (Error "ERR_SOCK_UNSPEC", waited)
        | exception Unix.Unix_error (e, _, _) -> (Error (error_of e), waited)

let peek t id =
  match find t id with
  | Error e -> Error e
  | Ok s -> (
      match Unix.select [ s.fd ] [] [] 0. with
      | [], _, _ -> Ok 0
      | _ -> (
          let chunk = Bytes.create 65536 in
          match Unix.recv s.fd chunk 0 65536 [ Unix.MSG_PEEK ] with
          | n -> Ok n
          | exception Unix.Unix_error (e, _, _) -> Error (error_of e))
      | exception Unix.Unix_error (e, _, _) -> Error (error_of e))

let close t id =
  match Hashtbl.find_opt t.table id with
  | Some s when s.status <> Closed ->
      (try Unix.close s.fd with Unix.Unix_error _ -> ());
      s.status <- Closed
  | _ -> ()

let close_all t = Hashtbl.iter (fun id _ -> close t id) t.table
