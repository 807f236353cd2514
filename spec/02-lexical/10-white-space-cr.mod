MODULE white_space_cr
! @section 2.10
! @section 2.2
! @expect ok
! @description A lone carriage return separates tokens like any other line break.
  VAR num x;
  PROC main()
    x := 1;x := 2;
    IF x = 1THENx := 3;ENDIF
  ENDPROC
ENDMODULE
