MODULE tperase_use
! @format 3
! @section 13
! @expect ok
! @description TPErase clears the FlexPendant's display; lines already written stay in the program's output, which TPErase does not change (reading: the output is the sequence of lines written).
! @output first
! @output second
! @exit 0
  PROC main()
    TPWrite "first";
    TPErase;
    TPWrite "second";
  ENDPROC
ENDMODULE
