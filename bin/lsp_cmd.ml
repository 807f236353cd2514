(* rapid-sem lsp: the language server (doc/editor.md), over standard input and output. *)

open Cmdliner

let cmd =
  let allow_unknown =
    Arg.(value & flag & info [ "allow-unknown" ]
           ~doc:"Report a name that is neither declared nor installed as a warning, as $(b,check --allow-unknown).")
  in
  let run allow_unknown io =
    Cli.guard @@ fun () ->
    match Rapid_run.Run_setup.read_io io with
    | Error m -> prerr_endline m; Cli.exit_static_error
    | Ok io -> Rapid_lsp.Lsp_server.run { allow_unknown; io } stdin stdout
  in
  let doc = "the language server: diagnostics, hover, definition, references, symbols, completion, rename" in
  let man = [
    `S Manpage.s_description;
    `P "Serves the Language Server Protocol 3.17 on standard input and output for an editor \
        (doc/editor.md has the set-ups of Neovim, VS Code and Emacs). The diagnostics are those of \
        $(b,rapid-sem check) on the task of each open module: the modules of its folder, or of a \
        backup's RAPID/TASKn folder.";
    `S Manpage.s_exit_status;
    `P "0 after the client's shutdown and exit; 1 at an exit without shutdown or the end of input.";
  ] in
  Cmd.v (Cmd.info "lsp" ~doc ~man) Term.(const run $ allow_unknown $ Run_args.io_arg)
