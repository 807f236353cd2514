MODULE access_constant
! @format 2
! @section 5.2
! @section 11
! @expect ok
! @description Table of section 5.2, row constant: legal for in and ref (Dim's datobj) parameters.
  CONST num limit := 10;
  CONST num table{3} := [1, 2, 3];
  VAR num n;
  PROC main()
    take_in limit;
    take_in table{2};
    n := Dim(table, 1);
  ENDPROC

  PROC take_in(num x)
  ENDPROC
  PROC take_var(VAR num x)
  ENDPROC
  PROC take_pers(PERS num x)
  ENDPROC
  PROC take_inout(INOUT num x)
  ENDPROC
ENDMODULE
