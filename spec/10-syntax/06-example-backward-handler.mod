MODULE example_backward_handler
! @section 6.2
! @expect ok
! @description The MoveTo example of sections 6.2 and 6.3 (without the execution-order numbers the manual prints before each line).
  PROC MoveTo ()
    MoveL p1,v500,z10,tool1;
    MoveC p2,p3,v500,z10,tool1;
    MoveL p4,v500,z10,tool1;
  BACKWARD
    MoveL p4,v500,z10,tool1;
    MoveC p2,p3,v500,z10,tool1;
    MoveL p1,v500,z10,tool1;
  ENDPROC
ENDMODULE
