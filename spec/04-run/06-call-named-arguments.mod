MODULE call_named_arguments
! @format 3
! @section 4.6
! @section 3.11
! @expect ok
! @description Required arguments may carry their parameter's name (section 4.6's move example); the values reach the parameters named.
! @output tool=1 dest=2 data=3
! @exit 0
  PROC move(num tool, num dest, num movedata)
    TPWrite "tool=" + NumToStr(tool, 0) + " dest=" + NumToStr(dest, 0) + " data=" + NumToStr(movedata, 0);
  ENDPROC
  PROC main()
    move tool := 1, dest := 2, movedata := 3;
  ENDPROC
ENDMODULE
