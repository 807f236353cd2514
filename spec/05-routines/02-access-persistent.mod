MODULE access_persistent
! @format 2
! @section 5.2
! @expect ok
! @description Table of section 5.2, row persistent (restored from the text: pers parameters alias persistents): legal for in, pers, inout and ref parameters.
  PERS num total := 0;
  PERS num table{3} := [0, 0, 0];
  VAR num d;
  PROC main()
    take_in total;
    take_pers total;
    take_pers table{1};
    take_inout total;
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
