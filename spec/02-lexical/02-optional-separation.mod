MODULE optional_separation
! @section 2.2
! @expect ok
! @description Delimiters need no white space around them.
  VAR num reg1;VAR num arr{3};
  PROC main()
    reg1:=reg1+1;IF reg1>2 THEN reg1:=0;ENDIF
    arr{1}:=[reg1*2,-3,reg1 DIV 2];
  ENDPROC
ENDMODULE
