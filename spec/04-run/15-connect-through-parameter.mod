MODULE connect_through_parameter
! @format 3
! @section 4.15
! @section 12
! @expect ok
! @description Section 4.15: the CONNECT target "must be (or denote) a module variable (not a routine variable)", and a parameter used as target is a VAR or INOUT one: what it denotes is checked when CONNECT runs. Through a parameter bound to a module variable it connects; bound to a routine variable or, through INOUT, to a persistent, it raises ERR_CNTNOTVAR (chapter 12).
! @output module variable: 
! @output connected
! @output routine variable: 
! @output cntnotvar
! @output persistent: 
! @output cntnotvar
! @output passed on: 
! @output connected
! @exit 0
  VAR intnum module_int;
  VAR intnum other_int;
  PERS intnum pers_int := 0;
  PROC connect_var(VAR intnum target)
    CONNECT target WITH on_interrupt;
    TPWrite "connected";
  ENDPROC
  PROC connect_inout(INOUT intnum target)
    CONNECT target WITH on_interrupt;
    TPWrite "connected";
  ENDPROC
  PROC pass_on(VAR intnum target)
    connect_inout target;
  ENDPROC
  PROC main()
    VAR intnum routine_int;
    TPWrite "module variable: ";
    connect_var module_int;
    TPWrite "routine variable: ";
    connect_var routine_int;
    TPWrite "persistent: ";
    connect_inout pers_int;
    TPWrite "passed on: ";
    pass_on other_int;
  ERROR
    IF ERRNO = ERR_CNTNOTVAR THEN
      TPWrite "cntnotvar";
      TRYNEXT;
    ENDIF
  ENDPROC
  TRAP on_interrupt
    TPWrite "trap";
  ENDTRAP
ENDMODULE
