MODULE call_continues_after
! @format 3
! @section 4.6
! @section 5.4
! @expect ok
! @description After the procedure ends (at ENDPROC, an implicit return, section 5.4), execution continues with the statement after the call (section 4.6); calls nest.
! @output main 1
! @output outer 1
! @output inner
! @output outer 2
! @output main 2
! @exit 0
  PROC inner()
    TPWrite "inner";
  ENDPROC
  PROC outer()
    TPWrite "outer 1";
    inner;
    TPWrite "outer 2";
  ENDPROC
  PROC main()
    TPWrite "main 1";
    outer;
    TPWrite "main 2";
  ENDPROC
ENDMODULE
