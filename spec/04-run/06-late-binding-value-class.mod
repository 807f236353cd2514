MODULE late_binding_value_class
! @format 3
! @section 4.6
! @section 2.16
! @expect ok
! @description Section 2.16: an object of a non-value type (a clock) is passed only to a VAR (or REF) parameter. A late-bound call that passes one to the INOUT anytype parameter of Incr raises ERR_CALLPROC when it runs, as the direct call is a static error; to a VAR clock parameter it is an alias.
! @output to var: passed
! @output to inout: 
! @output callproc
! @exit 0
  VAR clock watch;
  PROC by_var(VAR clock c)
    TPWrite "to var: passed";
  ENDPROC
  PROC main()
    % "by_var" % watch;
    TPWrite "to inout: ";
    % "Incr" % watch;
  ERROR
    IF ERRNO = ERR_CALLPROC THEN
      TPWrite "callproc";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
