MODULE sig_waituntil_num
! @format 2
! @section 4.6
! @section 13
! @expect semantic-error 9:15
! @description WaitUntil waits for a bool condition (ABB: Cond, data type bool): a num is refused.
  VAR num count;
  PROC main()
    WaitUntil count \MaxTime:=2;
  ENDPROC
ENDMODULE
