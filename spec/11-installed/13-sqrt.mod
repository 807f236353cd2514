MODULE sqrt_use
! @format 3
! @section 13
! @expect ok
! @description Sqrt gives the square root; exact for perfect squares, compared with a tolerance otherwise.
! @output 4
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Num:=Sqrt(16);
    TPWrite "" \Bool:=Abs(Sqrt(2) - 1.41421) < 0.0001;
  ENDPROC
ENDMODULE
