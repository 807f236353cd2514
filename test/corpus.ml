(* The RAPID files of a folder tree that the tests read (spec/, examples/), in a stable order. *)

let rec files ~extensions dir =
  match Sys.readdir dir with
  | exception Sys_error _ -> []
  | entries ->
      Array.sort compare entries;
      List.concat_map (fun e ->
          let path = Filename.concat dir e in
          if Sys.is_directory path then files ~extensions path
          else if List.exists (Filename.check_suffix (String.lowercase_ascii e)) extensions then [ path ]
          else []) (Array.to_list entries)
