module P = Primitive
module V = Value
module W = Rapid_controller.World

let names = [ "assertequal"; "assertequalstr"; "asserttrue"; "assertfalse"; "assertequalpose"; "assertequaltarget";
              "asserterrno"; "assertsignal"; "assertattarget"; "assertfail" ]

let modelled name = List.mem (String.lowercase_ascii name) names

(* The value an argument holds, given by value or by reference. *)
let value ctx args name =
  match P.named_argument ctx args name with
  | Value v -> Some v
  | Location (box, i, _) -> Some box.(i)
  | Switch | Missing -> None

let text v = match Text_format.value_text v with s -> s | exception V.Type_mismatch _ -> "<a handle>"

let num = Text_format.num_text

(* The failure's message: the programmer's \Msg first, then the routine and what it found; one
   line, its control characters shown as the FlexPendant shows them (\0A). *)
let failed ctx args routine detail =
  let detail = routine ^ ": " ^ detail in
  match value ctx args "Msg" with
  | Some (V.String m) -> P.Assertion_failed (Text_format.display m ^ ": " ^ detail)
  | _ -> P.Assertion_failed detail

let passed = P.Returned None

let within ~tol expected actual = Float.abs (expected -. actual) <= tol

(* The error names of the installed environment by number, for AssertErrno's message: kernel.sys
   declares each as CONST errnum NAME := number. *)
let error_names =
  lazy
    (match Rapid_typing.Installed_env.modules () with
     | Error _ -> []
     | Ok modules ->
         List.concat_map (fun (m : Rapid_syntax.Ast.module_declaration) ->
             List.filter_map (fun (d : Rapid_syntax.Ast.data_declaration) ->
                 match d.it with
                 | Data_declaration { storage = Const; data_type = { it = Ident t; _ }; name = { it = Ident n; _ };
                                      initial_value = Some { it = Num_literal s; _ }; _ }
                   when String.lowercase_ascii t = "errnum" ->
                     Option.map (fun f -> (f, n)) (float_of_string_opt s)
                 | _ -> None) m.data_declarations) modules)

let error_text ctx n =
  let named = match List.assoc_opt n (Lazy.force error_names) with
    | Some name -> Some name
    | None -> if float_of_int (ctx.P.error_number "ERR_ASSERT") = n then Some "ERR_ASSERT" else None in
  match named with Some name -> name | None -> "error " ^ num n

(* A pose's position and orientation as numbers: trans [x,y,z], rot [q1,q2,q3,q4]. *)
let frame v =
  let floats v = Array.map V.num_value (V.components v) in
  match V.components v with
  | [| trans; rot |] | [| trans; rot; _; _ |] -> Some (floats trans, floats rot)
  | _ -> None

let distance a b = sqrt (Array.fold_left ( +. ) 0. (Array.mapi (fun i x -> (x -. b.(i)) ** 2.) a))

(* The angle between two orientations in degrees: q and -q are the same orientation, so the
   absolute value of the quaternions' dot product (normalised) gives half the angle. *)
let angle q r =
  let dot a b = Array.fold_left ( +. ) 0. (Array.mapi (fun i x -> x *. b.(i)) a) in
  let n = sqrt (dot q q *. dot r r) in
  if n = 0. then 180. else 2. *. acos (Float.min 1. (Float.abs (dot q r) /. n)) *. 180. /. Float.pi

let vector a = "[" ^ String.concat "," (Array.to_list (Array.map num a)) ^ "]"

let compare_frames ctx args routine ~tol ~rot_tol expected actual =
  match frame expected, frame actual with
  | Some (p, q), Some (p', q') ->
      let d = distance p p' and a = angle q q' in
      if d <= tol && a <= rot_tol then passed
      else
        failed ctx args routine
          (Printf.sprintf "expected %s %s, actual %s %s (%s mm and %s degrees apart; tolerance %s mm, %s degrees)"
             (vector p) (vector q) (vector p') (vector q') (num d) (num a) (num tol) (num rot_tol))
  | _ -> P.Failed "ERR_ARGVALERR"

let call ctx motion name args =
  let given p = P.named_num ctx args p in
  let tol default = Option.value (given "Tol") ~default in
  let rot_tol default = Option.value (given "RotTol") ~default in
  let negative p = match given p with Some t -> not (t >= 0.) | None -> false in
  let routine = name in
  (* A tolerance is a distance or an angle: a negative one (or NaN) is an argument error. *)
  if negative "Tol" || negative "RotTol" then Some (P.Failed "ERR_ARGVALERR")
  else
    match String.lowercase_ascii name with
    | "assertequal" -> (
        match P.named_num ctx args "Expected", P.named_num ctx args "Actual" with
        | Some e, Some a ->
            let tol = tol 0. in
            Some (if within ~tol e a then passed
                  else if tol = 0. then
                    failed ctx args routine (Printf.sprintf "expected %s, actual %s" (num e) (num a))
                  else failed ctx args routine
                      (Printf.sprintf "expected %s, actual %s (tolerance %s)" (num e) (num a) (num tol)))
        | _ -> Some (P.Failed "ERR_ARGVALERR"))
    | "assertequalstr" -> (
        match value ctx args "Expected", value ctx args "Actual" with
        | Some (V.String e as ev), Some (V.String a as av) ->
            Some (if e = a then passed else failed ctx args routine
                      (Printf.sprintf "expected %s, actual %s" (text ev) (text av)))
        | _ -> Some (P.Failed "ERR_ARGVALERR"))
    | ("asserttrue" | "assertfalse") as n -> (
        let want = n = "asserttrue" in
        match value ctx args "Condition" with
        | Some (V.Bool b) ->
            let word b = if b then "TRUE" else "FALSE" in
            Some (if b = want then passed
                  else failed ctx args routine (Printf.sprintf "expected %s, actual %s" (word want) (word b)))
        | _ -> Some (P.Failed "ERR_ARGVALERR"))
    | "assertequalpose" | "assertequaltarget" -> (
        match value ctx args "Expected", value ctx args "Actual" with
        | Some e, Some a -> Some (compare_frames ctx args routine ~tol:(tol 0.001) ~rot_tol:(rot_tol 0.01) e a)
        | _ -> Some (P.Failed "ERR_ARGVALERR"))
    | "asserterrno" -> (
        match P.named_num ctx args "Expected", P.named_num ctx args "Actual" with
        | Some e, Some a ->
            Some (if e = a then passed
                  else failed ctx args routine
                      (Printf.sprintf "expected %s, actual %s" (error_text ctx e) (error_text ctx a)))
        | _ -> Some (P.Failed "ERR_ARGVALERR"))
    | "assertsignal" -> (
        match Io_routines.signal ctx args "Signal", P.named_num ctx args "Expected" with
        | Ok id, Some e ->
            let a = W.read ctx.world id in
            let tol = tol 0. in
            Some (if within ~tol e a then passed
                  else failed ctx args routine
                      (Printf.sprintf "expected %s = %s, actual %s" (W.signal_name ctx.world id) (num e) (num a)))
        | Error err, _ -> Some (P.Failed err)
        | _, None -> Some (P.Failed "ERR_ARGVALERR"))
    | "assertattarget" -> (
        match value ctx args "Target" with
        | None -> Some (P.Failed "ERR_ARGVALERR")
        | Some target ->
            (* Where the robot is, as CRobT reads it with the same \Tool and \WObj. *)
            let parameters = ctx.parameters in
            let given = P.named_argument ctx args in
            let crobt_args = [| P.Missing; P.Missing; given "Tool"; given "WObj" |] in
            ctx.parameters <- [| "TaskRef"; "TaskName"; "Tool"; "WObj" |];
            let now = Motion_routines.call ctx motion "CRobT" crobt_args in
            ctx.parameters <- parameters;
            match now with
            | Some (P.Returned (Some actual), _) ->
                Some (compare_frames ctx args routine ~tol:(tol 0.1) ~rot_tol:(rot_tol 0.1) target actual)
            | Some (other, _) -> Some other
            | None -> Some P.Not_modelled)
    | "assertfail" -> (
        match value ctx args "Msg" with
        | Some (V.String m) -> Some (P.Assertion_failed ("AssertFail: " ^ Text_format.display m))
        | _ -> Some (P.Failed "ERR_ARGVALERR"))
    | _ -> None
