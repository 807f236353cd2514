MODULE assignment_to_function
! @format 2
! @section 4.5
! @section 3.6
! @expect semantic-error 8:5
! @description A function is not a data object; as assignment target it is refused at its name.
  PROC main()
    level := 1;
  ENDPROC
  FUNC num level()
    RETURN 0;
  ENDFUNC
ENDMODULE
