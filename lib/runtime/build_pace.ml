let space_overhead = 1000

let building f =
  let before = (Gc.get ()).space_overhead in
  if before >= space_overhead then f ()
  else begin
    Gc.set { (Gc.get ()) with space_overhead };
    Fun.protect ~finally:(fun () -> Gc.set { (Gc.get ()) with space_overhead = before }) f
  end
