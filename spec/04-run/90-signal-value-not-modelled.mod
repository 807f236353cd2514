MODULE signal_value_not_modelled
! @format 3
! @section 2.16
! @expect ok
! @description The value of an I/O signal (a semi-value object read in value context, section 2.16) needs a model of I/O, which rapid-sem does not have yet: the run ends as unsupported, exit status 4.
! @output before
! @exit 4
  VAR signaldi di1;
  PROC main()
    TPWrite "before";
    IF di1 = 1 TPWrite "one";
    TPWrite "after";
  ENDPROC
ENDMODULE
