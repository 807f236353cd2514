(* The EGM messages in the protocol buffer wire format (egm_protocol.mli gives the schema). *)

type header = { seqno : int option; tm : int option; mtype : int option }

let mtype_data = 2
let mtype_correction = 3

type pose = {
  pos : (float * float * float) option;
  orient : (float * float * float * float) option;
  euler : (float * float * float) option;
}

type robot = {
  r_header : header;
  feedback_joints : float list option;
  feedback_pose : pose option;
  planned_joints : float list option;
  planned_pose : pose option;
  motor_on : bool option;
  mci_running : bool option;
  convergence_met : bool option;
  rapid_running : bool option;
  utilization : float option;
}

type sensor = {
  s_header : header;
  set_joints : float list option;
  set_pose : pose option;
  set_external : float list option;
  speed_joints : float list option;
}

let empty_header = { seqno = None; tm = None; mtype = None }

let empty_robot = {
  r_header = empty_header; feedback_joints = None; feedback_pose = None; planned_joints = None;
  planned_pose = None; motor_on = None; mci_running = None; convergence_met = None;
  rapid_running = None; utilization = None }

let empty_sensor =
  { s_header = empty_header; set_joints = None; set_pose = None; set_external = None; speed_joints = None }

(* ------------------------------------------------------------------ the wire format *)

type value = Varint of int64 | Fixed64 of int64 | Bytes of string | Fixed32

exception Malformed of string

(* A varint: seven bits a byte, least significant first; ten bytes hold 64 bits, the tenth
   only one of them. *)
let read_varint s pos =
  let n = String.length s in
  let rec go acc shift =
    if !pos >= n then raise (Malformed "truncated varint");
    let b = Char.code s.[!pos] in
    incr pos;
    if shift = 63 && b > 1 then raise (Malformed "varint beyond 64 bits");
    let acc = Int64.logor acc (Int64.shift_left (Int64.of_int (b land 0x7f)) shift) in
    if b land 0x80 = 0 then acc else go acc (shift + 7) in
  go 0L 0

let read_fixed s pos k =
  if !pos + k > String.length s then raise (Malformed "truncated fixed-width field");
  let v = ref 0L in
  for i = k - 1 downto 0 do
    v := Int64.logor (Int64.shift_left !v 8) (Int64.of_int (Char.code s.[!pos + i]))
  done;
  pos := !pos + k;
  !v

(* Every field of a message, in order. *)
let fields s =
  let pos = ref 0 and out = ref [] in
  while !pos < String.length s do
    let key = read_varint s pos in
    let number = Int64.shift_right_logical key 3 and wire = Int64.to_int (Int64.logand key 7L) in
    if number = 0L || Int64.compare number 0x1fffffffL > 0 then raise (Malformed "field number out of range");
    let number = Int64.to_int number in
    let v = match wire with
      | 0 -> Varint (read_varint s pos)
      | 1 -> Fixed64 (read_fixed s pos 8)
      | 2 ->
          let len = read_varint s pos in
          if Int64.compare len 0L < 0 || Int64.compare len (Int64.of_int (String.length s - !pos)) > 0 then
            raise (Malformed "length beyond the message");
          let len = Int64.to_int len in
          let b = String.sub s !pos len in
          pos := !pos + len;
          Bytes b
      | 5 -> ignore (read_fixed s pos 4); Fixed32
      | w -> raise (Malformed (Printf.sprintf "wire type %d not supported" w)) in
    out := (number, v) :: !out
  done;
  List.rev !out

(* A submessage given more than once is the merge of its occurrences, which is the message of
   their bytes one after the other (protocol buffers). *)
let sub fs n =
  match List.filter_map (fun (k, v) -> match v with Bytes b when k = n -> Some b | _ -> None) fs with
  | [] -> None
  | parts -> Some (fields (String.concat "" parts))

let last_varint fs n =
  List.fold_left (fun acc (k, v) -> match v with Varint x when k = n -> Some x | _ -> acc) None fs

let int_field fs n = Option.map Int64.to_int (last_varint fs n)
let bool_field fs n = Option.map (fun x -> x <> 0L) (last_varint fs n)

let last_double fs n =
  List.fold_left (fun acc (k, v) ->
      match v with Fixed64 x when k = n -> Some (Int64.float_of_bits x) | _ -> acc) None fs

(* Repeated doubles, unpacked (proto2's default) or packed. *)
let doubles fs n =
  let out = ref [] in
  List.iter (fun (k, v) ->
      if k = n then match v with
        | Fixed64 x -> out := Int64.float_of_bits x :: !out
        | Bytes b ->
            if String.length b mod 8 <> 0 then raise (Malformed "packed doubles not a multiple of 8 bytes");
            let pos = ref 0 in
            while !pos < String.length b do out := Int64.float_of_bits (read_fixed b pos 8) :: !out done
        | _ -> ()) fs;
  List.rev !out

let need = function Some x -> x | None -> raise (Malformed "required field missing")

let header_of fs = match sub fs 1 with
  | None -> empty_header
  | Some h -> { seqno = int_field h 1; tm = int_field h 2; mtype = int_field h 3 }

let joints_of fs n = Option.map (fun j -> doubles j 1) (sub fs n)

let triple fs = (need (last_double fs 1), need (last_double fs 2), need (last_double fs 3))

let pose_of fs n =
  Option.map (fun p ->
      { pos = Option.map triple (sub p 1);
        orient = Option.map (fun q ->
            (need (last_double q 1), need (last_double q 2), need (last_double q 3), need (last_double q 4))) (sub p 2);
        euler = Option.map triple (sub p 3) }) (sub fs n)

let state fs n = Option.map (fun s -> need (int_field s 1)) (sub fs n)

let guard f s = try Ok (f (fields s)) with Malformed m -> Error m

let decode_robot =
  guard (fun fs ->
      let fb = sub fs 2 and pl = sub fs 3 in
      let part m f = Option.bind m f in
      { r_header = header_of fs;
        feedback_joints = part fb (fun f -> joints_of f 1); feedback_pose = part fb (fun f -> pose_of f 2);
        planned_joints = part pl (fun f -> joints_of f 1); planned_pose = part pl (fun f -> pose_of f 2);
        motor_on = Option.map (fun s -> s = 1) (state fs 4);
        mci_running = Option.map (fun s -> s = 3) (state fs 5);
        convergence_met = bool_field fs 6;
        rapid_running = Option.map (fun s -> s = 2) (state fs 8);
        utilization = last_double fs 10 })

let decode_sensor =
  guard (fun fs ->
      let pl = sub fs 2 and sp = sub fs 3 in
      let part m f = Option.bind m f in
      { s_header = header_of fs;
        set_joints = part pl (fun f -> joints_of f 1); set_pose = part pl (fun f -> pose_of f 2);
        set_external = part pl (fun f -> joints_of f 3);
        speed_joints = part sp (fun f -> joints_of f 1) })

(* ------------------------------------------------------------------ encoding *)

let put_varint b x =
  let rec go x =
    let low = Int64.to_int (Int64.logand x 0x7fL) and rest = Int64.shift_right_logical x 7 in
    if rest = 0L then Buffer.add_char b (Char.chr low)
    else (Buffer.add_char b (Char.chr (low lor 0x80)); go rest) in
  go x

let key b n wire = put_varint b (Int64.of_int ((n lsl 3) lor wire))

let put_int b n x = key b n 0; put_varint b (Int64.of_int x)

let put_double b n f =
  key b n 1;
  let x = Int64.bits_of_float f in
  for i = 0 to 7 do
    Buffer.add_char b (Char.chr (Int64.to_int (Int64.logand (Int64.shift_right_logical x (8 * i)) 0xffL)))
  done

let put_sub b n f =
  let inner = Buffer.create 64 in
  f inner;
  key b n 2; put_varint b (Int64.of_int (Buffer.length inner)); Buffer.add_buffer b inner

let opt f = function Some x -> f x | None -> ()

let put_header b h =
  put_sub b 1 (fun s -> opt (put_int s 1) h.seqno; opt (put_int s 2) h.tm; opt (put_int s 3) h.mtype)

let put_joints b n = opt (fun js -> put_sub b n (fun s -> List.iter (put_double s 1) js))

let put_triple b n (x, y, z) = put_sub b n (fun s -> put_double s 1 x; put_double s 2 y; put_double s 3 z)

let put_pose b n = opt (fun p ->
    put_sub b n (fun s ->
        opt (put_triple s 1) p.pos;
        opt (fun (u0, u1, u2, u3) ->
            put_sub s 2 (fun q -> put_double q 1 u0; put_double q 2 u1; put_double q 3 u2; put_double q 4 u3)) p.orient;
        opt (put_triple s 3) p.euler))

let put_state b n v = put_sub b n (fun s -> put_int s 1 v)

let encode_robot r =
  let b = Buffer.create 256 in
  put_header b r.r_header;
  if r.feedback_joints <> None || r.feedback_pose <> None then
    put_sub b 2 (fun s -> put_joints s 1 r.feedback_joints; put_pose s 2 r.feedback_pose);
  if r.planned_joints <> None || r.planned_pose <> None then
    put_sub b 3 (fun s -> put_joints s 1 r.planned_joints; put_pose s 2 r.planned_pose);
  opt (fun on -> put_state b 4 (if on then 1 else 2)) r.motor_on;
  opt (fun run -> put_state b 5 (if run then 3 else 2)) r.mci_running;
  opt (fun c -> put_int b 6 (if c then 1 else 0)) r.convergence_met;
  opt (fun run -> put_state b 8 (if run then 2 else 1)) r.rapid_running;
  opt (put_double b 10) r.utilization;
  Buffer.contents b

let encode_sensor m =
  let b = Buffer.create 128 in
  put_header b m.s_header;
  if m.set_joints <> None || m.set_pose <> None || m.set_external <> None then
    put_sub b 2 (fun s -> put_joints s 1 m.set_joints; put_pose s 2 m.set_pose; put_joints s 3 m.set_external);
  if m.speed_joints <> None then put_sub b 3 (fun s -> put_joints s 1 m.speed_joints);
  Buffer.contents b
