(* Golden tests of the command line (Catala's practice): each test/golden/NAME.cmd holds the
   arguments of one rapid-sem run, NAME.out what it must print and its exit status, byte for byte.
   scripts/promote-golden.sh rewrites the .out files after a deliberate change. *)

let golden_dir = "golden"
let binary = Filename.concat (Sys.getcwd ()) "../bin/main.exe"

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      really_input_string ic (in_channel_length ic))

(* Runs rapid-sem with [args] in [golden_dir]; the transcript is what NAME.out holds. *)
let transcript args =
  let out = Filename.temp_file "rapid-sem" ".out" and err = Filename.temp_file "rapid-sem" ".err" in
  let command =
    Printf.sprintf "cd %s && %s %s > %s 2> %s" (Filename.quote golden_dir) (Filename.quote binary)
      args (Filename.quote out) (Filename.quote err)
  in
  let status = Sys.command command in
  let text = Printf.sprintf "$ rapid-sem %s\n--- stdout\n%s--- stderr\n%s--- exit %d\n" args
      (read_file out) (read_file err) status in
  Sys.remove out; Sys.remove err;
  text

let cases () =
  Sys.readdir golden_dir |> Array.to_list
  |> List.filter (fun f -> Filename.check_suffix f ".cmd")
  |> List.sort compare
  |> List.map Filename.chop_extension

let case name =
  Alcotest.test_case name `Quick (fun () ->
      let args = String.trim (read_file (Filename.concat golden_dir (name ^ ".cmd"))) in
      let expected = read_file (Filename.concat golden_dir (name ^ ".out")) in
      Alcotest.(check string) (name ^ ".out") expected (transcript args))

let suite = ("cli", List.map case (cases ()))
