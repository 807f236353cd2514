MODULE precedence
! @format 3
! @section 3.1
! @expect ok
! @description The evaluation order of section 3.1's table: * before +, operators of equal priority from left to right, AND before OR, parentheses first.
! @output 14
! @output 20
! @output 3
! @output 2
! @output TRUE
! @exit 0
  PROC main()
    VAR num two := 2;
    VAR bool t := TRUE;
    VAR bool f := FALSE;
    TPWrite "" \Num:=two + 3 * 4;
    TPWrite "" \Num:=(two + 3) * 4;
    TPWrite "" \Num:=10 - 4 - 3;
    TPWrite "" \Num:=12 / two / 3;
    TPWrite "" \Bool:=t OR f AND f;
  ENDPROC
ENDMODULE
