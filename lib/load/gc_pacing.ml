external idle : unit -> bool = "rapid_sem_gc_idle"
external forget_pace : unit -> unit = "rapid_sem_gc_forget_pace"
external owe_marking : unit -> unit = "rapid_sem_gc_owe_marking"

let read_marked f =
  if not (idle ()) then f ()
  else begin
    forget_pace ();
    (* a minor collection, then a slice that begins the cycle: its marking phase *)
    ignore (Gc.major_slice 1);
    let v = f () in
    owe_marking ();
    v
  end
