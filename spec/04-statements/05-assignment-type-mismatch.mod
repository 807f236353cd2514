MODULE assignment_type_mismatch
! @format 2
! @section 4.5
! @section 1.4
! @expect semantic-error 9:10
! @description The semantic error of section 1.4: VAR num a; a := "John"; refused at the right-hand side.
  VAR num a;
  PROC main()
    a := "John";
  ENDPROC
ENDMODULE
