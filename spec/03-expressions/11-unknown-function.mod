MODULE unknown_function
! @format 2
! @section 3.11
! @expect semantic-error 8:10
! @description A function that is neither declared nor installed; refused at its name.
  VAR num x;
  PROC main()
    x := nosuch(1);
  ENDPROC
ENDMODULE
