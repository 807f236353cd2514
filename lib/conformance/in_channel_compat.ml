(* Reading a file's lines as bytes, whatever their encoding; OCaml 4.13 has no In_channel. *)
let read_lines path =
  match open_in_bin path with
  | exception Sys_error m -> Error m
  | ic ->
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
          let rec loop acc =
            match input_line ic with
            | line -> loop (line :: acc)
            | exception End_of_file -> Ok (List.rev acc)
            | exception Sys_error m -> Error m
          in
          loop [])
