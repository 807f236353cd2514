MODULE alternatives_both_given
! @format 2
! @section 5.2
! @expect semantic-error 10:28
! @description At most one of mutually exclusive optional parameters may be given; the second is refused at its backslash.
  VAR pose p;
  PROC arcweld(pose position \num speed | num time)
  ENDPROC
  PROC main()
    arcweld p \speed := 25 \time := 2;
  ENDPROC
ENDMODULE
