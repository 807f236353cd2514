module V = Value
module W = Rapid_controller.World
module S = Rapid_controller.Services
module K = Rapid_controller.Sockets
open Primitive

let same = Rapid_typing.Types.same_name  (* without lowered copies: every call site asks [modelled] *)

let arg = named_argument

let present = named_present

let value ctx args name = match arg ctx args name with
  | Value v -> Some v | Location (box, i, _) -> Some box.(i) | Switch | Missing -> None

let num = named_num
let str ctx args name = match value ctx args name with Some (V.String s) -> Some s | _ -> None

let store = named_store

let ( let* ) r f = match r with Ok v -> f v | Error name -> Failed name
let done_ = Returned None
let ret v = Returned (Some v)
let of_unit = function Ok () -> done_ | Error e -> Failed e

let services ctx = W.services ctx.world

(* The identity of the object in an iodev, dir, socketdev or rawbytes variable (0: none). *)
let object_id ctx args name = match value ctx args name with
  | Some (V.Handle h) -> V.handle_id h | _ -> 0

let set_object ctx args name id =
  match arg ctx args name with
  | Location (box, i, _) ->
      let kind = match box.(i) with V.Handle h -> V.handle_kind h | _ -> "object" in
      box.(i) <- V.Handle (V.make_handle ~kind id)
  | _ -> ()

(* A rawbytes object gets its identity at its first use. *)
let raw_id ctx args name =
  match object_id ctx args name with
  | 0 -> let id = S.new_object (services ctx) in set_object ctx args name id; id
  | id -> id

let integer = function Some f when Float.is_integer f -> Some (int_of_float f) | _ -> None

(* ---------------------------------------------------------------- files *)

let path ctx args name = Option.value (str ctx args name) ~default:""

let write_text ctx args text = of_unit (S.write (services ctx) (object_id ctx args "IODevice") text)

let device_input ctx args = S.input (services ctx) (object_id ctx args "IODevice")

(* ReadStr and ReadNum: up to 80 bytes, ending before a delimiter (by default a line feed),
   which is consumed; \DiscardHeaders skips delimiters before the text; None at the end of the
   file. *)
let read_field ic ~delims ~discard =
  let is_delim c = String.contains delims c in
  let peek () = try let p = pos_in ic in let c = input_char ic in seek_in ic p; Some c with End_of_file -> None in
  if discard then begin
    let rec skip () = match peek () with Some c when is_delim c -> ignore (input_char ic); skip () | _ -> () in
    skip ()
  end;
  match peek () with
  | None -> None
  | Some _ ->
      let b = Buffer.create 80 in
      let rec go () =
        if Buffer.length b < 80 then
          match input_char ic with
          | c when is_delim c -> ()
          | c -> Buffer.add_char b c; go ()
          | exception End_of_file -> () in
      go ();
      Some (Buffer.contents b)

(* \Delim adds its characters to the line feed, which always ends a field (R-13-s). *)
let delimiters ctx args = match str ctx args "Delim" with Some d -> "\n" ^ d | None -> "\n"

let read_byte ic = try Some (input_byte ic) with End_of_file -> None

(* WriteAnyBin's encoding (R-13-t): a tag and the value, then a check byte, the sum of the
   bytes modulo 256. *)
let encode_any v =
  let b = Buffer.create 32 in
  let float f = Buffer.add_int64_be b (Int64.bits_of_float f) in
  let rec go = function
    | V.Num f -> Buffer.add_char b 'n'; float f; Ok ()
    | V.Dnum f -> Buffer.add_char b 'd'; float f; Ok ()
    | V.Bool x -> Buffer.add_char b 'b'; Buffer.add_char b (if x then '\001' else '\000'); Ok ()
    | V.String s -> Buffer.add_char b 's'; Buffer.add_uint8 b (String.length s land 255); Buffer.add_string b s; Ok ()
    | V.Record cs -> Buffer.add_char b 'r'; Buffer.add_int32_be b (Int32.of_int (Array.length cs)); all cs
    | V.Array es -> Buffer.add_char b 'a'; Buffer.add_int32_be b (Int32.of_int (Array.length es)); all es
    | V.Handle _ -> Error "ERR_ARGVALERR"
  and all xs = Array.fold_left (fun acc x -> match acc with Ok () -> go x | e -> e) (Ok ()) xs in
  match go v with
  | Error e -> Error e
  | Ok () ->
      let body = Buffer.contents b in
      let sum = ref 0 in
      String.iter (fun c -> sum := (!sum + Char.code c) land 255) body;
      Ok ("RA" ^ body ^ String.make 1 (Char.chr !sum))

exception Short
exception Bad

let decode_any s off =
  let n = String.length s in
  let need k p = if p + k > n then raise Short in
  let rec go p =
    need 1 p;
    match s.[p] with
    | 'n' -> need 8 (p + 1); (V.Num (Int64.float_of_bits (String.get_int64_be s (p + 1))), p + 9)
    | 'd' -> need 8 (p + 1); (V.Dnum (Int64.float_of_bits (String.get_int64_be s (p + 1))), p + 9)
    | 'b' -> need 1 (p + 1); (V.Bool (s.[p + 1] <> '\000'), p + 2)
    | 's' ->
        need 1 (p + 1); let l = Char.code s.[p + 1] in need l (p + 2); (V.String (String.sub s (p + 2) l), p + 2 + l)
    | 'r' | 'a' as tag ->
        need 4 (p + 1);
        let count = Int32.to_int (String.get_int32_be s (p + 1)) in
        if count < 0 || count > n then raise Bad;
        let p = ref (p + 5) in
        let xs = Array.init count (fun _ -> let v, q = go !p in p := q; v) in
        ((if tag = 'r' then V.Record xs else V.Array xs), !p)
    | _ -> raise Bad in
  try
    need 2 off;
    if String.sub s off 2 <> "RA" then raise Bad;
    let v, p = go (off + 2) in
    need 1 p;
    let sum = ref 0 in
    for i = off + 2 to p - 1 do sum := (!sum + Char.code s.[i]) land 255 done;
    if Char.code s.[p] <> !sum then raise Bad;
    Ok (v, p + 1)
  with Short -> Error "ERR_RANYBIN_EOF" | Bad -> Error "ERR_RANYBIN_CHK"

(* The same structure: ReadAnyBin only stores data of the type of its target. *)
let rec same_shape a b = match a, b with
  | V.Num _, V.Num _ | V.Dnum _, V.Dnum _ | V.Bool _, V.Bool _ | V.String _, V.String _ -> true
  | V.Record x, V.Record y | V.Array x, V.Array y ->
      Array.length x = Array.length y && Array.for_all2 same_shape x y
  | _ -> false

(* ---------------------------------------------------------------- raw data *)

let raw ctx args name = let id = raw_id ctx args name in let b, n = S.rawbytes (services ctx) id in (id, b, n)

let index_in k ~size = match k with
  | Some i when i >= 1 && i + size - 1 <= S.rawbytes_capacity -> Ok i
  | _ -> Error "ERR_OUTOFBND"

let int_bytes ~size ~network v =
  let b = Bytes.make size '\000' in
  for k = 0 to size - 1 do
    let byte = Int64.to_int (Int64.logand (Int64.shift_right v (8 * k)) 0xFFL) in
    Bytes.set b (if network then size - 1 - k else k) (Char.chr byte)
  done;
  b

let bytes_int b ~size ~network ~signed =
  let v = ref 0L in
  for k = size - 1 downto 0 do
    let byte = Char.code (Bytes.get b (if network then size - 1 - k else k)) in
    v := Int64.logor (Int64.shift_left !v 8) (Int64.of_int byte)
  done;
  if signed && size < 8 && Int64.logand !v (Int64.shift_left 1L (8 * size - 1)) <> 0L then
    Int64.sub !v (Int64.shift_left 1L (8 * size))
  else !v

let float4_bytes ~network f =
  int_bytes ~size:4 ~network (Int64.of_int32 (Int32.bits_of_float f))

(* The bytes PackRawBytes writes for a value with its encoding. *)
let pack_bytes ctx args v =
  let network = present ctx args "Network" in
  if present ctx args "Hex1" then
    match v with
    | V.Num f when Float.is_integer f && f >= 0. && f <= 255. -> Ok (Bytes.make 1 (Char.chr (int_of_float f)))
    | _ -> Error "ERR_ARGVALERR"
  else if present ctx args "Float4" then
    match v with V.Num f | V.Dnum f -> Ok (float4_bytes ~network f) | _ -> Error "ERR_ARGVALERR"
  else match integer (num ctx args "IntX") with
    | Some x when List.mem x [ 1; 2; 4; 8; -1; -2; -4; -8 ] -> (
        let size = abs x and signed = x < 0 in
        match v with
        | V.Num f | V.Dnum f when Float.is_integer f ->
            let lo, hi =
              if size = 8 then
                (if signed then (-9.223372036854775808e18, 9.223372036854775807e18) else (0., 1.8446744073709551615e19))
              else
                let r = Float.pow 2. (float_of_int (8 * size)) in
                if signed then (-. r /. 2., r /. 2. -. 1.) else (0., r -. 1.) in
            if f < lo || f > hi then Error "ERR_ARGVALERR"
            else
              let i =
                if f >= 9.223372036854775807e18 then Int64.of_float (f -. 1.8446744073709551616e19)
                else Int64.of_float f in
              Ok (int_bytes ~size ~network i)
        | _ -> Error "ERR_ARGVALERR")
    | Some _ -> Error "ERR_ARGVALERR"
    | None -> (
        (* \ASCII, or no encoding named: a string is its characters (none for "", R-13-raw1), a
           byte one character. *)
        match v with
        | V.String s -> Ok (Bytes.of_string s)
        | V.Num f when Float.is_integer f && f >= 0. && f <= 255. && present ctx args "ASCII" ->
            Ok (Bytes.make 1 (Char.chr (int_of_float f)))
        | _ -> Error "ERR_ARGVALERR")

let unpack ctx args b n start =
  let network = present ctx args "Network" in
  let take size = if start + size - 1 > n then Error "ERR_OUTOFBND" else Ok (Bytes.sub b (start - 1) size) in
  let target = value ctx args "Value" in
  if present ctx args "Hex1" then Result.map (fun x -> V.num (float_of_int (Char.code (Bytes.get x 0)))) (take 1)
  else if present ctx args "Float4" then
    Result.map (fun x ->
        let f = Int32.float_of_bits (Int64.to_int32 (bytes_int x ~size:4 ~network ~signed:false)) in
        match target with Some (V.Dnum _) -> V.dnum f | _ -> V.num f) (take 4)
  else match integer (num ctx args "IntX") with
    | Some x when List.mem x [ 1; 2; 4; 8; -1; -2; -4; -8 ] ->
        Result.map (fun bs ->
            let i = bytes_int bs ~size:(abs x) ~network ~signed:(x < 0) in
            let f =
              if x = 8 && Int64.compare i 0L < 0 then Int64.to_float i +. 1.8446744073709551616e19
              else Int64.to_float i in
            match target with Some (V.Dnum _) -> V.dnum f | _ -> V.num f) (take (abs x))
    | Some _ -> Error "ERR_ARGVALERR"
    | None -> (
        (* \ASCII:=0 reads no byte and gives "" (R-13-raw1). *)
        match integer (num ctx args "ASCII") with
        | Some k when k >= 0 && k <= 80 -> Result.map (fun bs -> V.String (Bytes.to_string bs)) (take k)
        | _ -> Error "ERR_ARGVALERR")

(* ---------------------------------------------------------------- sockets *)

let sockets ctx = S.sockets (services ctx)

(* A blocking socket call waits on the host, at most its \Time (default 60 s), whatever
   --max-time leaves (R-13-sockwait1): the run's bound is the virtual clock's, not the peer's. *)
let timeout ctx args =
  match num ctx args "Time" with
  | Some t when not (t > 0.) || not (Float.is_finite t) -> Error "ERR_ARGVALERR"
  | t -> Ok (Option.value t ~default:60.)

let waited ctx seconds = W.advance_to ctx.world (W.now ctx.world +. seconds)

(* R-14-n: a blocking call (SocketAccept, SocketReceive, SocketReceiveFrom) that cannot go on at
   once is a waiting instruction: interrupts are served while it waits (§8) and, with several
   tasks, the others run. While anything else can happen at a virtual time (a task that runs or
   waits for something but the host, a timed event before the call's deadline, the robot
   moving), its wait keeps the virtual clock within [socket_slice] of the host's: each look first
   waits on the host until the host has waited as long as the virtual clock moved since the call
   (the clock followed), then lets the clock move on by one slice at most; data that comes moves
   the clock on by the host time the host waited beyond it. Once nothing else can happen — one
   task, or every task waiting on the host (W.only_host_waits) — the clock holds (R-13-sockwait1,
   R-13-sockwait2): each look waits on the host for [hold_slice] (shared among the tasks that
   wait on the host) and lets the clock move on by a microsecond only, and \Time is the host's
   (the clock jumps to the deadline when it passes). The call itself runs when the socket is
   ready. *)
let socket_slice = 0.02   (* §8: a response to an interrupt is 2-30 ms late *)
let hold_slice = 0.25

let blocking ctx ~standstill ~what id ~timeout (call : timeout:float -> outcome) =
  let w = ctx.world and k = sockets ctx in
  if K.readable k id ~within:0. then call ~timeout
  else begin
    let start = W.now w and host_start = Unix.gettimeofday () in
    let deadline = start +. timeout in
    let host () = Unix.gettimeofday () -. host_start in
    (* The clock has reached a time, at its resolution (a microsecond). *)
    let reached t = W.seconds (W.now w) >= W.seconds t in
    (* Nothing else can happen at a virtual time: only the host can end any task's wait, the
       robot at a standstill, no timed event before the deadline but the waits' own looks. *)
    let alone () =
      W.only_host_waits w
      && not (standstill () > W.now w)
      && (match W.next_change w with None -> true | Some t -> t >= deadline) in
    (* The host time the clock did not follow (it held), as of the last look that followed. *)
    let lag = ref 0. and held = ref false in
    (* One Wake at a time: with several tasks the socket is looked at every turn. *)
    let next_look = ref (Float.min deadline (start +. socket_slice)) in
    W.wake_at w !next_look;
    W.host_wait_begin w;
    let looked ready = if ready then W.host_wait_end w; ready in
    Wait { W.what = what; deadline = Some deadline; poll = None;
           satisfied = (fun () ->
               let now = W.now w in
               if reached deadline then looked (K.readable k id ~within:0.)
               else if alone () then begin
                 held := true;
                 let slice = hold_slice /. float_of_int (max 1 (W.host_waiters w)) in
                 let ready = K.readable k id ~within:(Float.min slice (timeout -. host ())) in
                 if ready then ()
                 else if host () >= timeout then W.advance_to w deadline
                 else (next_look := now +. 1e-6; W.wake_at w !next_look);
                 looked ready
               end
               else begin
                 (* After a hold the clock follows from where it held: the host time of the
                    hold is not caught up, but it counts toward \Time. *)
                 if !held then (held := false; lag := host () -. (now -. start));
                 let ready = K.readable k id ~within:((now -. start) -. (host () -. !lag)) in
                 let now = W.now w in
                 if ready then begin
                   let ahead = Float.min (start +. host () -. !lag) deadline in
                   if ahead > now then W.advance_to w ahead
                 end
                 else if (now -. start) +. !lag >= timeout then W.advance_to w deadline
                 else if reached !next_look then begin
                   next_look := Float.min deadline (now +. socket_slice);
                   W.wake_at w !next_look
                 end;
                 looked ready
               end);
           finish = (fun ~timed_out ->
               W.host_wait_end w;
               if timed_out then Rapid_observable.Wait.error "ERR_SOCK_TIMEOUT"
               else match call ~timeout:(Float.max socket_slice (deadline -. W.now w)) with
                 | Failed e -> Rapid_observable.Wait.error e
                 | _ -> None) }
  end

(* The bytes SocketSend sends: \Str, \RawData or \Data, cut to \NoOfBytes. *)
let send_data ctx args =
  let* data =
    match str ctx args "Str", arg ctx args "RawData", value ctx args "Data" with
    | Some s, _, _ -> Ok s
    | _, Location _, _ -> let _, b, n = raw ctx args "RawData" in Ok (Bytes.sub_string b 0 n)
    | _, _, Some (V.Array es) ->
        let bad = Array.exists (function V.Num f -> not (Float.is_integer f && f >= 0. && f <= 255.) | _ -> true) es in
        if bad then Error "ERR_ARGVALERR"
        else Ok (String.init (Array.length es) (fun i -> Char.chr (int_of_float (V.num_value es.(i)))))
    | _ -> Error "ERR_ARGVALERR" in
  match integer (num ctx args "NoOfBytes") with
  | None when present ctx args "NoOfBytes" -> Failed "ERR_ARGVALERR"
  | None -> Returned (Some (V.String data))
  | Some k when k >= 1 && k <= String.length data -> Returned (Some (V.String (String.sub data 0 k)))
  | Some _ -> Failed "ERR_ARGVALERR"

(* Where SocketReceive puts what it receives, and how much fits: a string 80 bytes, a rawbytes
   1024, a byte array its size. *)
let receive_target ctx args =
  if present ctx args "Str" then Ok (`Str, 80)
  else if present ctx args "RawData" then Ok (`Raw, S.rawbytes_capacity)
  else match value ctx args "Data" with
    | Some (V.Array es) -> Ok (`Data, Array.length es)
    | _ -> Error "ERR_ARGVALERR"

let deliver ctx args target data =
  (match target with
   | `Str -> store ctx args "Str" (V.String data)
   | `Raw ->
       let id, b, _ = raw ctx args "RawData" in
       Bytes.fill b 0 S.rawbytes_capacity '\000';
       Bytes.blit_string data 0 b 0 (String.length data);
       S.set_rawbytes_length (services ctx) id (String.length data)
   | `Data -> (
       match arg ctx args "Data" with
       | Location (box, i, _) -> (
           match box.(i) with
           | V.Array es ->
               String.iteri (fun k c -> if k < Array.length es then es.(k) <- V.num (float_of_int (Char.code c))) data
           | _ -> ())
       | _ -> ()));
  store ctx args "NoRecBytes" (V.num (float_of_int (String.length data)))

let receive_size ctx args capacity =
  match integer (num ctx args "ReadNoOfBytes") with
  | None when present ctx args "ReadNoOfBytes" -> Error "ERR_ARGVALERR"
  | None -> Ok (capacity, false)
  | Some k when k >= 1 && k <= capacity -> Ok (k, true)
  | Some _ -> Error "ERR_ARGVALERR"

let names = [
  "Open"; "Close"; "Rewind"; "Write"; "WriteBin"; "WriteStrBin"; "WriteAnyBin"; "ReadAnyBin";
  "WriteRawBytes"; "ReadRawBytes"; "ReadNum"; "ReadStr"; "ReadStrBin"; "ReadBin"; "ClearIOBuff";
  "MakeDir"; "RemoveDir"; "RemoveFile"; "RenameFile"; "CopyFile"; "OpenDir"; "CloseDir"; "ReadDir";
  "IsFile"; "FileSize";
  "SocketCreate"; "SocketConnect"; "SocketBind"; "SocketListen"; "SocketAccept"; "SocketSend";
  "SocketSendTo"; "SocketReceiveFrom"; "SocketPeek"; "SocketReceive"; "SocketClose"; "SocketGetStatus";
  "ClearRawBytes"; "CopyRawBytes"; "RawBytesLen"; "PackRawBytes"; "UnpackRawBytes";
  "TextTabInstall"; "TextTabGet"; "TextGet"; "TextTabFreeToUse";
]

let modelled name = List.exists (same name) names

let call ?(standstill = fun () -> neg_infinity) (ctx : context) name args =
  let sv () = services ctx in
  let dev () = object_id ctx args "IODevice" in
  match String.lowercase_ascii name with
  (* ------------------------------------------------------------ files *)
  | "open" ->
      Some (
        let obj = Option.value (str ctx args "Object") ~default:"" in
        let path = match str ctx args "File" with
          | Some f ->
              if obj <> "" && obj.[String.length obj - 1] <> ':' && obj.[String.length obj - 1] <> '/' then
                obj ^ "/" ^ f
              else obj ^ f
          | None -> obj in
        (* Without \Read, \Write or \Append: \Write for a character file, \Append with \Bin
           (R-13-s). *)
        let mode =
          if present ctx args "Read" then S.Read
          else if present ctx args "Write" then S.Write
          else if present ctx args "Append" || present ctx args "Bin" then S.Append
          else S.Write in
        if S.is_open (sv ()) (dev ()) then Failed "ERR_FILEOPEN"
        else let* id = S.open_file (sv ()) path mode in
          set_object ctx args "IODevice" id; done_)
  | "close" -> S.close_file (sv ()) (dev ()); Some done_
  | "rewind" -> Some (of_unit (S.rewind (sv ()) (dev ())))
  | "cleariobuff" -> Some (if S.is_open (sv ()) (dev ()) then done_ else Failed "ERR_FILEACC")
  | "write" ->
      Some (
        let text = Option.value (str ctx args "String") ~default:"" in
        let v = List.find_map (fun n -> value ctx args n) [ "Num"; "Bool"; "Pos"; "Orient"; "Dnum" ] in
        let line = Text_format.tpwrite text v in
        write_text ctx args (if present ctx args "NoNewLine" then line else line ^ "\n"))
  | "writestrbin" -> Some (write_text ctx args (Option.value (str ctx args "Str") ~default:""))
  | "writebin" ->
      Some (
        match value ctx args "Buffer", integer (num ctx args "NChar") with
        | Some (V.Array es), Some n when n >= 0 && n <= Array.length es ->
            let bytes = Array.sub es 0 n in
            if Array.exists (function V.Num f -> not (Float.is_integer f && f >= 0. && f <= 255.) | _ -> true) bytes
            then Failed "ERR_ARGVALERR"
            else write_text ctx args (String.init n (fun i -> Char.chr (int_of_float (V.num_value bytes.(i)))))
        | Some (V.Array _), Some _ -> Failed "ERR_OUTOFBND"
        | _ -> Failed "ERR_ARGVALERR")
  | "writeanybin" ->
      Some (match value ctx args "Data" with
          | Some v -> (match encode_any v with Ok s -> write_text ctx args s | Error e -> Failed e)
          | None -> Failed "ERR_ARGVALERR")
  | "writerawbytes" ->
      Some (
        let _, b, n = raw ctx args "RawData" in
        match integer (num ctx args "NoOfBytes") with
        | Some k when k >= 0 && k <= n -> write_text ctx args (Bytes.sub_string b 0 k)
        | Some _ -> Failed "ERR_ARGVALERR"
        | None when present ctx args "NoOfBytes" -> Failed "ERR_ARGVALERR"
        | None -> write_text ctx args (Bytes.sub_string b 0 n))
  | "readrawbytes" ->
      Some (
        let* ic = device_input ctx args in
        let id, b, _ = raw ctx args "RawData" in
        let got = try input ic b 0 S.rawbytes_capacity with Sys_error _ -> -1 in
        (* Nothing left: ERR_RANYBIN_EOF, the rawbytes unchanged (R-13-raw2). *)
        if got < 0 then Failed "ERR_FILEACC"
        else if got = 0 then Failed "ERR_RANYBIN_EOF"
        else (S.set_rawbytes_length (sv ()) id got; done_))
  | "readanybin" ->
      Some (
        let* ic = device_input ctx args in
        let start = pos_in ic in
        let rest = try really_input_string ic (in_channel_length ic - start) with _ -> "" in
        match decode_any rest 0 with
        | Error e -> seek_in ic start; Failed e
        | Ok (v, used) ->
            (* Data of another type are not read: the next ReadAnyBin sees them again. *)
            match value ctx args "Data" with
            | Some target when same_shape target v -> seek_in ic (start + used); store ctx args "Data" v; done_
            | _ -> seek_in ic start; Failed "ERR_RANYBIN_CHK")
  | "readstr" ->
      Some (
        let* ic = device_input ctx args in
        (match integer (num ctx args "Line") with
         | Some l when l >= 1 -> seek_in ic 0; for _ = 2 to l do ignore (read_field ic ~delims:"\n" ~discard:false) done
         | _ -> ());
        match read_field ic ~delims:(delimiters ctx args) ~discard:(present ctx args "DiscardHeaders") with
        | None -> ret (V.String "EOF")
        | Some s ->
            let s = if present ctx args "RemoveCR" && s <> "" && s.[String.length s - 1] = '\r'
              then String.sub s 0 (String.length s - 1) else s in
            ret (V.String s))
  | "readnum" ->
      Some (
        let* ic = device_input ctx args in
        match read_field ic ~delims:(delimiters ctx args) ~discard:false with
        | None -> ret (V.num 9.998e36)
        | Some s -> (
            match Library.str_to_val (V.String (String.trim s)) V.S_num with
            | Some v -> ret v
            | None -> Failed "ERR_RCVDATA"))
  | "readstrbin" ->
      Some (
        let* ic = device_input ctx args in
        match integer (num ctx args "NoOfChars") with
        | Some k when k >= 1 && k <= 80 ->
            let b = Bytes.create k in
            let got = try input ic b 0 k with Sys_error _ -> 0 in
            let rec more got =
              if got < k then match input ic b got (k - got) with 0 -> got | n -> more (got + n) else got in
            let got = if got = 0 then 0 else more got in
            if got = 0 then ret (V.String "EOF") else ret (V.String (Bytes.sub_string b 0 got))
        | _ -> Failed "ERR_ARGVALERR")
  | "readbin" ->
      Some (let* ic = device_input ctx args in
            ret (V.num (match read_byte ic with Some c -> float_of_int c | None -> 511.)))
  | "isfile" ->
      Some (
        let* kind = S.file_kind (sv ()) (path ctx args "Path") in
        let is k = kind = Some k in
        ret (V.Bool (
            if present ctx args "Directory" then is Unix.S_DIR
            else if present ctx args "Fifo" then is Unix.S_FIFO
            else if present ctx args "RegFile" then is Unix.S_REG
            else if present ctx args "BlockSpec" then is Unix.S_BLK
            else if present ctx args "CharSpec" then is Unix.S_CHR
            else kind <> None)))
  | "filesize" -> Some (let* size = S.file_size (sv ()) (path ctx args "Path") in ret (V.num (float_of_int size)))
  | "removefile" -> Some (of_unit (S.remove_file (sv ()) (path ctx args "Path")))
  | "makedir" -> Some (of_unit (S.make_dir (sv ()) (path ctx args "Path")))
  | "removedir" -> Some (of_unit (S.remove_dir (sv ()) (path ctx args "Path")))
  | "renamefile" -> Some (of_unit (S.rename_file (sv ()) ~src:(path ctx args "OldPath") ~dst:(path ctx args "NewPath")))
  | "copyfile" -> Some (of_unit (S.copy_file (sv ()) ~src:(path ctx args "OldPath") ~dst:(path ctx args "NewPath")))
  | "opendir" ->
      Some (let* id = S.open_dir (sv ()) (path ctx args "Path") in
            set_object ctx args "Dev" id; done_)
  | "closedir" -> S.close_dir (sv ()) (object_id ctx args "Dev"); Some done_
  | "readdir" ->
      Some (let* next = S.read_dir (sv ()) (object_id ctx args "Dev") in
            match next with
            | Some n when String.length n > 80 -> Failed "ERR_STRTOOLNG"
            | Some n -> store ctx args "FileName" (V.String n); ret (V.Bool true)
            | None -> ret (V.Bool false))
  (* ------------------------------------------------------------ raw data *)
  | "rawbyteslen" -> let _, _, n = raw ctx args "RawData" in Some (ret (V.num (float_of_int n)))
  | "clearrawbytes" ->
      Some (
        let id, b, n = raw ctx args "RawData" in
        let* from = match integer (num ctx args "FromIndex") with
          | None when not (present ctx args "FromIndex") -> Ok 1
          | Some k when k >= 1 && k <= S.rawbytes_capacity -> Ok k
          | _ -> Error "ERR_OUTOFBND" in
        Bytes.fill b (from - 1) (S.rawbytes_capacity - from + 1) '\000';
        S.set_rawbytes_length (sv ()) id (min n (from - 1)); done_)
  | "copyrawbytes" ->
      Some (
        let _, fb, fn = raw ctx args "FromRawData" in
        let tid, tb, tn = raw ctx args "ToRawData" in
        (* FromIndex may stand right after the valid data: without \NoOfBytes nothing is copied
           (R-13-raw3), an empty rawbytes from 1 too. *)
        let* from =
          match integer (num ctx args "FromIndex") with
          | Some k when k >= 1 && k <= fn + 1 -> Ok k | _ -> Error "ERR_OUTOFBND" in
        let* count = match integer (num ctx args "NoOfBytes") with
          | None when not (present ctx args "NoOfBytes") -> Ok (fn - from + 1)
          | Some k when k >= 1 && from + k - 1 <= fn -> Ok k
          | _ -> Error "ERR_OUTOFBND" in
        let* into = index_in (integer (num ctx args "ToIndex")) ~size:count in
        if into > tn + 1 then Failed "ERR_OUTOFBND"
        else begin
          let chunk = Bytes.sub fb (from - 1) count in
          Bytes.blit chunk 0 tb (into - 1) count;
          S.set_rawbytes_length (sv ()) tid (max tn (into + count - 1)); done_
        end)
  | "packrawbytes" ->
      Some (
        let* v = match value ctx args "Value" with Some v -> Ok v | None -> Error "ERR_ARGVALERR" in
        let* data = pack_bytes ctx args v in
        let id, b, n = raw ctx args "RawData" in
        let* start = index_in (integer (num ctx args "StartIndex")) ~size:(Bytes.length data) in
        (* Packing starts at most right after the data already there: no gaps. *)
        if start > n + 1 then Failed "ERR_OUTOFBND"
        else begin
          Bytes.blit data 0 b (start - 1) (Bytes.length data);
          S.set_rawbytes_length (sv ()) id (max n (start + Bytes.length data - 1)); done_
        end)
  | "unpackrawbytes" ->
      Some (
        let _, b, n = raw ctx args "RawData" in
        (* \ASCII:=0 reads nothing, so it may also start right after the valid data (R-13-raw1). *)
        let nothing = integer (num ctx args "ASCII") = Some 0 in
        let* start =
          match integer (num ctx args "StartIndex") with
          | Some k when k >= 1 && (k <= n || (nothing && k = n + 1)) -> Ok k | _ -> Error "ERR_OUTOFBND" in
        let* v = unpack ctx args b n start in
        match value ctx args "Value", v with
        | Some (V.String _), V.String _ | Some (V.Num _), V.Num _ | Some (V.Dnum _), V.Dnum _ ->
            store ctx args "Value" v; done_
        | Some (V.Dnum _), V.Num f -> store ctx args "Value" (V.dnum f); done_
        | _ -> Failed "ERR_ARGVALERR")
  (* ------------------------------------------------------------ sockets *)
  | "socketcreate" ->
      Some (
        let k = sockets ctx in
        let old = object_id ctx args "Socket" in
        if old > 0 && K.status k old <> K.Closed then Failed "ERR_SOCK_IS_CONN"
        else let* id = K.socket k ~udp:(present ctx args "UDP") in
          set_object ctx args "Socket" id; done_)
  | "socketbind" ->
      Some (
        match str ctx args "LocalAddress", integer (num ctx args "LocalPort") with
        | Some a, Some p -> of_unit (K.bind (sockets ctx) (object_id ctx args "Socket") a p)
        | _ -> Failed "ERR_SOCK_ADDR_INVALID")
  | "socketlisten" -> Some (of_unit (K.listen (sockets ctx) (object_id ctx args "Socket")))
  | "socketaccept" ->
      Some (
        let* timeout = timeout ctx args in
        let id = object_id ctx args "Socket" in
        blocking ctx ~standstill ~what:"a client at the socket (SocketAccept)" id ~timeout @@ fun ~timeout ->
        let r, w = K.accept (sockets ctx) id ~timeout in
        waited ctx w;
        let* client, address = r in
        let old = object_id ctx args "ClientSocket" in
        if old > 0 then K.close (sockets ctx) old;
        set_object ctx args "ClientSocket" client;
        store ctx args "ClientAddress" (V.String address); done_)
  | "socketconnect" ->
      Some (
        let* timeout = timeout ctx args in
        match str ctx args "Address", integer (num ctx args "Port") with
        | Some a, Some p ->
            let r, w = K.connect (sockets ctx) (object_id ctx args "Socket") a p ~timeout in
            waited ctx w; of_unit r
        | _ -> Failed "ERR_SOCK_ADDR_INVALID")
  | "socketsend" ->
      Some (match send_data ctx args with
          | Returned (Some (V.String data)) -> of_unit (K.send (sockets ctx) (object_id ctx args "Socket") data)
          | r -> r)
  | "socketsendto" ->
      Some (match send_data ctx args, str ctx args "RemoteAddress", integer (num ctx args "RemotePort") with
          | Returned (Some (V.String data)), Some a, Some p ->
              of_unit (K.send_to (sockets ctx) (object_id ctx args "Socket") a p data)
          | (Failed _ as r), _, _ -> r
          | _ -> Failed "ERR_SOCK_ADDR_INVALID")
  | "socketreceive" ->
      Some (
        let* target, capacity = receive_target ctx args in
        let* max, exact = receive_size ctx args capacity in
        let* timeout = timeout ctx args in
        let id = object_id ctx args "Socket" in
        blocking ctx ~standstill ~what:"data at the socket (SocketReceive)" id ~timeout @@ fun ~timeout ->
        let r, w = K.receive (sockets ctx) id ~max ~exact ~timeout in
        waited ctx w;
        let* data = r in
        deliver ctx args target data; done_)
  | "socketreceivefrom" ->
      Some (
        let* target, capacity = receive_target ctx args in
        let* max, _ = receive_size ctx args capacity in
        let* timeout = timeout ctx args in
        let id = object_id ctx args "Socket" in
        blocking ctx ~standstill ~what:"data at the socket (SocketReceiveFrom)" id ~timeout @@ fun ~timeout ->
        let r, w = K.receive_from (sockets ctx) id ~max ~timeout in
        waited ctx w;
        let* data, address, port = r in
        deliver ctx args target data;
        store ctx args "RemoteAddress" (V.String address);
        store ctx args "RemotePort" (V.num (float_of_int port)); done_)
  | "socketpeek" ->
      Some (let* n = K.peek (sockets ctx) (object_id ctx args "Socket") in ret (V.num (float_of_int n)))
  | "socketclose" -> K.close (sockets ctx) (object_id ctx args "Socket"); Some done_
  | "socketgetstatus" ->
      Some (ret (V.num (float_of_int (K.status_number (K.status (sockets ctx) (object_id ctx args "Socket"))))))
  (* ------------------------------------------------------------ text resources (ch. 15) *)
  | "texttabinstall" ->
      Some (
        let* contents = S.read_file (sv ()) (path ctx args "File") in
        (* A file that is not a text resource cannot be installed (R-15-c). *)
        match Rapid_controller.Text_tables.parse contents with
        | Error _ -> Failed "ERR_FILEACC"
        | Ok table -> Rapid_controller.Text_tables.install (S.texts (sv ())) table; done_)
  | "texttabfreetouse" ->
      Some (ret (V.Bool (Rapid_controller.Text_tables.free_to_use (S.texts (sv ()))
                           (Option.value (str ctx args "TableName") ~default:""))))
  | "texttabget" ->
      Some (match Rapid_controller.Text_tables.find (S.texts (sv ()))
                    (Option.value (str ctx args "TableName") ~default:"") with
          | Some n -> ret (V.num (float_of_int n))
          | None -> Failed "ERR_TXTNOEXIST")
  | "textget" ->
      Some (match integer (num ctx args "Table"), integer (num ctx args "Index") with
          | Some t, Some i -> (
              match Rapid_controller.Text_tables.text (S.texts (sv ())) t i with
              | Some text when String.length text <= 80 -> ret (V.String text)
              | Some _ -> Failed "ERR_STRTOOLNG"
              | None -> Failed "ERR_TXTNOEXIST")
          | _ -> Failed "ERR_TXTNOEXIST")
  | _ -> None
