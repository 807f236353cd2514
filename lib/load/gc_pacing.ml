external idle : unit -> bool = "rapid_sem_gc_idle"
external marking : unit -> bool = "rapid_sem_gc_marking"
external forget_pace : unit -> unit = "rapid_sem_gc_forget_pace"
external owe_marking : unit -> unit = "rapid_sem_gc_owe_marking"

(* a minor collection, then a slice that begins the cycle: its marking phase *)
let begin_cycle () =
  if idle () then begin
    forget_pace ();
    ignore (Gc.major_slice 1)
  end

let read_marked f =
  if idle () then begin_cycle ();
  if not (marking ()) then f ()
  else begin
    forget_pace ();
    let v = f () in
    owe_marking ();
    v
  end
