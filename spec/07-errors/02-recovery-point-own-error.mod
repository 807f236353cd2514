MODULE recovery_point_own_error
! @format 3
! @section 7.2
! @expect ok
! @description A recovery point is an ordinary ERROR clause with a list (section 7.2): an error of its list raised in the routine itself is handled there.
! @output handler 56
! @output after
! @exit 0
  PROC main()
    RAISE 56;
    TPWrite "after";
  ERROR (56)
    TPWrite "handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
