MODULE reference_target_semi_value
! @format 2
! @section 2.16
! @section 4.5
! @expect semantic-error 9:5
! @description Section 2.16: sig1 represents an input device and refuses the assignment sig1 := 1.
  VAR signaldi sig1;
  PROC main()
    sig1 := 1;
  ENDPROC
ENDMODULE
