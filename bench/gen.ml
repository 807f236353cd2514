(* A generated module in the style of CAD / offline-programming output: long procedures of
   MoveL with inline robtarget aggregates, a block of CONST robtarget declarations, and at
   regular intervals the cell logic that uses every statement form of chapter 4, so that the
   benchmark times the whole grammar and not only aggregates.

   Deterministic: the same seed and size give the same text on every run of the same OCaml
   version (Random.State is seeded explicitly, and floats are printed with fixed precision). *)

type t = { rng : Random.State.t; out : Buffer.t; mutable targets : int; mutable paths : int;
           mutable logic : int }

let pr g fmt = Printf.bprintf g.out fmt
let line g s = Buffer.add_string g.out s; Buffer.add_char g.out '\n'

(* CAD tools print the shortest decimal for a fixed precision: "1125.58", "-0.7", "0". *)
let decimal g precision x =
  let s = Printf.sprintf "%.*f" precision x in
  let n = ref (String.length s) in
  if String.contains s '.' then begin
    while s.[!n - 1] = '0' do decr n done;
    if s.[!n - 1] = '.' then decr n
  end;
  let s = String.sub s 0 !n in
  Buffer.add_string g.out (if s = "-0" then "0" else s)

let coordinate g = decimal g 2 (Random.State.float g.rng 5000. -. 2500.)

(* A unit quaternion, as the orientation part of a robtarget: the installed type orient
   wants q1^2 + q2^2 + q3^2 + q4^2 = 1, and CAD tools write normalised ones. *)
let quaternion g =
  let r () = Random.State.float g.rng 2. -. 1. in
  let a = r () and b = r () and c = r () and d = r () in
  let n = sqrt ((a *. a) +. (b *. b) +. (c *. c) +. (d *. d)) in
  let n = if n = 0. then 1. else n in
  Buffer.add_char g.out '[';
  decimal g 5 (a /. n); Buffer.add_char g.out ',';
  decimal g 5 (b /. n); Buffer.add_char g.out ',';
  decimal g 5 (c /. n); Buffer.add_char g.out ',';
  decimal g 5 (d /. n);
  Buffer.add_char g.out ']'

(* A robtarget aggregate: [trans, rot, robconf, extax]; the external axes are mostly the
   "not used" value 9E+09, with a track axis on some targets. *)
let robtarget g =
  Buffer.add_string g.out "[[";
  coordinate g; Buffer.add_char g.out ','; coordinate g; Buffer.add_char g.out ',';
  coordinate g; Buffer.add_string g.out "],";
  quaternion g;
  pr g ",[%d,%d,%d,%d]," (Random.State.int g.rng 4 - 2) (Random.State.int g.rng 4 - 2)
    (Random.State.int g.rng 4 - 2) (Random.State.int g.rng 8);
  if Random.State.int g.rng 10 = 0 then begin
    Buffer.add_char g.out '['; decimal g 1 (Random.State.float g.rng 4000.);
    Buffer.add_string g.out ",9E+09,9E+09,9E+09,9E+09,9E+09]]"
  end
  else Buffer.add_string g.out "[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]"

let pick g a = a.(Random.State.int g.rng (Array.length a))
let speeds = [| "v50"; "v100"; "v200"; "v500"; "v1000"; "v2000"; "vmax"; "vSeam" |]
let zones = [| "fine"; "z0"; "z1"; "z5"; "z10"; "z50"; "zSeam" |]
let tools = [| "tool0"; "tWeldGun"; "tGripper" |]
let wobjs = [| "wobj0"; "wobjPart"; "wobjTable" |]

let motion_tail g =
  pr g ", %s, %s, %s" (pick g speeds) (pick g zones) (pick g tools);
  if Random.State.int g.rng 4 > 0 then pr g "\\WObj:=%s" (pick g wobjs);
  Buffer.add_string g.out ";\n"

(* One motion instruction of a CAD path. *)
let move g =
  match Random.State.int g.rng 100 with
  | n when n < 80 ->
      Buffer.add_string g.out "    MoveL "; robtarget g; motion_tail g
  | n when n < 88 ->
      pr g "    MoveJ p%d" (1 + Random.State.int g.rng (max 1 g.targets)); motion_tail g
  | n when n < 93 ->
      Buffer.add_string g.out "    MoveC "; robtarget g; Buffer.add_string g.out ", ";
      robtarget g; motion_tail g
  | n when n < 95 ->
      pr g "    MoveL Offs(p%d,0,0,%d), %s, %s, %s;\n"
        (1 + Random.State.int g.rng (max 1 g.targets)) (10 * Random.State.int g.rng 20)
        (pick g speeds) (pick g zones) (pick g tools)
  | n when n < 97 -> pr g "    SetDO doGun, %d;\n" (Random.State.int g.rng 2)
  | n when n < 98 -> pr g "    WaitTime %s;\n" (pick g [| "0.2"; "0.5"; "1"; "1.5E-1" |])
  | _ -> pr g "    ! seam %d, segment %d\n" g.paths (Random.State.int g.rng 1000)

let header g seed =
  line g "%%%";
  line g "  VERSION:1";
  line g "  LANGUAGE:ENGLISH";
  line g "%%%";
  line g "";
  pr g "MODULE CadPaths%d\n" seed;
  line g "  ! Generated for the rapid-sem parse benchmark: paths as an offline programming";
  line g "  ! tool writes them, with the cell logic that calls them.";
  line g "  RECORD seampoint";
  line g "    num index;";
  line g "    robtarget target;";
  line g "    string label; ! last line of the record may carry a comment";
  line g "  ENDRECORD";
  line g "  LOCAL RECORD weldparams";
  line g "    num current;";
  line g "    num voltage;";
  line g "  ENDRECORD";
  line g "  ALIAS num seamid;";
  line g "  LOCAL ALIAS string label;";
  line g "";
  line g "  PERS tooldata tWeldGun := [TRUE,[[12.5,0,310.25],[0.92388,0,0.38268,0]],\
          [3.2,[0,0,120],[1,0,0,0],0,0,0]];";
  line g "  PERS tooldata tGripper := [TRUE,[[0,0,180],[1,0,0,0]],[1.5,[0,0,60],[1,0,0,0],0,0,0]];";
  line g "  PERS wobjdata wobjPart := [FALSE,TRUE,\"\",[[1200,-350,620],[1,0,0,0]],\
          [[0,0,0],[1,0,0,0]]];";
  line g "  TASK PERS wobjdata wobjTable := [FALSE,TRUE,\"\",[[0,900,450],[0.70711,0,0,0.70711]],\
          [[0,0,0],[1,0,0,0]]];";
  line g "  CONST speeddata vSeam := [12.5,500,5000,1000];";
  line g "  CONST zonedata zSeam := [FALSE,0.3,0.5,0.5,0.05,0.5,0.05];";
  line g "  VAR num nCount := 0;";
  line g "  VAR num nProgram := 1;";
  line g "  VAR num nTable{4,3} := [[1,2,3],[4,5,6],[7,8,9],[10,11,12]];";
  line g "  LOCAL CONST string sPrefix := \"Path_\";";
  line g "  CONST string sBanner := \"Cell \"\"A\"\" \\\\ line 2 \\41\\42\";";
  line g "  CONST num nMask := 0xFF;";
  line g "  CONST num nBits := 0b1011;";
  line g "  CONST num nOct := 0o17;";
  line g "  CONST num nTol := 1.5E-3;";
  line g "  CONST num nMaxRetry := 3;";
  line g "  VAR bool bAbort := FALSE;";
  line g "  VAR intnum irStop;";
  line g "  VAR errnum ERR_SEAM := -1;";
  line g "  VAR seampoint spLast;";
  line g "  VAR weldparams wpCurrent := [180,22.5];";
  line g "  ! taught and generated targets"

let target g =
  g.targets <- g.targets + 1;
  pr g "  CONST robtarget p%d := " g.targets; robtarget g; Buffer.add_string g.out ";\n"

(* The cell logic: every statement form of chapter 4, the BACKWARD, ERROR (with and without an
   error number list) and UNDO clauses of §5.4-§5.6 and §7, functions and traps. [k] makes the
   names of each copy distinct. *)
let logic g =
  g.logic <- g.logic + 1;
  let k = g.logic in
  pr g {|
  PROC main%d()
    ! cell main loop
    CONNECT irStop WITH tStop%d;
    ISignalDI diStop, 1, irStop;
    nCount := 0;
    FOR i FROM 1 TO %d STEP 2 DO
      Path_%d;
      IF bAbort THEN
        BREAK;
      ENDIF
    ENDFOR
    WHILE NOT bAbort AND nCount < nMaxRetry DO
      nCount := nCount + 1;
      IF nCount MOD 2 = 0 CONTINUE;
      nTable{nCount, 2} := -nTable{1, nCount} * 2.5 / 3 DIV 1 + 7;
      spLast.target.trans.z := spLast.target.trans.z + 0.5;
    ENDWHILE
    TEST nProgram
    CASE 1, 2:
      Path_%d;
    CASE 3:
      %%sPrefix + NumToStr(nProgram, 0)%%;
    DEFAULT:
      TPWrite sBanner + " unknown program " \Num:=nProgram;
    ENDTEST
    IF nProgram > 10 THEN
      GOTO done;
    ELSEIF nProgram < 0 OR bAbort XOR TRUE THEN
      nProgram := Abs(nProgram);
    ELSE
      nProgram := nProgram + 1;
    ENDIF
    WeldSeam%d p1 \Via:=p2, nCount, nTable;
    WeldSeam%d p2 \Fast, nCount, nTable;
  done:
    RETURN;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      nProgram := 1;
      RETRY;
    ELSEIF ERRNO = ERR_WAIT_MAXTIME THEN
      TRYNEXT;
    ELSE
      RAISE;
    ENDIF
  UNDO
    bAbort := FALSE;
  ENDPROC

  PROC WeldSeam%d(robtarget pStart, \robtarget Via | num Offset, INOUT num nDone,
      VAR num nLog{*,*}, \switch Fast, \wobjdata WObj)
    VAR num nSpeed := 100;
    IF Present(Via) THEN
      MoveC Via, pStart, v100, z1, tWeldGun\WObj:=wobjPart;
    ELSE
      MoveL pStart, v100, fine, tWeldGun\WObj?WObj;
    ENDIF
    IF Present(Fast) nSpeed := nSpeed * 2;
    nDone := nDone + 1;
    IF nDone > 1000 RAISE ERR_SEAM;
  BACKWARD
    MoveL pStart, v100, fine, tWeldGun;
  ERROR (ERR_SEAM, 4711)
    RAISE ERR_SEAM;
  ENDPROC

  FUNC num Distance%d(pos a, pos b)
    RETURN Sqrt(Pow(a.x - b.x, 2) + Pow(a.y - b.y, 2) + Pow(a.z - b.z, 2));
  ERROR
    RETURN -1;
  ENDFUNC

  LOCAL FUNC bool InRange%d(num v, \num lo, \num hi)
    IF Present(lo) AND v < lo RETURN FALSE;
    RETURN NOT (Present(hi) AND v >= hi) OR v <> v;
  ENDFUNC

  TRAP tStop%d
    bAbort := TRUE;
    StopMove;
    IF nCount >= 3 EXIT;
  UNDO
    StartMove;
  ENDTRAP
|}
    k k (3 + k mod 17) (max 1 g.paths) (max 1 g.paths) k k k k k k

let path g moves =
  g.paths <- g.paths + 1;
  pr g "\n  PROC Path_%d()\n" g.paths;
  pr g "    ! seam group %d: %d motions\n" g.paths moves;
  for _ = 1 to moves do move g done;
  if g.paths mod 5 = 0 then begin
    line g "  ERROR";
    line g "    IF ERRNO = ERR_PATH_STOP TRYNEXT;";
    line g "    RAISE;"
  end;
  line g "  ENDPROC"

(* The text stops growing once it reaches [size] bytes: the module is then closed, so the
   result is a little larger than [size]. A tenth of it is CONST robtarget declarations,
   the rest procedures of 500 to 3000 motions, with the cell logic after every 200 KB. *)
let generate ~seed ~size =
  let g = { rng = Random.State.make [| seed |]; out = Buffer.create (size + 65536);
            targets = 0; paths = 0; logic = 0 } in
  header g seed;
  target g;
  target g;
  while Buffer.length g.out < size / 10 do target g done;
  let next_logic = ref 0 in
  logic g;
  while Buffer.length g.out < size do
    let remaining = (size - Buffer.length g.out) / 160 in
    path g (max 1 (min remaining (500 + Random.State.int g.rng 2500)));
    if Buffer.length g.out >= !next_logic then begin
      logic g;
      next_logic := Buffer.length g.out + 200_000
    end
  done;
  line g "ENDMODULE";
  Buffer.contents g.out
