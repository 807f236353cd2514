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

(* The major heap used to begin with the image's blocks, 1 MB, read at start-up; it now begins
   with almost nothing, and grew by 15 % at a time: a run then went through more, smaller major
   cycles (10,000 moves 4.6 % more instructions, a recursion 9,000 deep 2.2 %). Steps of 8 MB
   bring both below what they were with the image in the heap (bench/README.md, "Start-up: the
   image in the executable's data"). *)
let heap_increment = 1_048_576

let () =
  if usable then begin
    Gc_pacing.begin_cycle ();
    if (Gc.get ()).major_heap_increment = 15 then Gc.set { (Gc.get ()) with major_heap_increment = heap_increment };
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
