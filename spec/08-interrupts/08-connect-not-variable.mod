MODULE connect_not_variable
! @format 3
! @section 4.15
! @expect ok
! @description A CONNECT target must be a variable (section 4.15); an INOUT parameter may be one, but bound to a persistent it is not: ERR_CNTNOTVAR, which only the run can tell. Bound to a variable it connects.
! @output connected TRUE
! @output ERR_CNTNOTVAR TRUE
  VAR intnum v;
  PERS intnum p := 0;
  TRAP t
  ENDTRAP
  PROC attach(INOUT intnum target)
    CONNECT target WITH t;
  ENDPROC
  PROC main()
    attach v;
    TPWrite "connected " \Bool:=(v <> 0);
    attach p;
    TPWrite "not reached";
  ERROR
    TPWrite "ERR_CNTNOTVAR " \Bool:=(ERRNO = ERR_CNTNOTVAR);
    RETURN;
  ENDPROC
ENDMODULE
