MODULE module_variable_keeps_value
! @format 3
! @section 2.21
! @expect ok
! @description Module variables are static (section 2.21): their value stays from one call of a routine to the next, until the next assignment.
! @output 1
! @output 2
! @output 3
! @exit 0
  VAR num calls;
  PROC count()
    calls := calls + 1;
    TPWrite "" \Num:=calls;
  ENDPROC
  PROC main()
    count;
    count;
    count;
  ENDPROC
ENDMODULE
