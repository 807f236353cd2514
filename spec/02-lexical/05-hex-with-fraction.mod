MODULE hex_with_fraction
! @section 2.5
! @expect lexical-error 7:10
! @description A hex literal has no fraction: 0x1 touches the literal .5.
  VAR num x;
  PROC main()
    x := 0x1.5;
  ENDPROC
ENDMODULE
