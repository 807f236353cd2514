MODULE assignment_to_loop_variable
! @format 2
! @section 4.5
! @section 4.18
! @expect semantic-error 11:7
! @description A loop variable is read-only and cannot be updated by the statements of the FOR loop; refused at the target.
  VAR num a{10};
  PROC main()
    FOR i FROM 1 TO 10 DO
      a{i} := 0;
      i := i + 1;
    ENDFOR
  ENDPROC
ENDMODULE
