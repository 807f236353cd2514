MODULE letter_case_lookup
! @format 2
! @section 2.3
! @expect ok
! @description A name is found whatever the letter case of its use.
  VAR num Counter;
  PROC Main()
    counter := COUNTER + 1;
    helper;
  ENDPROC
  PROC HELPER()
  ENDPROC
ENDMODULE
