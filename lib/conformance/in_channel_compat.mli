val read_lines : string -> (string list, string) result
(** The lines of a file, split at LF; a CR before an LF stays at the end of its line. *)
