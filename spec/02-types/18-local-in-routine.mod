MODULE local_in_routine
! @format 2
! @section 2.18
! @expect semantic-error 8:5
! @description The LOCAL directive can only be used at module level, not inside a routine; refused at LOCAL.
  PROC main()
    VAR num a;
    LOCAL VAR num b;
  ENDPROC
ENDMODULE
