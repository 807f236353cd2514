open Cmdliner

type t = { fs : string option; quota : int option; net : string list; map : string list }

let term =
  let fs = Arg.(value & opt (some string) None & info [ "fs" ] ~docv:"ROOT"
                  ~doc:"The folder that holds the controller's mass memory: HOME:, TEMP:, RAMDISK: and \
                        REMOVABLE: are folders under it, and no RAPID path reaches outside it (default \
                        .rapid-sem/fs under the current folder, made when a program first uses a file).") in
  let quota = Arg.(value & opt (some int) None & info [ "fs-quota" ] ~docv:"BYTES"
                     ~doc:"The bytes a run may write into the files of --fs in all (default 256 MiB, \
                           268435456); a write beyond raises ERR_FILEACC, as a full mass memory does.") in
  let net = Arg.(value & opt_all string [] & info [ "net" ] ~docv:"HOST:PORT,..."
                   ~doc:"Addresses beyond the loopback that sockets may bind or connect to (PORT * for any port). \
                         Without it only 127.0.0.0/8 is reachable.") in
  let map = Arg.(value & opt_all string [] & info [ "map-address" ] ~docv:"FROM=TO,..."
                   ~doc:"Read the RAPID address FROM as TO, e.g. 192.168.125.1=127.0.0.1 (the controller's \
                         service port on the loopback), before the --net check.") in
  Term.(const (fun fs quota net map -> { fs; quota; net; map }) $ fs $ quota $ net $ map)

let install t world =
  let module K = Rapid_controller.Sockets in
  let all parse items = List.fold_left (fun acc s -> match acc, parse s with
      | Ok l, Ok x -> Ok (l @ x) | (Error _ as e), _ -> e | _, Error e -> Error e) (Ok []) items in
  match all K.parse_allowed t.net, all K.parse_mapping t.map with
  | Error e, _ -> Error ("--net " ^ e)
  | _, Error e -> Error ("--map-address " ^ e)
  | _ when Option.fold ~none:false ~some:(fun q -> q < 0) t.quota -> Error "--fs-quota: a number of bytes, 0 or more"
  | Ok allowed, Ok mapping ->
      let root = Option.value t.fs ~default:Rapid_controller.File_sandbox.default_root in
      Rapid_controller.World.set_services world
        (Rapid_controller.Services.create ~sandbox:(Rapid_controller.File_sandbox.create root)
           ?max_total_size:t.quota ~sockets:(K.create ~allowed ~mapping ()) ());
      Ok ()
