open Geom

type speeddata = { v_tcp : float; v_ori : float; v_leax : float; v_reax : float }
type zonedata = {
  finep : bool; pzone_tcp : float; pzone_ori : float; pzone_eax : float;
  zone_ori : float; zone_leax : float; zone_reax : float;
}
type stop_type = Inpos | Stoptime | Fllwtime
type stoppointdata = {
  stop_type : stop_type; progsynch : bool;
  inpos_position : float; inpos_speed : float; inpos_mintime : float; inpos_maxtime : float;
  stoptime : float; followtime : float;
}
type tooldata = { tool_robhold : bool; tframe : pose; tool_mass : float }
type wobjdata = { wobj_robhold : bool; ufprog : bool; ufmec : string; uframe : pose; oframe : pose }
type loaddata = { mass : float; cog : pos; aom : orient; ix : float; iy : float; iz : float }

let vmax (r : Robot.t) = { v_tcp = r.max_tcp_speed; v_ori = 500.; v_leax = 5000.; v_reax = 1000. }

(* installed-facts.md §3 "speeddata": vN = [N, 500, 5000, 1000]. *)
let speeddata =
  List.map (fun n -> (Printf.sprintf "v%d" n,
                      { v_tcp = float_of_int n; v_ori = 500.; v_leax = 5000.; v_reax = 1000. }))
    [ 5; 10; 20; 30; 40; 50; 60; 80; 100; 150; 200; 300; 400; 500; 600; 800; 1000; 1500; 2000;
      2500; 3000; 4000; 5000; 6000; 7000 ]
  @ [ ("vmax", vmax Robot.irb120) ]

(* installed-facts.md §3 "zonedata", the table row by row. *)
let zonedata =
  let z name finep t o e zo l r =
    (name, { finep; pzone_tcp = t; pzone_ori = o; pzone_eax = e; zone_ori = zo; zone_leax = l; zone_reax = r }) in
  [ z "fine" true 0. 0. 0. 0. 0. 0.;
    z "z0" false 0.3 0.3 0.3 0.03 0.3 0.03;
    z "z1" false 1. 1. 1. 0.1 1. 0.1;
    z "z5" false 5. 8. 8. 0.8 8. 0.8;
    z "z10" false 10. 15. 15. 1.5 15. 1.5;
    z "z15" false 15. 23. 23. 2.3 23. 2.3;
    z "z20" false 20. 30. 30. 3.0 30. 3.0;
    z "z30" false 30. 45. 45. 4.5 45. 4.5;
    z "z40" false 40. 60. 60. 6.0 60. 6.0;
    z "z50" false 50. 75. 75. 7.5 75. 7.5;
    z "z60" false 60. 90. 90. 9.0 90. 9.0;
    z "z80" false 80. 120. 120. 12. 120. 12.;
    z "z100" false 100. 150. 150. 15. 150. 15.;
    z "z150" false 150. 225. 225. 23. 225. 23.;
    z "z200" false 200. 300. 300. 30. 300. 30. ]

let stoppointdata =
  let inpos n = (Printf.sprintf "inpos%d" n,
                 { stop_type = Inpos; progsynch = true; inpos_position = float_of_int n;
                   inpos_speed = float_of_int n; inpos_mintime = 0.; inpos_maxtime = 20.;
                   stoptime = 0.; followtime = 0. }) in
  let timed kind name x =
    (name, { stop_type = kind; progsynch = kind = Fllwtime; inpos_position = 0.; inpos_speed = 0.;
             inpos_mintime = 0.; inpos_maxtime = 0.;
             stoptime = (if kind = Stoptime then x else 0.);
             followtime = (if kind = Fllwtime then x else 0.) }) in
  [ inpos 20; inpos 50; inpos 100;
    timed Stoptime "stoptime0_5" 0.5; timed Stoptime "stoptime1_0" 1.0; timed Stoptime "stoptime1_5" 1.5;
    timed Fllwtime "fllwtime0_5" 0.5; timed Fllwtime "fllwtime1_0" 1.0; timed Fllwtime "fllwtime1_5" 1.5 ]

(* installed-facts.md §3, BASE module data [RC-BASE]. *)
let load0 = { mass = 0.001; cog = { x = 0.; y = 0.; z = 0.001 }; aom = unit_orient; ix = 0.; iy = 0.; iz = 0. }
let tool0 = { tool_robhold = true; tframe = identity; tool_mass = load0.mass }
let wobj0 = { wobj_robhold = false; ufprog = true; ufmec = ""; uframe = identity; oframe = identity }

let find table name =
  let n = String.lowercase_ascii name in
  List.assoc_opt n (List.map (fun (k, v) -> (String.lowercase_ascii k, v)) table)
