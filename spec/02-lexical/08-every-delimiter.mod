MODULE every_delimiter
! @section 2.8
! @expect ok
! @description Every delimiter of section 2.8, simple and compound, in a place where the grammar allows it.
  VAR num a{3};
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e := 1;
  VAR num f := 1;
  VAR pos p;
  PROC main(\switch s)
    ! { } ( ) [ ] , . = < > + - * / : ; ! \ ? := <> >= <=
    a{1} := (b + c - d) * e / f;
    b := a{2};
    p := [1, 2, 3];
    p.x := 1;
    IF a{1} = b AND a{1} < b AND a{1} > b AND a{1} <> b AND a{1} >= b AND a{1} <= b THEN
      lbl:
      q \on, c;
      q \on ? s, c;
    ENDIF
  ENDPROC
ENDMODULE
