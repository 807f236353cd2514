MODULE access_read_only_variable
! @format 2
! @section 5.2
! @section 4.18
! @section 12
! @expect ok
! @description Table of section 5.2, row read-only variable (FOR loop variable, ERRNO, INTNO): legal for in and ref (Present's datobj) parameters.
  VAR bool b;
  PROC main()
    FOR i FROM 1 TO 3 DO
      take_in i;
      b := Present(i);
    ENDFOR
    take_in ERRNO;
    b := Present(ERRNO);
  ENDPROC
  TRAP on_event
    take_in INTNO;
  ENDTRAP

  PROC take_in(num x)
  ENDPROC
  PROC take_var(VAR num x)
  ENDPROC
  PROC take_pers(PERS num x)
  ENDPROC
  PROC take_inout(INOUT num x)
  ENDPROC
ENDMODULE
