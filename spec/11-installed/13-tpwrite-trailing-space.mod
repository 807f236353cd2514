MODULE tpwrite_trailing_space
! @format 3
! @section 13
! @expect ok
! @description TPWrite writes its text as it is, spaces included; the value follows the text directly, with no separator.
! @output   two leading, two trailing  
! @output value 7
! @output value7
! @exit 0
  PROC main()
    TPWrite "  two leading, two trailing  ";
    TPWrite "value " \Num:=7;
    TPWrite "value" \Num:=7;
  ENDPROC
ENDMODULE
