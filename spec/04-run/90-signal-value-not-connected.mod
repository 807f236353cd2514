MODULE signal_value_not_connected
! @format 3
! @section 2.16
! @expect ok
! @description A signal variable declared in the program is connected to no signal of the I/O configuration: reading its value (a semi-value object in value context, section 2.16) raises ERR_NO_ALIASIO_DEF at the statement (doc/rulings.md R-8-a).
! @output before
! @exit 1
! @error ERR_NO_ALIASIO_DEF 12:5
  VAR signaldi di1;
  PROC main()
    TPWrite "before";
    IF di1 = 1 TPWrite "one";
    TPWrite "after";
  ENDPROC
ENDMODULE
