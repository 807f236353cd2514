(** The installed environment as rapid-sem's build computed it (lib/load/gen): linking this
    module makes {!Rapid_typing.Installed_env.modules} take the installed modules from it, and
    the first task's check and lowering start from its state, instead of parsing, checking and
    lowering the installed modules at every start. *)

val in_use : unit -> bool
(** Whether the image is what the installed environment comes from: it is, unless other source
    files were registered or record types made before this module was initialised (the image's ids
    would collide with theirs), and then the environment is computed as before. *)

val data : string
(** The marshalled {!Rapid_runtime.Installed_level.t}, for the test that compares it with the
    environment computed now. *)

val in_data : unit -> Rapid_runtime.Installed_level.t
(** The same environment as blocks in the executable's data, which start-up takes: what
    [Marshal.from_string data 0] would make, without reading or allocating (bench/README.md,
    "Start-up: the image in the executable's data"). The same value at every call. *)

val trees : string
(** The marshalled installed modules with their declarations, read only where a run needs them
    (Rapid_typing.Installed_env.modules). *)
