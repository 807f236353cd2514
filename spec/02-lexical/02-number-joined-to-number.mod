MODULE number_joined_to_number
! @section 2.2
! @expect lexical-error 7:10
! @description 1.2.3 is the literal 1.2 touching the literal .3: numeric literals must be separated.
  VAR num x;
  PROC main()
    x := 1.2.3;
  ENDPROC
ENDMODULE
