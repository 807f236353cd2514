external idle : unit -> bool = "rapid_sem_gc_idle"
external forget_pace : unit -> unit = "rapid_sem_gc_forget_pace"

(* a minor collection, then a slice that begins the cycle: its marking phase *)
let begin_cycle () =
  if idle () then begin
    forget_pace ();
    ignore (Gc.major_slice 1)
  end
