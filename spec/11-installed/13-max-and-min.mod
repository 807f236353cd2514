MODULE max_and_min
! @format 3
! @section 13
! @expect ok
! @description Max gives the larger and Min the smaller of two values.
! @output 7
! @output -1
! @output 3
! @output -5
! @exit 0
  PROC main()
    TPWrite "" \Num:=Max(3, 7);
    TPWrite "" \Num:=Max(-1, -5);
    TPWrite "" \Num:=Min(3, 7);
    TPWrite "" \Num:=Min(-1, -5);
  ENDPROC
ENDMODULE
