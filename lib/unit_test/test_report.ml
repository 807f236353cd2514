module T = Test_suite

let seconds t = Printf.sprintf "%.3f s" t

let location (r : T.result) = match r.verdict with
  | Passed -> None
  | Failed { at; message } -> Some ((match at with Some a -> a ^ ": " | None -> r.test.file ^ ": ") ^ message)

let line (r : T.result) =
  let word = match r.verdict with Passed -> "PASS" | Failed _ -> "FAIL" in
  let head = Printf.sprintf "%s %-40s %s" word r.test.name (seconds r.time) in
  match location r with
  | None -> [ head ]
  | Some l -> head :: ("  " ^ l) :: List.map (fun o -> "  | " ^ o) r.output

let failed rs = List.length (List.filter (fun (r : T.result) -> r.verdict <> Passed) rs)

let total_time rs = List.fold_left (fun a (r : T.result) -> a +. r.time) 0. rs

let summary rs =
  let f = failed rs in
  let n = List.length rs in
  Printf.sprintf "%d passed, %d failed (%d test%s, %s virtual)" (n - f) f n (if n = 1 then "" else "s")
    (seconds (total_time rs))

let junit rs =
  let x = Xml_text.escape in
  let b = Buffer.create 4096 in
  let modules = List.fold_left (fun acc (r : T.result) ->
      if List.mem r.test.module_name acc then acc else acc @ [ r.test.module_name ]) [] rs in
  Buffer.add_string b "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  Printf.bprintf b "<testsuites name=\"rapid-sem test\" tests=\"%d\" failures=\"%d\" errors=\"0\" time=\"%.3f\">\n"
    (List.length rs) (failed rs) (total_time rs);
  List.iter (fun m ->
      let mine = List.filter (fun (r : T.result) -> r.test.module_name = m) rs in
      Printf.bprintf b
        "  <testsuite name=\"%s\" tests=\"%d\" failures=\"%d\" errors=\"0\" skipped=\"0\" time=\"%.3f\">\n"
        (x m) (List.length mine) (failed mine) (total_time mine);
      List.iter (fun (r : T.result) ->
          Printf.bprintf b "    <testcase classname=\"%s\" name=\"%s\" file=\"%s\" line=\"%d\" time=\"%.3f\""
            (x m) (x r.test.name) (x r.test.file) r.test.line r.time;
          let out () =
            if r.output <> [] then
              Printf.bprintf b "      <system-out>%s</system-out>\n" (x (String.concat "\n" r.output ^ "\n")) in
          match r.verdict, location r with
          | Failed { message; _ }, Some l ->
              Printf.bprintf b ">\n      <failure message=\"%s\" type=\"failure\">%s</failure>\n" (x message) (x l);
              out ();
              Buffer.add_string b "    </testcase>\n"
          | _ when r.output <> [] -> Buffer.add_string b ">\n"; out (); Buffer.add_string b "    </testcase>\n"
          | _ -> Buffer.add_string b "/>\n") mine;
      Buffer.add_string b "  </testsuite>\n") modules;
  Buffer.add_string b "</testsuites>\n";
  Buffer.contents b
