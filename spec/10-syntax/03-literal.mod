MODULE literal
! @section 3.5
! @section 2.5
! @section 2.6
! @section 2.7
! @expect ok
! @description The literals of section 3.5: 0.5, 1E2, "limit", TRUE.
  VAR num x;
  VAR string s;
  VAR bool b;
  PROC main()
    x := 0.5;
    x := 1E2;
    s := "limit";
    b := TRUE;
  ENDPROC
ENDMODULE
