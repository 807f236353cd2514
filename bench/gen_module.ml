(* Writes one generated CAD-style module: gen_module.exe [--seed N] [--size BYTES] -o FILE *)

let () =
  let seed = ref 1 and size = ref 1_048_576 and output = ref "" in
  Arg.parse
    [ ("--seed", Arg.Set_int seed, "N  seed of the generator (default 1)");
      ("--size", Arg.Set_int size,
       "BYTES  size to reach before the module is closed (default 1 MiB)");
      ("-o", Arg.Set_string output, "FILE  where to write the module (default: standard output)") ]
    (fun a -> raise (Arg.Bad ("unexpected argument " ^ a)))
    "gen_module.exe [--seed N] [--size BYTES] [-o FILE]";
  let text = Gen.generate ~seed:!seed ~size:!size in
  if !output = "" then print_string text
  else begin
    let oc = open_out_bin !output in
    output_string oc text;
    close_out oc
  end
