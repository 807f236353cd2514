MODULE bench_records
  ! 200,000 record updates and calls of an Offs-like function on a pos.
  FUNC pos shift(pos p, num dx, num dy, num dz)
    VAR pos q;
    q := p;
    q.x := p.x + dx;
    q.y := p.y + dy;
    q.z := p.z + dz;
    RETURN q;
  ENDFUNC

  PROC main()
    VAR pos p := [0, 0, 0];
    FOR k FROM 1 TO 200000 DO
      p := shift(p, 1, -1, 0.5);
      p.z := p.z - 0.25;
    ENDFOR
    TPWrite "x=" \Num:=p.x;
    TPWrite "y=" \Num:=p.y;
    TPWrite "z=" \Num:=p.z;
  ENDPROC
ENDMODULE
