MODULE index_zero_in_target
! @format 3
! @section 3.6
! @section 4.5
! @section 12
! @expect ok
! @description Indices start at 1: assigning to element 0 raises ERR_OUTOFBND at the assignment (chapter 12).
! @exit 1
! @error ERR_OUTOFBND 13:5
  VAR num a{3};
  PROC main()
    VAR num i := 0;
    a{i} := 1;
    TPWrite "after";
  ENDPROC
ENDMODULE
