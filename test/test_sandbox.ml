(* The sandbox of the mass memory under attack (doc/services.md, "Files, in a sandbox"): links
   that lead out, whether or not their targets exist; files that would block the host (FIFOs,
   sockets); the quota of all files written in a run. *)

module FS = Rapid_controller.File_sandbox
module S = Rapid_controller.Services

let temp_dir = Test_services.temp_dir
let write_file = Test_services.write_file
let remove_tree d = ignore (Sys.command ("rm -rf " ^ Filename.quote d))

(* A module whose [main] tries each statement in turn and prints the error it raised. *)
let attempts statements =
  let cases = List.mapi (fun i s -> Printf.sprintf "    CASE %d:\n      %s\n" (i + 1) s) statements in
  Printf.sprintf
    "MODULE t\n  VAR iodev f;\n  VAR dir d;\n  PROC main()\n    FOR i FROM 1 TO %d DO\n      Try i;\n    ENDFOR\n\
    \  ENDPROC\n  PROC Try(num what)\n    TEST what\n%s    ENDTEST\n    Close f;\n\
    \    TPWrite ValToStr(what) + \" ok\";\n  ERROR\n    Close f;\n\
    \    IF ERRNO = ERR_FILEOPEN TPWrite ValToStr(what) + \" ERR_FILEOPEN\";\n\
    \    IF ERRNO = ERR_FILEACC TPWrite ValToStr(what) + \" ERR_FILEACC\";\n\
    \    IF ERRNO = ERR_FILEEXIST TPWrite ValToStr(what) + \" ERR_FILEEXIST\";\n    RETURN;\n  ENDPROC\nENDMODULE\n"
    (List.length statements) (String.concat "" cases)

let numbered outcomes = List.mapi (fun i o -> Printf.sprintf "%d %s" (i + 1) o) outcomes

(* Links whose targets are outside and do not exist yet (absolute, relative, through a chain of
   links inside, under a folder link) create nothing outside; links that stay inside still
   work, dangling or not. *)
let dangling_links () =
  let outside = temp_dir () in
  let sandbox = FS.temporary () in
  Fun.protect ~finally:(fun () -> FS.remove sandbox; remove_tree outside) (fun () ->
      ignore (FS.resolve sandbox "HOME:/");
      let root = FS.root sandbox in
      let home = Filename.concat root "HOME" in
      let out name = Filename.concat outside name in
      write_file (Filename.concat home "a.txt") "a\n";
      Unix.symlink (out "new.txt") (Filename.concat home "dl");
      (* From HOME, ../.. is the folder that holds the sandbox's root. *)
      Unix.symlink (Filename.concat "../.." (Filename.basename root ^ "-escaped.txt")) (Filename.concat home "rel");
      Unix.symlink "c2" (Filename.concat home "c1");
      Unix.symlink (out "chain.txt") (Filename.concat home "c2");
      Unix.symlink (out "sub") (Filename.concat home "dd");
      Unix.symlink outside (Filename.concat home "od");
      Unix.mkdir (Filename.concat home "real") 0o755;
      Unix.symlink "real" (Filename.concat home "in");
      Unix.symlink "real/made.txt" (Filename.concat home "inl");
      let statements = [
        "Open \"HOME:/dl\", f \\Write;"; "Open \"HOME:/dl\", f \\Append;"; "Open \"HOME:/dl\", f \\Write \\Bin;";
        "Open \"HOME:/rel\", f \\Write;"; "Open \"HOME:/c1\", f \\Append;"; "Open \"HOME:/dd/x.txt\", f \\Write;";
        "Open \"HOME:/od/new.txt\", f \\Write;"; "CopyFile \"HOME:/a.txt\", \"HOME:/dl\";";
        "CopyFile \"HOME:/a.txt\", \"HOME:/c1\";"; "MakeDir \"HOME:/dd\";"; "MakeDir \"HOME:/od/sub\";";
        "RenameFile \"HOME:/a.txt\", \"HOME:/rel\";"; "RemoveFile \"HOME:/dl\";"; "OpenDir d, \"HOME:/dd\";";
        "Open \"HOME:/in/f.txt\", f \\Write;"; "Open \"HOME:/inl\", f \\Write;";
        "CopyFile \"HOME:/a.txt\", \"HOME:/in/b.txt\";";
      ] in
      let out_lines = Test_services.run_with (S.create ~sandbox ()) (attempts statements) in
      Alcotest.(check (list string)) "outcomes"
        (numbered [ "ERR_FILEOPEN"; "ERR_FILEOPEN"; "ERR_FILEOPEN"; "ERR_FILEOPEN"; "ERR_FILEOPEN"; "ERR_FILEOPEN";
                    "ERR_FILEOPEN"; "ERR_FILEACC"; "ERR_FILEACC"; "ERR_FILEACC"; "ERR_FILEACC"; "ERR_FILEACC";
                    "ERR_FILEACC"; "ERR_FILEACC"; "ok"; "ok"; "ok" ])
        out_lines;
      Alcotest.(check (list string)) "nothing made outside" [] (Array.to_list (Sys.readdir outside));
      Alcotest.(check bool) "nothing beside the root" false
        (Sys.file_exists (Filename.concat (Filename.dirname root) (Filename.basename root ^ "-escaped.txt")));
      Alcotest.(check bool) "a.txt kept" true (Sys.file_exists (Filename.concat home "a.txt"));
      List.iter (fun f -> Alcotest.(check bool) f true (Sys.file_exists (Filename.concat home f)))
        [ "real/f.txt"; "real/made.txt"; "real/b.txt" ];
      List.iter (fun p -> Alcotest.(check bool) p true (Result.is_error (FS.resolve sandbox p)))
        [ "HOME:/dl"; "HOME:/rel"; "HOME:/c1"; "HOME:/dd/x"; "HOME:/od" ])

(* A link put in the way after the path was checked (the race of a host process against the
   run): the operations reach the location from the root without following any link, so they
   fail and make nothing outside. *)
let link_after_check () =
  let outside = temp_dir () in
  let sandbox = FS.temporary () in
  Fun.protect ~finally:(fun () -> FS.remove sandbox; remove_tree outside) (fun () ->
      let located p = match FS.locate sandbox p with Ok l -> l | Error e -> Alcotest.fail e in
      let home = Filename.concat (FS.root sandbox) "HOME" in
      ignore (located "HOME:");
      Unix.mkdir (Filename.concat home "d") 0o755;
      let in_folder = located "HOME:/d/f.txt" and last = located "HOME:/x.txt" and folder = located "HOME:/d/e" in
      let listing = located "HOME:/d" in
      Unix.rmdir (Filename.concat home "d");
      Unix.symlink outside (Filename.concat home "d");
      Unix.symlink (Filename.concat outside "x.txt") (Filename.concat home "x.txt");
      let failed what r = Alcotest.(check bool) what true (Result.is_error r) in
      failed "a folder on the way" (FS.open_file sandbox in_folder Rapid_controller.Sandbox_calls.Write);
      failed "the last component" (FS.open_file sandbox last Rapid_controller.Sandbox_calls.Append);
      failed "a new file" (FS.open_file sandbox last Rapid_controller.Sandbox_calls.Create_new);
      failed "a folder" (FS.make_folder sandbox folder);
      failed "a listing" (FS.read_folder sandbox listing);
      Alcotest.(check bool) "the link's kind, not its target's" true
        (match FS.kind sandbox last with Some (Unix.S_LNK, _) -> true | _ -> false);
      Alcotest.(check (list string)) "nothing made outside" [] (Array.to_list (Sys.readdir outside)))

(* Runs the binary on a module with these arguments, at most 20 s; its exit status and output. *)
let run_binary args text =
  let dir = temp_dir () in
  Fun.protect ~finally:(fun () -> remove_tree dir) (fun () ->
      let file = Filename.concat dir "t.mod" and output = Filename.concat dir "out.txt" in
      write_file file text;
      let out = Unix.openfile output [ Unix.O_WRONLY; Unix.O_CREAT ] 0o644 in
      let devnull = Unix.openfile "/dev/null" [ Unix.O_RDWR ] 0 in
      let binary = Test_services.binary in
      let pid = Unix.create_process binary (Array.of_list ((binary :: "run" :: args) @ [ file ])) devnull out devnull in
      Unix.close devnull; Unix.close out;
      let status = match Test_services.wait_bounded pid 20. with
        | Some (Unix.WEXITED n) -> n | Some _ -> -1 | None -> Alcotest.fail "the run blocked: killed after 20 s" in
      (status, String.split_on_char '\n' (String.trim (Test_services.read_file output))))

(* A FIFO, a socket or a device opened as a file would block the host or reach what is not a
   file: refused at once with ERR_FILEOPEN (Open) or ERR_FILEACC (the other routines). *)
let special_files () =
  let root = temp_dir () in
  Fun.protect ~finally:(fun () -> remove_tree root) (fun () ->
      let home = Filename.concat root "HOME" in
      Unix.mkdir home 0o755;
      Unix.mkfifo (Filename.concat home "p") 0o644;
      let s = Unix.socket Unix.PF_UNIX Unix.SOCK_STREAM 0 in
      Fun.protect ~finally:(fun () -> Unix.close s) (fun () ->
          Unix.bind s (Unix.ADDR_UNIX (Filename.concat home "s"));
          Unix.symlink "/dev/zero" (Filename.concat home "zero");
          let statements = [
            "Open \"HOME:/p\", f \\Read;"; "Open \"HOME:/p\", f \\Write;"; "Open \"HOME:/p\", f \\Append \\Bin;";
            "Open \"HOME:/s\", f \\Read;"; "CopyFile \"HOME:/p\", \"HOME:/c.txt\";"; "TextTabInstall \"HOME:/p\";";
            "Open \"HOME:/zero\", f \\Read;";
          ] in
          let status, lines = run_binary [ "--fs"; root ] (attempts statements) in
          Alcotest.(check int) "exit status" 0 status;
          Alcotest.(check (list string)) "outcomes"
            (numbered [ "ERR_FILEOPEN"; "ERR_FILEOPEN"; "ERR_FILEOPEN"; "ERR_FILEOPEN"; "ERR_FILEACC"; "ERR_FILEACC";
                        "ERR_FILEOPEN" ])
            lines))

(* All files written in a run share a quota (256 MiB by default, --fs-quota): a write beyond
   it raises ERR_FILEACC, as a full mass memory does (R-13-sandbox1). *)
let quota () =
  let sandbox = FS.temporary () in
  Fun.protect ~finally:(fun () -> FS.remove sandbox) (fun () ->
      let statements = [
        "Open \"HOME:/a.txt\", f \\Write; Write f, \"123456789\";";
        "Open \"TEMP:/b.txt\", f \\Write; Write f, \"12345\";";
        "Open \"TEMP:/c.txt\", f \\Write; Write f, \"1234\";"; "CopyFile \"HOME:/a.txt\", \"HOME:/d.txt\";";
        "Open \"TEMP:/e.txt\", f \\Write; WriteStrBin f, \"xxxxx\";";
      ] in
      let out = Test_services.run_with (S.create ~sandbox ~max_total_size:20 ()) (attempts statements) in
      Alcotest.(check (list string)) "outcomes"
        (numbered [ "ok"; "ok"; "ERR_FILEACC"; "ERR_FILEACC"; "ERR_FILEACC" ]) out;
      Alcotest.(check int) "c.txt empty" 0 (Unix.stat (Filename.concat (FS.root sandbox) "TEMP/c.txt")).Unix.st_size;
      Alcotest.(check bool) "d.txt not made" false (Sys.file_exists (Filename.concat (FS.root sandbox) "HOME/d.txt")));
  Alcotest.(check int) "the default" (256 * 1024 * 1024) S.max_total_size;
  let root = temp_dir () in
  Fun.protect ~finally:(fun () -> remove_tree root) (fun () ->
      let status, lines = run_binary [ "--fs"; root; "--fs-quota"; "5" ]
          (attempts [ "Open \"HOME:/a.txt\", f \\Write; Write f, \"1234\";";
                      "Open \"HOME:/b.txt\", f \\Write; Write f, \"1\";" ]) in
      Alcotest.(check int) "exit status" 0 status;
      Alcotest.(check (list string)) "--fs-quota 5" (numbered [ "ok"; "ERR_FILEACC" ]) lines)

let suite = ("sandbox", [
    Alcotest.test_case "links out of the sandbox, dangling or not" `Quick dangling_links;
    Alcotest.test_case "a link put in the way after the check" `Quick link_after_check;
    Alcotest.test_case "FIFOs, sockets and devices refused at once" `Quick special_files;
    Alcotest.test_case "the quota of a run's files" `Quick quota;
  ])
