(** Source files and regions.

    A region is packed into one immediate integer (file, first character, length) so that every
    node of the syntax tree can carry one at the cost of a single word: CAD-generated modules hold
    millions of literals, and a boxed region per node would dominate the memory a parse takes.
    Positions count characters (Unicode code points after decoding), not bytes. *)

type file
(** A loaded source file: its name and where its lines start. *)

type pos = { line : int; col : int }
(** 1-based line and column. *)

type region
(** A stretch of one file, from its first character up to (not including) its [stop]. *)

module Table : Hashtbl.S with type key = region
(** Tables keyed by region (the elaboration's, the lowering's): the same operations as
    [Hashtbl]'s, with an integer's hash and equality. *)


val register : name:string -> line_starts:int array -> file
(** [register ~name ~line_starts] records a file whose line [i+1] starts at character offset
    [line_starts.(i)]; [line_starts.(0)] is [0]. Ids are reused after 1023 files (927 while
    {!keep} has kept none, so that up to 32 files registered just before it are kept), except
    those {!keep} protects. *)

val keep : unit -> unit
(** The files registered so far keep their ids for the life of the process: files parsed once
    and used by every later check (the installed modules), whose regions must never equal those
    of a file registered later. *)

val name : file -> string

type registry
(** The files registered so far, their ids and which are kept. *)

val registry : unit -> registry

val registered : unit -> int
(** How many files were registered (ids given). *)

val registered_in : registry -> int
(** How many files were registered when {!registry} made it. *)

val restore_registry : registry -> unit
(** Makes the table of files what {!registry} saw: for the installed environment computed when
    rapid-sem was built (lib/load/installed_image.ml), whose regions name those files' ids;
    restored before any other file is registered. *)

val no_region : region
(** The region of a node that was not read from a file (generated trees). *)

val region : file -> int -> int -> region
(** [region f start stop] covers characters [start] to [stop - 1] of [f]. Offsets beyond what
    a region can hold are clamped. *)

val file_of : region -> file option
val start_offset : region -> int
val stop_offset : region -> int
val start : region -> pos
val stop : region -> pos
val span : region -> region -> region
(** [span a b] runs from the start of [a] to the end of [b] (same file). *)

val pos_of_offset : file -> int -> pos

val to_string : region -> string
(** [FILE:LINE:COL] of the region's start, the form every diagnostic begins with. *)

val to_range_string : region -> string
(** [FILE:LINE:COL-LINE:COL]. *)
