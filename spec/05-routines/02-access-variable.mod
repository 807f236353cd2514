MODULE access_variable
! @format 2
! @section 5.2
! @expect ok
! @description Table of section 5.2, row variable: legal for in, var, inout and ref parameters; elements and components of variables too.
  VAR num n;
  VAR num table{3};
  VAR pos p;
  VAR num d;
  PROC main()
    take_in n;
    take_var n;
    take_var table{2};
    take_var p.x;
    take_inout n;
    take_inout p.y;
    d := Dim(table, 1);
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
