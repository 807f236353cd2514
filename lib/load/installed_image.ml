open Rapid_syntax

let data = Installed_image_data.image
let trees = Installed_image_data.trees

(* At initialisation, before anything parses: the image's regions name its files by their ids,
   and its record types have their ids, so both are taken before any other file or record type. *)
let usable =
  Source.registered () = Installed_image_data.files_before
  && Rapid_typing.Types.record_ids_used () = Installed_image_data.records_before

(* The environment as blocks in the executable's data (installed_image_stubs.c): the same value
   [Marshal.from_string data 0] would make, with nothing to read or allocate. *)
external in_data_block : unit -> Obj.t = "rapid_sem_installed_image"

let in_data () : Installed_level.t = Obj.obj (in_data_block ())

let () =
  if usable then begin
    Gc_pacing.begin_cycle ();
    Source.restore_registry (Marshal.from_string Installed_image_data.files 0);
    Rapid_typing.Types.restore_record_ids Installed_image_data.record_ids;
    Rapid_typing.Installed_env.set_image
      ~level:(fun () ->
          let t = in_data () in
          Installed_level.install t;
          Installed_level.level t)
      ~trees:(fun () -> Marshal.from_string Installed_image_data.trees 0)
  end

let in_use () = usable
